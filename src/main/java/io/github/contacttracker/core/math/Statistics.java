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

import java.util.Arrays;

/**
 * The order statistics every room uses, defined once: the median, a quantile, a weighted quantile, the
 * interquartile mean, and the factor that turns a median absolute deviation into a standard deviation. Each works
 * on the first {@code n} values of a primitive array (the median, quantile and interquartile mean in place, with no
 * allocation, so the rings of every particle can use them), ignores NaN (a pixel or a measure that is missing), and
 * returns NaN when no number is left, so that an empty sample is never read as 0.
 * <p>
 * The median of an even count is the mean of the two middle values: the value a symmetric distribution's centre
 * is estimated by without a bias towards either side. The quantile interpolates linearly between the two
 * neighbouring ranks (Hyndman and Fan's definition 7, the default of R and NumPy), so that it moves smoothly with
 * the sample and its 0.5 is the median; the weighted quantile is the inverse of the weighted distribution.
 */
public final class Statistics {

	/**
	 * A normal distribution's standard deviation per median absolute deviation, 1 / Phi^-1(3/4): half of a normal
	 * sample lies within 0.6745 sigma of its median, so the median of |x - median| times this is sigma.
	 */
	public static final double MAD_TO_SIGMA = 1.482602218505602;

	private Statistics() {}

	/**
	 * @param v the values; its first {@code n} are reordered (the median in the middle, no larger before it, none
	 *        smaller after it; NaN last)
	 * @param n how many of them to use
	 * @return the median of the numbers among the first {@code n} values; NaN if there is none. Found by selection,
	 *         not by sorting: linear time.
	 */
	public static double median(final double[] v, final int n) {
		final int m = numbersFirst(v, n);
		if (m == 0) return Double.NaN;
		final int k = m / 2;
		select(v, m, k);
		if (m % 2 == 1) return v[k];
		double lower = v[0]; // the largest of those before the k-th: the one before it in sorted order
		for (int i = 1; i < k; i++)
			if (v[i] > lower) lower = v[i];
		return 0.5 * (lower + v[k]);
	}

	/**
	 * @param v the values, reordered as {@link #median(double[], int)} says
	 * @return the median of the numbers among them; NaN if there is none
	 */
	public static double median(final double[] v) {
		return median(v, v.length);
	}

	/**
	 * @param v the values; its first {@code n} are sorted in place, NaN last
	 * @param n how many of them to use
	 * @param q which quantile, clamped to [0, 1] (a rank asked of a sample smaller than it, such as the 20th
	 *        brightest of 17 pixels, is its extreme)
	 * @return the {@code q}-quantile of the numbers among the first {@code n} values, by linear interpolation between
	 *         the two neighbouring ranks (0.5 gives the median); NaN if there is none or {@code q} is NaN
	 */
	public static double quantile(final double[] v, final int n, final double q) {
		final int m = numbersFirst(v, n);
		Arrays.sort(v, 0, m);
		if (m == 0 || Double.isNaN(q)) return Double.NaN;
		final double pos = Math.min(Math.max(q, 0), 1) * (m - 1);
		final int i = (int) Math.floor(pos);
		if (i >= m - 1) return v[m - 1];
		return v[i] + (pos - i) * (v[i + 1] - v[i]);
	}

	/**
	 * @param v the values, sorted in place, NaN last
	 * @param q which quantile, clamped to [0, 1]
	 * @return {@link #quantile(double[], int, double)} of all of them
	 */
	public static double quantile(final double[] v, final double q) {
		return quantile(v, v.length, q);
	}

	/**
	 * The quantile of a sample whose values count unequally (a blob found on a coarser grid stands for more pixels):
	 * the smallest value at which the weights of the values up to it reach {@code q} of all the weight, the inverse
	 * of the weighted empirical distribution. No interpolation: between two values of very different weight a line
	 * drawn by rank would mean nothing.
	 *
	 * @param values the values; the first {@code n} are used, none is moved
	 * @param weights each value's weight, at least 0
	 * @param n how many to use
	 * @param q which quantile, clamped to [0, 1]
	 * @return that quantile of the numbers among the first {@code n} values (a NaN value and its weight are left
	 *         out); NaN if there is no number or {@code q} is NaN. Sorts an index of the values: for a sample taken
	 *         once per image, not per pixel.
	 */
	public static double weightedQuantile(final double[] values, final double[] weights, final int n,
		final double q)
	{
		if (n < 0 || n > values.length || n > weights.length) throw new IllegalArgumentException("a sample of " + n +
			" values out of arrays of " + values.length + " values and " + weights.length + " weights");
		final Integer[] order = new Integer[n];
		int m = 0;
		double total = 0;
		for (int i = 0; i < n; i++)
			if (!Double.isNaN(values[i])) {
				order[m++] = i;
				total += weights[i];
			}
		if (m == 0 || Double.isNaN(q)) return Double.NaN;
		Arrays.sort(order, 0, m, (a, b) -> Double.compare(values[a], values[b]));
		final double reach = Math.min(Math.max(q, 0), 1) * total;
		double sum = 0;
		for (int i = 0; i < m; i++) {
			sum += weights[order[i]];
			if (sum >= reach) return values[order[i]];
		}
		return values[order[m - 1]];
	}

