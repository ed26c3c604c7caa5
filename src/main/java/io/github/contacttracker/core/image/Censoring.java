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

import io.github.contacttracker.core.math.CensoredNormal;

/**
 * Which pixels a least-squares fit of a model to the data may use when the pixel type clips, and how: saturated
 * cores at its maximum, dark rings pushed below 0 by bright particles, and confocal backgrounds whose noise the
 * detector's offset cuts at 0.
 * <p>
 * At the saturation a clipped pixel's true value is unknown, so it is left out. Leaving out only the clipped ones is
 * not enough: near a clip level the pixels kept are those whose noise happened to pull them away from it, a selection
 * bias of the order of the noise. So a pixel is also left out where the model, at the current estimate and not the
 * data, comes within {@value #MARGIN_SIGMAS} noise standard deviations of a clip level: whether such a pixel is used
 * then does not depend on its own noise, and the pixels used are (to within the normal tail beyond the margin) never
 * clipped. The price is the information of that band.
 * <p>
 * At the floor (0 for unsigned integers) the fit is <em>linked</em> instead, where the noise there is known: every
 * pixel is kept, those read as the floor too, and the model a pixel is fitted with is the mean of its normal noise
 * rounded and clipped at the floor, {@code E(m) = f + (m - f) Phi(z) + sigma phi(z)}, {@code z = (m - f - 1/2) /
 * sigma} ({@link #mean}; its slope {@link #slope} scales the pixel's gradient). Far above the floor that is the
 * model itself. No band moves with the model, and the background of a confocal slice, a fifth of it at 0, is
 * fitted with all its pixels: with the band, a set that moved with every round of profile and centres, fits on
 * dense confocal packings did not settle. The noise is the background's own where the frame's background is
 * clipped ({@link #withFloorNoise}: the profile measures it as a censored normal; the frame's estimate, read from
 * pixel differences, is not that of the pixels near the floor), and the frame's where it is not (then only the
 * particles' own dark parts come near the floor). Where a clipped background's noise is not known, the band.
 */
public final class Censoring {

	/** Margin between the model and a clip level, in noise standard deviations (0.1% of normal noise goes beyond). */
	static final double MARGIN_SIGMAS = 3;

	/**
	 * How far above the floor (noise standard deviations, past the half level of rounding) the link is worked out:
	 * beyond, it differs from the model by under 1e-8 of the noise and its slope from 1 by under 1e-8.
	 */
	static final double LINK_SIGMAS = 6;

	private final double floor, saturation, lowest, highest, noise, floorNoise, linkTop;
	private final boolean backgroundClipped;

	/**
	 * @param floorNoise the noise standard deviation at the floor that links it, or NaN: the band at the floor
	 */
	private Censoring(final double floor, final double saturation, final double noise, final boolean backgroundClipped,
		final double floorNoise)
	{
		final double margin = MARGIN_SIGMAS * noise;
		final boolean linked = floor > Double.NEGATIVE_INFINITY && floorNoise > 0;
		this.noise = noise;
		this.floor = floor;
		this.saturation = saturation;
		this.floorNoise = linked ? floorNoise : Double.NaN;
		lowest = linked ? Double.NEGATIVE_INFINITY : floor + margin;
		highest = saturation - margin;
		linkTop = linked ? floor + ROUNDING + LINK_SIGMAS * floorNoise : Double.NEGATIVE_INFINITY;
		this.backgroundClipped = backgroundClipped;
	}

	/** Integer pixels (the only ones with a floor) are rounded: a value read as the floor stood below half a level above. */
	private static final double ROUNDING = 0.5;

	/**
	 * @param plane the data, with its clip levels
	 * @param noise the noise standard deviation (grey levels)
	 * @return the rule for this frame: the floor linked with the frame's noise where its background is not clipped;
	 *         where it is, banded until the background's own noise is known ({@link #withFloorNoise})
	 */
	public static Censoring of(final Plane plane, final double noise) {
		final double floor = plane.floor(), sigma = Math.max(noise, 0);
		final boolean clipped = floor > Double.NEGATIVE_INFINITY && clippedBackground(plane, floor);
		return new Censoring(floor, plane.saturation(), sigma, clipped, clipped ? Double.NaN : sigma);
	}

	/**
	 * @param background the noise standard deviation of the frame's clipped background, as a censored normal (the
	 *        profile's {@code floorNoise}; NaN where not measured)
	 * @return this rule, the floor linked with that noise where the background is clipped and it is known; else this
	 */
	public Censoring withFloorNoise(final double background) {
		if (!backgroundClipped || !(background > 0) || floor == Double.NEGATIVE_INFINITY) return this;
		return new Censoring(floor, saturation, noise, true, background);
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
	 *         (measured as a censored normal) instead of fitting it: banded, no pixel it may use shows it; linked, the
	 *         profile measured it from more pixels than a fit holds
	 */
	public boolean backgroundClipped() {
		return backgroundClipped;
	}

	/** @return the noise standard deviation the margin is made of (grey levels; 0 where not known) */
	public double noise() {
		return noise;
	}

	/**
	 * @return whether an observed value is at a clip level and left out (its true value unknown): at the saturation,
	 *         and at the floor unless it is linked
	 */
	public boolean clipped(final double value) {
		return value >= saturation || value <= floor && !linked();
	}

	/** @return whether the floor is linked ({@link #mean}) rather than banded */
	public boolean linked() {
		return linkTop > Double.NEGATIVE_INFINITY;
	}

	/**
	 * @return the model value below which a pixel is fitted through the link ({@link #mean}, {@link #slope}); minus
	 *         infinity where the floor is not linked
	 */
	public double linkTop() {
		return linkTop;
	}

	/** @return the noise standard deviation the floor is linked with (NaN where it is not) */
	public double floorNoise() {
		return floorNoise;
	}

	/**
	 * @return the mean of a pixel whose noiseless value is {@code model}: its normal noise of the floor's standard
	 *         deviation added, rounded, and clipped at the floor, {@code f + (m - f) Phi(z) + sigma phi(z)} with
	 *         {@code z = (m - f - 1/2) / sigma} (the values above the floor taken as unrounded)
	 */
	public double mean(final double model) {
		final double[] out = new double[2];
		link(model, out);
		return out[0];
	}

	/** @return the derivative of {@link #mean} with respect to the model: {@code Phi(z) + phi(z) / (2 sigma)} */
	public double slope(final double model) {
		final double[] out = new double[2];
		link(model, out);
		return out[1];
	}

	/**
	 * The link at {@code model}: its {@link #mean} into {@code out[0]} and its {@link #slope} into {@code out[1]},
	 * from one exponential (the fit's passes need both at every pixel near the floor).
	 */
	public void link(final double model, final double[] out) {
		final double z = (model - floor - ROUNDING) / floorNoise, density = CensoredNormal.normalDensity(z);
		final double below = CensoredNormal.normalCdf(z, density);
		out[0] = floor + (model - floor) * below + floorNoise * density;
		out[1] = below + density * ROUNDING / floorNoise;
	}

	/** @return whether a pixel whose model value is {@code model} is usable: not within the margin of a clip level */
	public boolean usable(final double model) {
		return model > lowest && model < highest;
	}

	/** @return whether every model value from {@code lo} to {@code hi} is usable (the band is an interval) */
	public boolean usableBetween(final double lo, final double hi) {
		return usable(lo) && usable(hi);
	}

	/** @return whether any model value can be unusable (the pixel type clips at a level that is not linked) */
	public boolean active() {
		return lowest > Double.NEGATIVE_INFINITY || highest < Double.POSITIVE_INFINITY;
	}
}
