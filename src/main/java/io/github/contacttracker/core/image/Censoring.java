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

	private final double floor, saturation, lowest, highest, noise;
	private final boolean backgroundClipped;

	private Censoring(final double floor, final double saturation, final double noise,
		final boolean backgroundClipped)
	{
		final double margin = MARGIN_SIGMAS * noise;
		this.noise = noise;
		this.floor = floor;
		this.saturation = saturation;
		lowest = floor + margin;
		highest = saturation - margin;
		this.backgroundClipped = backgroundClipped;
	}

	/**
	 * @param plane the data, with its clip levels
	 * @param noise the noise standard deviation (grey levels)
	 */
	public static Censoring of(final Plane plane, final double noise) {
		final double floor = plane.floor();
		return new Censoring(floor, plane.saturation(), Math.max(noise, 0), floor > Double.NEGATIVE_INFINITY &&
			clippedBackground(plane, floor));
	}

	/**
	 * More than this share of a frame's pixels at the floor: its background itself is clipped (confocal slices with the
	 * detector's offset subtracted), and the band beside the floor takes the whole background out of a fit.
	 */
	public static final double CLIPPED_BACKGROUND = 0.05;

	/** @return whether more than {@link #CLIPPED_BACKGROUND} of the frame's pixels lie at the floor */
	private static boolean clippedBackground(final Plane plane, final double floor) {
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

	/**
	 * @return whether the frame's background is clipped at the floor: a fit then holds its background at the profile's
	 *         instead of fitting it (no pixel it may use shows it), and uses the pixels the band leaves, where the
	 *         particles stand clear of the floor and the clipping biases nothing
	 */
	public boolean backgroundClipped() {
		return backgroundClipped;
	}

	/** @return the noise standard deviation the margin is made of (grey levels; 0 where not known) */
	public double noise() {
		return noise;
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
