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

import static io.github.contacttracker.core.track.FramePass.pass;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.function.BooleanSupplier;
import java.util.function.IntFunction;
import java.util.function.Supplier;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.track.FramePass.Progress;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.parallel.Parallelization;
import net.imglib2.type.numeric.RealType;

/**
 * Localizes every frame of a time series, frames in parallel. Results come back in frame order whatever the
 * number of threads, so a run is reproducible. The profile methods (deblend, fit) first measure the movie's profile
 * on a few sample frames ({@link ProfileStage}: the {@link ProfileRounds} on the frames chosen here), then refine
 * every other frame with it; each pass over frames is a {@link FramePass}.
 * <p>
 * The threads are the caller's: every pass runs on {@link Parallelization#getTaskExecutor()} of the calling thread
 * (the imglib2 idiom), so a front end decides once, e.g. {@code Parallelization.runWithNumThreads(n, () ->
 * stackTracker.track(...))}; without that, imglib2's default task executor runs on the common ForkJoinPool (all
 * processors). No thread pool is created here.
 */
public final class StackTracker {

	/** Hears about progress; called from worker threads. */
	@FunctionalInterface
	public interface ProgressListener {
		/** @param framesDone frames finished so far, of {@code frames} */
		void progress(int framesDone, int frames);
	}

	private final ContactTracker tracker;

	/** @param params the localizer's parameters */
	public StackTracker(final TrackerParameters params) {
		this.tracker = new ContactTracker(params);
	}

	/**
	 * @param requested a number of threads asked for; below 1 means "all available processors"
	 * @return the number of threads to run with
	 */
	private static int threads(final int requested) {
		return requested < 1 ? Runtime.getRuntime().availableProcessors() : requested;
	}

	/**
	 * Runs {@code work} with {@code threads} threads as imglib2's task executor of this thread (below 1: all
	 * processors), the way a front end owns the threads of a run. Unlike {@code Parallelization.runWithNumThreads
	 * (int, Callable)}, exceptions pass unchanged (a user error stays an {@code IllegalArgumentException}). One
	 * thread is the calling thread itself (imglib2's sequential executor), not a pool of one that it waits for: a
	 * Spark task's work then runs on the task's thread, and Spark's metrics count its CPU time.
	 */
	public static <R> R withThreads(final int threads, final Supplier<R> work) {
		final List<R> out = new ArrayList<>(1);
		final Runnable run = () -> out.add(work.get()); // a Runnable: it does not wrap exceptions
		if (threads(threads) == 1) Parallelization.runSingleThreaded(run);
		else Parallelization.runWithNumThreads(threads(threads), run);
		return out.get(0);
	}

	/** Localizes all frames of a list. */
	public <T extends RealType<T>> List<FrameResult> track(final List<? extends RandomAccessibleInterval<T>> frames,
		final boolean keepRegions)
	{
		return track(frames.size(), frames::get, keepRegions, null, () -> false);
	}

