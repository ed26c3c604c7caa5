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

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Equilibrium configurations of particles interacting with a known {@link PairInteraction}, by Metropolis Monte
 * Carlo in a periodic {@code width x height} box (minimum-image distances): the ground truth for pair
 * potentials measured from images. Deterministic: equal arguments and seed give equal configurations.
 * <p>
 * Start: random placement without overlap. Each sweep tries one displacement per particle (uniform in a square
 * of side {@code 2 step}), accepted with probability {@code min(1, exp(-dU))}. During the equilibration
 * sweeps the step is tuned towards 40% acceptance, then fixed (changing it while sampling would bias the
 * sampling). Configurations are taken every {@code sweepsBetween} sweeps.
 */
public final class MonteCarloFluid {

	/** Sweeps before the first configuration is taken. */
	public static final int EQUILIBRATION_SWEEPS = 500;

	private final PairInteraction interaction;
	private final int particles;
	private final double width, height;

	/**
	 * @param interaction the pair potential
	 * @param particles number of particles
	 * @param width box width (px)
	 * @param height box height (px)
	 * @throws IllegalArgumentException when the box is smaller than twice the potential's range (the minimum image
	 *           would then miss interactions)
	 */
	public MonteCarloFluid(final PairInteraction interaction, final int particles, final double width,
		final double height)
	{
		if (particles < 1) throw new IllegalArgumentException("need at least one particle, not " + particles);
		if (!(Math.min(width, height) > 2 * interaction.range()))
			throw new IllegalArgumentException("the box (" + width + " x " + height + " px) must be larger than twice the " +
				"potential's range (" + interaction.range() + " px)");
		this.interaction = interaction;
		this.particles = particles;
		this.width = width;
		this.height = height;
	}

	/**
	 * @param samples configurations to take
	 * @param sweepsBetween sweeps between two configurations (more: less correlated samples)
	 * @param seed random seed
	 * @return per configuration the centres {@code {x, y}} (px), in {@code [0, width) x [0, height)}
	 */
	public List<List<double[]>> sample(final int samples, final int sweepsBetween, final long seed) {
		if (samples < 1 || sweepsBetween < 1)
			throw new IllegalArgumentException("need at least one sample and one sweep between samples");
		final SplittableRandom random = new SplittableRandom(seed);
		final double[] x = new double[particles], y = new double[particles];
		place(x, y, random);
		double step = 0.1 * interaction.range();
		for (int s = 0; s < EQUILIBRATION_SWEEPS; s++) {
			final double accepted = sweep(x, y, step, random) / (double) particles;
			// gentle multiplicative tuning towards 40% acceptance, capped so the step stays sensible
			step = Math.min(0.25 * Math.min(width, height), step * Math.exp(0.5 * (accepted - 0.4)));
		}
		final List<List<double[]>> out = new ArrayList<>(samples);
		for (int k = 0; k < samples; k++) {
			for (int s = 0; s < sweepsBetween; s++)
				sweep(x, y, step, random);
			final List<double[]> config = new ArrayList<>(particles);
			for (int i = 0; i < particles; i++)
				config.add(new double[] { x[i], y[i] });
			out.add(List.copyOf(config));
		}
		return out;
	}

	private void place(final double[] x, final double[] y, final SplittableRandom random) {
		for (int i = 0; i < particles; i++) {
			for (int attempt = 0;; attempt++) {
				if (attempt > 100_000)
					throw new IllegalArgumentException(particles + " particles do not fit in a " + width + " x " + height +
						" px box without overlapping");
				x[i] = random.nextDouble(width);
				y[i] = random.nextDouble(height);
				if (Double.isFinite(energy(x, y, i, x[i], y[i], i))) break;
			}
		}
	}

	/** @return the number of accepted moves */
	private int sweep(final double[] x, final double[] y, final double step, final SplittableRandom random) {
		int accepted = 0;
		for (int n = 0; n < particles; n++) {
			final int i = random.nextInt(particles);
			double nx = x[i] + random.nextDouble(-step, step), ny = y[i] + random.nextDouble(-step, step);
			nx -= width * Math.floor(nx / width);
			ny -= height * Math.floor(ny / height);
			final double after = energy(x, y, i, nx, ny, particles);
			if (after == Double.POSITIVE_INFINITY) {
				random.nextDouble(); // keep the random sequence independent of the outcome's branch
				continue;
			}
			final double delta = after - energy(x, y, i, x[i], y[i], particles);
			if (random.nextDouble() < Math.exp(-delta)) {
				x[i] = nx;
				y[i] = ny;
				accepted++;
			}
		}
		return accepted;
	}

	/** Energy (kT) of particle {@code i} placed at {@code (px, py)} with particles {@code 0..limit-1} but itself. */
	private double energy(final double[] x, final double[] y, final int i, final double px, final double py,
		final int limit)
	{
		final double range2 = interaction.range() * interaction.range();
		double e = 0;
		for (int j = 0; j < limit; j++) {
			if (j == i) continue;
			double dx = Math.abs(x[j] - px), dy = Math.abs(y[j] - py);
			if (dx > 0.5 * width) dx = width - dx;
			if (dy > 0.5 * height) dy = height - dy;
			final double d2 = dx * dx + dy * dy;
			if (d2 >= range2) continue;
			e += interaction.energyKt(Math.sqrt(d2));
			if (e == Double.POSITIVE_INFINITY) return e;
		}
		return e;
	}
}
