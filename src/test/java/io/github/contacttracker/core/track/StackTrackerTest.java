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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.real.FloatType;
import org.junit.jupiter.api.Test;

class StackTrackerTest {

	private static List<RandomAccessibleInterval<FloatType>> frames(final int count) {
		final List<RandomAccessibleInterval<FloatType>> frames = new ArrayList<>();
		for (int t = 0; t < count; t++) {
			final double[] img = TestImages.withUniformNoise(TestImages.render(64, 48, 20, TestImages.gaussian(150, 6),
				new double[] { 16 + 0.7 * t, 24 }, new double[] { 50, 22 - 0.3 * t }), 4, t);
			frames.add(TestImages.floats(img, 64, 48));
		}
		return frames;
	}

	@Test
	void parallelRunEqualsSerialRunInFrameOrder() {
		final TrackerParameters p = TrackerParameters.of(80, 20).withMethod(Method.PAPER);
		final List<RandomAccessibleInterval<FloatType>> frames = frames(9);
		// really serial: one thread (imglib2's default executor is the common ForkJoinPool, not one thread)
		final List<FrameResult> serial = StackTracker.withThreads(1, () -> new StackTracker(p).track(frames, false));
		final AtomicInteger calls = new AtomicInteger();
		final Set<String> workers = ConcurrentHashMap.newKeySet();
		// the first two frames wait for each other: they meet only if two threads really run at once
		final CountDownLatch both = new CountDownLatch(2);
		final List<FrameResult> parallel = StackTracker.withThreads(3, () -> new StackTracker(p).track(frames
			.size(), t -> {
				workers.add(Thread.currentThread().getName());
				if (t < 2) {
					both.countDown();
					try {
						both.await(10, TimeUnit.SECONDS);
					}
					catch (final InterruptedException e) {
						Thread.currentThread().interrupt();
					}
				}
				return frames.get(t);
			}, false, (done, total) -> {
				calls.incrementAndGet();
				assertEquals(9, total);
			}, () -> false));
		assertEquals(0, both.getCount(), "frames 1 and 2 must run at the same time on the caller's threads");
		assertTrue(workers.size() > 1, "the caller's three threads must share the frames: " + workers);
		assertEquals(9, calls.get());
		final List<Localization> a = StackTracker.spots(serial), b = StackTracker.spots(parallel);
		assertEquals(18, a.size());
		assertEquals(a, b);
		for (int t = 0; t < 9; t++)
			assertEquals(t, serial.get(t).spots().get(0).frame());
		final double left = Math.min(serial.get(4).spots().get(0).x(), serial.get(4).spots().get(1).x());
		assertEquals(16 + 0.7 * 4, left, 0.1);
	}

	@Test
	void profileMethodsCountEveryPassAndStayDeterministic() {
		final List<RandomAccessibleInterval<FloatType>> frames = frames(6);
		final TrackerParameters p = TrackerParameters.of(80, 20).withMethod(Method.FIT);
		final AtomicInteger last = new AtomicInteger(), announced = new AtomicInteger();
		final List<FrameResult> parallel = StackTracker.withThreads(2, () -> new StackTracker(p).track(frames
			.size(), frames::get, false, (done, total) -> {
				// iterative, refinement of the profile frames (all 6 here) in one or more rounds, final (none left:
				// the sample frames' last round is final)
				assertTrue(total >= 6 + 6 && total % 6 == 0, "total " + total);
				assertTrue(done <= total);
				announced.accumulateAndGet(total, Math::max);
				last.accumulateAndGet(done, Math::max);
			}, () -> false));
		assertEquals(announced.get(), last.get());
		assertEquals(StackTracker.spots(new StackTracker(p).track(frames, false)), StackTracker.spots(parallel));
		for (final FrameResult r : parallel)
			for (final Localization s : r.spots())
				assertTrue(!s.isFlagged(), s.flagSet().toString());
	}

	/**
	 * One frame of many groups (pairs of near particles and single ones, every group farther than 2 r_out from
	 * the next): its groups are spread over the caller's threads, and the spots are the same to the last bit on one
	 * thread and on three, and where the particles are.
	 */
	@Test
	void oneFramesGroupsSpreadOverThreadsGiveTheSameSpots() {
		final List<double[]> truth = new ArrayList<>();
		for (int g = 0; g < 5; g++) {
			truth.add(new double[] { 22 + 50 * g, 22 + 0.3 * g });
			if (g % 2 == 0) truth.add(new double[] { 22 + 50 * g + 0.4 * g, 40 });
		}
		final double[] img = TestImages.withUniformNoise(TestImages.render(264, 64, 20, TestImages.gaussian(150, 4),
			truth.toArray(new double[0][])), 4, 3);
		final List<RandomAccessibleInterval<FloatType>> frame = List.of(TestImages.floats(img, 264, 64));
		// r_out 14: groups of particles closer than 28 px, five of them
		final TrackerParameters p = TrackerParameters.of(60, 14).withMethod(Method.FIT);
		final List<Localization> one = StackTracker.spots(StackTracker.withThreads(1, () -> new StackTracker(p).track(
			frame, false)));
		final List<Localization> three = StackTracker.spots(StackTracker.withThreads(3, () -> new StackTracker(p).track(
			frame, false)));
		assertEquals(one, three);
		assertEquals(truth.size(), one.size());
		for (final double[] t : truth) {
			double nearest = Double.POSITIVE_INFINITY;
			for (final Localization s : one)
				nearest = Math.min(nearest, Math.hypot(s.x() - t[0], s.y() - t[1]));
			assertTrue(nearest < 0.1, "a particle at " + t[0] + ", " + t[1] + " found " + nearest + " px off");
		}
	}

