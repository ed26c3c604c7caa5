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
 * The Bessel function of the first kind of order zero, from the polynomial approximations of Abramowitz and
 * Stegun, <i>Handbook of Mathematical Functions</i> (1964), 9.4.1 for {@code |x| <= 3} (absolute error below
 * 5e-8) and 9.4.3 for {@code |x| > 3} (modulus and phase, absolute error below about 5e-8).
 */
public final class Bessel {

	private Bessel() {}

	/**
	 * @param x argument (any finite value; J0 is even)
	 * @return J0(x), absolute error below 1e-7
	 */
	public static double j0(final double x) {
		final double ax = Math.abs(x);
		if (ax <= 3) {
			// A&S 9.4.1, polynomial in (x/3)^2
			final double t = (ax / 3) * (ax / 3);
			return 1 + t * (-2.2499997 + t * (1.2656208 + t * (-0.3163866 + t * (0.0444479 + t * (-0.0039444
				+ t * 0.0002100)))));
		}
		// A&S 9.4.3: J0(x) = f0 cos(theta0) / sqrt(x), both polynomials in 3/x
		final double u = 3 / ax;
		final double f0 = 0.79788456 + u * (-0.00000077 + u * (-0.00552740 + u * (-0.00009512 + u * (0.00137237
			+ u * (-0.00072805 + u * 0.00014476)))));
		final double theta0 = ax - 0.78539816 + u * (-0.04166397 + u * (-0.00003954 + u * (0.00262573 + u * (
			-0.00054125 + u * (-0.00029333 + u * 0.00013558)))));
		return f0 * Math.cos(theta0) / Math.sqrt(ax);
	}
}
