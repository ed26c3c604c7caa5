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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.Deflater;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;

/**
 * The TIFF layouts of grey data that TIFF 6 allows beyond one sample in uncompressed strips: several samples per
 * pixel stored plane after plane (what Python's {@code tifffile.imwrite(path, stack)} writes for a stack of 3 or 4
 * frames) or side by side with extra samples (grey and alpha), in strips or tiles, uncompressed or compressed with
 * LZW, Deflate or PackBits, with or without a predictor, in either byte order. The bytes are written here, by
 * {@link Page}; each layout is read with every sample's values (as channels, by file and by offset), and a run
 * that does not choose a channel is refused in one line that says what the channels are; what cannot be read is
 * refused in one line naming the file and the layout.
 */
public class TiffLayoutsTest {

	@TempDir
	Path dir;

	/** @return the value of sample s of page t at (x, y), distinct for each and inside the sample's range */
	private static double value(final int t, final int s, final int x, final int y, final int bits, final int format) {
		final double v = (bits == 8 ? 3 : 900) + 31 * s + 7 * t + x + 2 * y + (x * y % 5);
		return format == 3 ? v / 8 - 40 : v;
	}

	/**
	 * One TIFF page's layout.
	 *
	 * @param planar 1 chunky, 2 planar
	 * @param photometric 1 grey (the extra samples then ExtraSamples), 2 RGB
	 * @param compression 1, 5 LZW, 8 or 32946 Deflate, 32773 PackBits (7 JPEG: written as if, to be refused)
	 * @param tile the tiles' side, 0 for strips of {@code rows} rows
	 */
	public record Page(int width, int height, int bits, int format, int samples, int planar, int photometric,
		int compression, int predictor, int tile, int rows)
	{
		/** @return the uncompressed bytes of one strip or tile of pixels x0.., y0.. of {@code sampleOf} (-1: all) */
		byte[] piece(final int t, final int x0, final int y0, final int pw, final int ph, final int sampleOf,
			final ByteOrder order, final Pixels pixels)
		{
			final int spp = sampleOf < 0 ? samples : 1, bytes = bits / 8;
			final ByteBuffer b = ByteBuffer.allocate(pw * ph * spp * bytes).order(order);
			for (int y = y0; y < y0 + ph; y++)
				for (int x = x0; x < x0 + pw; x++)
					for (int k = 0; k < spp; k++) {
						final int s = sampleOf < 0 ? k : sampleOf;
						// past the image's edge (a tile's padding) a value nobody reads
						final double v = x < width && y < height ? pixels.at(t, s, x, y) : 99;
						if (format == 3) b.putFloat((float) v);
						else if (bits == 8) b.put((byte) v);
						else if (bits == 16) b.putShort((short) v);
						else b.putInt((int) v);
					}
			final byte[] raw = b.array();
			if (predictor == 2) differences(raw, ph, pw * spp, spp, bytes, order);
			if (predictor == 3) floatDifferences(raw, ph, pw * spp, spp, bytes, order);
			return raw;
		}
	}

	/** The value of sample {@code s} of page {@code t} at {@code (x, y)}. */
	@FunctionalInterface
	public interface Pixels {
		double at(int t, int s, int x, int y);
	}

	/** Writes {@code pages} pages of {@code p}'s layout, each piece compressed, and returns the file. */
	public static Path write(final Path file, final Page p, final int pages, final ByteOrder order) throws IOException {
		return write(file, p, pages, order, (t, s, x, y) -> value(t, s, x, y, p.bits, p.format));
	}

