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
package io.github.contacttracker.core.profile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link EmpiricalProfile#informationOutside}: the share of a centre's information a frame's edge cuts off. */
class EmpiricalProfileTest {

	/** A bright core in a dark ring, reaching 30 px. */
	private static final EmpiricalProfile RING = ring();

	private static EmpiricalProfile ring() {
		final double[] c = new double[29];
		for (int j = 0; j < c.length; j++)
			c[j] = 100 * Math.exp(-j * j / 50.0) - 30 * Math.exp(-(j - 12) * (j - 12) / 8.0);
		return new EmpiricalProfile(1, c, 20, 1000);
	}

	@Test
	void nothingIsCutInsideTheFrame() {
		assertEquals(0, RING.informationOutside(100.3, 80.7, 1, 200, 160));
		// the reach just inside: still nothing
		assertEquals(0, RING.informationOutside(RING.radius() - 0.5, 80, 1, 200, 160));
	}

	/** A centre on the frame's edge (the outer edge of the first column): the pixels mirror about it, half is cut. */
	@Test
	void aCentreOnTheEdgeLosesHalf() {
		assertEquals(0.5, RING.informationOutside(-0.5, 80.2, 1, 200, 160), 1e-9);
		assertEquals(0.5, RING.informationOutside(100.4, 159.5, 1.3, 200, 160), 1e-9);
	}

	/**
	 * Against the sums written out with the profile's exact derivative (the method reads its table): the share of x's
	 * information from the columns left of the frame, for a centre 6.3 px inside it.
	 */
	@Test
	void theShareIsThatOfTheInformationOnX() {
		final double x = 5.8, y = 70.4, reach = RING.radius();
		double all = 0, out = 0;
		for (int py = (int) Math.ceil(y - reach); py <= y + reach; py++)
			for (int px = (int) Math.ceil(x - reach); px <= x + reach; px++) {
				final double dx = px - x, dy = py - y, r = Math.hypot(dx, dy);
				if (!(r < reach) || r == 0) continue;
				final double g = RING.derivative(r) * dx / r;
				all += g * g;
				if (px < 0) out += g * g;
			}
		final double expected = out / all;
		assertTrue(expected > 0.05 && expected < 0.45, "a cut worth testing: " + expected);
		assertEquals(expected, RING.informationOutside(x, y, 1, 200, 160), 1e-3 * expected);
	}

	@Test
	void theShareFallsAsTheCentreMovesIn() {
		double before = 0.5;
		for (double depth = 1; depth < RING.radius(); depth += 1) {
			final double share = RING.informationOutside(depth - 0.5, 60, 1, 200, 160);
			assertTrue(share < before, "at " + depth + " px: " + share + " after " + before);
			before = share;
		}
	}

	/**
	 * Where the bounds from the integrals serve (profiles smooth on the pixels' scale: 30 px across, Gaussians of
	 * sigma 3 and 5 px), they hold the sum over the pixels to within half {@link EmpiricalProfile#EDGE_MARGIN}, for
	 * centres near one edge and near a corner, at scales 0.7-1.3; a profile 3 px across is not sampled finely enough
	 * and is left to the sum. Either way {@link EmpiricalProfile#cutOff} decides as the sum does.
	 */
	@Test
	void theBoundsFromTheIntegralsHoldTheSums() {
		final java.util.Random random = new java.util.Random(7);
		// (a spot of sigma 1.2 px, about 3 px across: the pixels sample its slope coarsely)
		final EmpiricalProfile[] profiles = { RING, gauss(3), gauss(5), gauss(1.2), gauss(1.5) };
		final boolean[] serve = { true, true, true, false, false };
		for (int p = 0; p < profiles.length; p++) {
			final EmpiricalProfile profile = profiles[p];
			assertEquals(serve[p], profile.boundsServe(1), "profile " + p);
			int taken = 0;
			for (int trial = 0; trial < 400; trial++) {
				final double scale = 0.7 + 0.6 * random.nextDouble(), reach = profile.radius() * scale;
				final boolean corner = trial % 2 == 1;
				final double x = -0.5 + (random.nextDouble() * 1.3 - 0.3) * reach;
				final double y = corner ? 159.5 - (random.nextDouble() * 1.3 - 0.3) * reach : 80.3;
				final double exact = profile.informationOutside(x, y, scale, 200, 160);
				final String at = "profile " + p + " at (" + x + ", " + y + ") x" + scale;
				if (profile.boundsServe(scale)) {
					taken++;
					final double[] bounds = profile.edgeBounds(x, y, scale, 200, 160);
					assertTrue(exact >= bounds[0] - 0.5 * EmpiricalProfile.EDGE_MARGIN && exact <= bounds[1] + 0.5
						* EmpiricalProfile.EDGE_MARGIN, at + ": " + exact + " outside " + bounds[0] + ".." + bounds[1]);
				}
				assertEquals(exact >= 0.05, profile.cutOff(x, y, scale, 200, 160, 0.05), at + ": " + exact);
			}
			assertTrue(serve[p] == taken > 0, "profile " + p + ": bounds taken " + taken + " times");
		}
	}

	/** A Gaussian spot of this sigma (px), 80 grey levels high. */
	private static EmpiricalProfile gauss(final double sigma) {
		final double[] c = new double[(int) Math.ceil(5 * sigma / 0.5)];
		for (int j = 0; j < c.length; j++)
			c[j] = 80 * Math.exp(-0.5 * (j * 0.5) * (j * 0.5) / (sigma * sigma));
		return new EmpiricalProfile(0.5, c, 10, 1000);
	}
}
