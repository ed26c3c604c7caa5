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

/**
 * The mean and standard deviation of normal data of which the values at or below a floor were recorded as the floor
 * (a background clipped at 0: a confocal slice with the detector's offset subtracted), by maximum likelihood (the
 * Tobit model): an expectation-maximisation that puts in, for each clipped value, the mean and second moment of the
 * normal below the floor at the current estimate. The mean of the values above the floor alone lies too high (by
 * {@code sigma phi(a) / (1 - Phi(a))}, 2 grey levels for a background of 2 clipped at 0 with noise 4), and the mean of
 * all values, clipped ones at the floor, too (0.8 there).
 */
public final class CensoredNormal {

	private CensoredNormal() {}

	/** Iterations of the expectation-maximisation at most; it stops earlier once the mean moves by under 1e-9 sigma. */
	static final int ITERATIONS = 10_000;

	/**
	 * @param floor the level at or below which values were clipped
	 * @param clipped how many values were clipped
	 * @param n how many were not (above the floor)
	 * @param sum their sum
	 * @param sumOfSquares the sum of their squares
	 * @return {mean, standard deviation} of the normal, or null where the data cannot tell them (fewer than two values
	 *         above the floor, or none spread)
	 */
	public static double[] estimate(final double floor, final long clipped, final long n, final double sum,
		final double sumOfSquares)
	{
		if (n < 2 || clipped < 0) return null;
		double mean = sum / n, variance = sumOfSquares / n - mean * mean;
		if (!(variance > 0)) return null;
		if (clipped == 0) return new double[] { mean, Math.sqrt(variance) };
		final double total = n + clipped;
		for (int i = 0; i < ITERATIONS; i++) {
			final double sigma = Math.sqrt(variance), a = (floor - mean) / sigma;
			final double below = normalCdf(a);
			// the inverse Mills ratio phi(a) / Phi(a), by its asymptote where Phi(a) underflows
			final double mills = below > 1e-300 ? normalDensity(a) / below : -a;
			final double clippedMean = mean - sigma * mills;
			final double clippedVariance = variance * Math.max(0, 1 - a * mills - mills * mills);
			final double next = (sum + clipped * clippedMean) / total;
			final double second = (sumOfSquares + clipped * (clippedVariance + clippedMean * clippedMean)) / total;
			final double nextVariance = second - next * next;
			if (!(nextVariance > 0)) return null;
			final boolean settled = Math.abs(next - mean) < 1e-9 * sigma;
			mean = next;
			variance = nextVariance;
			if (settled) break;
		}
		return new double[] { mean, Math.sqrt(variance) };
	}

	/** @return the standard normal density at {@code z} */
	public static double normalDensity(final double z) {
		return Math.exp(-0.5 * z * z) / Math.sqrt(2 * Math.PI);
	}

	/**
	 * @return the standard normal distribution function at {@code z}, to an absolute error below 1e-7 (the error
	 *         function by the rational approximation 7.1.26 of Abramowitz and Stegun, Handbook of Mathematical
	 *         Functions, 1964)
	 */
	public static double normalCdf(final double z) {
		return normalCdf(z, normalDensity(z));
	}

	/**
	 * @return {@link #normalCdf(double)} from the density at {@code z} already known ({@code density}, which holds
	 *         the approximation's one exponential)
	 */
	public static double normalCdf(final double z, final double density) {
		final double x = Math.abs(z) / Math.sqrt(2), t = 1 / (1 + 0.3275911 * x);
		final double tail = 0.5 * t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t *
			1.061405429)))) * density * Math.sqrt(2 * Math.PI);
		return z >= 0 ? 1 - tail : tail;
	}
}