	/**
	 * Writes {@code pages} pages of {@code p}'s layout holding {@code pixels} (in the range of {@code p}'s samples),
	 * each piece compressed, and returns the file.
	 */
	public static Path write(final Path file, final Page p, final int pages, final ByteOrder order,
		final Pixels pixels) throws IOException
	{
		final ByteArrayOutputStream data = new ByteArrayOutputStream();
		data.write(new byte[8]);
		final List<long[]> offsets = new ArrayList<>(), counts = new ArrayList<>();
		final int pw = p.tile > 0 ? p.tile : p.width, ph = p.tile > 0 ? p.tile : p.rows;
		for (int t = 0; t < pages; t++) {
			final List<Long> at = new ArrayList<>(), n = new ArrayList<>();
			for (int s = 0; s < (p.planar == 2 ? p.samples : 1); s++)
				for (int y0 = 0; y0 < p.height; y0 += ph)
					for (int x0 = 0; x0 < p.width; x0 += pw) {
						// a tile is stored whole; a strip only as far as the image goes
						final byte[] raw = p.piece(t, x0, y0, pw, p.tile > 0 ? ph : Math.min(ph, p.height - y0), p.planar == 2 ?
							s : -1, order, pixels);
						final byte[] packed = compress(p.compression, raw);
						at.add((long) data.size());
						n.add((long) packed.length);
						data.write(packed);
						if (data.size() % 2 == 1) data.write(0);
					}
			offsets.add(at.stream().mapToLong(Long::longValue).toArray());
			counts.add(n.stream().mapToLong(Long::longValue).toArray());
		}
		final ByteBuffer b = ByteBuffer.allocate(data.size() + pages * 4096).order(order);
		b.put(data.toByteArray());
		b.put(0, (byte) (order == ByteOrder.LITTLE_ENDIAN ? 'I' : 'M')).put(1, b.get(0)).putShort(2, (short) 42).putInt(4,
			b.position());
		for (int t = 0; t < pages; t++) {
			final long[] at = offsets.get(t), n = counts.get(t);
			final List<int[]> entries = new ArrayList<>(); // tag, type, count, value or where the values go
			final Map<Integer, int[]> tables = new HashMap<>(); // tag -> values of those stored apart
			entries.add(new int[] { 256, 4, 1, p.width });
			entries.add(new int[] { 257, 4, 1, p.height });
			tables.put(258, filled(p.samples, p.bits));
			entries.add(new int[] { 258, 3, p.samples, 0 });
			entries.add(new int[] { 259, 3, 1, p.compression });
			entries.add(new int[] { 262, 3, 1, p.photometric });
			tables.put(p.tile > 0 ? 324 : 273, toInts(at));
			entries.add(new int[] { p.tile > 0 ? 324 : 273, 4, at.length, 0 });
			entries.add(new int[] { 277, 3, 1, p.samples });
			if (p.tile == 0) entries.add(new int[] { 278, 4, 1, p.rows });
			tables.put(p.tile > 0 ? 325 : 279, toInts(n));
			entries.add(new int[] { p.tile > 0 ? 325 : 279, 4, n.length, 0 });
			entries.add(new int[] { 284, 3, 1, p.planar });
			if (p.predictor != 1) entries.add(new int[] { 317, 3, 1, p.predictor });
			if (p.tile > 0) {
				entries.add(new int[] { 322, 3, 1, p.tile });
				entries.add(new int[] { 323, 3, 1, p.tile });
			}
			final int extra = p.samples - (p.photometric == 2 ? 3 : 1);
			if (extra > 0) {
				tables.put(338, filled(extra, 2));
				entries.add(new int[] { 338, 3, extra, 0 });
			}
			tables.put(339, filled(p.samples, p.format));
			entries.add(new int[] { 339, 3, p.samples, 0 });
			entries.sort(java.util.Comparator.comparingInt(e -> e[0])); // TIFF lists its entries by tag
			int apart = b.position() + 2 + entries.size() * 12 + 4;
			b.putShort((short) entries.size());
			for (final int[] e : entries) {
				b.putShort((short) e[0]).putShort((short) e[1]).putInt(e[2]);
				final int[] values = tables.get(e[0]);
				final int size = e[1] == 3 ? 2 : 4;
				if (values == null || values.length * size <= 4) {
					final int[] v = values == null ? new int[] { e[3] } : values;
					final int here = b.position();
					for (int i = 0; i < v.length; i++)
						if (size == 2) b.putShort(here + 2 * i, (short) v[i]);
						else b.putInt(here + 4 * i, v[i]);
					b.position(here + 4);
				}
				else {
					b.putInt(apart);
					for (int i = 0; i < values.length; i++)
						if (size == 2) b.putShort(apart + 2 * i, (short) values[i]);
						else b.putInt(apart + 4 * i, values[i]);
					apart += (values.length * size + 1) / 2 * 2;
				}
			}
			b.putInt(t == pages - 1 ? 0 : apart);
			b.position(apart);
		}
		Files.write(file, java.util.Arrays.copyOf(b.array(), b.position()));
		return file;
	}

