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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

import org.junit.jupiter.api.Test;

class NoiseModelTest {

	private static double[] meanAndStd(final NoiseModel noise, final RandomGenerator random, final int n) {
		double sum = 0, sum2 = 0, maxAbs = 0;
		for (int i = 0; i < n; i++) {
			final double v = noise.sample(random);
			sum += v;
			sum2 += v * v;
			maxAbs = Math.max(maxAbs, Math.abs(v));
		}
		final double mean = sum / n;
		return new double[] { mean, Math.sqrt(sum2 / n - mean * mean), maxAbs };
	}

	@Test
	void uniformSpreadMatchesSigma() {
		final NoiseModel uniform = NoiseModel.uniform(5);
		assertEquals(5 / Math.sqrt(3), uniform.sigma(), 1e-12);
		final double[] stats = meanAndStd(uniform, new SplittableRandom(11), 100_000);
		assertEquals(0, stats[0], 0.05);
		assertEquals(uniform.sigma(), stats[1], 0.03 * uniform.sigma());
		assertTrue(stats[2] <= 5 && stats[2] > 4.99, "range [-5, 5], max |v| " + stats[2]);
	}

	@Test
	void gaussianSpreadMatchesSigma() {
		final NoiseModel gaussian = NoiseModel.gaussian(2.5);
		final double[] stats = meanAndStd(gaussian, new Random(12), 100_000);
		assertEquals(0, stats[0], 0.03);
		assertEquals(2.5, stats[1], 0.03 * 2.5);
	}

	@Test
	void noneIsZeroAndDrawsNothing() {
		final SplittableRandom used = new SplittableRandom(5);
		assertEquals(0, NoiseModel.none().sample(used), 0);
		assertEquals(0, NoiseModel.none().sigma(), 0);
		assertEquals(new SplittableRandom(5).nextLong(), used.nextLong());
	}

	@Test
	void readableAndValidated() {
		assertEquals("uniform noise in [-5.0, 5.0] (sigma 2.887)", NoiseModel.uniform(5).toString());
		assertEquals("Gaussian noise (sigma 1.5)", NoiseModel.gaussian(1.5).toString());
		assertEquals("no noise", NoiseModel.none().toString());
		assertThrows(IllegalArgumentException.class, () -> NoiseModel.uniform(-1));
		assertThrows(IllegalArgumentException.class, () -> NoiseModel.gaussian(Double.NaN));
	}
}
