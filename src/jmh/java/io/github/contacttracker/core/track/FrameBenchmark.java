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
package io.github.contacttracker.core.track;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.SimulatedStack;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * One whole frame with the default method after a movie's start-up: a dense monolayer (a 512x512 8-bit frame of the
 * 5.53 um silica kind, rows of touching particles in a hexagonal lattice, noise as the kind's), its profile measured
 * once in the set-up ({@link StackTracker.ProfileStage}), then the frame tracked with it
 * ({@link StackTracker#trackWith}), as every frame of a long movie is: detection, iterative pass, joint fit, on
 * {@code threads} threads (one frame's independent groups of touching particles spread over them).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 4, time = 3)
@Measurement(iterations = 5, time = 3)
@Fork(1)
public class FrameBenchmark {

	@Param({ "1", "2" })
	public int threads;

	private final List<ArrayImg<UnsignedByteType, ?>> frames = new ArrayList<>();
	private StackTracker tracker;
	private StackTracker.ProfileStage stage;
	/** the particles in the frame */
	public int particles;

	@Setup
	public void setUp() {
		final ParticleType type = PaperParticles.silica553();
		final double d = type.diameterPx(), margin = 8;
		final List<double[]> centres = new ArrayList<>();
		// touching rows in pairs: a lattice with gaps between the pairs of rows, so that a frame holds groups of
		// touching particles and not one group
		for (int row = 0; ; row++) {
			final double y = margin + 0.5 * d + row * d * Math.sqrt(3) / 2 + (row / 2) * 0.6 * d;
			if (y + 0.5 * d + margin > 512) break;
			for (double x = margin + 0.5 * d + (row % 2) * 0.5 * d; x + 0.5 * d + margin <= 512; x += d)
				centres.add(new double[] { x, y });
		}
		particles = centres.size();
		final Random random = new Random(7);
		for (int t = 0; t < 4; t++)
			frames.add(eightBit(SimulatedStack.renderFrame(type, jitter(centres, random), 512, 512, type.noise(),
				new Random(t), 8).image()));
		tracker = new StackTracker(TrackerParameters.of(type.threshold(), type.rOut()));
		stage = StackTracker.withThreads(threads, () -> tracker.profileStage(frames.size(), frames::get, () -> false));
	}

	@SuppressWarnings("unchecked")
	private static ArrayImg<UnsignedByteType, ?> eightBit(final ArrayImg<?, ?> image) {
		return (ArrayImg<UnsignedByteType, ?>) image;
	}

	/** @return the centres moved by up to a tenth of a pixel (contacts kept within a rounding) */
	private static List<double[]> jitter(final List<double[]> centres, final Random random) {
		final List<double[]> out = new ArrayList<>(centres.size());
		for (final double[] c : centres)
			out.add(new double[] { c[0] + 0.1 * (random.nextDouble() - 0.5), c[1] + 0.1 * (random.nextDouble() - 0.5) });
		return out;
	}

	/** @return the spots of one frame (the frame after the sample's first) */
	@Benchmark
	public List<FrameResult> frame() {
		return StackTracker.withThreads(threads, () -> tracker.trackWith(stage, new int[] { 1 }, frames::get, () ->
			false));
	}
}