	private static int[] filled(final int n, final int v) {
		final int[] a = new int[n];
		java.util.Arrays.fill(a, v);
		return a;
	}

	private static int[] toInts(final long[] a) {
		final int[] out = new int[a.length];
		for (int i = 0; i < a.length; i++)
			out[i] = (int) a[i];
		return out;
	}

	/** The horizontal-difference predictor (2): each sample minus the same sample of the pixel before it. */
	private static void differences(final byte[] raw, final int rows, final int values, final int spp,
		final int bytes, final ByteOrder order)
	{
		final ByteBuffer b = ByteBuffer.wrap(raw).order(order);
		for (int y = 0; y < rows; y++)
			for (int i = (y + 1) * values - 1; i >= y * values + spp; i--)
				switch (bytes) {
					case 1 -> raw[i] -= raw[i - spp];
					case 2 -> b.putShort(2 * i, (short) (b.getShort(2 * i) - b.getShort(2 * (i - spp))));
					default -> b.putInt(4 * i, b.getInt(4 * i) - b.getInt(4 * (i - spp)));
				}
	}

	/**
	 * The floating-point predictor (3): each row's bytes reordered, the most significant byte of every sample first,
	 * then the next, and stored as byte-wise differences one pixel's samples apart.
	 */
	private static void floatDifferences(final byte[] raw, final int rows, final int values, final int spp,
		final int bytes, final ByteOrder order)
	{
		final int n = values * bytes;
		final byte[] row = new byte[n];
		for (int y = 0; y < rows; y++) {
			for (int k = 0; k < values; k++)
				for (int m = 0; m < bytes; m++)
					row[m * values + k] = raw[y * n + k * bytes + (order == ByteOrder.LITTLE_ENDIAN ? bytes - 1 - m : m)];
			for (int i = n - 1; i >= spp; i--)
				row[i] -= row[i - spp];
			System.arraycopy(row, 0, raw, y * n, n);
		}
	}

	static byte[] compress(final int compression, final byte[] raw) {
		return switch (compression) {
			case 5 -> lzw(raw);
			case 8, 32946 -> {
				final Deflater d = new Deflater();
				d.setInput(raw);
				d.finish();
				final ByteArrayOutputStream out = new ByteArrayOutputStream();
				final byte[] buf = new byte[4096];
				while (!d.finished())
					out.write(buf, 0, d.deflate(buf));
				d.end();
				yield out.toByteArray();
			}
			case 32773 -> packBits(raw);
			default -> raw;
		};
	}

