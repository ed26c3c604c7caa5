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
package io.github.contacttracker.pipeline;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.IntFunction;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.detect.OtherContrast;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;

/**
 * "Track a movie and write the outputs", the one way every front end runs Contact Tracker (command line, Fiji
 * command, batch scripts, TrackMate detector):
 * <ol>
 * <li>the output folders are checked, then the threshold against the data range (when the source asks for it),
 * frame by frame, before any tracking;</li>
 * <li>the frames are tracked on the caller's number of threads, with progress and cancellation;</li>
 * <li>{@code RADIUS} is set from the particle diameter where one was given;</li>
 * <li>the files are written all or none.</li>
 * </ol>
 * Bad input is an {@link InvalidInputException} with a one-line message; a cancelled run a
 * {@link java.util.concurrent.CancellationException}; nothing is written by a run that fails.
 */
public final class TrackingPipeline {

	private final SettingValues settings;
	private final TrackerParameters params;
	private final FrontEnd ui;

	/** @param settings the checked settings of the run, given on the command line (which names them in warnings) */
	public TrackingPipeline(final SettingValues settings) {
		this(settings, FrontEnd.COMMAND_LINE);
	}

	/**
	 * @param settings the checked settings of the run
	 * @param ui where the user gave the settings: the warnings name them as the user meets them there
	 */
	public TrackingPipeline(final SettingValues settings, final FrontEnd ui) {
		this.settings = settings;
		this.params = settings.parameters();
		this.ui = ui;
	}

	/** @return the settings */
	public SettingValues settings() {
		return settings;
	}

	/**
	 * Runs without files, one thread per processor, no progress: what previews, scripts and tests need.
	 *
	 * @param keepRegions whether to keep each spot's active areas (for overlays)
	 * @see #run(FrameSource, Outputs, int, boolean, StackTracker.ProgressListener, BooleanSupplier)
	 */
	public TrackingResult run(final FrameSource source, final boolean keepRegions) {
		try {
			return run(source, Outputs.NONE, 0, keepRegions, null, () -> false);
		}
		catch (final IOException e) {
			throw new AssertionError("no file is written", e);
		}
	}

	/**
	 * @param given the movie (inverted here for dark particles: {@link #frames})
	 * @param outputs the files to write ({@link Outputs#NONE} for none)
	 * @param threads worker threads (below 1: all processors)
	 * @param keepRegions whether to keep each spot's active areas (for overlays)
	 * @param progress progress, or {@code null}
	 * @param cancelled polled before each frame
	 * @return what was found
	 * @throws InvalidInputException for bad input (a missing output folder, a threshold outside the data, a
	 *         frame with NaN pixels), before anything is written
	 * @throws IOException when writing a file fails (none is left behind)
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public TrackingResult run(final FrameSource given, final Outputs outputs, final int threads,
		final boolean keepRegions, final StackTracker.ProgressListener progress, final BooleanSupplier cancelled)
		throws IOException
	{
		final long start = System.nanoTime();
		outputs.check();
		final FrameSource source = frames(given);
		checkThreshold(source);
		final StackTracker tracker = new StackTracker(params);
		final IntFunction<RandomAccessibleInterval> frame = source::frame; // raw: the pixel type varies by source
		@SuppressWarnings("unchecked")
		final List<FrameResult> frames = StackTracker.withThreads(threads, () -> tracker.track(source.frameCount(),
			(IntFunction) frame, keepRegions, progress, cancelled));
		return finish(frames, source.calibration(), outputs, start, frames.isEmpty() ? 0 : otherContrast(source, frames
			.get(0)));
	}

	/**
	 * @param source the frames as the run tracks them ({@link #frames})
	 * @param result the run's result on the first of them
	 * @return how many blobs of the contrast the run did not track stand out on the first frame as its particles do,
	 *         away from them ({@link OtherContrast}); 0 where the diameter is not known
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public int otherContrast(final FrameSource source, final FrameResult result) {
		final double d = settings.diameter();
		if (source.frameCount() == 0 || !(d > 0)) return 0;
		final RandomAccessibleInterval first = source.frame(0); // raw: the pixel type varies by source
		final Plane plane = Plane.of(first);
		final List<Localization> spots = result.spots();
		final double[] x = new double[spots.size()], y = new double[spots.size()];
		for (int k = 0; k < x.length; k++) {
			x[k] = spots.get(k).x() - plane.minX();
			y[k] = spots.get(k).y() - plane.minY();
		}
		return OtherContrast.blobs(plane, Plane.of((RandomAccessibleInterval) Inversion.of(first)), x, y, d);
	}

	/**
	 * @return the frames as the tracker sees them: inverted for dark particles ({@link SettingValues#dark()}), as
	 *         they are for bright ones; the threshold is checked against these
	 */
	public FrameSource frames(final FrameSource source) {
		return settings.dark() ? source.inverted() : source;
	}

