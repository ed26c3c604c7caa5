package io.github.contacttracker.core;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.function.IntFunction;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Localizes every frame of a time series, frames in parallel. Results come back in frame order whatever the
 * number of threads, so a run is reproducible.
 */
public final class StackTracker {

	/** Hears about progress; called from worker threads. */
	@FunctionalInterface
	public interface ProgressListener {
		/** @param framesDone frames finished so far, of {@code frames} */
		void progress(int framesDone, int frames);
	}

	private final ContactTracker tracker;
	private final int threads;

	/**
	 * @param params the localizer's parameters
	 * @param threads worker threads (1 for serial; values below 1 mean all available processors)
	 */
	public StackTracker(final TrackerParameters params, final int threads) {
		this.tracker = new ContactTracker(params);
		this.threads = threads < 1 ? Runtime.getRuntime().availableProcessors() : threads;
	}

	/** @return the number of worker threads */
	public int threads() {
		return threads;
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
	 * @param frame supplies frame {@code t}, 2D
	 * @param keepRegions whether to keep the active and second areas (for overlays; costs memory)
	 * @param listener progress, or null (for deblend and fit the progress also counts the iterative pass over
	 *        all frames and the refinement of the frames the profile is measured on)
	 * @param cancelled polled between frames; when it turns true the run stops with a
	 *        {@link CancellationException}
	 * @return one result per frame, in frame order
	 * @throws IllegalArgumentException if a frame is not 2D or holds NaN/infinite pixels (naming the frame)
	 */
	public <T extends RealType<T>> List<FrameResult> track(final int count,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final boolean keepRegions,
		final ProgressListener listener, final BooleanSupplier cancelled)
	{
		final TrackerParameters params = tracker.parameters();
		final int[] all = range(count);
		if (!params.method().needsProfile() || count == 0)
			return pass(tracker, null, all, frame, keepRegions, listener, cancelled, 0, count);
		// deblend and fit: iterative centres first; the profile measured on a spread of frames; those frames
		// refined with it and the profile measured again around the refined centres; then every frame.
		final int[] sample = profileFrames(count, frame);
		final int total = 2 * count + sample.length;
		final List<FrameResult> iterative = pass(new ContactTracker(params.withMethod(Method.ITERATIVE)), null, all,
			frame, false, listener, cancelled, 0, total);
		final List<FrameResult> firstRound = pass(tracker, profile(pick(iterative, sample), sample, frame, params
			.rOut()), sample, frame, false, listener, cancelled, count, total);
		return pass(tracker, profile(firstRound, sample, frame, params.rOut()), all, frame, keepRegions, listener,
			cancelled, count + sample.length, total);
	}

	/** At most this many frames, evenly spread over the stack, go into a profile measurement... */
	public static final int PROFILE_FRAMES = 64;
	/** ...and at most this many pixels in all (plenty for the profile's spline). */
	public static final long PROFILE_PIXELS = 8_000_000;

	/** The frames the profile is measured on: evenly spread, within both limits. */
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

	private static int[] range(final int count) {
		final int[] r = new int[count];
		for (int i = 0; i < count; i++)
			r[i] = i;
		return r;
	}

	private static List<FrameResult> pick(final List<FrameResult> results, final int[] indices) {
		final List<FrameResult> picked = new ArrayList<>(indices.length);
		for (final int t : indices)
			picked.add(results.get(t));
		return picked;
	}

	/**
	 * Measures the radial profile on frames {@code indices} (with their results, in the same order), the frames
	 * shared among the threads; null (each frame then measures its own) when they hold too few usable pixels.
	 */
	private <T extends RealType<T>> EmpiricalProfile profile(final List<FrameResult> results, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final double rOut)
	{
		// One estimator per frame, merged in frame order: the sums, and so the results, do not depend on the
		// number of threads.
		final int workers = Math.min(threads, indices.length);
		final ProfileEstimator[] parts = new ProfileEstimator[indices.length];
		final AtomicInteger next = new AtomicInteger();
		final Runnable work = () -> {
			for (int i = next.getAndIncrement(); i < indices.length; i = next.getAndIncrement()) {
				final ProfileEstimator part = ProfileEstimator.forROut(rOut);
				part.add(frame.apply(indices[i]), results.get(i).spots());
				parts[i] = part;
			}
		};
		final List<Thread> running = new ArrayList<>();
		for (int w = 1; w < workers; w++) {
			final Thread th = new Thread(work, "contact-tracker-profile");
			th.setDaemon(true);
			running.add(th);
			th.start();
		}
		work.run();
		try {
			for (final Thread th : running)
				th.join();
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new CancellationException("interrupted");
		}
		final ProfileEstimator all = parts[0];
		for (int i = 1; i < parts.length; i++)
			all.merge(parts[i]);
		try {
			return all.estimate();
		}
		catch (final IllegalStateException e) {
			return null;
		}
	}

	/** Localizes frames {@code indices}; results in that order. */
	private <T extends RealType<T>> List<FrameResult> pass(final ContactTracker tracker,
		final EmpiricalProfile profile, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final boolean keepRegions,
		final ProgressListener listener, final BooleanSupplier cancelled, final int doneBefore, final int total)
	{
		final int count = indices.length;
		final AtomicInteger done = new AtomicInteger(doneBefore);
		final List<FrameResult> results = new ArrayList<>(count);
		if (threads == 1 || count < 2) {
			for (int t = 0; t < count; t++) {
				if (cancelled.getAsBoolean()) throw new CancellationException("cancelled after " + t + " frames");
				results.add(one(tracker, profile, frame, indices[t], keepRegions));
				if (listener != null) listener.progress(done.incrementAndGet(), total);
			}
			return results;
		}
		final ExecutorService pool = Executors.newFixedThreadPool(Math.min(threads, count), r -> {
			final Thread th = new Thread(r, "contact-tracker");
			th.setDaemon(true);
			return th;
		});
		try {
			final List<Future<FrameResult>> futures = new ArrayList<>(count);
			for (int t = 0; t < count; t++) {
				final int index = indices[t];
				futures.add(pool.submit(() -> {
					if (cancelled.getAsBoolean()) throw new CancellationException("cancelled");
					final FrameResult r = one(tracker, profile, frame, index, keepRegions);
					if (listener != null) listener.progress(done.incrementAndGet(), total);
					return r;
				}));
			}
			for (final Future<FrameResult> f : futures)
				results.add(f.get());
			return results;
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new CancellationException("interrupted");
		}
		catch (final ExecutionException e) {
			final Throwable cause = e.getCause();
			if (cause instanceof RuntimeException) throw (RuntimeException) cause;
			if (cause instanceof Error) throw (Error) cause;
			throw new IllegalStateException(cause);
		}
		finally {
			pool.shutdownNow();
		}
	}

	private static <T extends RealType<T>> FrameResult one(final ContactTracker tracker,
		final EmpiricalProfile profile, final IntFunction<? extends RandomAccessibleInterval<T>> frame, final int t,
		final boolean keepRegions)
	{
		try {
			return tracker.analyse(Plane.of(frame.apply(t)), t, keepRegions, profile);
		}
		catch (final IllegalArgumentException e) {
			throw new IllegalArgumentException("frame " + (t + 1) + ": " + e.getMessage(), e);
		}
	}

	/** @return all spots of {@code results}, in frame order */
	public static List<Localization> spots(final List<FrameResult> results) {
		final List<Localization> all = new ArrayList<>();
		for (final FrameResult r : results)
			all.addAll(r.spots());
		return all;
	}
}