	/**
	 * The mean of the middle half of the numbers: as robust as the median to outliers in up to a quarter of the
	 * sample on either side, but not stuck on the integer steps of 8-bit data as a median is.
	 *
	 * @param v the values; its first {@code n} are sorted in place, NaN last
	 * @param n how many of them to use
	 * @return the mean of the numbers from rank m/4 to m - m/4 (m numbers); NaN if there is none
	 */
	public static double interquartileMean(final double[] v, final int n) {
		final int m = numbersFirst(v, n);
		if (m == 0) return Double.NaN;
		Arrays.sort(v, 0, m);
		final int lo = m / 4, hi = m - m / 4;
		double sum = 0;
		for (int i = lo; i < hi; i++)
			sum += v[i];
		return sum / (hi - lo);
	}

	/** Moves the numbers among the first {@code n} values before the NaNs; @return how many numbers there are */
	private static int numbersFirst(final double[] v, final int n) {
		if (n < 0 || n > v.length) throw new IllegalArgumentException("a sample of " + n + " values out of an array of "
			+ v.length);
		int m = 0;
		for (int i = 0; i < n; i++)
			if (!Double.isNaN(v[i])) {
				final double t = v[i];
				v[i] = v[m];
				v[m++] = t;
			}
		return m;
	}

	/**
	 * Puts into {@code v[k]} the value sorted order puts there, the values before it no larger, those after it no
	 * smaller (of the first {@code n}; no NaN): Hoare's selection, pivots the median of three.
	 */
	private static void select(final double[] v, final int n, final int k) {
		int lo = 0, hi = n - 1;
		while (hi > lo) {
			final double a = v[lo], b = v[(lo + hi) >>> 1], c = v[hi];
			final double pivot = a < b ? b < c ? b : Math.max(a, c) : a < c ? a : Math.max(b, c);
			int i = lo, j = hi;
			while (i <= j) {
				while (v[i] < pivot)
					i++;
				while (v[j] > pivot)
					j--;
				if (i <= j) {
					final double t = v[i];
					v[i++] = v[j];
					v[j--] = t;
				}
			}
			// v[lo..j] <= pivot, v[i..hi] >= pivot, and those between equal to it
			if (k <= j) hi = j;
			else if (k >= i) lo = i;
			else return;
		}
	}

	/**
	 * A robust standard deviation: started from 1.4826 x the median absolute deviation (at least 0.5, half a grey
	 * level), then the RMS of the values within {@code clip} sigmas of their mean, twice. Unlike the MAD alone it
	 * does not jump with the integer steps of 8-bit data (MAD of uniform noise of amplitude 5 rounded: 3.7 or 4.4
	 * instead of 2.9), and clipping drops outliers (a neighbour's light in part of a background annulus). Clipping a normal distribution at 3.5 sigmas
	 * lowers its RMS by 0.3%.
	 *
	 * @param values the values (not changed)
	 * @param clip how many sigmas from the mean a value may lie and still count
	 * @return the standard deviation; NaN for no values
	 */
	public static double clippedSigma(final double[] values, final double clip) {
		if (values.length == 0) return Double.NaN;
		final double[] dev = values.clone();
		final double med = quantile(dev, 0.5);
		for (int i = 0; i < dev.length; i++)
			dev[i] = Math.abs(values[i] - med);
		double centre = med, sigma = Math.max(MAD_TO_SIGMA * quantile(dev, 0.5), 0.5);
		for (int pass = 0; pass < 2; pass++) {
			double n = 0, sum = 0, sum2 = 0;
			for (final double v : values)
				if (Math.abs(v - centre) <= clip * sigma) {
					n++;
					sum += v;
					sum2 += v * v;
				}
			if (n < 2) break;
			centre = sum / n;
			sigma = Math.sqrt(Math.max(0, sum2 / n - centre * centre));
		}
		return sigma;
	}
}