	/**
	 * The distributed way (the profile stage once, shipped serialized, then the other frames in chunks, in any
	 * order) gives exactly the spots of one run: what the Spark job relies on.
	 */
	@Test
	void profileStageThenChunksEqualsOneRun() throws Exception {
		final List<RandomAccessibleInterval<FloatType>> frames = frames(70); // more than PROFILE_FRAMES
		final TrackerParameters p = TrackerParameters.of(80, 20).withMethod(Method.FIT);
		final List<Localization> whole = StackTracker.spots(new StackTracker(p).track(frames, false));
		final java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
		try (java.io.ObjectOutputStream out = new java.io.ObjectOutputStream(bytes)) {
			out.writeObject(new StackTracker(p).profileStage(frames.size(), frames::get, () -> false));
		}
		final StackTracker.ProfileStage stage;
		try (java.io.ObjectInputStream in = new java.io.ObjectInputStream(new java.io.ByteArrayInputStream(bytes
			.toByteArray())))
		{
			stage = (StackTracker.ProfileStage) in.readObject();
		}
		final int[] sample = stage.sample(), others = stage.others(frames.size());
		assertEquals(64, sample.length);
		assertEquals(6, others.length);
		final List<List<Localization>> byFrame = new ArrayList<>();
		for (int t = 0; t < frames.size(); t++)
			byFrame.add(null);
		for (int i = 0; i < sample.length; i++)
			byFrame.set(sample[i], stage.sampleResult(i).spots());
		// the chunks done last first, each on a tracker of its own (as on another machine)
		for (final int[] chunk : new int[][] { java.util.Arrays.copyOfRange(others, 3, 6), java.util.Arrays
			.copyOfRange(others, 0, 3) })
		{
			final List<FrameResult> r = new StackTracker(p).trackWith(stage, chunk, frames::get, () -> false);
			for (int i = 0; i < chunk.length; i++)
				byFrame.set(chunk[i], r.get(i).spots());
		}
		final List<Localization> distributed = new ArrayList<>();
		byFrame.forEach(distributed::addAll);
		assertTrue(whole.size() >= 70, whole.size() + " spots"); // particles leave the frame late in the movie
		assertEquals(whole, distributed);
	}

	@Test
	void cancellationStopsTheRun() {
		final List<RandomAccessibleInterval<FloatType>> frames = frames(4);
		assertThrows(CancellationException.class, () -> StackTracker.withThreads(2, () -> new StackTracker(
			TrackerParameters.of(80, 20)).track(frames.size(), frames::get, false, null, () -> true)));
	}

	@Test
	void badFrameIsNamed() {
		final List<RandomAccessibleInterval<FloatType>> frames = new ArrayList<>(frames(3));
		final float[] bad = new float[64 * 48];
		bad[100] = Float.POSITIVE_INFINITY;
		frames.set(1, ArrayImgs.floats(bad, 64, 48));
		final IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
			() -> StackTracker.withThreads(2, () -> new StackTracker(TrackerParameters.of(80, 20)).track(frames,
				false)));
		assertTrue(e.getMessage().startsWith("frame 2: pixel (36, 1) is Infinity"), e.getMessage());
	}

	/**
	 * A profile round whose detection removed one particle and added another keeps the frame's count but not its
	 * order: each spot's move is from its own particle before, not from the spot at its place in the list.
	 */
	@Test
	void roundMovesMatchParticlesWhenOneIsRemovedAndAnotherAdded() {
		final List<Localization> before = List.of(spot(10, 10), spot(40, 10), spot(70, 10));
		// the particle at (40, 10) removed, one at (100, 10) added, the others moved by 0.01 px
		final List<Localization> after = List.of(spot(10.01, 10), spot(70.01, 10), spot(100, 10));
		final double[] moves = RoundResults.moves(List.of(result(before)), List.of(result(after)));
		final double tolerance = io.github.contacttracker.core.fit.GroupFit.settled(0.02, 0.02);
		assertEquals(0.01 / tolerance, moves[0], 1e-9);
		assertEquals(0.01 / tolerance, moves[1], 1e-9);
		assertTrue(Double.isNaN(moves[2]), "the added particle has no move: " + moves[2]);
	}

	private static Localization spot(final double x, final double y) {
		return new Localization(0, x, y, x, y, 300, 0, 1, 10, 0, 3, 0.02, 0.02, 1, 1, 0);
	}

	private static FrameResult result(final List<Localization> spots) {
		return new FrameResult(spots, List.of(), List.of(), 1, 0, false);
	}
}