	/**
	 * The end of every run, also of one whose frames were tracked elsewhere (the Spark job's tasks): {@code RADIUS}
	 * set from the diameter, the files written all or none, the spots counted.
	 *
	 * @param frames one result per frame, in frame order
	 * @param calibration the movie's calibration (positions in its units)
	 * @param outputs the files to write
	 * @param startNanos {@link System#nanoTime()} when the run began
	 * @param otherContrast how many blobs of the contrast not tracked stand out on the first frame
	 *        ({@link #otherContrast})
	 * @throws IOException when writing a file fails (none is left behind)
	 */
	public TrackingResult finish(final List<FrameResult> frames, final Calibration calibration,
		final Outputs outputs, final long startNanos, final int otherContrast) throws IOException
	{
		final List<Localization> spots = withDiameter(StackTracker.spots(frames));
		outputs.write(spots, calibration, settings);
		int flagged = 0, discarded = 0, ownProfile = 0;
		for (final Localization s : spots)
			if (s.isFlagged()) flagged++;
		for (final FrameResult r : frames) {
			discarded += r.discarded();
			if (r.ownProfile()) ownProfile++;
		}
		final List<String> warnings = new ArrayList<>();
		if (ownProfile > 0 && frames.size() > 1) warnings.add("the particles' profile could not be measured over the " +
			"movie (too few isolated, unflagged particles); " + ownProfile + " frames measured their own, which is " +
			"less precise");
		final DetectionChoice choice = frames.isEmpty() ? null : frames.get(0).detection();
		final TrackerParameters used = choice == null ? params : params.withDetection(choice.detection());
		final String most = FlagAdvice.of(spots, used, ui);
		if (most != null) warnings.add(most);
		final String none = FlagAdvice.nothingFound(spots.size(), frames.size(), discarded, used, settings.dark(), ui);
		if (none != null) warnings.add(none);
		final String other = FlagAdvice.otherContrast(otherContrast, frames.isEmpty() ? 0 : frames.get(0).spots().size(),
			settings.dark(), ui);
		if (other != null) warnings.add(other);
		return new TrackingResult(frames, spots, flagged, discarded, (System.nanoTime() - startNanos) * 1e-9, List
			.copyOf(warnings), detection(frames));
	}

	/**
	 * @return what the detection {@code auto} chose for the movie and why, with the setting that overrides it in
	 *         this front end's terms; empty where it was given, or the threshold was kept because its components are
	 *         single particles (the run is then as it always was)
	 */
	private String detection(final List<FrameResult> frames) {
		final DetectionChoice choice = frames.isEmpty() ? null : frames.get(0).detection();
		if (choice == null || choice.said().isEmpty()) return "";
		final String other = choice.detection() == Detection.IMAGE ? TrackingSettings.BY_THRESHOLD
			: TrackingSettings.IMAGE;
		return choice.said() + " (to override, " + ui.set(TrackingSettings.DETECTION, other) + ")";
	}

	/**
	 * Refuses a threshold outside the data before any tracking, without holding the movie: frames are scanned one
	 * at a time until one has been seen whose values reach across the threshold from both sides (usually the
	 * first frame), so a valid threshold costs one frame's read, and a threshold outside the data is refused after
	 * one read-only pass, before anything is tracked or written. A NaN or infinite pixel in the frames scanned is
	 * refused here; one in a later frame by the tracker, naming its frame.
	 *
	 * @throws InvalidInputException naming the threshold, the data range and the movie
	 */
	public void checkThreshold(final FrameSource source) {
		if (!source.checksDataRange()) return;
		final double t = params.threshold();
		double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
		for (int i = 0; i < source.frameCount(); i++) {
			final double[] range = source.frameRange(i);
			min = Math.min(min, range[0]);
			max = Math.max(max, range[1]);
			if (t >= min && t <= max) return;
		}
		throw new InvalidInputException(String.format(Locale.ROOT, "threshold %s is outside the data range [%s, %s] " +
			"of '%s'", Numbers.fmt(t), Numbers.fmt(min), Numbers.fmt(max), source.name()));
	}

	/**
	 * @return the spots, their radius set from the particle diameter when one was given: half of it, each kind its
	 *         own when several were found ({@link KindRadii})
	 */
	private List<Localization> withDiameter(final List<Localization> spots) {
		final double diameter = settings.diameter();
		if (diameter <= 0) return spots;
		final double[] radius = KindRadii.of(spots, diameter);
		final List<Localization> out = new ArrayList<>(spots.size());
		for (final Localization s : spots)
			out.add(s.withRadius(radius[s.kind()]));
		return out;
	}

}
