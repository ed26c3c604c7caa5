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
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.function.IntFunction;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindProfiles;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.parallel.Parallelization;
import net.imglib2.parallel.TaskExecutor;
import net.imglib2.type.numeric.RealType;

/**
 * One pass of a frame's tracker over some frames of a movie, the frames shared among the threads of the caller's
 * task executor: what {@link StackTracker} runs over the whole movie and the profile rounds ({@link ProfileRounds})
 * over its sample frames. Results come back in the order the frames were asked for, and a failure is the first in
 * that order, whatever the number of threads, so a run is reproducible; cancelling and progress are counted in
 * passes over a frame.
 */
final class FramePass {

	private FramePass() {}

	/**
	 * Localizes frames {@code indices} on the caller's task executor; results in that order. A frame's failure
	 * (an exception or running out of memory) is caught in its task and the first failure in frame order rethrown
	 * as it was, so the error a user sees does not depend on the threads.
	 */
	static <T extends RealType<T>> List<FrameResult> pass(final ContactTracker tracker,
		final KindProfiles profile, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final boolean keepRegions,
		final Progress progress, final BooleanSupplier cancelled)
	{
		return pass(tracker, profile, indices, frame, keepRegions, progress, cancelled, null);
	}

	/**
	 * As {@link #pass(ContactTracker, KindProfiles, int[], IntFunction, boolean, Progress, BooleanSupplier)}, frame
	 * {@code indices[i]} refitting the particles of {@code earlier.get(i)} where the image detects (null: found anew).
	 */
	static <T extends RealType<T>> List<FrameResult> pass(final ContactTracker tracker,
		final KindProfiles profile, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final boolean keepRegions,
		final Progress progress, final BooleanSupplier cancelled, final List<FrameResult> earlier)
	{
		final TaskExecutor executor = Parallelization.getTaskExecutor();
		final Throwable[] failures = new Throwable[indices.length];
		final List<FrameResult> results = executor.forEachApply(positions(indices.length), i -> {
			try {
				// counted in passes over a frame: the profile methods track their sample frames once per profile round,
				// so a count of "frames" could exceed the movie's (117 on a 30-frame movie, seen in Fiji)
				if (cancelled.getAsBoolean()) throw new CancellationException("cancelled after " + progress.done.get() +
					" of " + progress.total + " passes over a frame");
				final FrameResult r = one(tracker, profile, frame, indices[i], keepRegions, earlier == null ? null : earlier
					.get(i).spots());
				progress.frameDone();
				return r;
			}
			catch (final RuntimeException | OutOfMemoryError e) {
				// out of memory too: the executor would wrap it in a RuntimeException, hiding it from the front ends
				failures[i] = e;
				return null;
			}
		});
		for (final Throwable e : failures)
			if (e instanceof OutOfMemoryError oom) throw oom;
			else if (e != null) throw (RuntimeException) e;
		return results;
	}

	private static <T extends RealType<T>> FrameResult one(final ContactTracker tracker,
		final KindProfiles profile, final IntFunction<? extends RandomAccessibleInterval<T>> frame, final int t,
		final boolean keepRegions, final List<Localization> particles)
	{
		try {
			return tracker.analyse(Plane.of(frame.apply(t)), t, keepRegions, profile, particles);
		}
		catch (final InvalidInputException e) {
			throw new InvalidInputException("frame " + (t + 1) + ": " + e.getMessage(), e);
		}
	}

	/** Frames done over frames to do, across the passes of one run. */
	static final class Progress {

		/** Hears that {@code done} passes over a frame of {@code total} are finished; called from worker threads. */
		@FunctionalInterface
		interface Listener {
			void progress(int done, int total);
		}

		final Listener listener;
		final AtomicInteger done = new AtomicInteger();
		int total;

		Progress(final Listener listener, final int total) {
			this.listener = listener;
			this.total = total;
		}

		void frameDone() {
			if (listener != null) listener.progress(done.incrementAndGet(), total);
		}
	}

	/** @return 0, 1, ..., {@code count - 1} */
	static int[] range(final int count) {
		final int[] r = new int[count];
		for (int i = 0; i < count; i++)
			r[i] = i;
		return r;
	}

	/** @return 0, 1, ..., {@code n - 1}, as the task executor's list of tasks */
	static List<Integer> positions(final int n) {
		final List<Integer> list = new ArrayList<>(n);
		for (int i = 0; i < n; i++)
			list.add(i);
		return list;
	}
}
