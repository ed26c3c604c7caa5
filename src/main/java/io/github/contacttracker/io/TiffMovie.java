/*-
 * #%L
 * Contact Tracker: sub-pixel localization of colloidal particles, also when they touch.
 * %%
 * Copyright (C) 2026 Contact Tracker developers
 * %%
 * This program is free software: you can redistribute it and/or modify
 * it under the terms of the GNU General Public License as
 * published by the Free Software Foundation, either version 3 of the
 * License, or (at your option) any later version.
 * 
 * This program is distributed in the hope that it will be useful,
 * but WITHOUT ANY WARRANTY; without even the implied warranty of
 * MERCHANTABILITY or FITNESS FOR A PARTICULAR PURPOSE.  See the
 * GNU General Public License for more details.
 * 
 * You should have received a copy of the GNU General Public
 * License along with this program.  If not, see
 * <http://www.gnu.org/licenses/gpl-3.0.html>.
 * #L%
 */
package io.github.contacttracker.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import ij.ImagePlus;
import ij.io.FileInfo;
import ij.io.FileOpener;
import ij.io.TiffDecoder;
import ij.process.ByteProcessor;
import ij.process.FloatProcessor;
import ij.process.ImageProcessor;
import ij.process.ShortProcessor;

/**
 * A TIFF file as a virtual stack: its planes are read when asked for, so a movie of any size is tracked in a fixed
 * heap.
 * <p>
 * Classic TIFF (multi-page, ImageJ stacks and hyperstacks, LZW/Deflate/PackBits compression, 8-, 16-bit signed or
 * unsigned and 32-bit integer or float) is read by ImageJ 1's own TIFF decoder, which also gives the calibration
 * and the hyperstack's dimensions. ImageJ 1.54p cannot read two kinds of TIFF, both read here by a small reader of
 * our own: <b>BigTIFF</b> (64-bit offsets, files over 4 GB; ImageJ reads its header as a classic TIFF and fails)
 * and <b>64-bit float</b> samples (what numpy writes by default; ImageJ stops at "Unsupported BitsPerSample: 64").
 * The same reader takes the pages ImageJ 1 reads wrongly or not at all: several samples per pixel stored plane
 * after plane (what tifffile writes for a stack of 3 or 4 frames) or grey with extra samples (alpha), each sample
 * read as a channel; pages whose predictor or gapped strips ImageJ 1 ignores ({@link #misreadByImageJ}); strips or
 * tiles, uncompressed or LZW, Deflate or PackBits ({@link TiffChunks}). It reads no
 * calibration. OME-TIFF is read as ImageJ 1 reads it (its planes, in file order); its OME-XML sizes and order are
 * checked so that channels or Z planes are not taken for time points.
 * <p>
 * Either way the file's directories are first read and checked by {@link TiffDirectories}, so that neither reader
 * believes a number the file has not backed (a looping chain, a size or a strip beyond the file), and ImageJ's
 * messages are caught ({@link ImageJMessages}). The same holds for a movie read by offset ({@link #openByOffset},
 * the Spark job's way, from any {@link SeekableBytes}): the same checks of its directories, then its planes, each
 * decoded by our reader.
 */
final class TiffMovie {

	private TiffMovie() {}

	/** @return whether the file starts with a TIFF or BigTIFF header */
	static boolean isTiff(final byte[] head) {
		return head.length >= 4 && (head[0] == 'I' && head[1] == 'I' && (head[2] == 42 || head[2] == 43) && head[3] == 0 ||
			head[0] == 'M' && head[1] == 'M' && head[2] == 0 && (head[3] == 42 || head[3] == 43));
	}

	/**
	 * @return the file as an image backed by a virtual stack
	 * @throws IOException naming the file and what is wrong
	 */
	static ImagePlus open(final Path file) throws IOException {
		// every directory checked before ImageJ's decoder or ours reads one: the file's numbers size nothing unchecked
		final TiffDirectories.Layout layout = TiffDirectories.read(file);
		if (samplesAsChannels(layout)) return channels(own(file, samplePlanes(layout), true), layout);
		if (layout.big() || misreadByImageJ(file.toString(), layout)) return own(file, layout, false);
		final Path abs = file.toAbsolutePath();
		final ImageJMessages.Result<FileInfo[]> info;
		try {
			info = ImageJMessages.call(file, () -> new TiffDecoder(abs.getParent().toString() + "/", abs.getFileName()
				.toString()).getTiffInfo());
		}
		catch (final IOException e) {
			// what ImageJ 1 cannot decode, ours may (64-bit float); if not, ours says why
			return own(file, layout, false);
		}
		if (info.value() == null || info.value().length == 0) throw new IOException("cannot read " + file + ": no " +
			"image in this TIFF" + (info.messages().isEmpty() ? "" : " (ImageJ: " + info.messages() + ")"));
		return ij(file, planes(file, info.value()));
	}

