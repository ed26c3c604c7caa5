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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;
import io.github.contacttracker.core.radial.Estimate;

class NearbyTest {

	private static final int W = 200, H = 150;

	private static EmpiricalProfile profile(final double top, final int samples) {
		final double[] c = new double[samples];
		for (int j = 0; j < c.length; j++)
			c[j] = top * Math.exp(-j * j / 40.0);
		return ProfileAccess.profile(1, c, 10, 1000);
	}

	private static Estimate at(final double x, final double y, final double scale) {
		return new Estimate(x, y, 0, 0, 1, null, Double.NaN, Double.NaN, 1, scale);
	}

	/**
	 * The definition the grid stands in for: every particle whose light ({@code radius() * scale}) reaches into the
	 * box grown by {@code margin}, in increasing order.
	 */
	private static int[] reaching(final Estimate[] e, final EmpiricalProfile[] of, final double x0, final double x1,
		final double y0, final double y1, final double margin)
	{
		final List<Integer> out = new ArrayList<>();
		for (int k = 0; k < e.length; k++) {
			final double reach = of[k].radius() * GroupFit.scaleOf(e[k]) + margin;
			if (!(e[k].x() < x0 - reach || e[k].x() > x1 + reach || e[k].y() < y0 - reach || e[k].y() > y1 + reach))
				out.add(k);
		}
		return out.stream().mapToInt(Integer::intValue).toArray();
	}

	/**
	 * 400 particles of two sizes, in and around a frame, moved 3,000 times (some far, some off the frame, some to a
	 * centre that is no number, some to a larger scale): after each move, boxes anywhere get from the grid, in
	 * increasing order, every particle whose light reaches them, and the grid's extra candidates are few.
	 */
	@Test
	void theGridHoldsEveryParticleWhoseLightReachesABox() {
		final Random random = new Random(17);
		final int n = 400;
		final EmpiricalProfile small = profile(100, 25), large = profile(60, 40);
		final EmpiricalProfile[] of = new EmpiricalProfile[n];
		final Estimate[] e = new Estimate[n];
		for (int k = 0; k < n; k++) {
			of[k] = k % 3 == 0 ? large : small;
			e[k] = at(-20 + random.nextDouble() * (W + 40), -20 + random.nextDouble() * (H + 40), 0.8 + 0.4 * random
				.nextDouble());
		}
		final Nearby grid = new Nearby(e, of, W, H);
		long extra = 0, found = 0;
		for (int move = 0; move < 3000; move++) {
			final int k = random.nextInt(n);
			final double kind = random.nextDouble();
			if (kind < 0.01) e[k] = at(Double.NaN, 5, 1); // no number
			else if (kind < 0.05) e[k] = at(-500 + 1000 * random.nextDouble(), H / 2.0, 1); // far, often off the frame
			else if (kind < 0.07) e[k] = at(e[k].x(), e[k].y(), 1.5); // its light reaching farther
			else e[k] = at(e[k].x() + random.nextGaussian() * 3, e[k].y() + random.nextGaussian() * 3, GroupFit.scaleOf(
				e[k]));
			grid.moved(k, e[k]);
			final double x0 = -10 + random.nextDouble() * (W + 20), y0 = -10 + random.nextDouble() * (H + 20);
			final double x1 = x0 + random.nextDouble() * 30, y1 = y0 + random.nextDouble() * 30;
			final double margin = random.nextBoolean() ? 0 : 5;
			final int[] want = reaching(e, of, x0, x1, y0, y1, margin);
			final int[] got = grid.near(x0, x1, y0, y1, grid.reach() + margin);
			for (int i = 1; i < got.length; i++)
				assertTrue(got[i - 1] < got[i], "increasing, each once");
			int j = 0;
			for (final int w : want) {
				while (j < got.length && got[j] < w)
					j++;
				assertTrue(j < got.length && got[j] == w, "particle " + w + " reaches the box, not among the grid's");
			}
			final int[] any = grid.nearInAnyOrder(x0, x1, y0, y1, grid.reach() + margin);
			Arrays.sort(any);
			assertEquals(Arrays.toString(got), Arrays.toString(any));
			extra += got.length - want.length;
			found += want.length;
		}
		// a superset, not every particle: the grid's cells are the largest reach across
		assertTrue(extra < 4 * found, "candidates beyond those reaching: " + extra + " for " + found);
	}
}
