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
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Random;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.plugin.filter.AVI_Writer;
import ij.process.FloatProcessor;

/**
 * Small valid files of every format the readers take, the seeds of the mutation suite and of the fuzz test's
 * corpus: an ImageJ stack (big-endian, ImageJ's description), a multi-page 16-bit TIFF, a BigTIFF, a 64-bit float
 * TIFF, an uncompressed AVI and a PNG, each a few frames of 16 x 12 pixels. And a way to find and change a TIFF's
 * directory entries, for the mutations.
 */
final class SeedFiles {

	private SeedFiles() {}

	/** Frame size of the seeds. */
	static final int W = 16, H = 12;

	/** @return each seed's file name and bytes */
	static Map<String, byte[]> all(final Path scratch) throws IOException {
		final Map<String, byte[]> seeds = new LinkedHashMap<>();
		final ImageStack stack = new ImageStack(W, H);
		for (int t = 0; t < 3; t++)
			stack.addSlice(null, new FloatProcessor(W, H, frame(t)).convertToByte(false));
		final ImagePlus movie = new ImagePlus("movie", stack);
		final Path imagej = scratch.resolve("imagej.tif");
		new FileSaver(movie).saveAsTiffStack(imagej.toString());
		seeds.put("imagej.tif", Files.readAllBytes(imagej));
		seeds.put("pages16.tif", tiff(scratch, false, 16, 1));
		seeds.put("big.tif", tiff(scratch, true, 16, 1));
		seeds.put("float64.tif", tiff(scratch, false, 64, 3));
		final Path avi = scratch.resolve("movie.avi");
		new AVI_Writer().writeImage(movie, avi.toString(), AVI_Writer.NO_COMPRESSION, 0);
		seeds.put("movie.avi", Files.readAllBytes(avi));
		final Path png = scratch.resolve("image.png");
		new FileSaver(new ImagePlus("one", movie.getStack().getProcessor(1))).saveAsPng(png.toString());
		seeds.put("image.png", Files.readAllBytes(png));
		return seeds;
	}

	/** A particle of radius 3 px at (6 + t, 6) on a background of 20. */
	private static float[] frame(final int t) {
		final float[] px = new float[W * H];
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++)
				px[y * W + x] = (x - 6 - t) * (x - 6 - t) + (y - 6) * (y - 6) <= 9 ? 200 : 20;
		return px;
	}

	private static byte[] tiff(final Path scratch, final boolean big, final int bits, final int format)
		throws IOException
	{
		final Path file = scratch.resolve("seed-" + big + bits + ".tif");
		TestMovies.writeTiff(file, big, bits, format, 2, W, H, SeedFiles::frame, null, 0);
		return Files.readAllBytes(file);
	}

	/**
	 * @return {@code seed} with 1 to 8 random bytes changed in its first 512 bytes (its header and directories),
	 *         the first of them past the format's magic number
	 */
	static byte[] randomHeaderBytes(final byte[] seed, final Random random) {
		final byte[] bytes = seed.clone();
		final int changes = 1 + random.nextInt(8), span = Math.min(512, bytes.length);
		for (int i = 0; i < changes; i++)
			bytes[(i == 0 ? 4 : 0) + random.nextInt(span - 4)] = (byte) random.nextInt(256);
		return bytes;
	}

	/** A TIFF's bytes with its first directory's entries found, to be changed in place. */
	static final class Tiff {

		final byte[] bytes;
		final ByteBuffer b;
		final boolean big;
		/** Where the first directory starts. */
		final int ifd;

		Tiff(final byte[] bytes) {
			this.bytes = bytes.clone();
			b = ByteBuffer.wrap(this.bytes).order(bytes[0] == 'I' ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
			big = b.getShort(2) == 43;
			ifd = (int) (big ? b.getLong(8) : b.getInt(4));
		}

		int entries() {
			return (int) (big ? b.getLong(ifd) : b.getShort(ifd) & 0xffff);
		}

		/** @return where the entry of {@code tag} starts, or -1 */
		int entry(final int tag) {
			for (int i = 0; i < entries(); i++) {
				final int at = ifd + (big ? 8 : 2) + i * (big ? 20 : 12);
				if ((b.getShort(at) & 0xffff) == tag) return at;
			}
			return -1;
		}

		/** Sets {@code tag}'s entry to the single value {@code v} (as LONG, or LONG8 in a BigTIFF). */
		Tiff set(final int tag, final long v) {
			final int at = entry(tag);
			if (at < 0) throw new IllegalArgumentException("no tag " + tag);
			if (big) b.putShort(at + 2, (short) 16).putLong(at + 4, 1).putLong(at + 12, v);
			else b.putShort(at + 2, (short) 4).putInt(at + 4, 1).putInt(at + 8, (int) v);
			return this;
		}

		/** Sets the count of {@code tag}'s entry, leaving its value. */
		Tiff count(final int tag, final long n) {
			final int at = entry(tag);
			if (big) b.putLong(at + 4, n);
			else b.putInt(at + 4, (int) n);
			return this;
		}

		/** Sets the first directory's number of entries. */
		Tiff entries(final long n) {
			if (big) b.putLong(ifd, n);
			else b.putShort(ifd, (short) n);
			return this;
		}

		/** @return where the pointer to the directory after the {@code k}-th (0-based) is */
		int nextPointer(final int k) {
			int at = ifd;
			for (int i = 0;; i++) {
				final long n = big ? b.getLong(at) : b.getShort(at) & 0xffff;
				final int next = at + (big ? 8 : 2) + (int) n * (big ? 20 : 12);
				if (i == k) return next;
				at = (int) (big ? b.getLong(next) : b.getInt(next));
				if (at == 0) return next;
			}
		}

		/** Points the {@code k}-th directory's successor at byte {@code to}. */
		Tiff next(final int k, final long to) {
			final int at = nextPointer(k);
			if (big) b.putLong(at, to);
			else b.putInt(at, (int) to);
			return this;
		}
	}
}
