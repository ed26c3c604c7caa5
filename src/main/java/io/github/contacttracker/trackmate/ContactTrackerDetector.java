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
package io.github.contacttracker.trackmate;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.TrackingSettings;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.settings.TrackMateSettings;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;

import org.scijava.Cancelable;

import fiji.plugin.trackmate.Logger;
import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.SpotCollection;
import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.algorithm.MultiThreaded;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;
import net.imglib2.view.Views;

/**
 * Runs Contact Tracker on a whole TrackMate movie at once, as a TrackMate 8 {@code SpotGlobalDetector}: TrackMate
 * calls {@link #checkInput()}, {@link #process()}, {@link #getResult()}, and {@link #getErrorMessage()} when one of
 * them returned {@code false}.
 * <p>
 * Whole-movie detection is what makes TrackMate's spots equal to the command line's: the {@code deblend} and
 * {@code fit} methods measure the particles' profile over frames spread through the movie, exactly as
 * {@link TrackingPipeline} does for every other front end. (A per-frame detector would measure it on each frame
 * alone and give other numbers.)
 * <p>
 * TrackMate hands over the WHOLE image (all channels and frames) and the interval to analyse: X, Y, Z (if the
 * image has it) and time, without a channel axis. The detector takes out the target channel and every frame of
 * the interval's time range itself. Images with more than one Z slice are refused in {@link #checkInput()}.
 * <p>
 * Spots are in TrackMate's convention: physical units, whole-image coordinates, pixel centre at
 * {@code index * pixel size}, {@code z = 0}; {@code FRAME} is the movie's frame index. See
 * {@link #toSpot(Localization, double, double)} for the values.
 */
