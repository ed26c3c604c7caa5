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

import io.github.contacttracker.core.InvalidInputException;
import java.nio.file.Path;

/**
 * The image a table of spots was measured on, as TrackMate's {@code <ImageData>} describes it: TrackMate opens
 * {@code folder/filename} beside the spots when it loads our XML (and, failing that, {@code filename} in the
 * XML's own folder).
 *
 * @param filename the image's file name, "" when the image is not a file (TrackMate then loads the spots alone and
 *        reports that it cannot find the image)
 * @param folder the folder holding it, "" for the XML file's folder
 * @param width image width (px)
 * @param height image height (px)
 * @param nslices Z slices (1 for the 2D images Contact Tracker handles)
 * @param nframes time points
 */
public record ImageSource(String filename, String folder, int width, int height, int nslices, int nframes) {

	/** @throws IllegalArgumentException when a size is below 1 */
	public ImageSource {
		if (filename == null) filename = "";
		if (folder == null) folder = "";
		if (width < 1 || height < 1 || nslices < 1 || nframes < 1)
			throw new InvalidInputException("image size must be at least 1 in every dimension, not " + width + " x " +
				height + " x " + nslices + " slices x " + nframes + " frames");
	}

	/**
	 * @param imageFile the image file; its absolute parent becomes {@link #folder()}
	 * @return the source of a 2D time-lapse ({@code nslices = 1})
	 */
	public static ImageSource of(final Path imageFile, final int width, final int height, final int nframes) {
		final Path abs = imageFile.toAbsolutePath().normalize();
		final Path parent = abs.getParent();
		return new ImageSource(abs.getFileName().toString(), parent == null ? "" : parent.toString(), width, height, 1,
			nframes);
	}
}
