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
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * The image file directories (IFDs) of a TIFF or BigTIFF, read and checked against the file before anything they
 * size is allocated: by our own reader, and before ImageJ's decoder sees the file (which believes every number it
 * reads: a directory chain that loops back made it read forever or run out of memory, a huge declared width ran
 * it out of memory, a strip beyond the end printed ImageJ's own error).
 * <p>
 * Checked: the chain of directories (every offset inside the file, no directory visited twice), every entry's
 * values inside the file (a tag's count cannot claim more bytes than the file has), and for every image: a
 * width, height, sample size and sample count that a frame can have ({@link FrameBudget}), strip tables of one
 * length, every strip inside the file, and strips that hold the frame (uncompressed) or could (compressed: no
 * codec ImageJ reads expands data more than {@link #MAX_EXPANSION} times).
 */
final class TiffDirectories {

	private TiffDirectories() {}

	/** What a directory's offset in the set of those seen and its layout take, without its strip tables. */
	private static final long BYTES_PER_DIRECTORY = 200;

	/** Bytes read at a directory's start: its entries, unless it has more than 40. */
	private static final int WINDOW = 512;

	/** An upper bound on how many times LZW, Deflate or PackBits expand their data (Deflate's limit is 1032). */
	static final long MAX_EXPANSION = 4096;

	/**
	 * One image's layout, from its directory.
	 *
	 * @param samples the samples stored per pixel in each strip or tile (1 for one sample of a planar image)
	 * @param planar TIFF's PlanarConfiguration: 1 chunky (a pixel's samples side by side), 2 planar (plane after plane)
	 * @param photometric TIFF's PhotometricInterpretation (0, 1 grey; 2 RGB)
	 * @param rowsPerStrip the rows each strip holds (the last one fewer); the image's height for tiles
	 * @param tileWidth the tiles' width, 0 for strips
	 * @param tileLength the tiles' height, 0 for strips
	 * @param predictor TIFF's Predictor: 1 none, 2 horizontal differences, 3 floating point
	 * @param sample the sample of each pixel this image is (0-based; of a chunky image read one sample at a time)
	 */
	record Directory(int width, int height, int bits, int samples, int format, int compression, long[] offsets,
		long[] counts, int planar, int photometric, int rowsPerStrip, int tileWidth, int tileLength, int predictor,
		int sample)
	{
		/** One sample per pixel, in strips of the whole image, no predictor. */
		Directory(final int width, final int height, final int bits, final int samples, final int format,
			final int compression, final long[] offsets, final long[] counts)
		{
			this(width, height, bits, samples, format, compression, offsets, counts, 1, 1, height, 0, 0, 1, 0);
		}

		/**
		 * @return each sample of the image as an image of one sample: of a planar image (PlanarConfiguration 2: the
		 *         strips or tiles of sample {@code s} the {@code s}-th share of the table) with its own strips; of a
		 *         chunky one, the same strips read for sample {@code s}
		 */
		List<Directory> samplePlanes() {
			final List<Directory> out = new ArrayList<>(samples);
			final int per = offsets.length / samples;
			for (int s = 0; s < samples; s++)
				out.add(planar == 2 ? new Directory(width, height, bits, 1, format, compression, Arrays.copyOfRange(offsets,
					s * per, (s + 1) * per), Arrays.copyOfRange(counts, s * per, (s + 1) * per), 1, photometric,
					rowsPerStrip, tileWidth, tileLength, predictor, 0) : new Directory(width, height, bits, samples, format,
						compression, offsets, counts, 1, photometric, rowsPerStrip, tileWidth, tileLength, predictor, s));
			return out;
		}

		/** @return whether the image is stored in tiles rather than strips */
		boolean tiled() {
			return tileWidth > 0;
		}

		/** @return the bytes one plane of it takes uncompressed */
		long planeBytes() {
			return ((long) width * bits * samples + 7) / 8 * height;
		}
	}

	/**
	 * The whole file's layout.
	 *
	 * @param firstNext where the first directory's pointer to the next one is (ImageJ's decoder is shown the first
	 *        directory alone by reading it as 0, when the planes are read by offset)
	 */
	record Layout(boolean little, boolean big, List<Directory> directories, long firstNext) {

		ByteOrder order() {
			return little ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
		}
	}

	/**
	 * Reads and checks every directory of {@code file}.
	 *
	 * @throws IOException naming the file and what is wrong with it
	 */
	static Layout read(final Path file) throws IOException {
		try (FileChannel ch = FileChannel.open(file)) {
			return read(SeekableBytes.of(ch, file));
		}
	}

	/**
	 * Reads and checks every directory of a TIFF read by offset, wherever its bytes are (a local file, or a Hadoop
	 * path in the Spark job): the same checks for both.
	 *
	 * @throws IOException naming the file and what is wrong with it
	 */
	static Layout read(final SeekableBytes ch) throws IOException {
		final String file = ch.name();
		final long size = ch.size();
		final ByteBuffer head = read(ch, 0, 16, ByteOrder.BIG_ENDIAN, size, file, "header");
		final boolean little = head.get(0) == 'I';
		head.order(little ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
		final boolean big = head.getShort(2) == 43;
		if (big && (head.getShort(4) != 8 || head.getShort(6) != 0))
			throw damaged(file, "BigTIFF header with offsets of " + head.getShort(4) + " bytes");
		final int entrySize = big ? 20 : 12, countSize = big ? 8 : 2, nextSize = big ? 8 : 4;
		final List<Directory> directories = new ArrayList<>();
		final Set<Long> seen = new HashSet<>();
		long ifd = big ? head.getLong(8) : head.getInt(4) & 0xffffffffL;
		if (ifd == 0) throw damaged(file, "no image directory");
		long held = 0; // bytes of what we keep per directory (its offset seen, its layout): bounded by the heap
		long firstNext = -1;
		while (ifd != 0) {
			if (ifd < (big ? 16 : 8) || ifd > size - countSize)
				throw damaged(file, "image directory " + (directories.size() + 1) + " at byte " + Long.toUnsignedString(
					ifd) + ", outside the file (" + size + " bytes)");
			// a chain that comes back to a directory would never end
			if (!seen.add(ifd)) throw damaged(file, "its chain of image directories loops back to byte " + ifd +
				" after " + directories.size() + (directories.size() == 1 ? " directory" : " directories"));
			// one read for a usual directory (a few dozen entries), a second one for a larger
			final ByteBuffer window = read(ch, ifd, (int) Math.min(WINDOW, size - ifd), head.order(), size, file,
				"directory");
			final long entries = big ? window.getLong(0) : window.getShort(0) & 0xffff;
			if (entries <= 0 || entries > (size - ifd - countSize - nextSize) / entrySize)
				throw damaged(file, "image directory " + (directories.size() + 1) + " claims " + Long.toUnsignedString(
					entries) + " entries, more than the file holds");
			final int length = (int) (entries * entrySize + nextSize);
			final ByteBuffer dir = countSize + length <= window.limit() ? window.slice(countSize, length).order(head
				.order()) : read(ch, ifd + countSize, length, head.order(), size, file, "directory");
			final Directory d = directory(ch, dir, (int) entries, big, size, file, directories.size() + 1);
			if (d != null) directories.add(d); // a directory without an image (EXIF, GPS) is passed over
			held += BYTES_PER_DIRECTORY + (d == null ? 0 : 16L * d.offsets().length);
			if (seen.size() % 1024 == 0) FrameBudget.checkDescription(file, "its " + seen.size() + " image directories " +
				"(and more)", held);
			final int next = (int) entries * entrySize;
			if (firstNext < 0) firstNext = ifd + countSize + next;
			ifd = big ? dir.getLong(next) : dir.getInt(next) & 0xffffffffL;
		}
		if (directories.isEmpty()) throw new IOException("cannot read " + file + ": no image in this TIFF");
		return new Layout(little, big, directories, firstNext);
	}

	private static IOException damaged(final String file, final String what) {
		return new IOException("cannot read " + file + ": damaged TIFF: " + what);
	}

	/** @return the bytes of one value of TIFF type {@code type} (1 for types we do not know) */
	private static int typeSize(final int type) {
		return switch (type) {
			case 3, 8 -> 2;
			case 4, 9, 11, 13 -> 4;
			case 5, 10, 12, 16, 17, 18 -> 8;
			default -> 1;
		};
	}

	/** @return the directory's image, checked; null for a directory without an image size */
	private static Directory directory(final SeekableBytes ch, final ByteBuffer dir, final int entries,
		final boolean big, final long size, final String file, final int index) throws IOException
	{
		long width = -1, height = -1, bits = 1, format = 1, compression = 1, samples = 1, planar = 1, photometric = 1;
		long rowsPerStrip = Integer.MAX_VALUE, tileWidth = 0, tileLength = 0, predictor = 1;
		// entries whose values are tables, read once the image's size bounds them
		int offsetsAt = -1, countsAt = -1, metaCountsAt = -1, metaAt = -1;
		boolean tiles = false;
		final int inline = big ? 8 : 4;
		for (int i = 0; i < entries; i++) {
			final int at = i * (big ? 20 : 12);
			final int tag = dir.getShort(at) & 0xffff, type = dir.getShort(at + 2) & 0xffff;
			final long count = count(dir, at, big);
			if (count < 0 || count > size) throw damaged(file, "tag " + tag + " of directory " + index + " claims " + Long
				.toUnsignedString(count) + " values, more than the file's " + size + " bytes");
			final long bytes = count * typeSize(type);
			if (bytes > inline) {
				final long offset = pointer(dir, at, big);
				if (offset < 0 || offset > size || bytes > size - offset) throw damaged(file, "tag " + tag + " of directory " +
					index + " has " + bytes + " bytes at byte " + Long.toUnsignedString(offset) + ", beyond the end of " +
					"the file (" + size + " bytes)");
			}
			switch (tag) {
				case 256 -> width = value(dir, at, type, big);
				case 257 -> height = value(dir, at, type, big);
				// one size and one format per sample (the readers check them alike): the first
				case 258 -> bits = bytes <= inline ? value(dir, at, type, big) : table(ch, dir, at, type, 1, big, size,
					file)[0];
				case 259 -> compression = value(dir, at, type, big);
				case 262 -> photometric = value(dir, at, type, big);
				case 277 -> samples = value(dir, at, type, big);
				case 278 -> rowsPerStrip = value(dir, at, type, big);
				case 284 -> planar = value(dir, at, type, big);
				case 317 -> predictor = value(dir, at, type, big);
				case 322 -> tileWidth = value(dir, at, type, big);
				case 323 -> tileLength = value(dir, at, type, big);
				case 339 -> format = bytes <= inline ? value(dir, at, type, big) : table(ch, dir, at, type, 1, big, size,
					file)[0];
				case 273, 324 -> {
					offsetsAt = at;
					tiles = tag == 324;
				}
				case 279, 325 -> countsAt = at;
				case 50838 -> metaCountsAt = at;
				case 50839 -> metaAt = at;
				default -> { /* other tags do not size anything a reader allocates */ }
			}
		}
		if (width < 0 && height < 0) return null;
		final String where = index == 1 ? "" : " (image directory " + index + ")";
		if (width <= 0 || height <= 0 || width > Integer.MAX_VALUE || height > Integer.MAX_VALUE)
			throw damaged(file, "an image of " + width + " x " + height + " pixels" + where);
		if (width > FrameBudget.MAX_PIXELS / height) throw damaged(file, "an image of " + width + " x " + height +
			" pixels" + where + ", more than one frame can hold (2^31)");
		if (bits < 1 || bits > 64) throw damaged(file, bits + " bits per sample" + where);
		if (samples < 1 || samples > 16) throw damaged(file, samples + " samples per pixel" + where);
		if (offsetsAt < 0 || countsAt < 0 || count(dir, offsetsAt, big) != count(dir, countsAt, big) || count(dir,
			offsetsAt, big) == 0) throw damaged(file, "its strip table is missing or its offsets and sizes differ in " +
				"number" + where);
		// at least one row (or one 16 x 16 tile) per strip: a bound on the tables before they are read
		final long most = samples * (tiles ? ((width + 15) / 16) * ((height + 15) / 16) : height);
		if (count(dir, offsetsAt, big) > most) throw damaged(file, count(dir, offsetsAt, big) + " strips for " + height +
			" rows" + where);
		final long[] offsets = table(ch, dir, offsetsAt, type(dir, offsetsAt), count(dir, offsetsAt, big), big, size,
			file);
		final long[] counts = table(ch, dir, countsAt, type(dir, countsAt), offsets.length, big, size, file);
		if (tiles && (tileWidth < 1 || tileLength < 1 || tileWidth > 65536 || tileLength > 65536))
			throw damaged(file, "tiles of " + tileWidth + " x " + tileLength + " pixels" + where);
		final Directory d = new Directory((int) width, (int) height, (int) bits, (int) samples, (int) format,
			(int) compression, offsets, counts, planar == 2 && samples > 1 && offsets.length % samples == 0 ? 2 : 1,
			(int) photometric, (int) Math.max(1, Math.min(height, rowsPerStrip)), tiles ? (int) tileWidth : 0, tiles ?
				(int) tileLength : 0, (int) predictor, 0);
		long stored = 0;
		for (int s = 0; s < offsets.length; s++) {
			// an uncompressed strip whose size overstates it (some writers give the whole plane's, or more) is read
			// as far as its rows need, as ImageJ reads it, where the file holds that much
			if (compression == 1 && !tiles && offsets[s] >= 0 && offsets[s] <= size && counts[s] > size - offsets[s]) {
				final long need = TiffChunks.stripBytes(d, s);
				if (need <= size - offsets[s]) counts[s] = need;
			}
			if (offsets[s] < 0 || counts[s] < 0 || offsets[s] > size || counts[s] > size - offsets[s])
				throw new IOException("cannot read " + file + ": truncated or damaged TIFF: strip " + (s + 1) + " of " +
					offsets.length + where + " (" + Long.toUnsignedString(counts[s]) + " bytes at byte " + Long
						.toUnsignedString(offsets[s]) + ") lies beyond the end of the file (" + size + " bytes)");
			stored += counts[s];
		}
		final long plane = d.planeBytes();
		if (compression == 1 && stored < plane && offsets[0] + plane > size) throw new IOException("cannot read " + file +
			": truncated TIFF: an image of " + width + " x " + height + " pixels" + where + " needs " + plane +
			" bytes, its strips hold " + stored);
		if (compression != 1 && stored * MAX_EXPANSION < plane) throw damaged(file, "an image of " + width + " x " +
			height + " pixels" + where + " in " + stored + " compressed bytes, more than any compression holds");
		FrameBudget.check(file, width, height, (int) Math.min(8, (bits * samples + 7) / 8));
		if (metaCountsAt >= 0 || metaAt >= 0) imageJMetadata(ch, dir, metaCountsAt, metaAt, big, size, file);
		return d;
	}

	/**
	 * ImageJ's own metadata (slice labels, display ranges, LUTs, ROIs, overlays): a header of (type, count) pairs
	 * and a table of the items' sizes, which ImageJ's decoder allocates as they say. Checked: the sizes add up to
	 * at most the metadata's bytes, and the header's counts to at most the items there are.
	 */
	private static void imageJMetadata(final SeekableBytes ch, final ByteBuffer dir, final int countsAt,
		final int dataAt, final boolean big, final long size, final String file) throws IOException
	{
		if (countsAt < 0 || dataAt < 0) throw damaged(file, "ImageJ metadata without its table of sizes");
		final long items = count(dir, countsAt, big);
		if (items > 100_000) throw damaged(file, "ImageJ metadata of " + items + " items");
		final long[] sizes = table(ch, dir, countsAt, type(dir, countsAt), items, big, size, file);
		long total = 0;
		for (final long s : sizes) {
			if (s < 0 || s > Integer.MAX_VALUE) throw damaged(file, "ImageJ metadata item of " + s + " bytes");
			total += s;
		}
		final long bytes = count(dir, dataAt, big);
		if (total > bytes) throw damaged(file, "ImageJ metadata items of " + total + " bytes in " + bytes);
		if (sizes.length == 0 || sizes[0] < 12 || sizes[0] > 804) return; // ImageJ ignores such a header
		final ByteBuffer header = read(ch, pointer(dir, dataAt, big), (int) sizes[0],
			dir.order(), size, file, "ImageJ metadata");
		if (header.getInt(0) != 0x494a494a) return; // not "IJIJ": ImageJ ignores it
		long declared = 0;
		for (int at = 4; at + 8 <= sizes[0]; at += 8) {
			final int n = header.getInt(at + 4);
			if (n < 0) throw damaged(file, "ImageJ metadata with " + n + " items of a kind");
			declared += n;
		}
		if (declared > sizes.length - 1) throw damaged(file, "ImageJ metadata declares " + declared + " items, its " +
			"table lists " + (sizes.length - 1));
	}

	private static int type(final ByteBuffer dir, final int at) {
		return dir.getShort(at + 2) & 0xffff;
	}

	/** @return the number of values of the entry at {@code at} */
	private static long count(final ByteBuffer dir, final int at, final boolean big) {
		return big ? dir.getLong(at + 4) : dir.getInt(at + 4) & 0xffffffffL;
	}

	/** @return where the values of the entry at {@code at} are, when they do not fit in the entry */
	private static long pointer(final ByteBuffer dir, final int at, final boolean big) {
		return big ? dir.getLong(at + 12) : dir.getInt(at + 8) & 0xffffffffL;
	}

	/** The single value of an entry (BYTE, SHORT, LONG or LONG8), stored in the entry itself. */
	private static long value(final ByteBuffer dir, final int at, final int type, final boolean big) {
		final int v = at + (big ? 12 : 8);
		return switch (type) {
			case 1, 6 -> dir.get(v) & 0xff;
			case 3, 8 -> dir.getShort(v) & 0xffff;
			case 16, 17 -> dir.getLong(v);
			default -> dir.getInt(v) & 0xffffffffL;
		};
	}

	/** The first {@code count} values of an entry (SHORT, LONG or LONG8), in the entry or where it points. */
	private static long[] table(final SeekableBytes ch, final ByteBuffer dir, final int at, final int type,
		final long count, final boolean big, final long size, final String file) throws IOException
	{
		final int bytes = type == 3 ? 2 : type == 16 ? 8 : 4;
		final long all = bytes * count(dir, at, big);
		// the caller bounded count; the values' place was checked against the file's length
		final ByteBuffer b = all <= (big ? 8 : 4) ? dir.slice(at + (big ? 12 : 8), (int) all).order(dir.order()) : read(ch,
			pointer(dir, at, big), (int) (bytes * count), dir.order(), size, file, "strip table");
		final long[] out = new long[(int) count];
		for (int i = 0; i < count; i++)
			out[i] = bytes == 2 ? b.getShort(i * 2) & 0xffff : bytes == 8 ? b.getLong(i * 8) : b.getInt(i * 4) & 0xffffffffL;
		return out;
	}

	/**
	 * Reads {@code length} bytes at {@code at}, which the caller has checked to lie inside the file of
	 * {@code size} bytes (a truncated file still ends with a message).
	 */
	static ByteBuffer read(final SeekableBytes ch, final long at, final int length, final ByteOrder order,
		final long size, final String file, final String what) throws IOException
	{
		if (at < 0 || length > size - at) throw new IOException("cannot read " + file + ": truncated TIFF: its " + what +
			" ends at byte " + (at + length) + ", beyond the end of the file (" + size + " bytes)");
		final ByteBuffer b = ByteBuffer.allocate(length);
		ch.read(at, b);
		b.flip();
		return b.order(order);
	}
}