	/** One FileInfo per plane: ImageJ describes the planes of its own contiguous stacks by one FileInfo. */
	private static FileInfo[] planes(final Path file, final FileInfo[] info) throws IOException {
		final FileInfo fi = info[0];
		if (info.length > 1 || fi.nImages <= 1) {
			for (final FileInfo f : info)
				f.nImages = 1;
			return info;
		}
		final long[] at = contiguous(file.toString(), fi, file.toFile().length());
		final FileInfo[] planes = new FileInfo[at.length];
		for (int i = 0; i < planes.length; i++) {
			planes[i] = (FileInfo) fi.clone();
			planes[i].nImages = 1;
			planes[i].longOffset = at[i];
		}
		return planes;
	}

	/**
	 * @param fi the one directory of an ImageJ stack whose planes follow each other
	 * @param length the file's length (bytes)
	 * @return where each plane starts, the description's image count checked against the file before anything is
	 *         allocated for each
	 */
	private static long[] contiguous(final String file, final FileInfo fi, final long length) throws IOException {
		final long bytes = (long) fi.width * fi.height * fi.getBytesPerPixel();
		final long step = bytes + fi.getGap();
		if (bytes <= 0 || step <= 0 || fi.nImages - 1L > (length - fi.getOffset() - bytes) / step) {
			final long whole = bytes <= 0 || step <= 0 ? 0 : Math.max(0, length - fi.getOffset()) / step;
			throw new IOException("cannot read " + file + ": truncated, it ends in plane " + (whole + 1) + " of " +
				fi.nImages);
		}
		final long[] at = new long[fi.nImages];
		for (int i = 0; i < at.length; i++)
			at[i] = fi.getOffset() + i * step;
		return at;
	}

	private static ImagePlus ij(final Path file, final FileInfo[] planes) throws IOException {
		final FileInfo first = (FileInfo) planes[0].clone();
		final ImagePlus one = firstPlane(file.toString(), first);
		final FileStack stack = new FileStack(file, planes.length, one.getWidth(), one.getHeight(), true, t -> {
			final ImageJMessages.Result<ImageProcessor> ip = ImageJMessages.call(file, () -> new FileOpener(
				(FileInfo) planes[t].clone()).openProcessor());
			if (ip.value() == null) throw new IOException("cannot read plane " + (t + 1) + " of " + file + (ip.messages()
				.isEmpty() ? "" : ": " + ip.messages()));
			return ip.value();
		});
		return withMetadata(file.toString(), file.getFileName().toString(), stack, one, (FileInfo) planes[0].clone(),
			planes.length);
	}

	/** @return plane 1 as ImageJ decodes it: the calibration (incl. signed 16-bit), the bit depth */
	private static ImagePlus firstPlane(final String file, final FileInfo first) throws IOException {
		final ImageJMessages.Result<ImagePlus> opened = ImageJMessages.call(file, () -> new FileOpener(first).openImage());
		if (opened.value() == null) throw new IOException("cannot read " + file + ": ImageJ could not decode its first " +
			"plane (" + describe(first) + (opened.messages().isEmpty() ? "" : "; " + opened.messages()) + ")");
		return opened.value();
	}

	/**
	 * @param one plane 1 as ImageJ opened it: its calibration (incl. signed 16-bit) and bit depth
	 * @param fi the first plane's description: the hyperstack's or the OME-XML's dimensions
	 * @return the image of {@code stack}
	 */
	private static ImagePlus withMetadata(final String file, final String title, final FileStack stack,
		final ImagePlus one, final FileInfo fi, final int planes) throws IOException
	{
		stack.setBitDepth(one.getBitDepth());
		final ImagePlus imp = new ImagePlus(title, stack);
		imp.setCalibration(one.getCalibration());
		imp.setFileInfo(fi);
		final Properties props = new FileOpener(fi).decodeDescriptionString(fi);
		if (props != null) {
			final int c = integer(props, "channels"), z = integer(props, "slices"), t = integer(props, "frames");
			if ((long) c * z * t == planes) imp.setDimensions(c, z, t);
		}
		else if (fi.description != null && fi.description.contains("<OME")) ome(file, imp, fi.description);
		return imp;
	}

