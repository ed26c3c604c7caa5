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
package io.github.contacttracker.lab.sim;

import java.util.random.RandomGenerator;

/**
 * Poisson deviates (photon counts), exact: by multiplying uniforms for small means, and by Hormann's transformed
 * rejection with squeeze (PTRS, 1993) for means of 10 and more, with log k! from Stirling's series.
 */
final class Poisson {

	private static final double[] LOG_FACTORIAL = new double[16];

	static {
		for (int k = 1; k < LOG_FACTORIAL.length; k++)
			LOG_FACTORIAL[k] = LOG_FACTORIAL[k - 1] + Math.log(k);
	}

	private Poisson() {}

	/** @return a Poisson deviate of mean {@code mean} ({@code >= 0}) */
	static long sample(final double mean, final RandomGenerator random) {
		if (!(mean >= 0) || !Double.isFinite(mean)) throw new IllegalArgumentException("Poisson mean " + mean);
		if (mean < 10) {
			final double limit = Math.exp(-mean);
			double product = random.nextDouble();
			long k = 0;
			while (product > limit) {
				product *= random.nextDouble();
				k++;
			}
			return k;
		}
		final double s = Math.sqrt(mean), logMean = Math.log(mean);
		final double b = 0.931 + 2.53 * s, a = -0.059 + 0.02483 * b;
		final double invAlpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2);
		while (true) {
			final double u = random.nextDouble() - 0.5, v = random.nextDouble();
			final double us = 0.5 - Math.abs(u);
			final long k = (long) Math.floor((2 * a / us + b) * u + mean + 0.43);
			if (us >= 0.07 && v <= vr) return k;
			if (k < 0 || us < 0.013 && v > us) continue;
			if (Math.log(v * invAlpha / (a / (us * us) + b)) <= -mean + k * logMean - logFactorial(k)) return k;
		}
	}

	/** @return ln k! */
	static double logFactorial(final long k) {
		if (k < LOG_FACTORIAL.length) return LOG_FACTORIAL[(int) k];
		final double n = k, n2 = n * n;
		return n * Math.log(n) - n + 0.5 * Math.log(2 * Math.PI * n) + 1 / (12 * n) - 1 / (360 * n * n2) + 1 / (1260 *
			n * n2 * n2);
	}
}
