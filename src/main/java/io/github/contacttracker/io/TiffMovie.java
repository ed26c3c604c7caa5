package io.github.contacttracker.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
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
 * That reader takes uncompressed, one-sample-per-pixel data, the way tifffile and numpy write them; it reads no
 * calibration. OME-TIFF is read as ImageJ 1 reads it (its planes, in file order); its OME-XML sizes and order are
 * checked so that channels or Z planes are not taken for time points.
 * <p>
 * Either way the file's directories are first read and checked by {@link TiffDirectories}, so that neither reader
 * believes a number the file has not backed (a looping chain, a size or a strip beyond the file), and ImageJ's
 * messages are caught ({@link ImageJMessages}).
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
		if (layout.big()) return own(file, layout);
		final Path abs = file.toAbsolutePath();
		final ImageJMessages.Result<FileInfo[]> info;
		try {
			info = ImageJMessages.call(file, () -> new TiffDecoder(abs.getParent().toString() + "/", abs.getFileName()
				.toString()).getTiffInfo());
		}
		catch (final IOException e) {
			// what ImageJ 1 cannot decode, ours may (64-bit float); if not, ours says why
			return own(file, layout);
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
		final long bytes = (long) fi.width * fi.height * fi.getBytesPerPixel();
		final long length = file.toFile().length();
		// the description's image count is checked against the file before a FileInfo is made for each
		final long end = fi.getOffset() + (fi.nImages - 1) * (bytes + fi.getGap()) + bytes;
		if (bytes <= 0 || end > length) {
			final long whole = bytes <= 0 ? 0 : (length - fi.getOffset()) / (bytes + fi.getGap());
			throw new IOException("cannot read " + file + ": truncated, it ends in plane " + (whole + 1) + " of " +
				fi.nImages);
		}
		final FileInfo[] planes = new FileInfo[fi.nImages];
		for (int i = 0; i < planes.length; i++) {
			planes[i] = (FileInfo) fi.clone();
			planes[i].nImages = 1;
			planes[i].longOffset = fi.getOffset() + i * (bytes + fi.getGap());
		}
		return planes;
	}

	private static ImagePlus ij(final Path file, final FileInfo[] planes) throws IOException {
		final FileInfo first = (FileInfo) planes[0].clone();
		// plane 1: the calibration (incl. signed 16-bit), the bit depth
		final ImageJMessages.Result<ImagePlus> opened = ImageJMessages.call(file, () -> new FileOpener(first).openImage());
		final ImagePlus one = opened.value();
		if (one == null) throw new IOException("cannot read " + file + ": ImageJ could not decode its first plane (" +
			describe(first) + (opened.messages().isEmpty() ? "" : "; " + opened.messages()) + ")");
		final FileStack stack = new FileStack(file, planes.length, one.getWidth(), one.getHeight(), true, t -> {
			final ImageJMessages.Result<ImageProcessor> ip = ImageJMessages.call(file, () -> new FileOpener(
				(FileInfo) planes[t].clone()).openProcessor());
			if (ip.value() == null) throw new IOException("cannot read plane " + (t + 1) + " of " + file + (ip.messages()
				.isEmpty() ? "" : ": " + ip.messages()));
			return ip.value();
		});
		stack.setBitDepth(one.getBitDepth());
		final ImagePlus imp = new ImagePlus(file.getFileName().toString(), stack);
		imp.setCalibration(one.getCalibration());
		final FileInfo fi = (FileInfo) planes[0].clone();
		imp.setFileInfo(fi);
		final Properties props = new FileOpener(fi).decodeDescriptionString(fi);
		if (props != null) {
			final int c = integer(props, "channels"), z = integer(props, "slices"), t = integer(props, "frames");
			if ((long) c * z * t == planes.length) imp.setDimensions(c, z, t);
		}
		else if (first.description != null && first.description.contains("<OME")) ome(file, imp, first.description);
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
	private static void ome(final Path file, final ImagePlus imp, final String xml) throws IOException {
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

	// ---- our own reader: BigTIFF and 64-bit float ----

	private static ImagePlus own(final Path file, final TiffDirectories.Layout layout) throws IOException {
		final List<TiffDirectories.Directory> planes = layout.directories();
		final TiffDirectories.Directory p0 = planes.get(0);
		for (final TiffDirectories.Directory p : planes) {
			if (p.compression() != 1) throw new IOException("cannot read " + file + ": compressed BigTIFF or 64-bit " +
				"TIFF (compression " + p.compression() + ") is not supported; save it uncompressed");
			if (p.samples() != 1) throw new IOException("cannot read " + file + ": " + p.samples() + " samples per pixel " +
				"(colour?); save one grey channel");
			final int bits = p.bits(), format = p.format();
			final boolean ok = (bits == 8 || bits == 16 || bits == 32) && (format == 1 || format == 2 || format == 3 &&
				bits == 32) || bits == 64 && format == 3;
			if (!ok) throw new IOException("cannot read " + file + ": " + bits + "-bit samples of format " + format +
				" are not supported (8/16/32-bit integer, 32/64-bit float)");
			if (p.width() != p0.width() || p.height() != p0.height() || p.bits() != p0.bits() || p.format() != p0
				.format()) throw new IOException("cannot read " + file + ": its pages differ in size or pixel type (a " +
					"pyramid or thumbnails?)");
		}
		final ByteOrder order = layout.order();
		final FileStack stack = new FileStack(file, planes.size(), p0.width(), p0.height(), true, t -> decode(file,
			planes.get(t), order));
		final int bits = p0.bits(), format = p0.format();
		stack.setBitDepth(bits == 8 ? 8 : bits == 16 ? 16 : 32);
		final ImagePlus imp = new ImagePlus(file.getFileName().toString(), stack);
		// signed integers are stored with an offset (ImageJ's way); the calibration gives back the file's values
		if (bits == 16 && format == 2) imp.getCalibration().setSigned16BitCalibration();
		if (bits == 8 && format == 2) imp.getCalibration().setFunction(ij.measure.Calibration.STRAIGHT_LINE,
			new double[] { -128, 1 }, "Gray Value");
		return imp;
	}

	/** Reads one plane's strips (positional reads: threads may read planes at once) and converts the samples. */
	private static ImageProcessor decode(final Path file, final TiffDirectories.Directory p, final ByteOrder order)
		throws IOException
	{
		final int n = p.width() * p.height(), bytes = p.bits() / 8;
		// the directory was checked: the plane's bytes fit the frame budget, its strips lie inside the file
		final ByteBuffer data = ByteBuffer.allocate(Math.multiplyExact(n, bytes)).order(order);
		try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
			final long size = ch.size();
			for (int s = 0; s < p.offsets().length && data.hasRemaining(); s++) {
				final int len = (int) Math.min(p.counts()[s], data.remaining());
				data.put(TiffDirectories.read(ch, p.offsets()[s], len, order, size, file, "strip " + (s + 1)));
			}
		}
		if (data.hasRemaining()) throw new IOException("cannot read " + file + ": a plane's strips hold fewer pixels " +
			"than " + p.width() + " x " + p.height());
		data.flip();
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
