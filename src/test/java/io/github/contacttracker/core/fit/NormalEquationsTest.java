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
package io.github.contacttracker.core.fit;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;

/**
 * The least-squares passes of {@link GroupFit} ({@link NormalEquations}): the fast paths for a group of one and of two
 * against the general one.
 */
class NormalEquationsTest {

	/**
	 * A ringed profile (bright core, dark ring) reaching 30 px, and noisy particles at {@code (x, y)} pairs on a plane
	 * with others' light.
	 */
	private static FitPixels pixels(final EmpiricalProfile profile, final double... centres) {
		final Random random = new Random(11);
		final int w = 70, h = 64, n = w * h;
		final int[] xs = new int[n], ys = new int[n];
		final double[] values = new double[n], fixed = new double[n];
		for (int y = 0, i = 0; y < h; y++)
			for (int x = 0; x < w; x++, i++) {
				xs[i] = x;
				ys[i] = y;
				fixed[i] = 0.01 * x;
				values[i] = 40 + 0.05 * x + fixed[i] + 3 * random.nextGaussian();
				for (int c = 0; c < centres.length; c += 2)
					values[i] += 1.1 * profile.value(Math.hypot(x - centres[c], y - centres[c + 1]) / 0.97);
			}
		return new FitPixels(xs, ys, values, fixed, n, 0.5 * (w - 1), 0.5 * (h - 1), 0.5 * (w - 1));
	}

	private static EmpiricalProfile ringed() {
		return ringed(120, 14);
	}

	/** A ringed profile of central height {@code peak} and dark ring at {@code ring} px (another kind of particle). */
	private static EmpiricalProfile ringed(final double peak, final double ring) {
		final double[] c = new double[29];
		for (int j = 0; j < c.length; j++)
			c[j] = peak * Math.exp(-j * j / 60.0) - 25 * Math.exp(-(j - ring) * (j - ring) / 8.0);
		return ProfileAccess.profile(1, c, 40, 1000);
	}

	/** A fast path's signature: {@link NormalEquations#accumulate} for a fixed group size. */
	@FunctionalInterface
	private interface Pass {
		double run(FitPixels px, double[] p, EmpiricalProfile[] profile, double[][] jtj, double[] jtr, double[] noise,
			double[] models);
	}

	/**
	 * Same J^T J, J^T r, residuals, noise weights and model values from {@code fast} as from the general pass, bit for
	 * bit, with and without J^T J.
	 */
	private static void assertSameAsGeneral(final FitPixels px, final double[] p, final int n,
		final EmpiricalProfile[] profile, final Pass fast)
	{
		final int np = p.length;
		for (final boolean hessian : new boolean[] { true, false }) {
			final double[][] jg = hessian ? new double[np][np] : null, jf = hessian ? new double[np][np] : null;
			final double[] rg = new double[np], rf = new double[np], ng = new double[4 * n], nf = new double[4 * n];
			final double[] mg = new double[px.count()], mf = new double[px.count()];
			final double rssGroup = NormalEquations.accumulateGroup(px, p, n, profile, jg, rg, ng, mg);
			final double rssFast = fast.run(px, p, profile, jf, rf, nf, mf);
			assertEquals(rssGroup, rssFast, 0);
			assertArrayEquals(rg, rf, 0);
			assertArrayEquals(ng, nf, 0);
			assertArrayEquals(mg, mf, 0);
			if (hessian) for (int r = 0; r < np; r++)
				assertArrayEquals(jg[r], jf[r], 0, "row " + r);
		}
	}

	@Test
	void singleMemberFastPathIsIdentical() {
		final EmpiricalProfile profile = ringed();
		final FitPixels px = pixels(profile, 34.3, 31.8);
		assertSameAsGeneral(px, new double[] { 34.1, 32.0, 1.05, 0.98, 39, 0.4, -0.2 }, 1, new EmpiricalProfile[] {
			profile }, (x, p, pr, jtj, jtr, noise, models) -> NormalEquations.accumulateSingle(x, p, pr[0], jtj, jtr,
				noise, models));
	}

	/**
	 * The pair's path against the general one, members near enough for shared pixels and far enough for pixels out
	 * of one member's reach (the profile reaches 30 px), each member of its own kind (profile).
	 */
	@Test
	void pairFastPathIsIdentical() {
		final EmpiricalProfile profile = ringed();
		final FitPixels px = pixels(profile, 24.3, 31.8, 47.6, 30.1);
		final double[] p = { 24.1, 32.0, 1.05, 0.98, 47.9, 30.0, 0.9, 1.04, 39, 0.4, -0.2 };
		int onlyOne = 0;
		for (int i = 0; i < px.count(); i++)
			if ((Math.hypot(px.x()[i] - p[0], px.y()[i] - p[1]) < 30 * p[3]) != (Math.hypot(px.x()[i] - p[4], px.y()[i] -
				p[5]) < 30 * p[7])) onlyOne++;
		assertTrue(onlyOne > 500, "pixels within reach of one member only: " + onlyOne);
		assertSameAsGeneral(px, p, 2, new EmpiricalProfile[] { profile, ringed(90, 11) }, (x, q, pr, jtj, jtr, noise,
			models) -> NormalEquations.accumulatePair(x, q, pr[0], pr[1], jtj, jtr, noise, models));
	}
}
