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
import java.io.RandomAccessFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.IntFunction;

import ij.ImagePlus;
import ij.ImageStack;
import ij.process.FloatProcessor;

/**
 * Small movies for tests: one Gaussian particle per frame moving along x, and a TIFF writer of our own for what
 * ImageJ does not write (BigTIFF, 64-bit float, signed integers, one directory per page, OME descriptions).
 */
public final class TestMovies {

	private TestMovies() {}

	/** Frame size. */
	public static final int W = 64, H = 48;
	/** The particle's width (Gaussian sigma, px). */
	public static final double SIGMA = 4;

	/** @return the true x of the particle in frame {@code t} (y is {@link #y()}) */
	public static double x(final int t) {
		return 20.3 + 2.1 * t;
	}

	/** @return the true y of the particle */
	public static double y() {
		return 23.6;
	}

	/** @return frame {@code t}: background {@code bg}, the particle's peak at {@code peak} */
	public static float[] frame(final int t, final double bg, final double peak) {
		final float[] px = new float[W * H];
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				final double dx = x - x(t), dy = y - y();
				px[y * W + x] = (float) (bg + (peak - bg) * Math.exp(-(dx * dx + dy * dy) / (2 * SIGMA * SIGMA)));
			}
		return px;
	}

	/** @return {@code n} frames from {@link #frame}, rounded to whole numbers */
	public static List<float[]> frames(final int n, final double bg, final double peak) {
		final List<float[]> frames = new ArrayList<>();
		for (int t = 0; t < n; t++) {
			final float[] f = frame(t, bg, peak);
			for (int i = 0; i < f.length; i++)
				f[i] = Math.round(f[i]);
			frames.add(f);
		}
		return frames;
	}

	/** @return the frames as an 8-bit ImageJ stack (values 0..255) */
	public static ImagePlus bytes(final List<float[]> frames) {
		final ImageStack stack = new ImageStack(W, H);
		for (final float[] f : frames)
			stack.addSlice(null, new FloatProcessor(W, H, f.clone()).convertToByte(false));
		return new ImagePlus("movie", stack);
	}

	/**
	 * Writes a little-endian TIFF, one directory and one strip per page, uncompressed.
	 *
	 * @param big BigTIFF (64-bit offsets) instead of classic TIFF
	 * @param bits bits per sample: 8, 16, 32 or 64
	 * @param format TIFF SampleFormat: 1 unsigned, 2 signed, 3 float
	 * @param description ImageDescription of the first page, or null
	 * @param dataAt where the pixel data starts (past the directories); beyond 4 GB for a test of BigTIFF's
	 *        offsets (the file is sparse: the gap takes no disk space)
	 */
	public static void writeTiff(final Path file, final boolean big, final int bits, final int format,
		final List<float[]> frames, final String description, final long dataAt) throws IOException
	{
		writeTiff(file, big, bits, format, frames.size(), W, H, frames::get, description, dataAt);
	}

	/**
	 * As {@link #writeTiff(Path, boolean, int, int, List, String, long)}, frames of any size made one at a time
	 * (a movie larger than the heap).
	 */
	public static void writeTiff(final Path file, final boolean big, final int bits, final int format,
		final int count, final int w, final int h, final IntFunction<float[]> frame, final String description,
		final long dataAt) throws IOException
	{
		final int bytes = bits / 8, planeBytes = w * h * bytes;
		final byte[] desc = description == null ? null : (description + "\0").getBytes(StandardCharsets.UTF_8);
		final int entries = desc == null ? 9 : 10;
		final int entrySize = big ? 20 : 12, header = big ? 16 : 8;
		final int ifdSize = (big ? 8 : 2) + entries * entrySize + (big ? 8 : 4);
		final long descAt = header + (long) count * ifdSize;
		final long data = Math.max(dataAt, descAt + (desc == null ? 0 : desc.length));
		try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
			raf.setLength(0);
			final ByteBuffer b = ByteBuffer.allocate((int) descAt).order(ByteOrder.LITTLE_ENDIAN);
			b.put((byte) 'I').put((byte) 'I');
			if (big) b.putShort((short) 43).putShort((short) 8).putShort((short) 0).putLong(header);
			else b.putShort((short) 42).putInt(header);
			for (int p = 0; p < count; p++) {
				final long next = p + 1 < count ? header + (long) (p + 1) * ifdSize : 0;
				if (big) b.putLong(entries);
				else b.putShort((short) entries);
				entry(b, big, 256, w);
				entry(b, big, 257, h);
				entry(b, big, 258, bits);
				entry(b, big, 259, 1);
				entry(b, big, 262, 1);
				if (desc != null) {
					b.putShort((short) 270).putShort((short) 2);
					if (big) b.putLong(desc.length).putLong(descAt);
					else b.putInt(desc.length).putInt((int) descAt);
				}
				entry(b, big, 273, data + (long) p * planeBytes);
				entry(b, big, 277, 1);
				entry(b, big, 279, planeBytes);
				entry(b, big, 339, format);
				if (big) b.putLong(next);
				else b.putInt((int) next);
			}
			raf.write(b.array());
			if (desc != null) raf.write(desc);
			raf.seek(data);
			for (int p = 0; p < count; p++) {
				final float[] f = frame.apply(p);
				final ByteBuffer px = ByteBuffer.allocate(planeBytes).order(ByteOrder.LITTLE_ENDIAN);
				for (final float v : f) {
					if (bits == 8) px.put((byte) v);
					else if (bits == 16) px.putShort((short) v);
					else if (bits == 32 && format == 3) px.putFloat(v);
					else if (bits == 32) px.putInt((int) v);
					else px.putDouble(v);
				}
				raf.write(px.array());
			}
		}
	}

	/** One entry with a single value held in the entry (LONG, or LONG8 in BigTIFF). */
	private static void entry(final ByteBuffer b, final boolean big, final int tag, final long value) {
		b.putShort((short) tag);
		if (big) b.putShort((short) 16).putLong(1).putLong(value);
		else b.putShort((short) 4).putInt(1).putInt((int) value);
	}
}
