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
package io.github.contacttracker.core.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class CensoredNormalTest {

	/**
	 * Normal samples (mean 2, deviation 4) with every value at or below 0 read as 0, from a fifth to four fifths of them
	 * clipped: the estimate is the normal's mean and deviation within four of its standard errors, where the mean of the
	 * values above the floor lies 1.4 to 5.5 higher.
	 */
	@Test
	void aClippedNormalsMeanAndDeviationAreRecovered() {
		final SplittableRandom random = new SplittableRandom(11);
		for (final double mean : new double[] { 3.4, 2, 0, -3.4 }) {
			final int total = 40_000;
			long clipped = 0, n = 0;
			double sum = 0, squares = 0;
			for (int i = 0; i < total; i++) {
				final double v = mean + 4 * gaussian(random);
				if (v <= 0) clipped++;
				else {
					n++;
					sum += v;
					squares += v * v;
				}
			}
			final double share = (double) clipped / total;
			assertTrue(share > 0.18 && share < 0.82, "clipped share " + share);
			final double[] e = CensoredNormal.estimate(0, clipped, n, sum, squares);
			// the standard error of the mean, from the information left by censoring, at most twice the uncensored one's
			final double error = 2 * 4 / Math.sqrt(total) / Math.sqrt(1 - share);
			assertEquals(mean, e[0], 4 * error, "mean at " + mean);
			assertEquals(4, e[1], 4 * error, "deviation at " + mean);
			assertTrue(sum / n - mean > 1.3, "the values above the floor alone lie high: " + sum / n);
		}
	}

	/** Nothing clipped: the sample's mean and deviation. */
	@Test
	void withNothingClippedItIsTheSamplesMeanAndDeviation() {
		final double[] e = CensoredNormal.estimate(0, 0, 4, 1 + 2 + 3 + 6, 1 + 4 + 9 + 36);
		assertEquals(3, e[0], 1e-12);
		assertEquals(Math.sqrt(50 / 4.0 - 9), e[1], 1e-12);
	}

	/** Too few values above the floor, or none spread, tell nothing. */
	@Test
	void tooLittleDataTellsNothing() {
		assertNull(CensoredNormal.estimate(0, 100, 1, 5, 25));
		assertNull(CensoredNormal.estimate(0, 100, 3, 15, 75));
	}

	/** The distribution function against values of the normal's table, to its stated accuracy. */
	@Test
	void theDistributionFunctionMatchesTheTable() {
		assertEquals(0.5, CensoredNormal.normalCdf(0), 1e-7);
		assertEquals(0.8413447461, CensoredNormal.normalCdf(1), 1e-7);
		assertEquals(0.0227501319, CensoredNormal.normalCdf(-2), 1e-7);
		assertEquals(0.9986501020, CensoredNormal.normalCdf(3), 1e-7);
		assertEquals(1.0 / Math.sqrt(2 * Math.PI), CensoredNormal.normalDensity(0), 1e-15);
	}

	private static double gaussian(final SplittableRandom random) {
		return Math.sqrt(-2 * Math.log(1 - random.nextDouble())) * Math.cos(2 * Math.PI * random.nextDouble());
	}
}
