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
package io.github.contacttracker.core.detect;

import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/**
 * The particles at seeds ({@link ImageDetection#particles}), each with the seed it stands at.
 *
 * @param particles the particles
 * @param x each particle's seed, x
 * @param y each particle's seed, y
 * @param warm each particle's fit to start from, where it had one (else null)
 */
record Seeded(Particle[] particles, double[] x, double[] y, Estimate[] warm) {

	static Seeded at(final Plane plane, final double[] x, final double[] y, final double d) {
		return at(plane, x, y, null, d);
	}

	/** @param warm each seed's fit to start from (null, or null entries: from the particle's first pass) */
	static Seeded at(final Plane plane, final double[] x, final double[] y, final Estimate[] warm, final double d) {
		final int[] seedOf = new int[x.length];
		final Particle[] ps = ImageDetection.particles(plane, x, y, ImageDetection.radius(d), ImageDetection.margin(
			d), seedOf);
		final double[] sx = new double[ps.length], sy = new double[ps.length];
		final Estimate[] start = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++) {
			sx[k] = x[seedOf[k]];
			sy[k] = y[seedOf[k]];
			if (warm != null) start[k] = warm[seedOf[k]];
		}
		return new Seeded(ps, sx, sy, start);
	}
}
