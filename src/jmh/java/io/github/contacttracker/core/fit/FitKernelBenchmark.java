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

import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;

/**
 * The fit's kernel: one pass of {@link NormalEquations} over a member's pixels, as a member of a dense group fitted in
 * turn sees them (a disc of 20 px radius, 1,257 pixels, other particles' light on them), with J^T J (the pass that
 * starts a step) and with the residuals alone (the pass that evaluates one); and the light of a touching neighbour
 * drawn on those pixels ({@link RowRuns#draw}, each sweep, for every neighbour that moved). Under the JVM's default
 * compilers; divide by the pixels for the cost per pixel.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class FitKernelBenchmark {

	private final NormalEquations passes = new NormalEquations();
	private FitPixels pixels;
	private EmpiricalProfile[] profile;
	private final double[] p = new double[GroupFit.PER_PARTICLE + GroupFit.BACKGROUND];
	private final double[][] jtj = new double[p.length][p.length];
	private final double[] jtr = new double[p.length], noise = new double[GroupFit.PER_PARTICLE];
	private RowRuns rows;
	private double[] light;

	@Setup
	public void setUp() {
		// a ringed profile (bright core, dark ring) reaching 30 px, as NormalEquationsTest's
		final double[] c = new double[29];
		for (int j = 0; j < c.length; j++)
			c[j] = 120 * Math.exp(-j * j / 60.0) - 25 * Math.exp(-(j - 14) * (j - 14) / 8.0);
		final EmpiricalProfile ringed = ProfileAccess.profile(1, c, 40, 1000);
		profile = new EmpiricalProfile[] { ringed };
		final Random random = new Random(11);
		final double cx = 40.3, cy = 39.6, radius = 20;
		final int size = 81, cap = size * size;
		final int[] xs = new int[cap], ys = new int[cap];
		final double[] values = new double[cap], fixed = new double[cap];
		int n = 0;
		for (int y = 0; y < size; y++)
			for (int x = 0; x < size; x++) {
				if (Math.hypot(x - cx, y - cy) >= radius) continue;
				xs[n] = x;
				ys[n] = y;
				// two touching neighbours' light, held fixed
				fixed[n] = 1.1 * ringed.value(Math.hypot(x - cx - 30, y - cy)) + ringed.value(Math.hypot(x - cx, y - cy +
					31));
				values[n] = 40 + fixed[n] + 1.05 * ringed.value(Math.hypot(x - cx, y - cy)) + 3 * random.nextGaussian();
				n++;
			}
		pixels = new FitPixels(xs, ys, values, fixed, n, cx, cy, radius);
		rows = RowRuns.of(xs, ys, n);
		light = new double[n];
		p[0] = cx + 0.3;
		p[1] = cy - 0.2;
		p[2] = 1;
		p[3] = 1;
		p[4] = 40;
	}

	/** @return the pass that starts a step: J^T J, J^T r, the residuals and their variances */
	@Benchmark
	public double normalEquations() {
		return passes.accumulate(pixels, p, 1, profile, jtj, jtr, noise, null);
	}

	/**
	 * @return a touching neighbour's light (30 px to the right, its profile reaching all 1,257 pixels' half) drawn on
	 *         the member's pixels, and taken out again
	 */
	@Benchmark
	public double neighbourLight() {
		final EmpiricalProfile ringed = profile[0];
		rows.draw(light, 70.3, 39.6, 1.02, 1.1, ringed.radius() * 1.02, ringed);
		rows.draw(light, 70.3, 39.6, 1.02, -1.1, ringed.radius() * 1.02, ringed);
		return light[light.length / 2];
	}

	/** @return the pass that evaluates a step: J^T r and the residuals alone */
	@Benchmark
	public double residuals() {
		return passes.accumulate(pixels, p, 1, profile, null, jtr, noise, null);
	}
}
