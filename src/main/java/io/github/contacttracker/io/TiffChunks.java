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

/**
 * One sample's plane of a TIFF image put together from the pieces it is stored in: strips (rows of the whole
 * width) or tiles (rectangles, the last ones reaching past the image), each compressed on its own
 * ({@link TiffCompression}), a pixel's samples side by side (chunky) or one sample per piece (planar), with the
 * horizontal-difference predictor (2, integers) or the floating-point one (3) undone row by row. The plane comes
 * out as its samples' bytes in the file's byte order, row after row, as an uncompressed strip would hold them.
 * <p>
 * Every piece's size follows from the directory; a piece whose compressed bytes are far more than it can need, or
 * whose data ends early, is refused in one line rather than believed.
 */
final class TiffChunks {

	private TiffChunks() {}

	/**
	 * Checks that the pieces of {@code p} can be read: a compression and predictor we decode, enough strips or tiles
	 * for the image, and pieces of a size a frame can have.
	 *
	 * @throws IOException one line naming the file and the layout
	 */
	static void check(final String file, final TiffDirectories.Directory p) throws IOException {
		if (!TiffCompression.supported(p.compression())) throw new IOException("cannot read " + file + ": " +
			TiffCompression.name(p.compression()) + "-compressed TIFF is not supported (LZW, Deflate and PackBits are); " +
			"save it uncompressed, e.g. tifffile.imwrite(p, a, photometric='minisblack')");
		final boolean floats = p.format() == 3;
		if (p.predictor() != 1 && !(p.predictor() == 2 && !floats && p.bits() <= 32 || p.predictor() == 3 && floats))
			throw new IOException("cannot read " + file + ": TIFF predictor " + p.predictor() + " for " + p.bits() +
				"-bit " + (floats ? "float" : "integer") + " samples is not supported; save it without a predictor");
		final long needed = pieces(p);
		if (p.offsets().length < needed) throw new IOException("cannot read " + file + ": damaged TIFF: " + p.offsets()
			.length + " " + (p.tiled() ? "tiles" : "strips") + " for an image of " + p.width() + " x " + p.height() +
			" pixels in " + (p.tiled() ? "tiles of " + p.tileWidth() + " x " + p.tileLength() : "strips of " + p
				.rowsPerStrip() + " rows") + ", which needs " + needed);
		if (pieceBytes(p) > Math.min(Integer.MAX_VALUE - 8L, 4 * p.planeBytes() + (16 << 20))) throw new IOException(
			"cannot read " + file + ": damaged TIFF: " + (p.tiled() ? "tiles of " + p.tileWidth() + " x " + p
				.tileLength() : "strips of " + p.rowsPerStrip() + " rows") + " for an image of " + p.width() + " x " + p
					.height() + " pixels");
	}

	/** @return the strips or tiles one sample's plane needs */
	private static long pieces(final TiffDirectories.Directory p) {
		if (!p.tiled()) return (p.height() + (long) p.rowsPerStrip() - 1) / p.rowsPerStrip();
		return ((p.width() + (long) p.tileWidth() - 1) / p.tileWidth()) * ((p.height() + (long) p.tileLength() - 1) / p
			.tileLength());
	}

	/**
	 * @return the bytes strip {@code s} of a stripped image holds uncompressed: its rows (the last strip of a plane
	 *         may hold fewer) times a row's bytes (one sample's where the samples lie in planes)
	 */
	static long stripBytes(final TiffDirectories.Directory p, final int s) {
		final long rows = Math.min(p.rowsPerStrip(), p.height() - s % pieces(p) * p.rowsPerStrip());
		final long rowBits = (long) p.width() * p.bits() * (p.planar() == 2 ? 1 : p.samples());
		return rows * ((rowBits + 7) / 8);
	}

	/** @return the bytes of one whole strip or tile, uncompressed */
	private static long pieceBytes(final TiffDirectories.Directory p) {
		final long pixels = p.tiled() ? (long) p.tileWidth() * p.tileLength() : (long) p.width() * p.rowsPerStrip();
		return pixels * p.samples() * (p.bits() / 8);
	}