	/**
	 * Localizes {@code count} frames supplied by index (so a long stack need not be held as views at once).
	 *
	 * @param count number of frames
	 * @param frame supplies frame {@code t}, 2D; called from the worker threads, so it must be thread-safe, and
	 *        may be called more than once for a frame (the profile methods read their sample frames twice)
	 * @param keepRegions whether to keep the active and second areas (for overlays; costs memory)
	 * @param listener progress, or null (for deblend and fit the progress also counts the iterative pass and the
	 *        rounds of profile and centres on the frames the profile is measured on)
	 * @param cancelled polled before each frame; when it turns true the run stops with a
	 *        {@link CancellationException}
	 * @return one result per frame, in frame order
	 * @throws IllegalArgumentException if a frame is not 2D or holds NaN/infinite pixels (naming the first such
	 *         frame, counted from 1)
	 */
	public <T extends RealType<T>> List<FrameResult> track(final int count,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final boolean keepRegions,
		final ProgressListener listener, final BooleanSupplier cancelled)
	{
		final TrackerParameters params = tracker.parameters();
		final int[] all = FramePass.range(count);
		if (!params.method().needsProfile() || count == 0)
			return pass(tracker, null, all, frame, keepRegions, progress(listener, count), cancelled);
		// deblend and fit: iterative centres on a spread of frames; the profile measured on them; those frames
		// refined with it and the profile measured again around the refined centres; then every frame.
		final int[] sample = profileFrames(count, frame);
		// the iterative pass and the first round on the sample; all frames at the end, but without regions to keep
		// the sample frames are done by then (see below)
		final Progress progress = progress(listener, 2 * sample.length + count - (keepRegions ? 0 : sample.length));
		final ProfileStage stage = profileStage(sample, frame, progress, cancelled);
		if (keepRegions) return stage.finish(pass(stage.tracker(tracker), stage.profile, all, frame, true, progress,
			cancelled));
		progress.total += sample.length - stage.sample.length; // frames left to the last pass
		final boolean[] done = new boolean[count];
		for (final int t : stage.sample)
			done[t] = true;
		final List<FrameResult> others = pass(stage.tracker(tracker), stage.profile, stage.others(count), frame, false,
			progress, cancelled);
		final List<FrameResult> results = new ArrayList<>(count);
		for (int t = 0, s = 0, o = 0; t < count; t++)
			results.add(done[t] ? stage.round.get(s++) : others.get(o++));
		return stage.finish(results);
	}

	/** @return the results, each with the detection chosen for the movie (as they are where none was chosen) */
	private static List<FrameResult> chosen(final List<FrameResult> results, final DetectionChoice choice) {
		if (choice == null) return results;
		final List<FrameResult> out = new ArrayList<>(results.size());
		for (final FrameResult r : results)
			out.add(r.withDetection(choice));
		return out;
	}

	/**
	 * The first stage of the profile methods on a movie, which a distributed front end runs once per movie before
	 * the frames are shared out: the profile measured on {@link #profileFrames sample frames} (null when it could
	 * not be, and each frame then measures its own), whether its rounds settled, and the sample frames' results.
	 * {@link #track(int, IntFunction, boolean, ProgressListener, BooleanSupplier)} is this stage followed by
	 * {@link #trackWith} on the other frames, so the two ways give the same spots.
	 */
	public static final class ProfileStage implements Serializable {

		private static final long serialVersionUID = 1L;

		private final int[] sample;
		private final KindProfiles profile;
		private final boolean settled;
		private final transient List<FrameResult> round;
		private final List<FrameResult> sampleResults;
		private final DetectionChoice choice;
		/** the typical fit of the sample frames' spots, where the particles were found by their image, else null */
		private final Misfit misfit;

		ProfileStage(final int[] sample, final KindProfiles profile, final boolean settled,
			final List<FrameResult> round, final DetectionChoice choice, final Misfit misfit)
		{
			this.sample = sample;
			this.profile = profile;
			this.settled = settled;
			this.round = round;
			this.choice = choice;
			this.misfit = misfit;
			this.sampleResults = new ArrayList<>(finish(round));
		}

		/**
		 * @return the detection {@link Detection#AUTO} chose for the movie, or null where it was given (or the method
		 *         does not choose)
		 */
		public DetectionChoice choice() {
			return choice;
		}

		/**
		 * @return a movie's results as they end: every spot flagged {@code NOT_CONVERGED} unless the rounds settled,
		 *         those found by the image whose light the profile does not describe flagged {@code MERGED}
		 *         ({@link Misfit}), each with the detection chosen
		 */
		List<FrameResult> finish(final List<FrameResult> results) {
			final List<FrameResult> flagged = RoundResults.flagged(results, settled);
			return chosen(misfit == null ? flagged : misfit.flagged(flagged), choice);
		}

		/** @return the tracker the movie's frames are refined with: {@code tracker}, with the chosen detection */
		ContactTracker tracker(final ContactTracker tracker) {
			return ProfileRounds.withChoice(tracker, choice);
		}

		/**
		 * @return the profile of each kind of particle every frame is refined with, or {@code null} when each frame
		 *         measures its own
		 */
		public KindProfiles profile() {
			return profile;
		}