	private static String describe(final FileInfo fi) {
		return fi.getBytesPerPixel() * 8 + "-bit, " + fi.width + " x " + fi.height + (fi.compression > 1 ?
			", compression " + fi.compression : "");
	}

	private static int integer(final Properties p, final String key) {
		try {
			return Math.max(1, (int) Double.parseDouble(p.getProperty(key, "1")));
		}
		catch (final NumberFormatException e) {
			return 1;
		}
	}

	private static final Pattern OME_SIZE = Pattern.compile("\\bSize([CZT])=\"(\\d+)\"");
	private static final Pattern OME_ORDER = Pattern.compile("\\bDimensionOrder=\"(XY[CZT]{3})\"");
	private static final Pattern OME_PIXEL = Pattern.compile("\\bPhysicalSizeX=\"([0-9.eE+-]+)\"");

	/**
	 * OME-TIFF: ImageJ 1 reads its planes in file order and ignores the OME-XML. The XML's sizes set the
	 * dimensions where the planes are in ImageJ's order, and planes in any other order of several dimensions are
	 * refused rather than mixed up; {@code PhysicalSizeX} (microns) sets the pixel size.
	 */
	private static void ome(final String file, final ImagePlus imp, final String xml) throws IOException {
		int c = 1, z = 1, t = 1;
		final Matcher m = OME_SIZE.matcher(xml);
		while (m.find()) {
			final int n = (int) Math.min(Integer.MAX_VALUE, Long.parseLong(m.group(2).substring(Math.max(0, m.group(2)
				.length() - 12))));
			switch (m.group(1)) {
				case "C" -> c = n;
				case "Z" -> z = n;
				default -> t = n;
			}
		}
		if ((long) c * z * t != imp.getStackSize()) return; // several series, or sizes we cannot trust: planes as they are
		final Matcher order = OME_ORDER.matcher(xml);
		final String dims = order.find() ? order.group(1) : "XYCZT";
		final long multi = List.of(c, z, t).stream().filter(n -> n > 1).count();
		if (multi > 1 && !dims.equals("XYCZT"))
			throw new IOException("cannot read " + file + ": OME-TIFF with planes in " + dims + " order (C=" + c + ", Z=" +
				z + ", T=" + t + "); re-save it from Fiji (Bio-Formats) as an ImageJ TIFF");
		imp.setDimensions(c, z, t);
		final Matcher px = OME_PIXEL.matcher(xml);
		if (px.find()) {
			final double size = Double.parseDouble(px.group(1));
			if (size > 0) {
				final ij.measure.Calibration cal = imp.getCalibration();
				cal.pixelWidth = cal.pixelHeight = size;
				cal.setUnit("micron");
			}
		}
	}

	// ---- our own reader: BigTIFF, 64-bit float, and every plane read by offset ----

