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
package io.github.contacttracker.core.radial;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;

/**
 * How a {@link Method} turns the first-pass particles of a frame into final centres: one strategy per method. A
 * refinement reads the immutable {@link Particle}s and returns new {@link Estimate}s; it keeps no state, so one
 * instance serves every frame and thread.
 */
public interface Refinement {

	/**
	 * The estimates of a frame, the disc centres the last radial-symmetry pass excluded ({@code null} when
	 * nothing was excluded: the overlay draws each second active area from them), and each particle's kind (1-based,
	 * 0 unclassified; {@code null}: none told apart).
	 */
	record Outcome(Estimate[] estimates, double[][] discs, int[] kinds) {
		/** Without kinds (every particle of kind 0). */
		public Outcome(final Estimate[] estimates, final double[][] discs) {
			this(estimates, discs, null);
		}
	}

	/**
	 * @param plane the frame
	 * @param particles its particles, first pass done and shape flags set
	 * @param params the parameters
	 * @param profile a radial profile measured beforehand (over a stack), or {@code null}; only the profile
	 *        methods use it, and measure their own on this frame when it is {@code null}
	 * @param noise the frame's noise standard deviation ({@link NoiseEstimate}, measured once per frame)
	 * @return one estimate per particle, same order
	 */
	Outcome refine(Plane plane, Particle[] particles, TrackerParameters params, EmpiricalProfile profile,
		double noise);

	/** The {@code first} method: the first pass is final. */
	Refinement FIRST_PASS = (plane, ps, params, profile, noise) -> {
		final Estimate[] e = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++)
			e[k] = ps[k].first();
		return new Outcome(e, null);
	};
}