	/** PackBits: runs of 3 or more equal bytes as a repeat, the rest as literals of up to 128 bytes. */
	private static byte[] packBits(final byte[] raw) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream();
		int i = 0;
		while (i < raw.length) {
			int run = 1;
			while (i + run < raw.length && run < 128 && raw[i + run] == raw[i])
				run++;
			if (run >= 3) {
				out.write(1 - run);
				out.write(raw[i]);
				i += run;
				continue;
			}
			int end = i;
			while (end < raw.length && end - i < 128 && !(end + 2 < raw.length && raw[end] == raw[end + 1] &&
				raw[end] == raw[end + 2]))
				end++;
			out.write(end - i - 1);
			out.write(raw, i, end - i);
			i = end;
		}
		return out.toByteArray();
	}

	/** TIFF's LZW: 9- to 12-bit codes, most significant bit first, the width growing as a decoder expects. */
	private static byte[] lzw(final byte[] raw) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream();
		final long[] acc = new long[2]; // bits held, how many
		final Map<Integer, Integer> table = new HashMap<>();
		int width = 9, next = 258;
		emit(out, acc, 256, width);
		int w = raw.length == 0 ? -1 : raw[0] & 0xff;
		for (int i = 1; i < raw.length; i++) {
			final int k = raw[i] & 0xff, key = w << 8 | k;
			final Integer known = table.get(key);
			if (known != null) {
				w = known;
				continue;
			}
			emit(out, acc, w, width);
			table.put(key, next++);
			if (next == 4094) {
				emit(out, acc, 256, width);
				table.clear();
				next = 258;
				width = 9;
			}
			else if (next >= 1 << width) width++;
			w = k;
		}
		if (w >= 0) {
			emit(out, acc, w, width);
			if (next + 1 >= 1 << width && width < 12) width++;
		}
		emit(out, acc, 257, width);
		if (acc[1] > 0) out.write((int) (acc[0] << 8 - acc[1]));
		return out.toByteArray();
	}

	private static void emit(final ByteArrayOutputStream out, final long[] acc, final int code, final int width) {
		acc[0] = acc[0] << width | code;
		acc[1] += width;
		while (acc[1] >= 8) {
			out.write((int) (acc[0] >>> acc[1] - 8));
			acc[1] -= 8;
		}
		acc[0] &= (1L << acc[1]) - 1;
	}

	/** Asserts that both readers give every sample of every page of {@code p} as a channel, with its values. */
	private static void assertChannels(final Path file, final Page p, final int pages) throws IOException {
		for (final ImagePlus imp : new ImagePlus[] { ImageFiles.open(file), ImageFiles.openByOffset(SeekableBytes.of(
			file)) })
		{
			assertEquals(p.samples, imp.getNChannels(), "channels");
			assertEquals(pages, imp.getNFrames(), "frames");
			assertEquals(p.format == 3 ? 32 : p.bits, imp.getBitDepth());
			for (int t = 0; t < pages; t++)
				for (int s = 0; s < p.samples; s++) {
					final ij.process.ImageProcessor ip = imp.getStack().getProcessor(imp.getStackIndex(s + 1, 1, t + 1));
					for (int y = 0; y < p.height; y++)
						for (int x = 0; x < p.width; x++)
							assertEquals(value(t, s, x, y, p.bits, p.format), ip.getf(x, y), 1e-6, file.getFileName() + ": page " +
								t + ", sample " + s + " at " + x + "," + y);
				}
			final InvalidInputException e = assertThrows(InvalidInputException.class, () -> ImagePlusFrames.of(imp, 0));
			assertEquals(1, e.getMessage().lines().count(), e.getMessage());
			assertTrue(e.getMessage().contains("has " + p.samples + " channels: choose one"), e.getMessage());
			assertTrue(p.planar == 2 ? e.getMessage().contains("plane after plane") && e.getMessage().contains(
				"tifffile.imwrite(p, a, photometric='minisblack')") : e.getMessage().contains(p.photometric == 2 ? "red, " +
					"green and blue" : "extra"), e.getMessage());
			final ImagePlusFrames two = ImagePlusFrames.of(imp, 2);
			assertEquals(pages, two.frameCount());
			assertEquals(value(pages - 1, 1, 5, 4, p.bits, p.format), two.frame(pages - 1).getAt(5, 4).getRealDouble(),
				1e-6);
		}
	}

	/** What tifffile writes for a stack of 3 or 4 frames of 8 bits: read as channels as 16-bit ones are. */
	@ParameterizedTest
	@CsvSource({ "3, 8", "4, 8", "3, 16", "4, 16", "3, 32" })
	void planarSamplesOfEveryDepthAreChannels(final int samples, final int bits) throws IOException {
		final Page p = new Page(21, 13, bits, 1, samples, 2, 2, 1, 1, 0, 13);
		assertChannels(write(dir.resolve("planar" + samples + "-" + bits + ".tif"), p, 1, ByteOrder.LITTLE_ENDIAN), p,
			1);
	}

	/**
	 * Chunky grey with extra samples (grey and alpha), and colour of 16 or 32 bits a sample (ImageJ 1 reads it only
	 * whole, not plane by plane): each sample a channel.
	 */
	@ParameterizedTest
	@CsvSource({ "2, 8, 1, 1", "2, 16, 1, 1", "3, 16, 1, 1", "2, 32, 3, 1", "3, 16, 1, 2", "4, 16, 1, 2", "3, 32, 3, 2" })
	void greyWithExtraSamplesAndDeepColourAreChannels(final int samples, final int bits, final int format,
		final int photometric) throws IOException
	{
		final Page p = new Page(19, 11, bits, format, samples, 1, photometric, 1, 1, 0, 4);
		assertChannels(write(dir.resolve("extra" + samples + "-" + bits + ".tif"), p, 1, ByteOrder.LITTLE_ENDIAN), p, 1);
	}

	/**
	 * Planar and chunky pages compressed (LZW, both Deflate codes, PackBits), with the horizontal predictor, in
	 * strips of several rows or in tiles past the image's edge, in both byte orders, one page or several.
	 */
	@ParameterizedTest
	@CsvSource({ // compression, predictor, tile, rows, planar, bits, pages, big-endian
		"5, 1, 0, 5, 2, 8, 1, false", "5, 2, 0, 5, 2, 16, 1, false", "8, 1, 0, 3, 2, 16, 1, false",
		"32946, 2, 0, 13, 2, 8, 1, true", "32773, 1, 0, 4, 2, 16, 1, true", "32773, 1, 0, 2, 2, 8, 1, false",
		"1, 1, 16, 0, 2, 16, 1, false", "5, 2, 16, 0, 2, 8, 1, false", "8, 1, 32, 0, 2, 16, 1, true",
		"5, 2, 0, 4, 1, 16, 1, true", "8, 2, 16, 0, 1, 8, 1, false", "5, 1, 0, 6, 2, 16, 3, false",
		"1, 1, 0, 13, 2, 16, 4, false", "32773, 1, 16, 0, 1, 16, 2, true" })
	void compressedTiledAndMultiPageLayoutsAreRead(final int compression, final int predictor, final int tile,
		final int rows, final int planar, final int bits, final int pages, final boolean bigEndian) throws IOException
	{
		final Page p = new Page(37, 13, bits, 1, planar == 2 ? 3 : 2, planar, planar == 2 ? 2 : 1, compression,
			predictor, tile, rows);
		assertChannels(write(dir.resolve("c" + compression + "p" + predictor + "t" + tile + "r" + rows + "-" + planar +
			".tif"), p, pages, bigEndian ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN), p, pages);
	}

	/**
	 * Pages of one sample that ImageJ 1's decoder reads without a word but wrongly: the floating-point predictor (it
	 * ignores it; in strips and tiles, one page or several) and signed 8-bit samples (it reads them as unsigned) are
	 * read by ours; JPEG (it decodes it wrongly) and half floats are refused in one line naming the layout and how
	 * to convert.
	 */
	@Test
	void oneSampleLayoutsImageJMisreadsAreReadByOursOrRefused() throws IOException {
		for (final Page p : new Page[] { new Page(37, 13, 32, 3, 1, 1, 1, 8, 3, 0, 5), new Page(37, 13, 32, 3, 1, 1, 1, 5,
			3, 16, 0) })
			for (final ByteOrder order : new ByteOrder[] { ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN })
				for (final int pages : new int[] { 1, 3 }) {
					final Path file = write(dir.resolve("predictor3-" + p.tile + order + pages + ".tif"), p, pages, order);
					for (final ImagePlus imp : new ImagePlus[] { ImageFiles.open(file), ImageFiles.openByOffset(SeekableBytes
						.of(file)) })
					{
						assertEquals(pages, imp.getStackSize());
						for (int t = 0; t < pages; t++)
							for (int y = 0; y < p.height; y++)
								for (int x = 0; x < p.width; x++)
									assertEquals(value(t, 0, x, y, 32, 3), imp.getStack().getProcessor(t + 1).getf(x, y), 1e-6, file
										.getFileName() + " page " + t + " at " + x + "," + y);
					}
				}
		// signed 8-bit: ImageJ 1 reads the bytes as unsigned (-5 as 251); ours gives the file's values, both ways
		final Path signed = write(dir.resolve("int8.tif"), new Page(16, 16, 8, 2, 1, 1, 1, 1, 1, 0, 16), 2,
			ByteOrder.LITTLE_ENDIAN);
		final byte[] s8 = Files.readAllBytes(signed);
		for (int i = 8; i < 8 + 256; i++)
			s8[i] = (byte) (i % 256 - 128); // page 1's pixels: -128 to 127
		Files.write(signed, s8);
		for (final ImagePlus imp : new ImagePlus[] { ImageFiles.open(signed), ImageFiles.openByOffset(SeekableBytes.of(
			signed)) })
		{
			final net.imglib2.RandomAccessibleInterval<? extends net.imglib2.type.numeric.RealType<?>> f = ImagePlusFrames
				.of(imp, 0).frame(0);
			for (int i = 0; i < 256; i++)
				assertEquals((i + 8) % 256 - 128, f.getAt(i % 16, i / 16).getRealDouble(), 0, "signed 8-bit pixel " + i);
		}
		assertRefused(write(dir.resolve("grey-jpeg.tif"), new Page(16, 16, 8, 1, 1, 1, 1, 7, 1, 0, 16), 1,
			ByteOrder.LITTLE_ENDIAN), "JPEG-compressed TIFF", "save it uncompressed");
		final Path half = write(dir.resolve("half.tif"), new Page(16, 16, 16, 1, 1, 1, 1, 1, 1, 0, 16), 1,
			ByteOrder.LITTLE_ENDIAN);
		final byte[] b = Files.readAllBytes(half);
		final ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
		final int ifd = bb.getInt(4);
		for (int e = 0; e < bb.getShort(ifd); e++)
			if (bb.getShort(ifd + 2 + 12 * e) == 339) bb.putShort(ifd + 2 + 12 * e + 8, (short) 3); // SampleFormat float
		Files.write(half, b);
		assertRefused(half, "16-bit float samples are not supported", "a.astype('float32')");
	}

	/**
	 * An uncompressed strip whose stated size overstates it (a public 512 x 512 16-bit monolayer states 4 MiB for its
	 * 512 KiB strip) is read as far as its rows need, as ImageJ reads it; where the file does not hold even that, it
	 * is refused in one line.
	 */
	@Test
	void anUncompressedStripWhoseSizeIsOverstatedIsReadAsFarAsItsRowsNeed() throws IOException {
		final Page p = new Page(16, 12, 16, 1, 1, 1, 1, 1, 1, 0, 12);
		final Path file = write(dir.resolve("overstated.tif"), p, 1, ByteOrder.LITTLE_ENDIAN);
		final byte[] b = Files.readAllBytes(file);
		final ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
		final int ifd = bb.getInt(4);
		long offset = -1;
		for (int e = 0; e < bb.getShort(ifd); e++) {
			final int at = ifd + 2 + 12 * e;
			if (bb.getShort(at) == 279) bb.putInt(at + 8, 4194304); // StripByteCounts: 4 MiB
			if (bb.getShort(at) == 273) offset = bb.getInt(at + 8); // StripOffsets
		}
		Files.write(file, b);
		for (final ImagePlus imp : new ImagePlus[] { ImageFiles.open(file), ImageFiles.openByOffset(SeekableBytes.of(
			file)) })
			for (int y = 0; y < p.height; y++)
				for (int x = 0; x < p.width; x++)
					assertEquals(value(0, 0, x, y, 16, 1), imp.getStack().getProcessor(1).getf(x, y), 0, "pixel " + x + "," +
						y);
		// the strip's rows need 16 x 12 x 2 bytes from its offset: a strip that starts too near the file's end for them
		// is refused
		assertTrue(offset > 0, "strip at " + offset);
		for (int e = 0; e < bb.getShort(ifd); e++)
			if (bb.getShort(ifd + 2 + 12 * e) == 273) bb.putInt(ifd + 2 + 12 * e + 8, b.length - 16 * 12 * 2 + 7);
		final Path cut = dir.resolve("overstated-cut.tif");
		Files.write(cut, b);
		assertRefused(cut, "truncated", "beyond the end of the file");
	}

	/** LZW of data long enough that its table fills and is cleared, the codes 12 bits wide. */
	@Test
	void longLzwDataFillsAndClearsTheTable() throws IOException {
		final Page p = new Page(300, 200, 16, 1, 3, 2, 2, 5, 1, 0, 200);
		assertChannels(write(dir.resolve("long-lzw.tif"), p, 1, ByteOrder.LITTLE_ENDIAN), p, 1);
	}

	/**
	 * Pages of one sample, the layout of a grey movie, in every compression we decode, with and without the
	 * horizontal predictor, in strips (of 5 rows: 8-bit ones then lie a byte apart, as TIFF's even offsets have
	 * them) or tiles, in either byte order: every value of every page is read by file (the command line's reader) and
	 * by offset (the Spark job's). ImageJ 1 alone gave wrong pixels without a word for two of them: PackBits with the
	 * predictor (it undoes the predictor only for LZW and Deflate) and uncompressed strips with a gap between them
	 * (it reads them as one run of bytes).
	 */
	@Test
	void oneSamplePagesOfEveryCompressionAreReadByFileAndByOffset() throws IOException {
		int files = 0;
		for (final int compression : new int[] { 1, 5, 8, 32946, 32773 })
			for (final int predictor : new int[] { 1, 2 })
				for (final int bits : new int[] { 8, 16 })
					for (final int tile : new int[] { 0, 16 }) {
						final Page p = new Page(37, 13, bits, 1, 1, 1, 1, compression, predictor, tile, tile > 0 ? 0 : 5);
						final ByteOrder order = files++ % 2 == 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
						final Path file = write(dir.resolve("one-" + compression + "-" + predictor + "-" + bits + "-" + tile +
							".tif"), p, 3, order);
						for (final boolean byOffset : new boolean[] { false, true }) {
							final ImagePlus imp = byOffset ? ImageFiles.openByOffset(SeekableBytes.of(file)) : ImageFiles.open(file);
							final String what = file.getFileName() + (byOffset ? " by offset" : " by file");
							assertEquals(3, imp.getStackSize(), what);
							assertEquals(bits, imp.getBitDepth(), what);
							for (int t = 0; t < 3; t++)
								for (int y = 0; y < p.height; y++)
									for (int x = 0; x < p.width; x++)
										assertEquals(value(t, 0, x, y, bits, 1), imp.getStack().getProcessor(t + 1).getf(x, y), 0, what +
											": page " + t + " at " + x + "," + y);
						}
					}
	}

	/** What we do not decode, or damaged pieces: one line naming the file and what is wrong, nothing else thrown. */
	@Test
	void unreadableLayoutsAreRefusedInOneLine() throws IOException {
		final Page jpeg = new Page(16, 16, 8, 1, 3, 2, 2, 7, 1, 0, 16);
		assertRefused(write(dir.resolve("jpeg.tif"), jpeg, 1, ByteOrder.LITTLE_ENDIAN), "JPEG-compressed TIFF is not " +
			"supported", "photometric='minisblack'");
		final Page floatPredictorOnIntegers = new Page(16, 16, 16, 1, 3, 2, 2, 8, 3, 0, 16);
		assertRefused(write(dir.resolve("predictor3.tif"), floatPredictorOnIntegers, 1, ByteOrder.LITTLE_ENDIAN),
			"predictor 3 for 16-bit integer samples is not supported", "without a predictor");
		// LZW data cut short, and LZW data with a code the table does not hold yet
		final Page lzw = new Page(40, 30, 16, 1, 3, 2, 2, 5, 1, 0, 30);
		final Path cut = write(dir.resolve("cut-lzw.tif"), lzw, 1, ByteOrder.LITTLE_ENDIAN);
		final byte[] bytes = Files.readAllBytes(cut);
		final byte[] damaged = bytes.clone();
		for (int i = 20; i < 60; i++)
			damaged[i] = (byte) 0xff; // codes of 511 where the table holds a few hundred
		Files.write(cut, damaged);
		assertRefused(cut, "damaged LZW data", "strip 1 of 1");
		// a Deflate strip of garbage
		final Page deflate = new Page(40, 30, 8, 1, 3, 2, 2, 8, 1, 0, 30);
		final Path bad = write(dir.resolve("bad-deflate.tif"), deflate, 1, ByteOrder.LITTLE_ENDIAN);
		final byte[] d = Files.readAllBytes(bad);
		for (int i = 8; i < 30; i++)
			d[i] = (byte) (i * 37);
		Files.write(bad, d);
		assertRefused(bad, "damaged Deflate data", "bad-deflate.tif");
	}

	/**
	 * Files of each layout with bytes changed at random (in the directory, the tables, the compressed data): every
	 * one is read or refused with an {@link IOException} of one line naming the file, by file and by offset; nothing
	 * else is thrown. Cases: {@code contact.tracker.fuzz.cases} (default 300), from {@code contact.tracker.fuzz.seed}.
	 */
	@Test
	void damagedLayoutsAreReadOrRefusedInOneLine() throws IOException {
		final Page[] layouts = { new Page(37, 13, 16, 1, 3, 2, 2, 5, 2, 0, 5), new Page(37, 13, 8, 1, 4, 2, 2, 8, 1, 16,
			0), new Page(37, 13, 16, 1, 2, 1, 1, 32773, 1, 0, 4), new Page(37, 13, 32, 3, 3, 2, 2, 5, 1, 16, 0) };
		final int cases = Integer.getInteger("contact.tracker.fuzz.cases", 300);
		final java.util.SplittableRandom rnd = new java.util.SplittableRandom(Long.getLong("contact.tracker.fuzz.seed",
			20261205L));
		int read = 0, refused = 0;
		for (int c = 0; c < cases; c++) {
			final long seed = rnd.nextLong();
			final java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
			final Page p = layouts[r.nextInt(layouts.length)];
			final Path file = write(dir.resolve("mutant" + c + ".tif"), p, 1 + r.nextInt(2), r.nextBoolean()
				? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
			final byte[] b = Files.readAllBytes(file);
			final int changes = 1 + r.nextInt(8);
			for (int k = 0; k < changes; k++) {
				final int at = r.nextInt(4) == 0 ? b.length - 1 - r.nextInt(Math.min(b.length, 400)) : r.nextInt(b.length);
				b[at] = (byte) (r.nextBoolean() ? r.nextInt(256) : b[at] ^ 1 << r.nextInt(8));
			}
			Files.write(file, b);
			for (final boolean byOffset : new boolean[] { false, true }) {
				try {
					final ImagePlus imp = byOffset ? ImageFiles.openByOffset(SeekableBytes.of(file)) : ImageFiles.open(file);
					for (int i = 1; i <= imp.getStackSize(); i++)
						imp.getStack().getProcessor(i);
					read++;
				}
				catch (final IOException | UncheckedIOException e) {
					final String m = e instanceof UncheckedIOException u ? u.getCause().getMessage() : e.getMessage();
					assertTrue(m != null && m.lines().count() == 1 && m.contains(file.getFileName().toString()), "seed " +
						seed + ": " + m);
					refused++;
				}
				catch (final RuntimeException | OutOfMemoryError e) {
					throw new AssertionError("seed " + seed + " (" + p + "), by " + (byOffset ? "offset" : "file") + ": " + e,
						e);
				}
			}
			Files.delete(file);
		}
		System.out.println("TIFF layout mutants: " + cases + " files, " + read + " reads, " + refused + " refusals");
		assertTrue(read > 0 && refused > 0, read + " read, " + refused + " refused");
	}

	/** Asserts that the file is refused in one line naming it and saying {@code what} and {@code how}. */
	private static void assertRefused(final Path file, final String what, final String how) {
		for (final boolean byOffset : new boolean[] { false, true }) {
			String m = null;
			try {
				final ImagePlus imp = byOffset ? ImageFiles.openByOffset(SeekableBytes.of(file)) : ImageFiles.open(file);
				for (int i = 1; i <= imp.getStackSize(); i++)
					imp.getStack().getProcessor(i);
			}
			catch (final IOException e) {
				m = e.getMessage();
			}
			catch (final UncheckedIOException e) { // a plane of a virtual stack, read when asked for
				m = e.getCause().getMessage();
			}
			assertTrue(m != null, file + " was read");
			assertEquals(1, m.lines().count(), m);
			assertTrue(m.contains(file.toString()) && m.contains(what) && m.contains(how), m);
			assertFalse(m.contains("Exception"), m);
		}
	}
}
