package io.github.contacttracker.trackmate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.detection.SpotDetector;
import fiji.plugin.trackmate.detection.SpotDetectorFactory;
import io.github.contacttracker.core.ContactTracker;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.FinalInterval;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.view.Views;

/**
 * The detector driven the way TrackMate 8 drives it: {@code factory.getDetector(img, settings, interval, frame)}
 * on the WHOLE calibrated image, then {@code checkInput()}, {@code process()}, {@code getResult()}, and
 * {@code getErrorMessage()} on failure. Its spots must be the core's localizations times the calibration.
 */
class ContactTrackerDetectorTest {

	private static final double DX = 0.1, DY = 0.2, DT = 0.5; // anisotropic, to catch x/y mix-ups

	private final SpotDetectorFactory<FloatType> factory = new ContactTrackerDetectorFactory<>();

	/** What TrackMate does per frame; fails the test with TrackMate's error message when the detector fails. */
	private List<Spot> detect(final ImgPlus<FloatType> img, final Map<String, Object> settings, final Interval interval,
		final int frame)
	{
		assertNull(factory.checkSettings(settings));
		final SpotDetector<FloatType> detector = factory.getDetector(img, settings, interval, frame);
		final boolean ok = detector.checkInput() && detector.process();
		assertTrue(ok, () -> detector.getErrorMessage());
		assertTrue(detector.getProcessingTime() >= 0);
		return detector.getResult();
	}

	/** The interval TrackMate builds: the image's dimensions without time, a one-wide channel axis if any. */
	private static Interval trackMateInterval(final ImgPlus<?> img, final int channel) {
		final List<long[]> ranges = new ArrayList<>();
		for (int d = 0; d < img.numDimensions(); d++) {
			if (d == img.dimensionIndex(Axes.TIME)) continue;
			if (d == img.dimensionIndex(Axes.CHANNEL)) ranges.add(new long[] { channel - 1, channel - 1 });
			else ranges.add(new long[] { img.min(d), img.max(d) });
		}
		final long[] min = new long[ranges.size()], max = new long[ranges.size()];
		for (int i = 0; i < min.length; i++) {
			min[i] = ranges.get(i)[0];
			max[i] = ranges.get(i)[1];
		}
		return new FinalInterval(min, max);
	}

	private static ImgPlus<FloatType> imgPlus(final ArrayImg<FloatType, FloatArray> img, final AxisType... axes) {
		final double[] cal = new double[axes.length];
		for (int d = 0; d < axes.length; d++)
			cal[d] = axes[d] == Axes.X ? DX : axes[d] == Axes.Y ? DY : axes[d] == Axes.TIME ? DT : 1;
		return new ImgPlus<>(img, "test", axes, cal);
	}

	/** Asserts the spots are exactly the localizations scaled by the calibration, in the same order. */
	private static void assertSpotsEqualCoreTimesCalibration(final List<Localization> expected, final List<Spot> spots) {
		assertEquals(expected.size(), spots.size());
		for (int i = 0; i < spots.size(); i++) {
			final Localization l = expected.get(i);
			final Spot s = spots.get(i);
			assertEquals(l.x() * DX, s.getFeature(Spot.POSITION_X), 0, "x of spot " + i);
			assertEquals(l.y() * DY, s.getFeature(Spot.POSITION_Y), 0, "y of spot " + i);
			assertEquals(0, s.getFeature(Spot.POSITION_Z), 0);
			assertEquals(l.radius() * Math.sqrt(DX * DY), s.getFeature(Spot.RADIUS), 1e-12);
			assertEquals(l.quality(), s.getFeature(Spot.QUALITY), 0);
			assertEquals(l.firstX() * DX, s.getFeature(SpotColumn.FIRST_PASS_X.key()), 0);
			assertEquals(l.firstY() * DY, s.getFeature(SpotColumn.FIRST_PASS_Y.key()), 0);
			assertEquals(l.activeArea(), s.getFeature(SpotColumn.ACTIVE_AREA.key()), 0);
			assertEquals(l.secondArea(), s.getFeature(SpotColumn.SECOND_AREA.key()), 0);
			assertEquals(l.has(Flag.SECOND_PASS) ? 1 : 0, s.getFeature(SpotColumn.FLAG_SECOND_PASS.key()), 0);
			for (final SpotColumn c : SpotColumn.values())
				if (!c.isTrackMateKey()) {
					final Double v = s.getFeature(c.key());
					if (v != null) assertTrue(Double.isFinite(v), c.key());
				}
		}
	}

