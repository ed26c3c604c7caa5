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

/**
 * The frame size an AVI declares, checked before ImageJ's {@code AVI_Reader} allocates frames of that size: the
 * main header ({@code avih}) and the video stream's bitmap header ({@code strf}) inside the {@code hdrl} list. The
 * reader itself checks the chunk structure and the frames (its messages become our one line); what it believes
 * without a check is the frame's width, height and palette size.
 */
final class AviHeader {

	private AviHeader() {}

	/** The header list is read whole: real ones are a few kilobytes. */
	private static final int MAX_HEADER = 1 << 20;

	/**
	 * @throws IOException naming the file and what is wrong with its header
	 */
	static void check(final Path file) throws IOException {
		try (FileChannel ch = FileChannel.open(file)) {
			final long size = ch.size();
			final ByteBuffer list = ByteBuffer.allocate((int) Math.min(size, 12 + 12 + MAX_HEADER)).order(
				ByteOrder.LITTLE_ENDIAN);
			while (list.hasRemaining() && ch.read(list, list.position()) >= 0) {
				// read until full or the end of the file
			}
			list.flip();
			// RIFF size "AVI " then, first, LIST size "hdrl"
			if (list.limit() < 24 || !fourcc(list, 12).equals("LIST") || !fourcc(list, 20).equals("hdrl")) return;
			final long end = Math.min(list.limit(), 20 + (list.getInt(16) & 0xffffffffL));
			boolean video = false;
			for (int at = 24; at + 8 <= end;) {
				final String id = fourcc(list, at);
				final long length = list.getInt(at + 4) & 0xffffffffL;
				if (id.equals("LIST")) {
					at += 12; // into the stream's list
					continue;
				}
				if (at + 8 + length > end) throw new IOException("cannot read " + file + ": damaged AVI: its '" + id +
					"' header of " + length + " bytes runs past its header list");
				// the reader sizes its frames by the main header's width and the bitmap's height: both checked
				if (id.equals("avih") && length >= 40) FrameBudget.check(file, list.getInt(at + 8 + 32) & 0xffffffffL, list
					.getInt(at + 8 + 36) & 0xffffffffL, 4);
				if (id.equals("strh") && length >= 4) video = fourcc(list, at + 8).equals("vids");
				if (id.equals("strf") && video && length >= 40) {
					final long w = list.getInt(at + 8 + 4), h = Math.abs((long) list.getInt(at + 8 + 8));
					final int bits = list.getShort(at + 8 + 14);
					final long colours = list.getInt(at + 8 + 32) & 0xffffffffL;
					if (colours > 256) throw new IOException("cannot read " + file + ": damaged AVI: a palette of " +
						colours + " colours");
					if (bits < 0 || bits > 64) throw new IOException("cannot read " + file + ": damaged AVI: " + bits +
						" bits per pixel");
					FrameBudget.check(file, w, h, 4);
					return;
				}
				at += 8 + length + (length & 1);
			}
		}
	}

	private static String fourcc(final ByteBuffer b, final int at) {
		final char[] c = new char[4];
		for (int i = 0; i < 4; i++)
			c[i] = (char) (b.get(at + i) & 0xff);
		for (int i = 0; i < 4; i++)
			if (c[i] < ' ' || c[i] > '~') c[i] = '?'; // a damaged file's bytes, shown on one line
		return new String(c);
	}
}
