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
package io.github.contacttracker.lab.sim;

/**
 * The image of a uniformly bright disc seen through a Gaussian blur: a flat top of height {@code amplitude} that
 * falls to half at the disc's edge over a width set by the blur, as a bead imaged slightly out of focus or a
 * fluorescent sphere through a microscope's point spread function. The convolution of the disc with the 2D Gaussian
 * is integrated numerically (radius by Simpson's rule, angle by the trapezoidal rule, which converges fast for the
 * periodic integrand) and tabulated once, so that evaluating it costs a table lookup.
 */
public final class BlurredDisc implements RadialProfile {

	/** Table spacing (px). */
	private static final double STEP = 0.01;
	/** Radial and angular integration points: the profile is exact to about 1e-6 of its amplitude. */
	private static final int RADIAL = 200, ANGULAR = 128;

	private final TabulatedProfile table;

	/**
	 * @param radius the disc's radius (px, positive)
	 * @param sigma the blur's standard deviation (px, positive)
	 * @param amplitude the flat top's height above the background (grey levels; negative for dark discs)
	 */
	public BlurredDisc(final double radius, final double sigma, final double amplitude) {
		if (!(radius > 0) || !(sigma > 0) || !Double.isFinite(radius + sigma + amplitude))
			throw new IllegalArgumentException("a blurred disc needs a positive radius and blur, not " + radius + " and " +
				sigma);
		final double max = radius + 8 * sigma;
		final int n = (int) Math.ceil(max / STEP) + 1;
		final double[] r = new double[n], v = new double[n];
		for (int i = 0; i < n; i++) {
			r[i] = i * STEP;
			v[i] = amplitude * fraction(r[i], radius, sigma);
		}
		table = new TabulatedProfile(r, v);
	}

	/** @return the share of the disc's light that the blur brings to distance {@code r} of its centre, in [0, 1] */
	static double fraction(final double r, final double radius, final double sigma) {
		final double s2 = 2 * sigma * sigma;
		final double h = radius / RADIAL;
		double sum = 0;
		for (int i = 0; i <= RADIAL; i++) {
			final double rho = i * h;
			// mean over the angle of exp(-|r - rho|^2 / 2 sigma^2), trapezoidal on the periodic integrand
			double ring = 0;
			for (int k = 0; k < ANGULAR; k++) {
				final double c = Math.cos(Math.PI * (k + 0.5) / ANGULAR);
				ring += Math.exp(-(r * r + rho * rho - 2 * r * rho * c) / s2);
			}
			ring /= ANGULAR;
			final double w = i == 0 || i == RADIAL ? 1 : i % 2 == 1 ? 4 : 2;
			sum += w * rho * ring;
		}
		// the 2D Gaussian's normalisation 1 / (2 pi sigma^2) times the angle's 2 pi
		return sum * h / 3 * 2 / s2;
	}

	@Override
	public double value(final double r) {
		return table.value(r);
	}

	@Override
	public double reach(final double level) {
		return table.reach(level);
	}
}
