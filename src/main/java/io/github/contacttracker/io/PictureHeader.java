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
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The size a single picture (PNG, JPEG, GIF, BMP) declares in its header, checked ({@link FrameBudget}) before
 * ImageJ's opener decodes it into an image of that size. Other formats ImageJ opens are read as they are; running
 * out of memory on one is still a refusal ({@link ImageJMessages}).
 */
final class PictureHeader {

	private PictureHeader() {}

	/** JPEG's frame header may follow metadata (EXIF, thumbnails): this much of the file is searched. */
	private static final int JPEG_SEARCH = 1 << 16;

	/** @throws IOException naming the file when its declared size is impossible or does not fit */
	static void check(final Path file) throws IOException {
		final byte[] bytes;
		try (InputStream in = Files.newInputStream(file)) {
			bytes = in.readNBytes(JPEG_SEARCH);
		}
		final ByteBuffer b = ByteBuffer.wrap(bytes);
		final int n = bytes.length;
		if (n >= 24 && (bytes[0] & 0xff) == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G')
			FrameBudget.check(file, b.getInt(16) & 0xffffffffL, b.getInt(20) & 0xffffffffL, 4);
		else if (n >= 10 && bytes[0] == 'G' && bytes[1] == 'I' && bytes[2] == 'F' && bytes[3] == '8')
			FrameBudget.check(file, b.order(ByteOrder.LITTLE_ENDIAN).getShort(6) & 0xffff, b.getShort(8) & 0xffff, 4);
		else if (n >= 26 && bytes[0] == 'B' && bytes[1] == 'M')
			FrameBudget.check(file, b.order(ByteOrder.LITTLE_ENDIAN).getInt(18), Math.abs((long) b.getInt(22)), 4);
		else if (n >= 4 && (bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xd8) jpeg(file, b);
	}

	/** The first start-of-frame marker's size; segments before it are skipped by their lengths. */
	private static void jpeg(final Path file, final ByteBuffer b) throws IOException {
		int at = 2;
		while (at + 9 <= b.limit()) {
			if ((b.get(at) & 0xff) != 0xff) return; // not a marker: leave the file to the decoder
			final int marker = b.get(at + 1) & 0xff;
			if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
				FrameBudget.check(file, b.getShort(at + 7) & 0xffff, b.getShort(at + 5) & 0xffff, 4);
				return;
			}
			at += 2 + (b.getShort(at + 2) & 0xffff);
		}
	}
}
