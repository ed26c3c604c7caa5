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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;

/**
 * {@link RowRuns#draw}, which finds each row's pixels within reach from the reach, against its definition: the test
 * {@code dx^2 + dy^2 < reach^2} at every pixel and the profile's table read there, summed in the same order: equal
 * to the last bit, on pixel sets with gaps (censored pixels, separate windows on one row) and particles whose reach
 * cuts the rows anywhere, or misses them.
 */
class RowRunsTest {

	private static EmpiricalProfile profile() {
		final double[] c = new double[30];
		for (int j = 0; j < c.length; j++)
			c[j] = 200 * Math.exp(-j * j / 40.0) - 15 * Math.exp(-(j - 9) * (j - 9) / 5.0);
		return ProfileAccess.profile(1, c, 10, 1000);
	}

	/** The definition, pixel by pixel. */
	private static void reference(final int[] px, final int[] py, final int count, final double[] light,
		final double kx, final double ky, final double ks, final double ka, final double reach,
		final EmpiricalProfile profile)
	{
		final double[] table = profile.valueTable();
		final int last = table.length - 1;
		final double reach2 = reach * reach, perStep = 1 / (ks * EmpiricalProfile.TABLE_STEP);
		for (int i = 0; i < count; i++) {
			final double dx = px[i] - kx, dy = py[i] - ky, d2 = dx * dx + dy * dy;
			if (!(d2 < reach2)) continue;
			final double t = Math.sqrt(d2) * perStep;
			final int k = (int) t;
			if (k < last) light[i] += ka * (table[k] + (t - k) * (table[k + 1] - table[k]));
		}
	}

	@Test
	void drawsOnExactlyThePixelsWithinReachAsATestPerPixelDoes() {
		final EmpiricalProfile profile = profile();
		final Random random = new Random(11);
		int drawn = 0;
		for (int trial = 0; trial < 300; trial++) {
			// pixels in row order over a 60 x 50 box: each pixel kept with a chance, so that rows hold several runs
			final double keep = 0.5 + 0.5 * random.nextDouble();
			final int[] px = new int[3000], py = new int[3000];
			int count = 0;
			for (int y = -5; y < 45; y++)
				for (int x = 10; x < 70; x++)
					if (random.nextDouble() < keep) {
						px[count] = x;
						py[count++] = y;
					}
			final RowRuns rows = RowRuns.of(px, py, count);
			final double[] expected = new double[count], actual = new double[count];
			for (int particle = 0; particle < 4; particle++) {
				// centres inside, near and far outside the box, at any fraction of a pixel; on a row or a column exactly
				double kx = -40 + 150 * random.nextDouble(), ky = -40 + 130 * random.nextDouble();
				if (random.nextInt(5) == 0) kx = Math.rint(kx);
				if (random.nextInt(5) == 0) ky = Math.rint(ky);
				final double ks = 0.5 + 1.5 * random.nextDouble(), ka = 50 * random.nextGaussian();
				// the profile's reach, or an integer reach (a pixel exactly on the edge is out)
				final double reach = random.nextBoolean() ? profile.radius() * ks : 1 + random.nextInt(30);
				reference(px, py, count, expected, kx, ky, ks, ka, reach, profile);
				rows.draw(actual, kx, ky, ks, ka, reach, profile);
			}
			assertArrayEquals(expected, actual, 0, "trial " + trial);
			for (final double v : expected)
				if (v != 0) drawn++;
		}
		assertTrue(drawn > 100_000, "the particles' light reached " + drawn + " pixels: too few to test the draw");
	}

	@Test
	void aCentreOrReachThatIsNoNumberDrawsNothingAsTheTestDoes() {
		final EmpiricalProfile profile = profile();
		final int[] px = { 3, 4, 5, 7, 3, 4 }, py = { 0, 0, 0, 0, 1, 1 };
		final RowRuns rows = RowRuns.of(px, py, px.length);
		final double[][] cases = { { Double.NaN, 0, 10 }, { 4, Double.NaN, 10 }, { Double.POSITIVE_INFINITY, 0, 10 },
			{ 4, 0, Double.NaN }, { 4, 0, Double.POSITIVE_INFINITY }, { 1e12, -1e12, 5 } };
		for (final double[] c : cases) {
			final double[] expected = new double[px.length], actual = new double[px.length];
			reference(px, py, px.length, expected, c[0], c[1], 1, 7, c[2], profile);
			rows.draw(actual, c[0], c[1], 1, 7, c[2], profile);
			assertArrayEquals(expected, actual, 0, java.util.Arrays.toString(c));
		}
	}
}
