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
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

/**
 * The lossless compressions of TIFF 6 that microscopy files use, decoded into a caller's buffer: LZW (5), Deflate
 * (8, and 32946, its older code) and PackBits (32773), besides none (1). Our TIFF reader needs them for the layouts
 * ImageJ 1 does not read (samples stored plane after plane, tiles, BigTIFF), which writers compress as often as
 * any other.
 * <p>
 * Damaged data never throws anything but an {@link IOException}: a code the LZW table does not hold yet, a Deflate
 * stream that does not parse, or data that ends before the strip or tile is full are each one line.
 */
final class TiffCompression {

	private TiffCompression() {}

	/** @return whether {@code compression} (TIFF's Compression tag) is one {@link #decode} reads */
	static boolean supported(final int compression) {
		return compression == 1 || compression == 5 || compression == 8 || compression == 32946 || compression == 32773;
	}

	/** @return the compression's name, for messages */
	static String name(final int compression) {
		return switch (compression) {
			case 1 -> "none";
			case 5 -> "LZW";
			case 7 -> "JPEG";
			case 8, 32946 -> "Deflate";
			case 32773 -> "PackBits";
			case 34925 -> "LZMA";
			case 50000 -> "Zstd";
			default -> "compression " + compression;
		};
	}

	/**
	 * Decodes {@code in} until the first {@code length} bytes of {@code out} are written.
	 *
	 * @param what the strip or tile, and the file, for a message
	 * @throws IOException when the data is damaged or holds fewer bytes than {@code out}
	 */
	static void decode(final int compression, final byte[] in, final byte[] out, final int length, final String what)
		throws IOException
	{
		final int n = switch (compression) {
			case 1 -> {
				System.arraycopy(in, 0, out, 0, Math.min(in.length, length));
				yield Math.min(in.length, length);
			}
			case 5 -> lzw(in, out, length, what);
			case 8, 32946 -> deflate(in, out, length, what);
			case 32773 -> packBits(in, out, length);
			default -> throw new IOException("cannot read " + what + ": " + name(compression) + " is not supported");
		};
		if (n < length) throw new IOException("cannot read " + what + ": damaged " + name(compression) + " data (" + n +
			" of " + length + " bytes)");
	}

	/** @return the bytes written: PackBits runs (n+1 literal bytes for n in 0..127, 1-n copies for n in -127..-1) */
	private static int packBits(final byte[] in, final byte[] out, final int length) {
		int i = 0, o = 0;
		while (i < in.length && o < length) {
			final int n = in[i++];
			if (n >= 0) {
				final int len = Math.min(n + 1, Math.min(in.length - i, length - o));
				System.arraycopy(in, i, out, o, len);
				i += n + 1;
				o += len;
			}
			else if (n != -128 && i < in.length) {
				final int len = Math.min(1 - n, length - o);
				final byte b = in[i++];
				for (int k = 0; k < len; k++)
					out[o++] = b;
			}
		}
		return o;
	}

	private static int deflate(final byte[] in, final byte[] out, final int length, final String what)
		throws IOException
	{
		final Inflater inflater = new Inflater();
		try {
			inflater.setInput(in);
			int o = 0;
			while (o < length) {
				final int n = inflater.inflate(out, o, length - o);
				o += n;
				if (n == 0 && (inflater.finished() || inflater.needsInput() || inflater.needsDictionary())) break;
			}
			return o;
		}
		catch (final DataFormatException e) {
			throw new IOException("cannot read " + what + ": damaged Deflate data (" + e.getMessage() + ")");
		}
		finally {
			inflater.end();
		}
	}

	private static final int CLEAR = 256, END = 257, FIRST = 258, CODES = 4096;

	/**
	 * TIFF's LZW: codes of 9 to 12 bits, most significant bit first, the code width growing one code early (after
	 * code 510, 1022 and 2046 are added), 256 clearing the table and 257 ending the data.
	 *
	 * @return the bytes written
	 */
	private static int lzw(final byte[] in, final byte[] out, final int limit, final String what) throws IOException {
		// the table: each code is its prefix's string and one more byte; its first byte and length kept for speed
		final int[] prefix = new int[CODES], length = new int[CODES];
		final byte[] last = new byte[CODES], first = new byte[CODES];
		for (int c = 0; c < 256; c++) {
			last[c] = first[c] = (byte) c;
			length[c] = 1;
		}
		final long bits = 8L * in.length;
		long at = 0;
		int width = 9, next = FIRST, previous = -1, o = 0;
		while (o < limit && at + width <= bits) {
			final int b = (int) (at >>> 3);
			final int window = (in[b] & 0xff) << 16 | (b + 1 < in.length ? in[b + 1] & 0xff : 0) << 8 | (b + 2 < in.length ?
				in[b + 2] & 0xff : 0);
			final int code = window >>> 24 - (int) (at & 7) - width & (1 << width) - 1;
			at += width;
			if (code == END) break;
			if (code == CLEAR) {
				width = 9;
				next = FIRST;
				previous = -1;
				continue;
			}
			if (code > next || code == next && previous < 0) throw new IOException("cannot read " + what +
				": damaged LZW data (code " + code + " where the table holds " + next + ")");
			if (previous >= 0 && next < CODES) { // the new entry: the previous string and the first byte of this one
				prefix[next] = previous;
				first[next] = first[previous];
				last[next] = code == next ? first[previous] : first[code];
				length[next] = length[previous] + 1;
				next++;
				if (next + 1 >= 1 << width && width < 12) width++;
			}
			o = write(code, prefix, last, length, out, o, limit);
			previous = code;
		}
		return o;
	}

	/** Writes the string of {@code code} at {@code o}, what fits below {@code limit}; @return the position after it. */
	private static int write(final int code, final int[] prefix, final byte[] last, final int[] length,
		final byte[] out, final int o, final int limit)
	{
		final int end = o + length[code];
		int c = code;
		for (int p = end - 1; p >= o; p--) {
			if (p < limit) out[p] = last[c];
			c = prefix[c];
		}
		return Math.min(end, limit);
	}
}
