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
package io.github.contacttracker.potential;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The static error from the MSD's intercept, on simulated Brownian motion with a known localization error. */
class StaticErrorTest {

	/**
	 * 100 particles on a 20 px grid, 200 frames, D = 0.01 px^2/frame per axis, positions measured with Gaussian
	 * errors of sigma = 0.05 px (x) and 0.03 px (y): the estimate recovers both within 10% and D within 5%.
	 */
	@Test
	void recoversAKnownErrorFromBrownianMotion() {
		final double d = 0.01, sx = 0.05, sy = 0.03;
		final StaticError.Result r = StaticError.estimate(brownian(100, 200, d, sx, sy, 7), 2, 4);
		assertEquals(100, r.tracks(), "every particle one track");
		assertEquals(100 * 199, r.steps());
		assertEquals(sx, r.sigmaX(), 0.1 * sx, "sigma_x");
		assertEquals(sy, r.sigmaY(), 0.1 * sy, "sigma_y");
		assertEquals(d, r.diffusionX(), 0.05 * d, "D along x");
		assertEquals(d, r.diffusionY(), 0.05 * d, "D along y");
		// the reported standard error of the variance matches the estimate's actual error: within 3 of it
		final double truth = 0.5 * (sx * sx + sy * sy), got = 0.5 * (r.varianceX() + r.varianceY());
		assertTrue(Math.abs(got - truth) < 3 * r.varianceError() && r.varianceError() < 0.15 * truth, "variance " + got +
			" vs " + truth + ", standard error " + r.varianceError());
	}

	/** Exact positions: the intercept is zero within its statistical error (here 2e-4 px^2), never a made-up error. */
	@Test
	void exactPositionsHaveNoStaticError() {
		final StaticError.Result r = StaticError.estimate(brownian(100, 200, 0.01, 0, 0, 8), 2, 4);
		assertTrue(Math.abs(r.varianceX()) < 2e-4 && Math.abs(r.varianceY()) < 2e-4, "variances " + r.varianceX() +
			", " + r.varianceY());
	}

	/** A step longer than the largest allowed breaks a track in two. */
	@Test
	void aJumpBreaksTheTrack() {
		final List<List<double[]>> frames = new ArrayList<>();
		for (int f = 0; f < 10; f++)
			frames.add(List.of(new double[] { f < 5 ? 10 : 30, 10 }));
		assertEquals(2, StaticError.tracks(SpotSet.ofPositions(frames, 1), 5).size());
		assertThrows(IllegalArgumentException.class, () -> StaticError.estimate(SpotSet.ofPositions(frames, 1), 5, 6),
			"no track spans 6 frames");
	}

	private static SpotSet brownian(final int particles, final int frames, final double d, final double sx,
		final double sy, final long seed)
	{
		final Random rnd = new Random(seed);
		final double[] x = new double[particles], y = new double[particles];
		for (int k = 0; k < particles; k++) {
			x[k] = 20 * (k % 10);
			y[k] = 20 * (k / 10);
		}
		final double step = Math.sqrt(2 * d);
		final List<List<double[]>> out = new ArrayList<>();
		for (int f = 0; f < frames; f++) {
			final List<double[]> frame = new ArrayList<>();
			for (int k = 0; k < particles; k++) {
				if (f > 0) {
					x[k] += step * rnd.nextGaussian();
					y[k] += step * rnd.nextGaussian();
				}
				frame.add(new double[] { x[k] + sx * rnd.nextGaussian(), y[k] + sy * rnd.nextGaussian() });
			}
			out.add(frame);
		}
		return SpotSet.ofPositions(out, 1);
	}
}
