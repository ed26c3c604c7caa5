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

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.junit.jupiter.api.Test;

class EstimateTest {

	private static Estimate at(final double x, final double y, final double scale) {
		return new Estimate(x, y, 0, 0, 1, null, Double.NaN, Double.NaN, 1, scale);
	}

	/** The test without a root gives the distance's verdict, also at the limit itself and off the numbers. */
	@Test
	void closerThanIsTheDistancesVerdict() {
		final Random random = new Random(5);
		final double[] odd = { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, -0.0, 1e-300 };
		for (int i = 0; i < 200_000; i++) {
			final Estimate a = at(random.nextGaussian() * 20, random.nextGaussian() * 20, 1);
			final Estimate b = i % 1000 == 0 ? at(odd[random.nextInt(odd.length)], 3, 1) : at(random.nextGaussian() *
				20, random.nextGaussian() * 20, 1);
			final double d = a.distanceTo(b);
			// limits around the distance itself, at the last bits, and a few that are no distance at all
			final double limit = switch (i % 6) {
				case 0 -> d;
				case 1 -> Math.nextUp(d);
				case 2 -> Math.nextDown(d);
				case 3 -> Math.max(Math.abs(a.x() - b.x()), Math.abs(a.y() - b.y()));
				case 4 -> random.nextDouble() * 40;
				default -> odd[random.nextInt(odd.length)];
			};
			assertEquals(d < limit, a.closerThan(b, limit), a + " " + b + " " + limit);
		}
	}
}
