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
 * That reader takes uncompressed, one-sample-per-pixel data, the way tifffile and numpy write them; it reads no
 * calibration. OME-TIFF is read as ImageJ 1 reads it (its planes, in file order); its OME-XML sizes and order are
 * checked so that channels or Z planes are not taken for time points.
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
	static ImagePlus open(final Path file, final byte[] head) throws IOException {
		final boolean big = head[2] == 43 || head[3] == 43;
		if (big) return own(file);
		final Path abs = file.toAbsolutePath();
		final FileInfo[] info;
		try {
			info = new TiffDecoder(abs.getParent().toString() + "/", abs.getFileName().toString()).getTiffInfo();
		}
		catch (final IOException e) {
			// what ImageJ 1 cannot decode, ours may (64-bit float); if not, ours says why
			return own(file);
		}
		if (info == null || info.length == 0) throw new IOException("cannot read " + file + ": no image in this TIFF");
		return ij(file, planes(file, info));
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
		final FileInfo[] planes = new FileInfo[fi.nImages];
		for (int i = 0; i < planes.length; i++) {
			planes[i] = (FileInfo) fi.clone();
			planes[i].nImages = 1;
			planes[i].longOffset = fi.getOffset() + i * (bytes + fi.getGap());
			if (planes[i].getOffset() + bytes > length)
				throw new IOException("cannot read " + file + ": truncated, it ends in plane " + (i + 1) + " of " +
					planes.length);
		}
		return planes;
	}

	private static ImagePlus ij(final Path file, final FileInfo[] planes) throws IOException {
		final FileInfo first = (FileInfo) planes[0].clone();
		final FileOpener opener = new FileOpener(first);
		final ImagePlus one = opener.openImage(); // plane 1: the calibration (incl. signed 16-bit), the bit depth
		if (one == null) throw new IOException("cannot read " + file + ": ImageJ could not decode its first plane (" +
			describe(first) + ")");
		final FileStack stack = new FileStack(file.toString(), stackFolder(file), planes.length, one.getWidth(), one
			.getHeight(), true, t -> {
				final ImageProcessor ip = new FileOpener((FileInfo) planes[t].clone()).openProcessor();
				if (ip == null) throw new IOException("cannot read plane " + (t + 1) + " of " + file);
				return ip;
			});
		return withMetadata(file.toString(), file.getFileName().toString(), stack, one, (FileInfo) planes[0].clone(),
			planes.length);
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
			if (c * z * t == planes) imp.setDimensions(c, z, t);
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
			final int n = Integer.parseInt(m.group(2));
			switch (m.group(1)) {
				case "C" -> c = n;
				case "Z" -> z = n;
				default -> t = n;
			}
		}
		if (c * z * t != imp.getStackSize()) return; // several series, or sizes we cannot trust: planes as they are
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

	/** One plane's layout, from its image file directory. */
	private record Plane(int width, int height, int bits, int format, int compression, long[] offsets, long[] counts) {}

	/**
	 * Every plane's layout, from the chain of image file directories.
	 *
	 * @param firstNext where the first directory's pointer to the next one is (4 bytes in a classic TIFF)
	 */
	private record Layout(List<Plane> planes, ByteOrder order, boolean big, long firstNext) {}

	private static ImagePlus own(final Path file) throws IOException {
		final SeekableBytes bytes = SeekableBytes.of(file);
		final Layout layout = layout(bytes);
		final Plane p0 = layout.planes.get(0);
		if (p0.compression != 1) throw new IOException("cannot read " + file + ": compressed BigTIFF or 64-bit TIFF " +
			"(compression " + p0.compression + ") is not supported; save it uncompressed");
		return own(bytes, file.getFileName().toString(), stackFolder(file), layout);
	}

	private static ImagePlus own(final SeekableBytes bytes, final String title, final String folder,
		final Layout layout)
	{
		final List<Plane> planes = layout.planes;
		final Plane p0 = planes.get(0);
		final FileStack stack = new FileStack(bytes.name(), folder, planes.size(), p0.width, p0.height, true,
			t -> decode(bytes, planes.get(t), layout.order));
		stack.setBitDepth(p0.bits == 8 ? 8 : p0.bits == 16 ? 16 : 32);
		final ImagePlus imp = new ImagePlus(title, stack);
		// signed integers are stored with an offset (ImageJ's way); the calibration gives back the file's values
		if (p0.bits == 16 && p0.format == 2) imp.getCalibration().setSigned16BitCalibration();
		if (p0.bits == 8 && p0.format == 2) imp.getCalibration().setFunction(ij.measure.Calibration.STRAIGHT_LINE,
			new double[] { -128, 1 }, "Gray Value");
		return imp;
	}

	/** @return the folder a local file's virtual stack names (ImageJ's convention) */
	private static String stackFolder(final Path file) {
		final Path parent = file.toAbsolutePath().getParent();
		return parent == null ? "/" : parent.toString();
	}

	/**
	 * A TIFF, BigTIFF or OME-TIFF read plane by plane by offset, wherever its bytes are ({@link SeekableBytes}): the
	 * same image, pixels and calibration as {@link #open} gives for the file, for uncompressed data (what large
	 * movies are). Classic TIFF's calibration and dimensions come from ImageJ's decoder, shown the first directory
	 * only (so a long movie's chain of directories is walked once, by our reader, and never buffered).
	 *
	 * @throws IOException one line naming the file, and for what it cannot read, how to convert it
	 */
	static ImagePlus openByOffset(final SeekableBytes bytes, final String title) throws IOException {
		final ByteBuffer head = ByteBuffer.allocate((int) Math.min(16, bytes.size()));
		bytes.read(0, head);
		final Layout layout;
		if (!isTiff(head.array())) throw new IOException("cannot read " + bytes.name() + ": not a TIFF (the Spark job " +
			"reads TIFF, BigTIFF and OME-TIFF); convert it, e.g. in Fiji: open it, then File > Save As > Tiff...");
		layout = layout(bytes);
		for (final Plane p : layout.planes)
			if (p.compression != 1) throw new IOException("cannot read " + bytes.name() + ": compressed TIFF " +
				"(compression " + p.compression + "), which cannot be read plane by plane by offset; save it " +
				"uncompressed (Fiji: File > Save As > Tiff..., or tifffile without compression)");
		if (layout.big) return own(bytes, title, "", layout);
		final FileInfo[] info;
		try {
			info = new TiffDecoder(bytes.stream(layout.firstNext), title).getTiffInfo();
		}
		catch (final IOException e) {
			return own(bytes, title, "", layout); // what ImageJ 1 cannot decode (64-bit float), as open() does
		}
		if (info == null || info.length == 0) throw new IOException("cannot read " + bytes.name() + ": no image in " +
			"this TIFF");
		final FileInfo fi = info[0];
		final List<Plane> planes = new ArrayList<>(layout.planes);
		if (fi.nImages > planes.size()) { // an ImageJ stack written with one directory: contiguous planes
			final Plane p0 = planes.get(0);
			final long bytesPerPlane = (long) fi.width * fi.height * fi.getBytesPerPixel();
			planes.clear();
			for (int i = 0; i < fi.nImages; i++) {
				final long at = fi.getOffset() + i * (bytesPerPlane + fi.getGap());
				if (at + bytesPerPlane > bytes.size()) throw new IOException("cannot read " + bytes.name() + ": truncated," +
					" it ends in plane " + (i + 1) + " of " + fi.nImages);
				planes.add(new Plane(p0.width, p0.height, p0.bits, p0.format, 1, new long[] { at }, new long[] {
					bytesPerPlane }));
			}
		}
		final FileInfo first = (FileInfo) fi.clone();
		first.nImages = 1;
		first.inputStream = bytes.stream(-1);
		final ImagePlus one = new FileOpener(first).openImage();
		if (one == null) throw new IOException("cannot read " + bytes.name() + ": ImageJ could not decode its first " +
			"plane (" + describe(fi) + ")");
		final Plane p0 = planes.get(0);
		final FileStack stack = new FileStack(bytes.name(), "", planes.size(), p0.width, p0.height, true, t -> decode(
			bytes, planes.get(t), layout.order));
		final FileInfo described = (FileInfo) fi.clone();
		described.nImages = 1;
		return withMetadata(bytes.name(), title, stack, one, described, planes.size());
	}

	/** Reads the chain of image file directories (classic or BigTIFF), by offset. */
	private static Layout layout(final SeekableBytes bytes) throws IOException {
		final String file = bytes.name();
		final List<Plane> planes = new ArrayList<>();
		final ByteBuffer head = read(bytes, 0, 16, ByteOrder.BIG_ENDIAN);
		final boolean little = head.get(0) == 'I';
		head.order(little ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
		final boolean big = head.getShort(2) == 43;
		long ifd = big ? head.getLong(8) : head.getInt(4) & 0xffffffffL;
		final long size = bytes.size();
		long firstNext = -1;
		while (ifd != 0) {
			if (ifd < 8 || ifd >= size || planes.size() > 10_000_000)
				throw new IOException("cannot read " + file + ": damaged TIFF (directory offset " + ifd + ")");
			final ByteBuffer n = read(bytes, ifd, big ? 8 : 2, head.order());
			final long entries = big ? n.getLong(0) : n.getShort(0) & 0xffff;
			final int entrySize = big ? 20 : 12;
			final ByteBuffer dir = read(bytes, ifd + (big ? 8 : 2), (int) (entries * entrySize + (big ? 8 : 4)), head
				.order());
			planes.add(plane(bytes, dir, (int) entries, big));
			final int next = (int) entries * entrySize;
			if (firstNext < 0) firstNext = ifd + (big ? 8 : 2) + next;
			ifd = big ? dir.getLong(next) : dir.getInt(next) & 0xffffffffL;
		}
		if (planes.isEmpty()) throw new IOException("cannot read " + file + ": no image in this TIFF");
		final Plane p0 = planes.get(0);
		for (final Plane p : planes)
			if (p.width != p0.width || p.height != p0.height || p.bits != p0.bits || p.format != p0.format)
				throw new IOException("cannot read " + file + ": its pages differ in size or pixel type (a pyramid or " +
					"thumbnails?)");
		return new Layout(planes, head.order(), big, firstNext);
	}

	private static Plane plane(final SeekableBytes ch, final ByteBuffer dir, final int entries, final boolean big)
		throws IOException
	{
		final String file = ch.name();
		int width = 0, height = 0, bits = 1, format = 1, compression = 1, samples = 1;
		long[] offsets = null, counts = null;
		for (int i = 0; i < entries; i++) {
			final int at = i * (big ? 20 : 12);
			final int tag = dir.getShort(at) & 0xffff, type = dir.getShort(at + 2) & 0xffff;
			final long count = big ? dir.getLong(at + 4) : dir.getInt(at + 4) & 0xffffffffL;
			switch (tag) {
				case 256 -> width = (int) value(dir, at, type, big);
				case 257 -> height = (int) value(dir, at, type, big);
				case 258 -> bits = (int) value(dir, at, type, big);
				case 259 -> compression = (int) value(dir, at, type, big);
				case 277 -> samples = (int) value(dir, at, type, big);
				case 339 -> format = (int) value(dir, at, type, big);
				case 273, 324 -> offsets = values(ch, dir, at, type, count, big);
				case 279, 325 -> counts = values(ch, dir, at, type, count, big);
				default -> { /* other tags do not change the pixels */ }
			}
		}
		if (samples != 1) throw new IOException("cannot read " + file + ": " + samples + " samples per pixel (colour?); " +
			"save one grey channel");
		final boolean ok = (bits == 8 || bits == 16 || bits == 32) && (format == 1 || format == 2 || format == 3 && bits ==
			32) || bits == 64 && format == 3;
		if (!ok) throw new IOException("cannot read " + file + ": " + bits + "-bit samples of format " + format +
			" are not supported (8/16/32-bit integer, 32/64-bit float)");
		if (width <= 0 || height <= 0 || offsets == null || counts == null || offsets.length != counts.length)
			throw new IOException("cannot read " + file + ": damaged TIFF directory (size or strips missing)");
		return new Plane(width, height, bits, format, compression, offsets, counts);
	}

	/** The single value of an entry (SHORT, LONG or LONG8), stored in the entry itself. */
	private static long value(final ByteBuffer dir, final int at, final int type, final boolean big) {
		final int v = at + (big ? 12 : 8);
		return switch (type) {
			case 3 -> dir.getShort(v) & 0xffff;
			case 16 -> dir.getLong(v);
			default -> dir.getInt(v) & 0xffffffffL;
		};
	}

	private static long[] values(final SeekableBytes ch, final ByteBuffer dir, final int at, final int type,
		final long count, final boolean big) throws IOException
	{
		final String file = ch.name();
		final int size = type == 3 ? 2 : type == 16 ? 8 : 4;
		if (count > 100_000_000) throw new IOException("cannot read " + file + ": damaged TIFF (" + count + " strips)");
		final int v = at + (big ? 12 : 8);
		final ByteBuffer b = size * count <= (big ? 8 : 4) ? dir.slice(v, (int) (size * count)).order(dir.order()) : read(
			ch, big ? dir.getLong(v) : dir.getInt(v) & 0xffffffffL, (int) (size * count), dir.order());
		final long[] out = new long[(int) count];
		for (int i = 0; i < count; i++)
			out[i] = size == 2 ? b.getShort(i * 2) & 0xffff : size == 8 ? b.getLong(i * 8) : b.getInt(i * 4) & 0xffffffffL;
		return out;
	}

	private static ByteBuffer read(final SeekableBytes bytes, final long at, final int length, final ByteOrder order)
		throws IOException
	{
		final ByteBuffer b = ByteBuffer.allocate(length);
		bytes.read(at, b);
		b.flip();
		return b.order(order);
	}

	/** Reads one plane's strips (positional reads: threads may read planes at once) and converts the samples. */
	private static ImageProcessor decode(final SeekableBytes file, final Plane p, final ByteOrder order)
		throws IOException
	{
		final int n = p.width * p.height, bytes = p.bits / 8;
		final ByteBuffer data = ByteBuffer.allocate(n * bytes).order(order);
		for (int s = 0; s < p.offsets.length && data.hasRemaining(); s++) {
			final int len = (int) Math.min(p.counts[s], data.remaining());
			file.read(p.offsets[s], data.slice(data.position(), len));
			data.position(data.position() + len);
		}
		if (data.hasRemaining()) throw new IOException("cannot read " + file.name() + ": a plane's strips hold fewer pixels " +
			"than " + p.width + " x " + p.height);
		data.flip();
		switch (p.bits) {
			case 8: {
				final byte[] px = new byte[n];
				data.get(px);
				if (p.format == 2) for (int i = 0; i < n; i++)
					px[i] ^= (byte) 0x80; // signed bytes as unsigned with an offset, as ImageJ stores signed data
				return new ByteProcessor(p.width, p.height, px);
			}
			case 16: {
				final short[] px = new short[n];
				data.asShortBuffer().get(px);
				if (p.format == 2) for (int i = 0; i < n; i++)
					px[i] ^= (short) 0x8000; // ImageJ's signed 16-bit: value + 32768, undone by the calibration
				return new ShortProcessor(p.width, p.height, px, null);
			}
			case 32: {
				final float[] px = new float[n];
				for (int i = 0; i < n; i++)
					px[i] = p.format == 3 ? data.getFloat() : p.format == 2 ? data.getInt() : data.getInt() & 0xffffffffL;
				return new FloatProcessor(p.width, p.height, px);
			}
			default: {
				final float[] px = new float[n];
				for (int i = 0; i < n; i++)
					px[i] = (float) data.getDouble(); // 32-bit float keeps 7 digits, far below any image's noise
				return new FloatProcessor(p.width, p.height, px);
			}
		}
	}
}