	/** @param samples whether the layout's images are the samples of the file's, each read on its own */
	private static ImagePlus own(final Path file, final TiffDirectories.Layout layout, final boolean samples)
		throws IOException
	{
		final List<TiffDirectories.Directory> planes = checked(file.toString(), layout.directories(), samples);
		final TiffDirectories.Directory p0 = planes.get(0);
		return own(file.getFileName().toString(), new FileStack(file, planes.size(), p0.width(), p0.height(), true, t -> {
			try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
				return decode(SeekableBytes.of(ch, file), planes.get(t), layout.order());
			}
		}), p0);
	}

	private static ImagePlus own(final SeekableBytes bytes, final String title, final TiffDirectories.Layout layout,
		final boolean samples) throws IOException
	{
		final List<TiffDirectories.Directory> planes = checked(bytes.name(), layout.directories(), samples);
		final TiffDirectories.Directory p0 = planes.get(0);
		return own(title, new FileStack(bytes.name(), "", planes.size(), p0.width(), p0.height(), true, t -> decode(
			bytes, planes.get(t), layout.order())), p0);
	}

	/** @return the image of {@code stack}, whose planes are of {@code p0}'s pixel type */
	private static ImagePlus own(final String title, final FileStack stack, final TiffDirectories.Directory p0) {
		final int bits = p0.bits(), format = p0.format();
		stack.setBitDepth(bits == 8 ? 8 : bits == 16 ? 16 : 32);
		final ImagePlus imp = new ImagePlus(title, stack);
		// signed integers are stored with an offset (ImageJ's way); the calibration gives back the file's values
		if (bits == 16 && format == 2) imp.getCalibration().setSigned16BitCalibration();
		if (bits == 8 && format == 2) imp.getCalibration().setFunction(ij.measure.Calibration.STRAIGHT_LINE,
			new double[] { -128, 1 }, "Gray Value");
		return imp;
	}

	/**
	 * @return whether the file's images hold several samples per pixel that are not ImageJ's colour: samples stored
	 *         plane after plane (PlanarConfiguration 2, at any bit depth: Python's {@code tifffile.imwrite} writes a
	 *         stack of 3 or 4 frames so, and ImageJ 1 reads such pages wrongly or not at all), or grey samples side by
	 *         side with extra ones (grey and alpha), or colour of more than 8 bits a sample (ImageJ 1 reads it only
	 *         whole). Each sample is read as a channel, by our reader. Chunky 8-bit RGB (a colour camera's) is left to
	 *         ImageJ, which reads it as colour.
	 */
	private static boolean samplesAsChannels(final TiffDirectories.Layout layout) {
		final TiffDirectories.Directory d0 = layout.directories().get(0);
		if (d0.samples() < 2 || d0.planar() != 2 && d0.photometric() == 2 && d0.bits() == 8) return false;
		for (final TiffDirectories.Directory d : layout.directories())
			if (d.samples() != d0.samples() || d.planar() != d0.planar()) return false;
		return true;
	}

	/**
	 * @return whether ImageJ 1's decoder would give wrong pixels without a word, which our reader gives right: the
	 *         floating-point predictor (3), which it ignores; the horizontal predictor (2) on anything but LZW and
	 *         Deflate data (PackBits, none), which it ignores too; uncompressed strips with a gap between them, which
	 *         it reads as one run of bytes from the first; and signed 8-bit samples, which it reads as unsigned
	 * @throws IOException naming the file and the layout, for a compression neither decoder reads right (JPEG, which
	 *         ImageJ 1 decodes wrongly; LZMA, Zstd, ...)
	 */
	private static boolean misreadByImageJ(final String file, final TiffDirectories.Layout layout) throws IOException {
		boolean misread = false;
		for (final TiffDirectories.Directory d : layout.directories()) {
			if (!TiffCompression.supported(d.compression())) TiffChunks.check(file, d);
			misread |= d.predictor() == 3 || d.predictor() == 2 && !differencedByImageJ(d.compression()) || gapped(d) ||
				d.bits() == 8 && d.format() == 2;
		}
		return misread;
	}

	/** @return whether ImageJ 1 undoes the horizontal predictor on data of this compression: LZW and Deflate only */
	private static boolean differencedByImageJ(final int compression) {
		return compression == 5 || compression == 8 || compression == 32946;
	}

	/** @return whether {@code d} is stored in uncompressed strips that do not follow each other byte for byte */
	private static boolean gapped(final TiffDirectories.Directory d) {
		if (d.compression() != 1 || d.tiled()) return false;
		final long rowBytes = d.planeBytes() / Math.max(1, d.height());
		for (int s = 0; s + 1 < d.offsets().length; s++) {
			final long rows = Math.min(d.rowsPerStrip(), d.height() - (long) s * d.rowsPerStrip());
			if (rows <= 0) break;
			if (d.offsets()[s + 1] != d.offsets()[s] + rows * rowBytes) return true;
		}
		return false;
	}

	/** @return the layout with each image's samples as images of one sample each, page after page */
	private static TiffDirectories.Layout samplePlanes(final TiffDirectories.Layout layout) {
		final List<TiffDirectories.Directory> planes = new ArrayList<>();
		for (final TiffDirectories.Directory d : layout.directories())
			planes.addAll(d.samplePlanes());
		return new TiffDirectories.Layout(layout.little(), layout.big(), planes, layout.firstNext());
	}

	/**
	 * Set on an image whose channels are its pages' samples ({@link #samplesAsChannels}): what they are and, for a
	 * user who wrote frames so, how to write them as frames; said when a run does not choose a channel.
	 */
	static final String SAMPLES = "contact-tracker.samples";

	/** @return the image with its planes as channels, one per sample, and the file's pages as time points */
	private static ImagePlus channels(final ImagePlus imp, final TiffDirectories.Layout layout) {
		final TiffDirectories.Directory d0 = layout.directories().get(0);
		final int n = d0.samples(), pages = layout.directories().size();
		imp.setDimensions(n, 1, pages);
		imp.setProperty(SAMPLES, d0.planar() == 2 ? "they are the " + n + " samples of " + (pages == 1 ? "one page" :
			"each of its " + pages + " pages") + ", stored plane after plane (TIFF PlanarConfiguration 2), as Python's " +
			"tifffile.imwrite stores a stack of " + n + " frames: if they are frames, save one page per frame: " +
			"tifffile.imwrite(p, a, photometric='minisblack')" : d0.photometric() == 2 ? "they are the red, green and " +
				"blue" + (n > 3 ? " (and " + (n - 3) + " extra)" : "") + " samples of each pixel, " + d0.bits() + "-bit colour" :
				"they are the " + n + " samples of each pixel, grey and " + (n - 1) + " extra (TIFF ExtraSamples, e.g. " +
					"alpha): channel 1 is the grey");
		return imp;
	}

	/**
	 * @param samples whether the planes are the samples of the file's images (each plane one sample of its pixels)
	 * @return {@code planes}, which our reader decodes: one sample each, of one size and pixel type, in strips or
	 *         tiles it reads ({@link TiffChunks#check})
	 */
	private static List<TiffDirectories.Directory> checked(final String file,
		final List<TiffDirectories.Directory> planes, final boolean samples) throws IOException
	{
		final TiffDirectories.Directory p0 = planes.get(0);
		for (final TiffDirectories.Directory p : planes) {
			if (p.samples() != 1 && !samples) throw new IOException("cannot read " + file + ": " + p.samples() + " samples per pixel " +
				"(colour?); save one grey channel");
			final int bits = p.bits(), format = p.format();
			final boolean ok = (bits == 8 || bits == 16 || bits == 32) && (format == 1 || format == 2 || format == 3 &&
				bits == 32) || bits == 64 && format == 3;
			if (!ok) throw new IOException("cannot read " + file + ": " + bits + "-bit " + (format == 3 ? "float" : format ==
				2 ? "signed integer" : format == 1 ? "integer" : "format " + format) + " samples are not supported " +
				"(8/16/32-bit integer, 32/64-bit float); convert them, e.g. tifffile.imwrite(p, a.astype('float32'), " +
				"photometric='minisblack')");
			if (p.width() != p0.width() || p.height() != p0.height() || p.bits() != p0.bits() || p.format() != p0
				.format()) throw new IOException("cannot read " + file + ": its pages differ in size or pixel type (a " +
					"pyramid or thumbnails?)");
			if (!simple(p)) TiffChunks.check(file, p);
		}
		return planes;
	}

	/**
	 * A TIFF, BigTIFF or OME-TIFF read plane by plane by offset, wherever its bytes are ({@link SeekableBytes}): the
	 * same image, pixels and calibration as {@link #open} gives for the file, uncompressed or compressed (LZW,
	 * Deflate, PackBits: each strip or tile is found by its offset and decoded by {@link TiffChunks}), after the
	 * same checks of its directories ({@link TiffDirectories}); what {@link #open} refuses (JPEG, LZMA, ...) is
	 * refused in the same line. Classic TIFF's calibration and dimensions come from ImageJ's decoder, shown the first
	 * directory only (so a long movie's chain of directories is walked once, by {@link TiffDirectories}, and never
	 * buffered).
	 *
	 * @throws IOException one line naming the file, and for what it cannot read, how to convert it
	 */
	static ImagePlus openByOffset(final SeekableBytes bytes, final String title) throws IOException {
		final String file = bytes.name();
		final ByteBuffer head = ByteBuffer.allocate((int) Math.min(16, bytes.size()));
		bytes.read(0, head);
		if (!isTiff(head.array())) throw new IOException("cannot read " + file + ": not a TIFF (the Spark job " +
			"reads TIFF, BigTIFF and OME-TIFF); convert it, e.g. in Fiji: open it, then File > Save As > Tiff...");
		final TiffDirectories.Layout layout = TiffDirectories.read(bytes);
		if (samplesAsChannels(layout)) return channels(own(bytes, title, samplePlanes(layout), true), layout);
		if (layout.big()) return own(bytes, title, layout, false);
		if (misreadByImageJ(file, layout)) return own(bytes, title, layout, false);
		final ImageJMessages.Result<FileInfo[]> info;
		try {
			info = ImageJMessages.call(file, () -> new TiffDecoder(bytes.stream(layout.firstNext()), title)
				.getTiffInfo());
		}
		catch (final IOException e) {
			return own(bytes, title, layout, false); // what ImageJ 1 cannot decode (64-bit float), as open() does
		}
		if (info.value() == null || info.value().length == 0) throw new IOException("cannot read " + file + ": no " +
			"image in this TIFF" + (info.messages().isEmpty() ? "" : " (ImageJ: " + info.messages() + ")"));
		final FileInfo fi = info.value()[0];
		List<TiffDirectories.Directory> planes = checked(file, layout.directories(), false);
		if (fi.nImages > planes.size()) { // an ImageJ stack written with one directory: contiguous planes
			final TiffDirectories.Directory p0 = planes.get(0);
			final long bytesPerPlane = (long) fi.width * fi.height * fi.getBytesPerPixel();
			final List<TiffDirectories.Directory> all = new ArrayList<>();
			for (final long at : contiguous(file, fi, bytes.size()))
				all.add(new TiffDirectories.Directory(p0.width(), p0.height(), p0.bits(), p0.samples(), p0.format(), 1,
					new long[] { at }, new long[] { bytesPerPlane }));
			planes = all;
		}
		final FileInfo first = (FileInfo) fi.clone();
		first.nImages = 1;
		first.inputStream = bytes.stream(-1);
		final ImagePlus one = firstPlane(file, first);
		final List<TiffDirectories.Directory> read = planes;
		final TiffDirectories.Directory p0 = read.get(0);
		final FileStack stack = new FileStack(file, "", read.size(), p0.width(), p0.height(), true, t -> decode(bytes,
			read.get(t), layout.order()));
		final FileInfo described = (FileInfo) fi.clone();
		described.nImages = 1;
		return withMetadata(file, title, stack, one, described, read.size());
	}

	/** @return whether the plane is stored as our reader reads a movie's: uncompressed strips of one sample */
	private static boolean simple(final TiffDirectories.Directory p) {
		return p.compression() == 1 && !p.tiled() && p.samples() == 1 && p.predictor() == 1;
	}

	/** @return the bytes of a {@link #simple} plane, its strips read one after the other into one buffer */
	private static ByteBuffer strips(final SeekableBytes file, final TiffDirectories.Directory p,
		final ByteOrder order) throws IOException
	{
		// the directory was checked: the plane's bytes fit the frame budget, its strips lie inside the file
		final ByteBuffer data = ByteBuffer.allocate(Math.multiplyExact(p.width() * p.height(), p.bits() / 8)).order(
			order);
		for (int s = 0; s < p.offsets().length && data.hasRemaining(); s++) {
			final int len = (int) Math.min(p.counts()[s], data.remaining());
			file.read(p.offsets()[s], data.slice(data.position(), len));
			data.position(data.position() + len);
		}
		if (data.hasRemaining()) throw new IOException("cannot read " + file.name() + ": a plane's strips hold fewer " +
			"pixels than " + p.width() + " x " + p.height());
		return data.flip();
	}

	/**
	 * Reads one plane (positional reads: threads may read planes at once) and converts the samples: a
	 * {@link #simple} plane strip after strip, any other by {@link TiffChunks}.
	 */
	private static ImageProcessor decode(final SeekableBytes file, final TiffDirectories.Directory p,
		final ByteOrder order) throws IOException
	{
		final int n = p.width() * p.height();
		final ByteBuffer data = simple(p) ? strips(file, p, order) : ByteBuffer.wrap(TiffChunks.plane(file, p, order))
			.order(order);
		switch (p.bits()) {
			case 8: {
				final byte[] px = new byte[n];
				data.get(px);
				if (p.format() == 2) for (int i = 0; i < n; i++)
					px[i] ^= (byte) 0x80; // signed bytes as unsigned with an offset, as ImageJ stores signed data
				return new ByteProcessor(p.width(), p.height(), px);
			}
			case 16: {
				final short[] px = new short[n];
				data.asShortBuffer().get(px);
				if (p.format() == 2) for (int i = 0; i < n; i++)
					px[i] ^= (short) 0x8000; // ImageJ's signed 16-bit: value + 32768, undone by the calibration
				return new ShortProcessor(p.width(), p.height(), px, null);
			}
			case 32: {
				final float[] px = new float[n];
				for (int i = 0; i < n; i++)
					px[i] = p.format() == 3 ? data.getFloat() : p.format() == 2 ? data.getInt() : data.getInt() & 0xffffffffL;
				return new FloatProcessor(p.width(), p.height(), px);
			}
			default: {
				final float[] px = new float[n];
				for (int i = 0; i < n; i++)
					px[i] = (float) data.getDouble(); // 32-bit float keeps 7 digits, far below any image's noise
				return new FloatProcessor(p.width(), p.height(), px);
			}
		}
	}
}
