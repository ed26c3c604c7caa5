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
package io.github.contacttracker.advisor;

/**
 * The margins the profile helper adds to what it measures when it turns a profile into settings. {@code r_out} lies
 * {@value #R_OUT_MARGIN_PX} px beyond the reach of the particles' light; the threshold lies
 * {@value #THRESHOLD_MARGIN_SIGMAS} noise sigmas above the brightest point between particles at contact, and a
 * particle or a dark ring must stand as far out of the noise to count; the profile is measured out to
 * {@value #AUTO_RADIUS_DIAMETERS} particle diameters unless a radius is given. The helper's steps and the report of
 * its suggestions share them.
 */
public final class Margins {

	/** Added to the reach for {@code r_out}: half the width of the gradient operator. */
	public static final double R_OUT_MARGIN_PX = 2;
	/** Noise margin of the threshold above the brightest point between particles at contact, in noise sigmas. */
	public static final double THRESHOLD_MARGIN_SIGMAS = 3;
	/** Default {@code max_radius}, in particle diameters. */
	public static final double AUTO_RADIUS_DIAMETERS = 2.5;

	private Margins() {}
}