	private static List<Localization> core(final RandomAccessibleInterval<FloatType> plane, final int frame) {
		return new ContactTracker(TestImages.params()).track(plane, frame);
	}

	@Test
	void calibrated2DFrameGivesTheCoreTimesTheCalibration() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final List<Spot> spots = detect(img, TestImages.settings(1), trackMateInterval(img, 1), 0);
		final List<Localization> expected = core(raw, 0);
		assertEquals(3, expected.size(), "the test frame must hold three particles");
		assertTrue(expected.stream().anyMatch(l -> l.has(Flag.SECOND_PASS)), "the close pair must use the second pass");
		assertSpotsEqualCoreTimesCalibration(expected, spots);
		// and the positions are where the particles are, in physical units
		for (final double[] c : TestImages.CENTRES)
			assertTrue(spots.stream().anyMatch(s -> Math.abs(s.getFeature(Spot.POSITION_X) - c[0] * DX) < 0.5 * DX &&
				Math.abs(s.getFeature(Spot.POSITION_Y) - c[1] * DY) < 0.5 * DY), "no spot near " + c[0] + ", " + c[1]);
	}

	@Test
	void timeLapseTakesOutTheRequestedFrame() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 3);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.TIME);
		final Interval interval = trackMateInterval(img, 1);
		assertEquals(2, interval.numDimensions(), "TrackMate's interval has no time axis");
		double previousX = Double.NEGATIVE_INFINITY;
		for (int t = 0; t < 3; t++) {
			final List<Spot> spots = detect(img, TestImages.settings(1), interval, t);
			assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(raw, 2, t), t), spots);
			assertEquals(3, spots.size(), "frame " + t);
			final double x = spots.stream().mapToDouble(s -> s.getFeature(Spot.POSITION_X)).min().getAsDouble();
			assertTrue(x > previousX, "frames must differ: the particles move right");
			previousX = x;
		}
	}

	@Test
	void multiChannelImageUsesTheTargetChannel() {
		// X, Y, C, T as TrackMate wraps a hyperstack; channel 1 is empty, channel 2 holds the particles
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 2, 2);
		for (int t = 0; t < 2; t++)
			TestImages.blank(Views.flatIterable(Views.hyperSlice(Views.hyperSlice(raw, 3, t), 2, 0)).cursor());
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.CHANNEL, Axes.TIME);
		final Interval interval = trackMateInterval(img, 2);
		assertEquals(3, interval.numDimensions(), "TrackMate's interval keeps a one-wide channel axis");

		final List<Spot> spots = detect(img, TestImages.settings(2), interval, 1);
		assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(Views.hyperSlice(raw, 3, 1), 2, 1), 1), spots);
		assertEquals(3, spots.size());
		assertTrue(detect(img, TestImages.settings(1), trackMateInterval(img, 1), 1).isEmpty(), "channel 1 is empty");
	}

	@Test
	void cropIntervalKeepsWholeImageCoordinates() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final Interval crop = new FinalInterval(new long[] { 38, 30 }, new long[] { 60, 52 }); // around the lone particle
		final List<Spot> spots = detect(img, TestImages.settings(1), crop, 0);
		final List<Localization> expected = core(Views.interval(raw, crop), 0);
		assertEquals(1, expected.size());
		assertSpotsEqualCoreTimesCalibration(expected, spots);
		assertEquals(TestImages.CENTRES[2][0] * DX, spots.get(0).getFeature(Spot.POSITION_X), 0.5 * DX);
		assertEquals(TestImages.CENTRES[2][1] * DY, spots.get(0).getFeature(Spot.POSITION_Y), 0.5 * DY);
	}

	@Test
	void singleZSliceIsAccepted() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 1, 2);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.Z, Axes.TIME);
		final List<Spot> spots = detect(img, TestImages.settings(1), trackMateInterval(img, 1), 1);
		assertSpotsEqualCoreTimesCalibration(core(Views.hyperSlice(Views.hyperSlice(raw, 3, 1), 2, 0), 1), spots);
	}

	@Test
	void stackWithSeveralZSlicesIsRefusedWithAClearMessage() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 4);
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y, Axes.Z);
		final SpotDetector<FloatType> detector = factory.getDetector(img, TestImages.settings(1),
			trackMateInterval(img, 1), 0);
		assertFalse(detector.checkInput());
		final String message = detector.getErrorMessage();
		assertNotNull(message);
		assertTrue(message.contains("4 Z slices") && message.contains("2D"), message);
		assertFalse(detector.process(), "process() must refuse too");
		assertTrue(detector.getResult().isEmpty());
	}

	@Test
	void invalidSettingsFailCheckInputNamingTheSetting() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT), Axes.X, Axes.Y);
		final Map<String, Object> settings = TestImages.settings(1);
		settings.put(DetectorSettings.KEY_THRESHOLD, 80); // an Integer, not a Double
		final SpotDetector<FloatType> detector = factory.getDetector(img, settings, null, 0);
		assertFalse(detector.checkInput());
		assertTrue(detector.getErrorMessage().contains("THRESHOLD"), detector.getErrorMessage());
	}

	@Test
	void missingChannelAndFrameAreNamed() {
		final ImgPlus<FloatType> img = imgPlus(TestImages.image(TestImages.WIDTH, TestImages.HEIGHT, 2), Axes.X, Axes.Y,
			Axes.TIME);
		final SpotDetector<FloatType> noChannel = factory.getDetector(img, TestImages.settings(2), null, 0);
		assertFalse(noChannel.checkInput());
		assertTrue(noChannel.getErrorMessage().contains("TARGET_CHANNEL is 2"), noChannel.getErrorMessage());
		final SpotDetector<FloatType> noFrame = factory.getDetector(img, TestImages.settings(1), null, 5);
		assertFalse(noFrame.checkInput());
		assertTrue(noFrame.getErrorMessage().contains("frame 5"), noFrame.getErrorMessage());
	}

	@Test
	void nonFinitePixelsFailProcessWithTheCoreMessage() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		raw.update(null).getCurrentStorageArray()[5 * TestImages.WIDTH + 7] = Float.NaN;
		final ImgPlus<FloatType> img = imgPlus(raw, Axes.X, Axes.Y);
		final SpotDetector<FloatType> detector = factory.getDetector(img, TestImages.settings(1), null, 0);
		assertTrue(detector.checkInput());
		assertFalse(detector.process());
		assertTrue(detector.getErrorMessage().startsWith("Contact Tracker failed on frame 0"), detector.getErrorMessage());
	}

	@Test
	void publicConstructorWorksWithoutSettingsMap() {
		final ArrayImg<FloatType, FloatArray> raw = TestImages.image(TestImages.WIDTH, TestImages.HEIGHT);
		final ContactTrackerDetector<FloatType> detector = new ContactTrackerDetector<>(imgPlus(raw, Axes.X, Axes.Y), null,
			0, TestImages.params(), 1);
		assertTrue(detector.checkInput() && detector.process(), detector.getErrorMessage());
		assertSpotsEqualCoreTimesCalibration(core(raw, 0), detector.getResult());
	}
}
