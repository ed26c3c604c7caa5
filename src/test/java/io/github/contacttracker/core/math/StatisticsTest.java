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
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** Each statistic against its definition on the sorted numbers of the sample. */
class StatisticsTest {

	/**
	 * The median by selection is the median of the sorted numbers, exactly: odd and even counts, one and two values,
	 * many ties (8-bit grey levels), spread values, sorted and reversed input, and samples holding NaN.
	 */
	@Test
	void theMedianIsThatOfTheSortedNumbers() {
		final SplittableRandom random = new SplittableRandom(3);
		for (int trial = 0; trial < 2000; trial++) {
			final int n = 1 + random.nextInt(trial < 1000 ? 12 : 700);
			final double[] v = sample(random, trial, n);
			final double[] sorted = numbers(v, n);
			final int m = sorted.length;
			final double want = m == 0 ? Double.NaN : m % 2 == 1 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1]
				+ sorted[m / 2]);
			assertEquals(want, Statistics.median(v, n), 0, "trial " + trial + ", " + n + " values");
		}
	}

	/** A quantile interpolates linearly between the neighbouring ranks of the sorted numbers, which it leaves sorted. */
	@Test
	void aQuantileInterpolatesTheSortedNumbers() {
		final SplittableRandom random = new SplittableRandom(5);
		for (int trial = 0; trial < 1000; trial++) {
			final int n = 1 + random.nextInt(300);
			final double[] v = sample(random, trial, n);
			final double[] sorted = numbers(v, n);
			final double q = random.nextDouble();
			final int m = sorted.length;
			final double pos = q * (m - 1);
			final int i = (int) pos;
			final double want = m == 0 ? Double.NaN : i + 1 < m ? sorted[i] + (pos - i) * (sorted[i + 1] - sorted[i])
				: sorted[m - 1];
			assertEquals(want, Statistics.quantile(v, n, q), m == 0 ? 0 : 1e-12 * (1 + Math.abs(want)), "trial " + trial);
			for (int k = 0; k + 1 < m; k++)
				assertTrue(v[k] <= v[k + 1], "sorted");
		}
		final double[] five = { 4, 0, 3, 1, 2 };
		assertEquals(1.2, Statistics.quantile(five, 0.3), 1e-12);
		assertEquals(0, Statistics.quantile(five, -1), 0, "q clamped to 0");
		assertEquals(4, Statistics.quantile(five, 7), 0, "q clamped to 1");
		assertEquals(2, Statistics.quantile(five.clone(), 0.5), 0);
		assertEquals(6, Statistics.quantile(new double[] { 9, 1, 5, 7 }, 0.5), 0, "the median of an even count");
	}

	/**
	 * A weighted quantile with whole weights is the plain inverse distribution of the sample in which each value
	 * stands as often as its weight says: the value at rank ceil(q N) of those N copies. Neither array is moved, and
	 * a NaN value's weight counts for nothing.
	 */
	@Test
	void aWeightedQuantileIsThatOfTheValuesRepeatedByWeight() {
		final SplittableRandom random = new SplittableRandom(7);
		for (int trial = 0; trial < 1000; trial++) {
			final int n = 1 + random.nextInt(60);
			final double[] v = sample(random, trial, n), weights = new double[v.length];
			final double[] copies = new double[4 * v.length];
			int total = 0;
			for (int i = 0; i < n; i++) {
				final int w = 1 + random.nextInt(4);
				weights[i] = w;
				if (!Double.isNaN(v[i])) for (int c = 0; c < w; c++)
					copies[total++] = v[i];
			}
			Arrays.sort(copies, 0, total);
			final double q = trial % 11 == 0 ? 0 : trial % 13 == 0 ? 1 : random.nextDouble();
			final double want = total == 0 ? Double.NaN : copies[Math.max(0, (int) Math.ceil(q * total) - 1)];
			final double[] before = v.clone(), weightsBefore = weights.clone();
			assertEquals(want, Statistics.weightedQuantile(v, weights, n, q), 0, "trial " + trial + ", q " + q);
			assertTrue(Arrays.equals(before, v) && Arrays.equals(weightsBefore, weights), "unmoved");
		}
		final double[] values = { 3, 1, 2 };
		assertEquals(3, Statistics.weightedQuantile(values, new double[] { 8, 1, 1 }, 3, 0.5), 0, "the heavy one");
		assertEquals(2, Statistics.weightedQuantile(values, new double[] { 1, 1, 1 }, 3, 0.5), 0, "equal weights");
		assertEquals(1, Statistics.weightedQuantile(values, new double[] { 1, 1, 1 }, 3, -2), 0, "q clamped to 0");
	}

	/** The interquartile mean drops a quarter of the numbers at each end. */
	@Test
	void theInterquartileMeanIsThatOfTheMiddleHalf() {
		assertEquals(4.5, Statistics.interquartileMean(new double[] { 100, 3, 4, 5, 6, -100, Double.NaN, 5, 4 }, 9),
			0);
		assertEquals(2, Statistics.interquartileMean(new double[] { 2 }, 1), 0);
	}

	/** No number: NaN, never 0; a count beyond the array is a caller's error, said. */
	@Test
	void anEmptySampleIsNaN() {
		assertTrue(Double.isNaN(Statistics.median(new double[0])));
		assertTrue(Double.isNaN(Statistics.median(new double[] { Double.NaN, Double.NaN })));
		assertTrue(Double.isNaN(Statistics.median(new double[] { 1, 2, 3 }, 0)));
		assertTrue(Double.isNaN(Statistics.quantile(new double[0], 0.5)));
		assertTrue(Double.isNaN(Statistics.quantile(new double[] { 1 }, Double.NaN)));
		assertTrue(Double.isNaN(Statistics.interquartileMean(new double[] { Double.NaN }, 1)));
		assertTrue(Double.isNaN(Statistics.weightedQuantile(new double[] { Double.NaN }, new double[] { 1 }, 1, 0.5)));
		assertTrue(Double.isNaN(Statistics.weightedQuantile(new double[0], new double[0], 0, 0.5)));
		assertThrows(IllegalArgumentException.class, () -> Statistics.weightedQuantile(new double[2], new double[1],
			2, 0.5));
		assertThrows(IllegalArgumentException.class, () -> Statistics.median(new double[2], 3));
	}

	/** The MAD of a large normal sample times the factor is its standard deviation. */
	@Test
	void theMadOfNormalNoiseGivesItsSigma() {
		final SplittableRandom random = new SplittableRandom(11);
		final int n = 200_001;
		final double sigma = 2.5;
		final double[] v = new double[n];
		for (int i = 0; i < n; i++)
			v[i] = 10 + sigma * gaussian(random);
		final double centre = Statistics.median(v.clone());
		for (int i = 0; i < n; i++)
			v[i] = Math.abs(v[i] - centre);
		// the sample MAD's relative standard error is about 1.17 / sqrt(n): 0.3 % here
		assertEquals(sigma, Statistics.MAD_TO_SIGMA * Statistics.median(v), 0.01 * sigma);
	}

	private static double[] sample(final SplittableRandom random, final int trial, final int n) {
		final double[] v = new double[n + 3];
		final int kind = trial % 5;
		for (int i = 0; i < v.length; i++)
			v[i] = kind == 0 ? random.nextInt(4) : kind == 1 ? random.nextInt(256) : kind == 2 ? gaussian(random) :
				kind == 3 ? i : -i;
		if (trial % 7 == 0) v[random.nextInt(n)] = Double.NaN;
		if (trial % 97 == 0) Arrays.fill(v, 0, n, Double.NaN);
		return v;
	}

	/** @return the numbers among the first {@code n} values, sorted */
	private static double[] numbers(final double[] v, final int n) {
		return Arrays.stream(v, 0, n).filter(d -> !Double.isNaN(d)).sorted().toArray();
	}

	private static double gaussian(final SplittableRandom random) {
		return Math.sqrt(-2 * Math.log(1 - random.nextDouble())) * Math.cos(2 * Math.PI * random.nextDouble());
	}
}
