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
 * The image of one isolated particle: grey levels above the background at a distance {@code r} (px) from its
 * centre. Radially symmetric by construction, as in the paper's simulations.
 */
@FunctionalInterface
public interface RadialProfile {

	/** Outermost radius (px) that {@link #reach(double)} examines. */
	double REACH_SCAN_LIMIT = 2000;

	/** Step (px) of the outer-to-inner scan in {@link #reach(double)}; narrower excursions can be missed. */
	double REACH_SCAN_STEP = 0.01;

	/**
	 * @param r distance from the particle centre (px, {@code >= 0})
	 * @return grey levels above background (negative where the image is darker than the background)
	 */
	double value(double r);

	/**
	 * The radius beyond which the profile stays below {@code level} in magnitude: the smallest {@code R} with
	 * {@code |value(r)| < level} for all {@code r > R}. Scans inwards from {@link #REACH_SCAN_LIMIT} in steps of
	 * {@link #REACH_SCAN_STEP} and refines the crossing by bisection.
	 *
	 * @param level a positive grey level
	 * @return the reach (px); 0 when the profile is below {@code level} everywhere
	 * @throws IllegalArgumentException when {@code level} is not positive, or the profile is still at or above
	 *         {@code level} at {@link #REACH_SCAN_LIMIT}
	 */
	default double reach(final double level) {
		return reachWithin(this, level, REACH_SCAN_LIMIT);
	}

	/**
	 * {@link #reach(double)} with a caller-supplied scan limit, for profiles that know a radius beyond which they
	 * are certainly below {@code level}.
	 *
	 * @param profile the profile
	 * @param level a positive grey level
	 * @param scanLimit radius (px) where the scan starts; the profile must be below {@code level} there
	 * @return the reach (px)
	 */
	static double reachWithin(final RadialProfile profile, final double level, final double scanLimit) {
		if (!(level > 0) || !Double.isFinite(level))
			throw new IllegalArgumentException("reach level must be a positive grey level, not " + level);
		if (Math.abs(profile.value(scanLimit)) >= level)
			throw new IllegalArgumentException("profile is still at " + profile.value(scanLimit) + " grey levels at r = "
				+ scanLimit + " px, not below " + level);
		final long steps = (long) Math.ceil(scanLimit / REACH_SCAN_STEP);
		for (long i = steps - 1; i >= 0; i--) {
			final double r = i * REACH_SCAN_STEP;
			if (Math.abs(profile.value(r)) >= level) {
				// the crossing lies in [r, next]: bisect, keeping |value(inside)| >= level > |value(outside)|
				double inside = r;
				double outside = Math.min((i + 1) * REACH_SCAN_STEP, scanLimit);
				while (outside - inside > 1e-10) {
					final double mid = 0.5 * (inside + outside);
					if (Math.abs(profile.value(mid)) >= level) inside = mid;
					else outside = mid;
				}
				return outside;
			}
		}
		return 0;
	}
}
