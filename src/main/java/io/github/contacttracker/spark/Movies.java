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
package io.github.contacttracker.spark;

import java.io.IOException;
import java.net.URI;
import java.util.LinkedHashMap;
import java.util.Map;

import ij.ImagePlus;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.ImageFiles;

/**
 * The movies open in this JVM (an executor runs many tasks of one movie): opening a TIFF walks its whole chain of
 * directories, which for a long movie costs more than a chunk's frames, so it is done once per executor.
 */
final class Movies {

	private Movies() {}

	/** A few movies at once: tasks of the same movie tend to run together. */
	private static final int KEPT = 4;

	/** A movie's frames, and whether its pixels are floating-point (the threshold is then suggested unrounded). */
	record Open(ImagePlusFrames frames, boolean floats) {}

	private static final Map<String, Open> OPEN = new LinkedHashMap<>(8, 0.75f, true) {

		private static final long serialVersionUID = 1L;

		@Override
		protected boolean removeEldestEntry(final Map.Entry<String, Open> eldest) {
			return size() > KEPT;
		}
	};

	/**
	 * @param channel 1-based, or 0 for single-channel images only
	 * @return the movie's frames, read by offset through Hadoop as they are needed
	 * @throws IOException naming the movie, in one line
	 */
	static Open open(final String uri, final String movie, final int channel) throws IOException {
		final String key = channel + "|" + uri;
		synchronized (OPEN) {
			final Open open = OPEN.get(key);
			if (open != null) return open;
		}
		final ImagePlus imp = ImageFiles.openByOffset(new HadoopBytes(URI.create(uri), movie));
		final Open open = new Open(ImagePlusFrames.of(imp, channel), imp.getBitDepth() == 32);
		synchronized (OPEN) {
			OPEN.put(key, open);
		}
		return open;
	}
}