	/**
	 * @param p a directory {@link #check}ed, of 8-, 16-, 32- or 64-bit samples
	 * @return sample {@code p.sample()} of every pixel, {@code p.bits() / 8} bytes each in {@code order}, row after row
	 * @throws IOException one line naming the file, when a piece is damaged
	 */
	static byte[] plane(final SeekableBytes file, final TiffDirectories.Directory p, final ByteOrder order)
		throws IOException
	{
		final int w = p.width(), h = p.height(), bytes = p.bits() / 8, spp = p.samples(), sample = p.sample();
		final int pw = p.tiled() ? p.tileWidth() : w, ph = p.tiled() ? p.tileLength() : p.rowsPerStrip();
		final int across = (w + pw - 1) / pw, pieces = (int) pieces(p);
		final byte[] out = new byte[Math.multiplyExact(w * h, bytes)];
		final byte[] piece = new byte[(int) pieceBytes(p)];
		final byte[] row = p.predictor() == 3 ? new byte[pw * spp * bytes] : null;
		for (int c = 0; c < pieces; c++) {
			final int r0 = c / across * ph, c0 = c % across * pw;
			// a tile is stored whole, past the image's edge; the last strip holds only the rows left
			final int stored = p.tiled() ? ph : Math.min(ph, h - r0), rows = Math.min(ph, h - r0), cols = Math.min(pw,
				w - c0);
			final int expected = stored * pw * spp * bytes;
			final String what = file.name() + " (" + (p.tiled() ? "tile " : "strip ") + (c + 1) + " of " + pieces + ")";
			final long count = p.counts()[c];
			if (p.compression() == 1) {
				if (count < expected) throw new IOException("cannot read " + what + ": it holds " + count + " bytes, its " +
					"pixels " + expected);
				file.read(p.offsets()[c], ByteBuffer.wrap(piece, 0, expected));
			}
			else {
				// no compression TIFF uses makes data more than twice as long (PackBits: 1 byte in 128)
				if (count > 2L * expected + 4096) throw new IOException("cannot read " + what + ": damaged TIFF: " + count +
					" compressed bytes for " + expected + " bytes of pixels");
				final byte[] in = new byte[(int) count];
				file.read(p.offsets()[c], ByteBuffer.wrap(in));
				TiffCompression.decode(p.compression(), in, piece, expected, what);
			}
			if (p.predictor() == 2) differences(piece, stored, pw * spp, spp, bytes, order);
			else if (p.predictor() == 3) floatDifferences(piece, stored, pw * spp, spp, bytes, order, row);
			for (int y = 0; y < rows; y++) {
				final int from = y * pw * spp * bytes, to = ((r0 + y) * w + c0) * bytes;
				if (spp == 1) System.arraycopy(piece, from, out, to, cols * bytes);
				else for (int x = 0; x < cols; x++)
					System.arraycopy(piece, from + (x * spp + sample) * bytes, out, to + x * bytes, bytes);
			}
		}
		return out;
	}

	/**
	 * Undoes the horizontal-difference predictor (2): each sample of a row was stored as its difference from the
	 * same sample of the pixel before it, in the file's byte order, modulo its size.
	 *
	 * @param values the samples in a row (pixels times samples per pixel)
	 */
	private static void differences(final byte[] piece, final int rows, final int values, final int spp,
		final int bytes, final ByteOrder order)
	{
		final ByteBuffer b = ByteBuffer.wrap(piece).order(order);
		for (int y = 0; y < rows; y++) {
			final int start = y * values;
			for (int i = start + spp; i < start + values; i++)
				switch (bytes) {
					case 1 -> piece[i] += piece[i - spp];
					case 2 -> b.putShort(2 * i, (short) (b.getShort(2 * i) + b.getShort(2 * (i - spp))));
					default -> b.putInt(4 * i, b.getInt(4 * i) + b.getInt(4 * (i - spp)));
				}
		}
	}

	/**
	 * Undoes the floating-point predictor (3): each row's bytes were reordered, the most significant byte of every
	 * sample first, then the next, and stored as byte-wise differences (one pixel's samples apart).
	 *
	 * @param row a buffer of one row's bytes
	 */
	private static void floatDifferences(final byte[] piece, final int rows, final int values, final int spp,
		final int bytes, final ByteOrder order, final byte[] row)
	{
		final int n = values * bytes;
		final boolean little = order == ByteOrder.LITTLE_ENDIAN;
		for (int y = 0; y < rows; y++) {
			final int start = y * n;
			for (int i = start + spp; i < start + n; i++)
				piece[i] += piece[i - spp];
			System.arraycopy(piece, start, row, 0, n);
			for (int k = 0; k < values; k++)
				for (int m = 0; m < bytes; m++) // m: the byte's significance, most significant first
					piece[start + k * bytes + (little ? bytes - 1 - m : m)] = row[m * values + k];
		}
	}
}
