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

/**
 * How large a frame a file may declare before anything is allocated for it. A file's header can claim any width
 * and height; a reader that believed it would try to allocate the frame and end in "out of memory" (or, over
 * 2^31 pixels, a negative array size). So every reader checks the declared frame against two bounds first:
 * <ul>
 * <li>what one Java array holds ({@link #MAX_PIXELS} pixels), and</li>
 * <li>a share of the heap: tracking holds a few frames at a time (the frame cache, one frame per worker thread
 * and their working copies), so one frame may take at most {@link #HEAP_SHARE} of the maximum heap.</li>
 * </ul>
 * A frame over the second bound may be a real, huge frame rather than a lie: the message then says how much heap
 * it needs. (Checks against the file's own length, which catch most lies, are the readers'.)
 */
final class FrameBudget {

	private FrameBudget() {}

	/** The most pixels a frame may have: the largest Java array, less the VM's header reserve. */
	static final long MAX_PIXELS = Integer.MAX_VALUE - 8;

	/** A frame may take at most this share of the maximum heap. */
	static final double HEAP_SHARE = 0.125;

	/**
	 * @param file the file (a path, or an address such as hdfs://nn/a.tif), for the message
	 * @param width the declared width (px)
	 * @param height the declared height (px)
	 * @param bytesPerPixel the bytes one pixel takes once read (at least 1)
	 * @throws IOException naming the file and the declared size when the frame is impossible or does not fit
	 */
	static void check(final Object file, final long width, final long height, final int bytesPerPixel)
		throws IOException
	{
		if (width <= 0 || height <= 0) throw new IOException("cannot read " + file + ": it declares a frame of " +
			width + " x " + height + " pixels");
		if (width > MAX_PIXELS / height) throw new IOException("cannot read " + file + ": it declares a frame of " +
			width + " x " + height + " pixels, more than one frame can hold (2^31)");
		final long bytes = width * height * Math.max(1, bytesPerPixel);
		final long heap = Runtime.getRuntime().maxMemory();
		if (bytes > heap * HEAP_SHARE) throw new IOException("cannot read " + file + ": its frames of " + width + " x " +
			height + " pixels (" + mb(bytes) + " MB each) need more than " + mb((long) (heap * HEAP_SHARE)) +
			" MB, an eighth of the Java heap (" + mb(heap) + " MB); if the size is real, give Java more memory " +
			"(CONTACT_TRACKER_JAVA_OPTS=-Xmx8g; in Fiji Edit > Options > Memory & Threads)");
	}

	/**
	 * Checks the memory a file's description takes as it is read (a TIFF's directories: a hostile file can chain
	 * millions of them), against the same share of the heap as a frame.
	 *
	 * @param file the file (a path, or an address such as hdfs://nn/a.tif), for the message
	 * @param what what takes the memory, e.g. "its 500000 image directories"
	 * @param bytes the bytes it takes so far
	 * @throws IOException naming the file when that is more than the share
	 */
	static void checkDescription(final Object file, final String what, final long bytes) throws IOException {
		final long heap = Runtime.getRuntime().maxMemory();
		if (bytes > heap * HEAP_SHARE) throw new IOException("cannot read " + file + ": " + what + " take more than " +
			mb((long) (heap * HEAP_SHARE)) + " MB to describe, an eighth of the Java heap (" + mb(heap) + " MB); if " +
			"the file is real, give Java more memory (CONTACT_TRACKER_JAVA_OPTS=-Xmx8g; in Fiji Edit > Options > " +
			"Memory & Threads)");
	}

	private static long mb(final long bytes) {
		return (bytes + (1 << 20) - 1) >> 20;
	}
}
