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
 * A Gaussian-damped Bessel ring pattern, the kind of curve the paper fitted to its 2.06 um particle image:
 * {@code value(r) = amplitude * J0(besselScale * r) * exp(-r^2 / (2 gaussianSigma^2))}. With
 * {@code besselScale = 0} it is a plain Gaussian spot.
 *
 * @param amplitude grey levels above background at the centre
 * @param besselScale radial frequency of the rings (1/px, {@code >= 0}); the first dark ring is near
 *        {@code 2.405 / besselScale}
 * @param gaussianSigma width of the Gaussian envelope (px, {@code > 0})
 */
public record GaussianBesselProfile(double amplitude, double besselScale, double gaussianSigma) implements RadialProfile {

	/** @throws IllegalArgumentException for a non-finite value, a negative scale or a non-positive sigma */
	public GaussianBesselProfile {
		if (!Double.isFinite(amplitude) || !(besselScale >= 0) || !Double.isFinite(besselScale)
			|| !(gaussianSigma > 0) || !Double.isFinite(gaussianSigma))
			throw new IllegalArgumentException("Gaussian-Bessel profile needs finite amplitude, besselScale >= 0 and "
				+ "gaussianSigma > 0, not " + amplitude + ", " + besselScale + ", " + gaussianSigma);
	}

	/** @return a plain Gaussian spot, {@code amplitude * exp(-r^2 / (2 sigma^2))} */
	public static GaussianBesselProfile gaussian(final double amplitude, final double sigma) {
		return new GaussianBesselProfile(amplitude, 0, sigma);
	}

	@Override
	public double value(final double r) {
		return amplitude * Bessel.j0(besselScale * r) * Math.exp(-r * r / (2 * gaussianSigma * gaussianSigma));
	}

	/**
	 * Same result as the interface's scan, but the scan starts where the envelope
	 * {@code |amplitude| min(1, sqrt(2 / (pi besselScale r))) exp(-r^2 / (2 sigma^2))} (a bound on
	 * {@code |value|}, since {@code |J0(x)| <= sqrt(2 / (pi x))}) has fallen below {@code level}, not at 2000 px.
	 */
	@Override
	public double reach(final double level) {
		if (!(level > 0) || !Double.isFinite(level))
			throw new IllegalArgumentException("reach level must be a positive grey level, not " + level);
		// the envelope decreases monotonically: double, then bisect, to find where it drops below level
		double below = 1;
		while (envelope(below) >= level)
			below *= 2;
		double above = 0;
		while (below - above > 1e-3) {
			final double mid = 0.5 * (above + below);
			if (envelope(mid) >= level) above = mid;
			else below = mid;
		}
		return RadialProfile.reachWithin(this, level, below);
	}

	private double envelope(final double r) {
		final double x = besselScale * r;
		final double besselBound = x <= 2 / Math.PI ? 1 : Math.sqrt(2 / (Math.PI * x));
		return Math.abs(amplitude) * besselBound * Math.exp(-r * r / (2 * gaussianSigma * gaussianSigma));
	}
}
