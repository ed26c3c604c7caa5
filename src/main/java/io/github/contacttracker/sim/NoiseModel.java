package io.github.contacttracker.sim;

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
