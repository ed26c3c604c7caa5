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

import io.github.contacttracker.settings.TrackMateSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import fiji.plugin.trackmate.Logger;
import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.SpotCollection;
import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import fiji.plugin.trackmate.detection.SpotGlobalDetectorFactory;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.FinalInterval;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.algorithm.MultiThreaded;
import net.imglib2.img.ImgView;
import net.imglib2.position.FunctionRandomAccessible;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.view.Views;

/**
 * The detector driven the way TrackMate 8 drives a global detector ({@code TrackMate.processGlobal}):
 * {@code factory.getDetector(img, settings, interval)} on the WHOLE calibrated image with TrackMate's interval
 * (the image's axes without channel, time included), then {@code setLogger}, {@code setNumThreads},
 * {@code checkInput()}, {@code process()}, {@code getResult()}, and {@code getErrorMessage()} on failure. Its
 * spots must be the core's localizations times the calibration, filed under the movie's frame numbers.
 */
class ContactTrackerDetectorTest {

	private static final double DX = 0.1, DY = 0.2, DT = 0.5; // anisotropic, to catch x/y mix-ups

	private final SpotGlobalDetectorFactory<FloatType> factory = new ContactTrackerDetectorFactory<>();

	/** What TrackMate does; fails the test with TrackMate's error message when the detector fails. */
	private SpotCollection detect(final ImgPlus<FloatType> img, final Map<String, Object> settings,
		final Interval interval)
	{
		assertNull(factory.checkSettings(settings));
		final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, settings, interval);
		((MultiThreaded) detector).setNumThreads(2);
		final boolean ok = detector.checkInput() && detector.process();
		assertTrue(ok, () -> detector.getErrorMessage());
		return detector.getResult();
	}

	/**
	 * The interval TrackMate builds for a global detector ({@code TMUtils.getIntervalWithTime}): every axis of
	 * the image but the channel, time limited to {@code [tstart, tend]}.
	 */
	static Interval trackMateInterval(final ImgPlus<?> img, final long tstart, final long tend) {
		final List<long[]> ranges = new ArrayList<>();
		for (int d = 0; d < img.numDimensions(); d++) {
			if (d == img.dimensionIndex(Axes.CHANNEL)) continue;
			if (d == img.dimensionIndex(Axes.TIME)) ranges.add(new long[] { tstart, tend });
			else ranges.add(new long[] { img.min(d), img.max(d) });
		}
		final long[] min = new long[ranges.size()], max = new long[ranges.size()];
		for (int i = 0; i < min.length; i++) {
			min[i] = ranges.get(i)[0];
			max[i] = ranges.get(i)[1];
		}
		return new FinalInterval(min, max);
	}

	private static Interval wholeMovie(final ImgPlus<?> img) {
		final int td = img.dimensionIndex(Axes.TIME);
		return trackMateInterval(img, 0, td < 0 ? 0 : img.max(td));
	}

	private static ImgPlus<FloatType> imgPlus(final ArrayImg<FloatType, FloatArray> img, final AxisType... axes) {
		final double[] cal = new double[axes.length];
		for (int d = 0; d < axes.length; d++)
			cal[d] = axes[d] == Axes.X ? DX : axes[d] == Axes.Y ? DY : axes[d] == Axes.TIME ? DT : 1;
		return new ImgPlus<>(img, "test", axes, cal);
	}

	/** The spots of one frame, sorted as the core sorts its localizations (by ID, i.e. creation order). */
	private static List<Spot> spotsOf(final SpotCollection spots, final int frame) {
		final List<Spot> list = new ArrayList<>();
		final Iterable<Spot> it = spots.iterable(frame, false);
		if (it != null) it.forEach(list::add);
		list.sort(Comparator.naturalOrder());
		return list;
	}

	/** Asserts the spots are exactly the localizations scaled by the calibration, in the same order. */
	private static void assertSpotsEqualCoreTimesCalibration(final List<Localization> expected, final List<Spot> spots,
		final int frame)
	{
		assertEquals(expected.size(), spots.size(), "spots in frame " + frame);
		for (int i = 0; i < spots.size(); i++) {
			final Localization l = expected.get(i);
			final Spot s = spots.get(i);
			assertEquals(l.x() * DX, s.getFeature(Spot.POSITION_X), 0, "x of spot " + i);
			assertEquals(l.y() * DY, s.getFeature(Spot.POSITION_Y), 0, "y of spot " + i);
			assertEquals(0, s.getFeature(Spot.POSITION_Z), 0);
			assertEquals(frame, s.getFeature(Spot.FRAME), 0, "FRAME is the movie's frame number");
			assertEquals(l.radius() * Math.sqrt(DX * DY), s.getFeature(Spot.RADIUS), 1e-12);
			assertEquals(l.quality(), s.getFeature(Spot.QUALITY), 0);
			assertEquals(l.firstX() * DX, s.getFeature(SpotColumn.FIRST_PASS_X.key()), 0);
			assertEquals(l.firstY() * DY, s.getFeature(SpotColumn.FIRST_PASS_Y.key()), 0);
			assertEquals(l.sigmaX() * DX, s.getFeature(SpotColumn.SIGMA_X.key()), 0);
			assertEquals(l.sigmaX() * 1000, s.getFeature(ContactTrackerSpotFeatures.SIGMA_X_MPX), 0,
				"in thousandths of a pixel too");
			assertEquals(l.sigmaY() * 1000, s.getFeature(ContactTrackerSpotFeatures.SIGMA_Y_MPX), 0);
			// as TrackMate's spot table shows it (java.text.DecimalFormat's default: 3 decimals), to 1 part in 100
			final double mpx = s.getFeature(ContactTrackerSpotFeatures.SIGMA_X_MPX);
			if (Double.isFinite(mpx) && mpx > 0) assertEquals(mpx, Double.parseDouble(new java.text.DecimalFormat("0.###",
				java.text.DecimalFormatSymbols.getInstance(java.util.Locale.ROOT)).format(mpx)), mpx / 100, "readable");
			assertEquals(l.activeArea(), s.getFeature(SpotColumn.ACTIVE_AREA.key()), 0);
			assertEquals(l.secondArea(), s.getFeature(SpotColumn.SECOND_AREA.key()), 0);
			assertEquals(l.has(Flag.SECOND_PASS) ? 1 : 0, s.getFeature(SpotColumn.FLAG_SECOND_PASS.key()), 0);
			assertEquals(l.kind(), s.getFeature(SpotColumn.KIND.key()), 0);
		}
	}

	/** A spot's kind is an integer spot feature TrackMate declares, shows and saves like the flags. */
	@Test
	void theKindIsAnIntegerSpotFeature() {
		final Localization l = new Localization(3, 10, 20, 10.5, 20.5, 40, 40, 1, 3.6, 0, 2, 0.01, 0.02, Double.NaN,
			Double.NaN, 0);
		assertEquals(0, ContactTrackerDetector.toSpot(l, DX, DY).getFeature(SpotColumn.KIND.key()), 0,
			"not classified");
		assertEquals(2, ContactTrackerDetector.toSpot(l.withKind(2), DX, DY).getFeature(SpotColumn.KIND.key()), 0);
		final ContactTrackerSpotFeatures<FloatType> features = new ContactTrackerSpotFeatures<>();
		assertTrue(features.getFeatures().contains("KIND"));
		assertTrue(features.getIsIntFeature().get("KIND"));
		assertEquals("Kind", features.getFeatureShortNames().get("KIND"));
		assertEquals(fiji.plugin.trackmate.Dimension.NONE, features.getFeatureDimensions().get("KIND"));
	}

	private static List<Localization> core(final RandomAccessibleInterval<FloatType> plane, final int frame) {
		return new ContactTracker(TestImages.params()).track(plane, frame);
	}

	/**
	 * Dark particles: a 32-bit frame of the particles negated (darker than the background) with {@code PARTICLES =
	 * dark} gives exactly the spots of the bright frame; without it, none of them.
	 */
	@Test
	void darkParticlesGiveTheSpotsOfTheBrightFrame() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ArrayImg<FloatType, FloatArray> dark = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final float[] px = dark.update(null).getCurrentStorageArray();
		for (int i = 0; i < px.length; i++)
			px[i] = -px[i];
		final Map<String, Object> settings = TestImages.settings(1);
		settings.put("PARTICLES", "dark");
		final ImgPlus<FloatType> img = imgPlus(dark, Axes.X, Axes.Y);
		assertSpotsEqualCoreTimesCalibration(core(raw, 0), spotsOf(detect(img, settings, wholeMovie(img)), 0), 0);
		settings.put("PARTICLES", "bright");
		final SpotGlobalDetector<FloatType> bright = factory.getDetector(img, settings, wholeMovie(img));
		assertFalse(bright.checkInput() && bright.process() && bright.getResult().getNSpots(false) > 0,
			"a threshold above a negated image's every pixel");
	}

	@Test
	void calibrated2DFrameGivesTheCoreTimesTheCalibration() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final SpotCollection spots = detect(img, TestImages.settings(1), wholeMovie(img));
		final List<Localization> expected = core(raw, 0);
		assertEquals(3, expected.size(), "the test frame must hold three particles");
		assertTrue(expected.stream().anyMatch(l -> l.has(Flag.SECOND_PASS)), "the close pair must use the second pass");
		assertSpotsEqualCoreTimesCalibration(expected, spotsOf(spots, 0), 0);
		// and the positions are where the particles are, in physical units
		for (final double[] c : TestImages.CENTRES)
			assertTrue(spotsOf(spots, 0).stream().anyMatch(s -> Math.abs(s.getFeature(Spot.POSITION_X) - c[0] * DX) < 0.5 *
				DX && Math.abs(s.getFeature(Spot.POSITION_Y) - c[1] * DY) < 0.5 * DY), "no spot near " + c[0] + ", " + c[1]);
		// as in TrackMate's SpotCollection.put: invisible until TrackMate's filters run
		assertEquals(0, spots.getNSpots(true));
	}

	@Test
	void timeLapseDetectsEveryFrameOfTheIntervalUnderItsOwnFrameNumber() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 4);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.TIME);
		final SpotCollection all = detect(img, TestImages.settings(1), wholeMovie(img));
		assertEquals(List.of(0, 1, 2, 3), new ArrayList<>(all.keySet()));
		double previousX = Double.NEGATIVE_INFINITY;
		for (int t = 0; t < 4; t++) {
			final List<Spot> spots = spotsOf(all, t);
			assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(raw, 2, t), t), spots, t);
			final double x = spots.stream().mapToDouble(s -> s.getFeature(Spot.POSITION_X)).min().getAsDouble();
			assertTrue(x > previousX, "frames must differ: the particles move right");
			previousX = x;
		}
		// TrackMate's tstart/tend: only frames 1 and 2, filed as frames 1 and 2
		final SpotCollection part = detect(img, TestImages.settings(1), trackMateInterval(img, 1, 2));
		assertEquals(List.of(1, 2), new ArrayList<>(part.keySet()));
		for (int t = 1; t <= 2; t++)
			assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(raw, 2, t), t), spotsOf(part, t), t);
	}

	@Test
	void multiChannelImageUsesTheTargetChannel() {
		// X, Y, C, T as TrackMate wraps a hyperstack; channel 1 is empty, channel 2 holds the particles
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 2, 2);
		for (int t = 0; t < 2; t++)
			TestImages.blank(Views.flatIterable(Views.hyperSlice(Views.hyperSlice(raw, 3, t), 2, 0)).cursor());
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.CHANNEL, Axes.TIME);
		final Interval interval = wholeMovie(img);
		assertEquals(3, interval.numDimensions(), "TrackMate's global interval drops the channel axis");

		final SpotCollection spots = detect(img, TestImages.settings(2), interval);
		for (int t = 0; t < 2; t++)
			assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(Views.hyperSlice(raw, 3, t), 2, 1), t),
				spotsOf(spots, t), t);
		assertEquals(6, spots.getNSpots(false));
		assertEquals(0, detect(img, TestImages.settings(1), interval).getNSpots(false), "channel 1 is empty");
	}

	@Test
	void cropIntervalKeepsWholeImageCoordinates() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final Interval crop = new FinalInterval(new long[] { 38, 30 }, new long[] { 60, 52 }); // around the lone particle
		final List<Spot> spots = spotsOf(detect(img, TestImages.settings(1), crop), 0);
		final List<Localization> expected = core(Views.interval(raw, crop), 0);
		assertEquals(1, expected.size());
		assertSpotsEqualCoreTimesCalibration(expected, spots, 0);
		assertEquals(TestImages.CENTRES[2][0] * DX, spots.get(0).getFeature(Spot.POSITION_X), 0.5 * DX);
		assertEquals(TestImages.CENTRES[2][1] * DY, spots.get(0).getFeature(Spot.POSITION_Y), 0.5 * DY);
	}

	@Test
	void singleZSliceIsAccepted() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 1, 2);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.Z, Axes.TIME);
		final SpotCollection spots = detect(img, TestImages.settings(1), wholeMovie(img));
		assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(Views.hyperSlice(raw, 3, 1), 2, 0), 1),
			spotsOf(spots, 1), 1);
	}

	@Test
	void stackWithSeveralZSlicesIsRefusedWithAClearMessage() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 4);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.Z);
		final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, TestImages.settings(1), wholeMovie(img));
		assertFalse(detector.checkInput());
		final String message = detector.getErrorMessage();
		assertNotNull(message);
		assertTrue(message.contains("4 Z slices") && message.contains("2D"), message);
		assertFalse(detector.process(), "process() must refuse too");
		assertEquals(0, detector.getResult().getNSpots(false));
	}

	@Test
	void invalidSettingsFailCheckInputNamingTheSetting() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT), Axes.X, Axes.Y);
		final Map<String, Object> settings = TestImages.settings(1);
		settings.put(TrackMateSettings.KEY_THRESHOLD, 80); // an Integer, not a Double
		final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, settings, null);
		assertFalse(detector.checkInput());
		assertTrue(detector.getErrorMessage().contains("GREY_THRESHOLD"), detector.getErrorMessage());
	}

	@Test
	void missingChannelIsNamed() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 2), Axes.X, Axes.Y,
			Axes.TIME);
		final SpotGlobalDetector<FloatType> noChannel = factory.getDetector(img, TestImages.settings(2), null);
		assertFalse(noChannel.checkInput());
		assertTrue(noChannel.getErrorMessage().contains("TARGET_CHANNEL is 2"), noChannel.getErrorMessage());
	}

	@Test
	void intervalOfTheWrongShapeOrOutsideTheImageIsRefused() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 2), Axes.X, Axes.Y,
			Axes.TIME);
		final SpotGlobalDetector<FloatType> wrongShape = factory.getDetector(img, TestImages.settings(1),
			new FinalInterval(10, 10, 1, 1));
		assertFalse(wrongShape.checkInput());
		assertTrue(wrongShape.getErrorMessage().contains("4 dimensions"), wrongShape.getErrorMessage());
		final SpotGlobalDetector<FloatType> outside = factory.getDetector(img, TestImages.settings(1),
			new FinalInterval(new long[] { 0, 0, 5 }, new long[] { 9, 9, 6 }));
		assertFalse(outside.checkInput());
		assertTrue(outside.getErrorMessage().contains("does not overlap"), outside.getErrorMessage());
	}

	@Test
	void nonFinitePixelsFailProcessWithTheCoreMessage() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		raw.update(null).getCurrentStorageArray()[5 * TestImages.WIDTH + 7] = Float.NaN;
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, TestImages.settings(1), null);
		assertTrue(detector.checkInput());
		assertFalse(detector.process());
		assertTrue(detector.getErrorMessage().startsWith("Contact Tracker failed: frame 1: pixel (7, 5) is NaN"),
			detector.getErrorMessage());
	}

	@Test
	void reportsProgressToTrackMatesLoggerAndHonoursCancel() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 3), Axes.X, Axes.Y,
			Axes.TIME);
		final List<Double> progress = new ArrayList<>();
		final List<String> status = new ArrayList<>();
		final Logger logger = new Logger() {

			@Override
			public void log(final String message, final Color color) {}

			@Override
			public void error(final String message) {}

			@Override
			public synchronized void setProgress(final double val) {
				progress.add(val);
			}

			@Override
			public void setStatus(final String s) {
				status.add(s);
			}
		};
		final ContactTrackerDetector<FloatType> detector = new ContactTrackerDetector<>(img, null, TestImages.settings(1));
		detector.setLogger(logger);
		assertTrue(detector.checkInput() && detector.process(), detector.getErrorMessage());
		assertEquals(3, progress.size(), "one progress report per frame");
		assertEquals(1.0, progress.stream().mapToDouble(Double::doubleValue).max().getAsDouble(), 0);
		assertTrue(status.get(0).contains("3 frames"), status.toString());
		assertEquals("", status.get(status.size() - 1), "the status line is cleared at the end");

		final ContactTrackerDetector<FloatType> cancelled = new ContactTrackerDetector<>(img, null, TestImages.settings(1));
		cancelled.cancel("user pressed cancel");
		assertTrue(cancelled.isCanceled());
		assertFalse(cancelled.checkInput() && cancelled.process());
		assertTrue(cancelled.getErrorMessage().contains("cancelled: user pressed cancel"), cancelled.getErrorMessage());
	}

	/**
	 * A movie on disk whose frame cannot be read (a broken file in Fiji's virtual stack) or that does not fit in
	 * memory: TrackMate shows the detector's one-line error message, not a stack trace.
	 */
	@Test
	void aFrameThatCannotBeReadOrDoesNotFitIsAnErrorMessageNotAStackTrace() {
		final ArrayImg<FloatType, FloatArray> frames = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 3);
		for (final Throwable failure : new Throwable[] { new UncheckedIOException(new IOException(
			"cannot read plane 2 of /data/broken.tif: truncated TIFF: strip 1 of 1 lies beyond the end of the file")),
			new OutOfMemoryError("Java heap space") })
		{
			// frame 2 fails as it is read, the way a FileStack plane or an over-large frame does
			final RandomAccessibleInterval<FloatType> failing = Views.interval(new FunctionRandomAccessible<>(3, (pos,
				out) -> {
				if (pos.getLongPosition(2) == 1) {
					if (failure instanceof Error) throw (Error) failure;
					throw (RuntimeException) failure;
				}
				out.set(frames.getAt(pos));
			}, FloatType::new), frames);
			final ImgPlus<FloatType> img = new ImgPlus<>(ImgView.wrap(failing), "broken.tif", new AxisType[] { Axes.X,
				Axes.Y, Axes.TIME }, new double[] { DX, DY, DT });
			final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, TestImages.settings(1), wholeMovie(
				img));
			((MultiThreaded) detector).setNumThreads(2);
			assertTrue(detector.checkInput(), detector.getErrorMessage());
			assertFalse(detector.process(), "refused");
			final String message = detector.getErrorMessage();
			assertEquals(1, message.lines().count(), message);
			assertTrue(failure instanceof Error ? message.contains("out of memory") && message.contains(
				"Memory & Threads") : message.contains("/data/broken.tif: truncated TIFF"), message);
		}
	}
}
