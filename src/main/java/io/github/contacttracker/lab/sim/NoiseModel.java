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

import io.github.contacttracker.core.Numbers;

/**
 * Additive, independent per-pixel noise in grey levels, drawn before rounding to integers. Any
 * {@link RandomGenerator} works as the source ({@code java.util.Random}, {@code SplittableRandom}, ...).
 */
public sealed interface NoiseModel {

	/** @return the standard deviation (grey levels) */
	double sigma();

	/** @return one noise value (grey levels) */
	double sample(RandomGenerator random);

	/** @return uniform noise in {@code [-amplitude, amplitude]}, the paper's "random fluctuations of amplitude a" */
	static NoiseModel uniform(final double amplitude) {
		return new Uniform(amplitude);
	}

	/** @return zero-mean Gaussian noise */
	static NoiseModel gaussian(final double sigma) {
		return new Gaussian(sigma);
	}

	/** @return no noise (quantisation only) */
	static NoiseModel none() {
		return Noiseless.INSTANCE;
	}

	/** Uniform in {@code [-amplitude, amplitude)}: standard deviation {@code amplitude / sqrt(3)}. */
	record Uniform(double amplitude) implements NoiseModel {

		/** @throws IllegalArgumentException for a negative or non-finite amplitude */
		public Uniform {
			if (!(amplitude >= 0) || !Double.isFinite(amplitude))
				throw new IllegalArgumentException("uniform noise amplitude must be >= 0, not " + amplitude);
		}

		@Override
		public double sigma() {
			return amplitude / Math.sqrt(3);
		}

		@Override
		public double sample(final RandomGenerator random) {
			return amplitude * (2 * random.nextDouble() - 1);
		}

		@Override
		public String toString() {
			return "uniform noise in [-" + amplitude + ", " + amplitude + "] (sigma " + Numbers.fmt(sigma(), 3) + ")";
		}
	}

	/** Zero-mean Gaussian. */
	record Gaussian(double sigma) implements NoiseModel {

		/** @throws IllegalArgumentException for a negative or non-finite sigma */
		public Gaussian {
			if (!(sigma >= 0) || !Double.isFinite(sigma))
				throw new IllegalArgumentException("Gaussian noise sigma must be >= 0, not " + sigma);
		}

		@Override
		public double sample(final RandomGenerator random) {
			return sigma * random.nextGaussian();
		}

		@Override
		public String toString() {
			return "Gaussian noise (sigma " + Numbers.fmt(sigma, 3) + ")";
		}
	}

	/** No noise: {@link #sample} is always 0 and draws nothing from the generator. */
	enum Noiseless implements NoiseModel {
		/** The only instance. */
		INSTANCE;

		@Override
		public double sigma() {
			return 0;
		}

		@Override
		public double sample(final RandomGenerator random) {
			return 0;
		}

		@Override
		public String toString() {
			return "no noise";
		}
	}
}