public final class ContactTrackerDetector<T extends RealType<T> & NativeType<T>> implements SpotGlobalDetector<T>,
	MultiThreaded, Cancelable
{
	private final ImgPlus<T> img;
	private final Interval interval;
	private final SettingValues settings;
	private final int targetChannel;
	private final String settingsError;

	private final List<RandomAccessibleInterval<T>> frames = new ArrayList<>();
	private int firstFrame;
	private double dx;
	private double dy;
	private SpotCollection result = new SpotCollection();
	private String errorMessage;
	private long processingTime;
	private int numThreads = Runtime.getRuntime().availableProcessors();
	private Logger logger;
	private volatile String cancelReason;

	/**
	 * @param img the whole image, as TrackMate gives it (X, Y and optionally channel, Z of size 1 and time axes)
	 * @param interval the region to analyse as TrackMate gives it (the image's axes without channel, time
	 *        included), or one with every axis of the image; {@code null} for the whole movie
	 * @param settings a Contact Tracker settings map ({@link TrackMateSettings}); invalid settings make
	 *        {@link #checkInput()} fail with their message
	 */
	public ContactTrackerDetector(final ImgPlus<T> img, final Interval interval, final Map<String, Object> settings) {
		this.img = img;
		this.interval = interval;
		this.settingsError = TrackMateSettings.check(settings);
		this.settings = settingsError == null ? TrackMateSettings.values(settings) : null;
		this.targetChannel = settingsError == null ? this.settings.channel() : 0;
	}

	@Override
	public boolean checkInput() {
		frames.clear();
		if (settingsError != null) return fail("Invalid Contact Tracker settings:\n" + settingsError);
		if (img == null) return fail("Contact Tracker: no image given.");
		final int n = img.numDimensions();
		final int xd = img.dimensionIndex(Axes.X);
		final int yd = img.dimensionIndex(Axes.Y);
		final int zd = img.dimensionIndex(Axes.Z);
		final int cd = img.dimensionIndex(Axes.CHANNEL);
		final int td = img.dimensionIndex(Axes.TIME);
		if (xd < 0 || yd < 0) return fail("Contact Tracker: the image has no X or no Y axis.");
		if (zd >= 0 && img.dimension(zd) > 1)
			return fail("Contact Tracker works on 2D images and 2D time-lapses, but this image has " +
				img.dimension(zd) + " Z slices. If the slices are time points, swap Z and T with " +
				"Image > Hyperstacks > Re-order Hyperstacks; otherwise project the stack to 2D first.");
		for (int d = 0; d < n; d++)
			if (d != xd && d != yd && d != zd && d != cd && d != td && img.dimension(d) > 1)
				return fail("Contact Tracker: the image has an axis of unknown type (dimension " + d + ", size " +
					img.dimension(d) + "); only X, Y, channel, time and a single Z slice are supported.");
		final long channels = cd < 0 ? 1 : img.dimension(cd);
		if (targetChannel > channels)
			return fail("Contact Tracker: TARGET_CHANNEL is " + targetChannel + " but the image has " + channels +
				(channels == 1 ? " channel." : " channels."));
		dx = img.averageScale(xd);
		dy = img.averageScale(yd);
		if (!(dx > 0) || !(dy > 0) || !Double.isFinite(dx) || !Double.isFinite(dy))
			return fail("Contact Tracker: the pixel size must be positive, not " + dx + " x " + dy + ".");

		// the crop and the frames, in whole-image indices
		final long[] xr = { img.min(xd), img.max(xd) };
		final long[] yr = { img.min(yd), img.max(yd) };
		final long[] tr = td < 0 ? new long[] { 0, 0 } : new long[] { img.min(td), img.max(td) };
		if (interval != null) {
			final boolean channelDropped = cd >= 0 && interval.numDimensions() == n - 1;
			if (!channelDropped && interval.numDimensions() != n)
				return fail("Contact Tracker: the detection interval has " + interval.numDimensions() +
					" dimensions, but the image has " + n + (cd < 0 ? "." : " (" + (n - 1) + " without channel)."));
			clip(xr, interval, intervalIndex(xd, cd, channelDropped));
			clip(yr, interval, intervalIndex(yd, cd, channelDropped));
			if (td >= 0) clip(tr, interval, intervalIndex(td, cd, channelDropped));
			if (xr[0] > xr[1] || yr[0] > yr[1] || tr[0] > tr[1])
				return fail("Contact Tracker: the detection interval does not overlap the image.");
		}
		firstFrame = (int) (tr[0] - (td < 0 ? 0 : img.min(td)));
		for (long t = tr[0]; t <= tr[1]; t++)
			frames.add(plane(n, xd, yd, cd, td, t, xr, yr));
		errorMessage = null;
		return true;
	}

	/** One 2D plane: every axis but X and Y sliced off, highest dimension first so indices stay valid. */
	private RandomAccessibleInterval<T> plane(final int n, final int xd, final int yd, final int cd, final int td,
		final long t, final long[] xr, final long[] yr)
	{
		RandomAccessibleInterval<T> view = img;
		for (int d = n - 1; d >= 0; d--) {
			if (d == xd || d == yd) continue;
			final long pos = d == td ? t : d == cd ? img.min(d) + targetChannel - 1 : img.min(d);
			view = Views.hyperSlice(view, d, pos);
		}
		if (yd < xd) view = Views.permute(view, 0, 1);
		return Views.interval(view, new long[] { xr[0], yr[0] }, new long[] { xr[1], yr[1] });
	}

	private static int intervalIndex(final int d, final int cd, final boolean channelDropped) {
		return channelDropped && cd < d ? d - 1 : d;
	}

	private static void clip(final long[] range, final Interval interval, final int d) {
		range[0] = Math.max(range[0], interval.min(d));
		range[1] = Math.min(range[1], interval.max(d));
	}

	@Override
	public boolean process() {
		final long start = System.currentTimeMillis();
		if (frames.isEmpty() && !checkInput()) return false;
		final int count = frames.size();
		final TrackingResult found;
		try {
			status("Contact Tracker: " + settings.get(TrackingSettings.METHOD) + " on " + count + (count == 1 ? " frame" :
				" frames"));
			found = new TrackingPipeline(settings, FrontEnd.TRACKMATE).run(source(), Outputs.NONE, numThreads, false, (done,
				total) -> progress((double) done / total), this::isCanceled);
		}
		catch (final CancellationException e) {
			return fail("Contact Tracker: detection cancelled" + (cancelReason == null ? "." : ": " + cancelReason));
		}
		catch (final InvalidInputException e) {
			// the core counts frames from 1 within what it was given; say where that starts in the movie
			return fail("Contact Tracker failed: " + e.getMessage() + (firstFrame == 0 ? "" : " (frames counted from " +
				"frame " + (firstFrame + 1) + " of the movie, the first one analysed)"));
		}
		catch (final UncheckedIOException e) {
			// a frame of a movie on disk (a virtual stack) that cannot be read: its reader's one line, no stack trace
			return fail("Contact Tracker failed: " + InvalidInputException.oneLine(e.getCause().getMessage()));
		}
		catch (final OutOfMemoryError e) {
			return fail("Contact Tracker: out of memory (" + InvalidInputException.oneLine(e.getMessage()) + "): give " +
				"Fiji more with Edit > Options > Memory & Threads, or use fewer threads");
		}
		catch (final IOException e) {
			throw new AssertionError("no file is written", e);
		}
		finally {
			status("");
		}
		if (logger != null) logger.log("Contact Tracker: " + found.summary(img.getName()) + "\n");
		// the pipeline's spots (RADIUS from the diameter where given), by frame of the analysed range
		final List<List<Spot>> byFrame = new ArrayList<>(count);
		for (int i = 0; i < count; i++)
			byFrame.add(new ArrayList<>());
		for (final Localization loc : found.spots())
			byFrame.get(loc.frame()).add(toSpot(loc.withFrame(firstFrame + loc.frame()), dx, dy));
		final SpotCollection spots = new SpotCollection();
		for (int i = 0; i < count; i++)
			spots.put(firstFrame + i, byFrame.get(i));
		result = spots;
		processingTime = System.currentTimeMillis() - start;
		return true;
	}

	/** @return the spots of the last successful {@link #process()}, by frame */
	@Override
	public SpotCollection getResult() {
		return result;
	}

	@Override
	public String getErrorMessage() {
		return errorMessage;
	}

	@Override
	public long getProcessingTime() {
		return processingTime;
	}

	@Override
	public void setLogger(final Logger logger) {
		this.logger = logger;
	}

	@Override
	public void setNumThreads() {
		numThreads = Runtime.getRuntime().availableProcessors();
	}

	@Override
	public void setNumThreads(final int numThreads) {
		this.numThreads = Math.max(1, numThreads);
	}

	@Override
	public int getNumThreads() {
		return numThreads;
	}

	@Override
	public boolean isCanceled() {
		return cancelReason != null;
	}

	@Override
	public void cancel(final String reason) {
		cancelReason = reason == null ? "cancelled" : reason;
	}

	@Override
	public String getCancelReason() {
		return cancelReason;
	}

	/** The frames to analyse as the pipeline reads them: views of the image, in pixel units. */
	private FrameSource source() {
		return FrameSource.of(frames.size(), frames::get, Calibration.PIXELS, img.getName(), null);
	}

	/**
	 * Converts a localization (pixels) into a TrackMate spot (physical units), with the same numbers as every
	 * other output through {@link SpotColumn}: {@code POSITION_X/Y}, {@code RADIUS}, {@code QUALITY} and every
	 * extra column (first-pass position, areas, solves, standard errors, flags as 0/1) as a spot feature, and the
	 * standard errors in thousandths of a pixel too ({@link ContactTrackerSpotFeatures#SIGMA_X_MPX}), NaN where
	 * undefined (so every spot has every declared feature; TrackMate saves and reloads NaN).
	 * {@code FRAME} and {@code VISIBILITY} are TrackMate's to set.
	 *
	 * @param loc the localization, in whole-image pixel indices
	 * @param pixelWidth pixel size along x
	 * @param pixelHeight pixel size along y
	 * @return a new spot with our extra features attached
	 */
	public static Spot toSpot(final Localization loc, final double pixelWidth, final double pixelHeight) {
		final Calibration cal = new Calibration(pixelWidth, pixelHeight, null, 1, null);
		final Spot spot = new Spot(SpotColumn.POSITION_X.value(loc, 0, cal), SpotColumn.POSITION_Y.value(loc, 0, cal),
			0, SpotColumn.RADIUS.value(loc, 0, cal), SpotColumn.QUALITY.value(loc, 0, cal));
		for (final SpotColumn c : SpotColumn.values())
			if (!c.isTrackMateKey()) spot.putFeature(c.key(), c.value(loc, 0, cal));
		spot.putFeature(ContactTrackerSpotFeatures.SIGMA_X_MPX, loc.sigmaX() * ContactTrackerSpotFeatures.MPX_PER_PX);
		spot.putFeature(ContactTrackerSpotFeatures.SIGMA_Y_MPX, loc.sigmaY() * ContactTrackerSpotFeatures.MPX_PER_PX);
		return spot;
	}

	private void status(final String status) {
		if (logger != null) logger.setStatus(status);
	}

	private void progress(final double fraction) {
		if (logger != null) logger.setProgress(fraction);
	}

	private boolean fail(final String message) {
		errorMessage = message;
		frames.clear();
		return false;
	}
}
