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
package io.github.contacttracker.ij;

import ij.ImagePlus;
import ij.gui.Roi;
import io.github.contacttracker.core.InvalidInputException;
import net.imglib2.Interval;
import net.imglib2.util.Intervals;

/**
 * What a Fiji user shows of an image: the frame on display and the area selected on it. The Fiji command tracks
 * and measures that part of that frame, and the profile helper's buttons and TrackMate's Measure work on them; the
 * command line reads whole movies from files and asks neither.
 */
public final class ShownImage {

	private ShownImage() {}

	/**
	 * The frame on display, as {@link ImagePlusFrames} counts frames: the time point shown, or the slice shown of
	 * a plain stack (whose slices are frames). What Fiji's preview and the profile helper's buttons work on.
	 *
	 * @param imp the image
	 * @return the 0-based index of the frame shown
	 */
	public static int frame(final ImagePlus imp) {
		final int[] czt = imp.convertIndexToPosition(imp.getCurrentSlice());
		return (imp.getNFrames() > 1 ? czt[2] : czt[1]) - 1;
	}

	/**
	 * The part of an image the Fiji command tracks and its button measures: the bounding rectangle of its area
	 * selection, as TrackMate detects within it. Only the Fiji front ends ask: an image opened from a file may carry
	 * a selection saved with it, which the command line does not use.
	 *
	 * @return the rectangle (x and y, pixel indices) of the image's area selection within the image, or {@code null}
	 *         when it has none (no selection, or a line or points)
	 * @throws InvalidInputException when the selection lies wholly outside the image
	 */
	public static Interval selection(final ImagePlus imp) {
		final Roi roi = imp.getRoi();
		if (roi == null || !roi.isArea()) return null;
		final java.awt.Rectangle b = roi.getBounds().intersection(new java.awt.Rectangle(imp.getWidth(), imp
			.getHeight()));
		if (b.isEmpty()) throw new InvalidInputException("the selection on '" + imp.getTitle() + "' lies outside the " +
			"image");
		return Intervals.createMinSize(b.x, b.y, b.width, b.height);
	}

	/** @return how {@code region} ({@link #selection}) is named in messages, e.g. {@code x 10-109, y 20-79} */
	public static String describe(final Interval region) {
		return "x " + region.min(0) + "-" + region.max(0) + ", y " + region.min(1) + "-" + region.max(1);
	}
}