		/** @return the sample frames (0-based, ascending) */
		public int[] sample() {
			return sample.clone();
		}

		/** @return the final result of sample frame {@code i} (of {@link #sample()}), flags included */
		public FrameResult sampleResult(final int i) {
			return sampleResults.get(i);
		}

		/** @return the frames of a movie of {@code count} frames that are not sample frames, ascending */
		public int[] others(final int count) {
			final boolean[] done = new boolean[count];
			for (final int t : sample)
				done[t] = true;
			final int[] rest = new int[count - sample.length];
			for (int t = 0, k = 0; t < count; t++)
				if (!done[t]) rest[k++] = t;
			return rest;
		}
	}

	/**
	 * Runs the {@link ProfileStage} of a movie (profile methods only), one thread per task of the caller's executor.
	 *
	 * @param count number of frames
	 * @param frame supplies frame {@code t} (thread-safe; read twice for the sample frames)
	 * @return the stage, or {@code null} when the method needs no profile
	 */
	public <T extends RealType<T>> ProfileStage profileStage(final int count,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final BooleanSupplier cancelled)
	{
		if (!tracker.parameters().method().needsProfile() || count == 0) return null;
		return profileStage(profileFrames(count, frame), frame, progress(null, 0), cancelled);
	}

	/**
	 * Localizes frames {@code indices} (not sample frames) with a movie's {@link ProfileStage}, exactly as
	 * {@link #track(int, IntFunction, boolean, ProgressListener, BooleanSupplier)} does them.
	 *
	 * @param stage the movie's stage, or {@code null} for a method that needs no profile
	 * @return one result per index, in that order, regions not kept
	 */
	public <T extends RealType<T>> List<FrameResult> trackWith(final ProfileStage stage, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final BooleanSupplier cancelled)
	{
		final Progress none = progress(null, 0);
		if (stage == null) return pass(tracker, null, indices, frame, false, none, cancelled);
		return stage.finish(pass(stage.tracker(tracker), stage.profile, indices, frame, false, none, cancelled));
	}

	/** @return the {@link ProfileStage} of a movie: the {@link ProfileRounds} on its {@code sample} frames */
	private <T extends RealType<T>> ProfileStage profileStage(final int[] sample,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final Progress progress,
		final BooleanSupplier cancelled)
	{
		final ProfileRounds.Outcome o = ProfileRounds.measure(tracker, sample, frame, progress, cancelled);
		return new ProfileStage(o.sample(), o.profile(), o.settled(), o.round(), o.choice(), o.misfit());
	}

	/** @return a run's progress, told to {@code listener} (null: to nobody) */
	private static Progress progress(final ProgressListener listener, final int total) {
		return new Progress(listener == null ? null : listener::progress, total);
	}

	/** At most this many frames, evenly spread over the stack, go into a profile measurement... */
	public static final int PROFILE_FRAMES = 64;
	/**
	 * ...and at most this many pixels in all: plenty for the profile's spline (15 frames of 512x512 with 12
	 * particles; the centres of the bench stack moved by 0.009 nm rms against 30 frames), and the profile rounds cost
	 * in proportion.
	 */
	public static final long PROFILE_PIXELS = 4_000_000;

	/**
	 * @return the frames the profile is measured on: evenly spread, within both limits (read: frame 0, for its size)
	 */
	private static <T extends RealType<T>> int[] profileFrames(final int count,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame)
	{
		final RandomAccessibleInterval<T> first = frame.apply(0);
		final long pixels = Math.max(1, first.dimension(0) * first.dimension(1));
		final int n = (int) Math.max(1, Math.min(Math.min(count, PROFILE_FRAMES), PROFILE_PIXELS / pixels));
		final int[] frames = new int[n];
		for (int i = 0; i < n; i++)
			frames[i] = (int) ((long) i * count / n);
		return frames;
	}

	/** @return all spots of {@code results}, in frame order */
	public static List<Localization> spots(final List<FrameResult> results) {
		return FrameResult.allSpots(results);
	}
}
