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
package io.github.contacttracker.lab.eval;

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;

/**
 * The paper's protocol: simulate a scenario at a separation with many noisy images, localize them with each
 * method, and compare the measured distance of the measured pair with the truth.
 */
public final class DistanceStudy {

	/** The separations (in diameters) of the paper's protocol, from well apart down to contact. */
	public static final double[] SEPARATIONS = { 2.0, 1.6, 1.4, 1.3, 1.2, 1.1, 1.05, 1.0 };

	private final ParticleType type;
	private final Scenario scenario;
	private final TrackerParameters base;
	private final int threads;

	/**
	 * @param type the particles (their threshold and r_out are used)
	 * @param scenario pair or triple
	 * @param threads worker threads for tracking (below 1: all processors)
	 */
	public DistanceStudy(final ParticleType type, final Scenario scenario, final int threads) {
		this.type = type;
		this.scenario = scenario;
		this.base = TrackerParameters.of(type.threshold(), type.rOut());
		this.threads = threads;
	}

	/** @return the tracker parameters the study uses (method aside) */
	public TrackerParameters parameters() {
		return base;
	}

	/** Simulates {@code images} frames at a separation (8-bit, as the paper's camera). */
	public SimulatedStack<?> simulate(final double separationOverD, final int images, final long seed) {
		return SimulatedStack.simulate(type, scenario, separationOverD, images, seed, 8);
	}

	/** Measures every method on one simulated stack. */
	public List<DistanceError> measure(final SimulatedStack<?> stack, final List<Method> methods) {
		final List<DistanceError> out = new ArrayList<>();
		for (final Method m : methods)
			out.add(measure(stack, track(stack, m), m));
		return out;
	}

	/** Tracks a stack with one method. */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public List<FrameResult> track(final SimulatedStack<?> stack, final Method method) {
		final StackTracker tracker = new StackTracker(base.withMethod(method));
		return StackTracker.withThreads(threads, () -> tracker.track((List) stack.frames(), false));
	}

	/** Compares frames tracked with {@code method} with the stack's truth. */
	public DistanceError measure(final SimulatedStack<?> stack, final List<FrameResult> results,
		final Method method)
	{
		final int[] pair = stack.measuredPairs().get(0);
		final double nmPerPx = type.pixelSizeNm(), maxMatch = type.diameterPx() / 2;
		double sum = 0, sumSq = 0, sigmaSum = 0;
		int measured = 0, failures = 0, fallbacks = 0, sigmaCount = 0;
		for (int t = 0; t < results.size(); t++) {
			final List<double[]> truth = stack.truth().get(t);
			final Localization a = nearest(results.get(t).spots(), truth.get(pair[0]), maxMatch);
			final Localization b = nearest(results.get(t).spots(), truth.get(pair[1]), maxMatch);
			if (a == null || b == null || a == b || a.has(Flag.MERGED) || b.has(Flag.MERGED)) {
				failures++;
				continue;
			}
			if (a.has(Flag.FELL_BACK) || b.has(Flag.FELL_BACK)) fallbacks++;
			final double trueD = dist(truth.get(pair[0])[0], truth.get(pair[0])[1], truth.get(pair[1])[0],
				truth.get(pair[1])[1]);
			final double d = dist(a.x(), a.y(), b.x(), b.y());
			final double err = (d - trueD) * nmPerPx;
			sum += err;
			sumSq += err * err;
			measured++;
			// Distance error from the two centres' errors, projected on the pair's axis.
			final double ux = (b.x() - a.x()) / d, uy = (b.y() - a.y()) / d;
			final double va = sq(a.sigmaX() * ux) + sq(a.sigmaY() * uy), vb = sq(b.sigmaX() * ux) + sq(b.sigmaY() * uy);
			if (Double.isFinite(va + vb)) {
				sigmaSum += Math.sqrt(va + vb) * nmPerPx;
				sigmaCount++;
			}
		}
		final double mean = measured > 0 ? sum / measured : Double.NaN;
		final double std = measured > 1 ? Math.sqrt(Math.max(0, (sumSq - sum * sum / measured) / (measured - 1)))
			: Double.NaN;
		return new DistanceError(stack.separationOverD(), method, results.size(), measured, failures,
			fallbacks, mean, std, sigmaCount > 0 ? sigmaSum / sigmaCount : Double.NaN);
	}

	private static Localization nearest(final List<Localization> spots, final double[] p, final double max) {
		Localization best = null;
		double bestD = max;
		for (final Localization s : spots) {
			final double d = dist(s.x(), s.y(), p[0], p[1]);
			if (d <= bestD) {
				bestD = d;
				best = s;
			}
		}
		return best;
	}

	private static double dist(final double x0, final double y0, final double x1, final double y1) {
		return Math.hypot(x1 - x0, y1 - y0);
	}

	private static double sq(final double v) {
		return v * v;
	}
}
