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
	 * @param listener progress, or null (for deblend and fit the stack is passed over three times, and the
	 *        progress counts all three)
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
		if (!params.method().needsProfile() || count == 0)
			return pass(tracker, null, count, frame, keepRegions, listener, cancelled, 0, count);
		// deblend and fit: iterative centres first, then the profile measured over the stack (re-measured once
		// around the refined centres), then the method with that profile.
		final int total = count * (1 + PROFILE_ROUNDS);
		List<FrameResult> results = pass(new ContactTracker(params.withMethod(Method.ITERATIVE)), null, count, frame,
			false, listener, cancelled, 0, total);
		for (int round = 0; round < PROFILE_ROUNDS; round++) {
			final EmpiricalProfile profile = profile(results, frame, params.rOut());
			results = pass(tracker, profile, count, frame, keepRegions && round == PROFILE_ROUNDS - 1, listener,
				cancelled, count * (1 + round), total);
		}
		return results;
	}

	/** Rounds of profile measurement and refinement for deblend and fit. */
	public static final int PROFILE_ROUNDS = 2;
	/** At most this many frames, evenly spread over the stack, go into a profile measurement... */
	public static final int PROFILE_FRAMES = 64;
	/** ...and no more once this many pixels within reach of a particle are in (plenty for the spline). */
	public static final int PROFILE_SAMPLES = 4_000_000;

	/**
	 * Measures the radial profile over up to {@link #PROFILE_FRAMES} frames; null (each frame then measures its
	 * own) when the stack holds too few usable pixels.
	 */
	private static <T extends RealType<T>> EmpiricalProfile profile(final List<FrameResult> results,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final double rOut)
	{
		final ProfileEstimator estimator = ProfileEstimator.forROut(rOut);
		final int step = Math.max(1, (int) Math.ceil(results.size() / (double) PROFILE_FRAMES));
		for (int t = 0; t < results.size() && estimator.profileSamples() < PROFILE_SAMPLES; t += step)
			estimator.add(frame.apply(t), results.get(t).spots());
		try {
			return estimator.estimate();
		}
		catch (final IllegalStateException e) {
			return null;
		}
	}

	private <T extends RealType<T>> List<FrameResult> pass(final ContactTracker tracker,
		final EmpiricalProfile profile, final int count, final IntFunction<? extends RandomAccessibleInterval<T>> frame,
		final boolean keepRegions, final ProgressListener listener, final BooleanSupplier cancelled,
		final int doneBefore, final int total)
	{
		final AtomicInteger done = new AtomicInteger(doneBefore);
		final List<FrameResult> results = new ArrayList<>(count);
		if (threads == 1 || count < 2) {
			for (int t = 0; t < count; t++) {
				if (cancelled.getAsBoolean()) throw new CancellationException("cancelled after " + t + " frames");
				results.add(one(tracker, profile, frame, t, keepRegions));
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
				final int index = t;
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
