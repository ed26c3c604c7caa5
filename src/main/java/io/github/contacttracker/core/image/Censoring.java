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
package io.github.contacttracker.core.image;

/**
 * Which pixels a least-squares fit of a model to the data may use when the pixel type clips: saturated cores at its
 * maximum, and dark rings pushed below 0 by bright particles. A clipped pixel's true value is unknown, so it is left
 * out. Leaving out only the clipped ones is not enough: near a clip level the pixels kept are those whose noise
 * happened to pull them away from it, a selection bias of the order of the noise. So a pixel is also left out where
 * the model, at the current estimate and not the data, comes within {@value #MARGIN_SIGMAS} noise standard
 * deviations of a clip level: whether such a pixel is used then does not depend on its own noise, and the pixels
 * used are (to within the normal tail beyond the margin) never clipped. The price is the information of that band.
 */
public final class Censoring {

	/** Margin between the model and a clip level, in noise standard deviations (0.1% of normal noise goes beyond). */
	static final double MARGIN_SIGMAS = 3;

	private final double floor, saturation, lowest, highest;

	private Censoring(final double floor, final double saturation, final double margin) {
		this(floor, saturation, floor + margin, saturation - margin);
	}

	private Censoring(final double floor, final double saturation, final double lowest, final double highest) {
		this.floor = floor;
		this.saturation = saturation;
		this.lowest = lowest;
		this.highest = highest;
	}

	/**
	 * @param plane the data, with its clip levels
	 * @param noise the noise standard deviation (grey levels)
	 */
	public static Censoring of(final Plane plane, final double noise) {
		final double floor = plane.floor(), margin = MARGIN_SIGMAS * Math.max(noise, 0);
		final Censoring banded = new Censoring(floor, plane.saturation(), margin);
		return floor > Double.NEGATIVE_INFINITY && backgroundClipped(plane, floor) ? new Censoring(floor, plane
			.saturation(), Double.NEGATIVE_INFINITY, banded.highest) : banded;
	}

	/**
	 * Where the frame's background itself is clipped at the floor (confocal images with the detector's offset
	 * subtracted: a third of the pixels at 0), the band beside the floor would take the whole background and every
	 * particle's rim out of the fit, leaving its background undetermined and every fit failed; there the band is
	 * dropped at the floor (the pixels at it are still left out), at the price of a bias of the order of the noise on
	 * the few pixels just above it.
	 */
	static final double CLIPPED_BACKGROUND = 0.05;

	/** @return whether more than {@link #CLIPPED_BACKGROUND} of the frame's pixels lie at the floor */
	private static boolean backgroundClipped(final Plane plane, final double floor) {
		final int w = plane.width(), h = plane.height();
		final double[] row = new double[w];
		long low = 0;
		for (int y = 0; y < h; y++) {
			plane.read(0, w - 1, y, y, row, 0);
			for (final double v : row)
				if (v <= floor) low++;
		}
		return low > CLIPPED_BACKGROUND * w * h;
	}

	/** @return whether an observed value is at a clip level (its true value unknown) */
	public boolean clipped(final double value) {
		return value <= floor || value >= saturation;
	}

	/** @return whether a pixel whose model value is {@code model} is usable: not within the margin of a clip level */
	public boolean usable(final double model) {
		return model > lowest && model < highest;
	}

	/** @return whether every model value from {@code lo} to {@code hi} is usable (the band is an interval) */
	public boolean usableBetween(final double lo, final double hi) {
		return usable(lo) && usable(hi);
	}

	/** @return whether any model value can be unusable (the pixel type clips) */
	public boolean active() {
		return lowest > Double.NEGATIVE_INFINITY || highest < Double.POSITIVE_INFINITY;
	}
}
