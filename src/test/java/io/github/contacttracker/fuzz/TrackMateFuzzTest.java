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
package io.github.contacttracker.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import ij.ImagePlus;
import io.github.contacttracker.settings.TrackMateSettings;
import io.github.contacttracker.trackmate.ContactTrackerDetectorFactory;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.Cursor;
import net.imglib2.FinalInterval;
import net.imglib2.Interval;
import net.imglib2.algorithm.MultiThreaded;
import net.imglib2.img.Img;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Fuzzes the TrackMate detector as TrackMate drives it: {@code checkSettings} on settings maps with keys missing,
 * of the wrong type, out of range or unknown, then {@code getDetector}, {@code checkInput}, {@code process} on
 * random images from 1x1 (8, 16 and 32 bits, floats with NaN and infinities; channel, Z and time axes; pixel sizes
 * of any value) with TrackMate's interval (every frame, a range of them, a crop down to one pixel wide, one outside
 * the image). The property: no exception escapes; a refusal is TrackMate's own error display, one line (settings:
 * one line per setting at fault, as TrackMate's own factories list them); a detection that succeeds has finite spots inside the image unless flagged.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases; a longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=TrackMateFuzzTest -Dcontact.tracker.fuzz.cases=3000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 */
class TrackMateFuzzTest {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 200;
	/** The least share of cases that must detect. */
	static final double REACH_FLOOR = 0.3;

	/** The header TrackMate's messages of invalid settings start with, on a line of its own. */
	private static final String SETTINGS_HEADER = "Invalid Contact Tracker settings:";

	@Test
	void noInputEndsInAnException() {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int detected = 0, refusedSettings = 0, refusedInput = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final ContactTrackerDetectorFactory<?> factory = new ContactTrackerDetectorFactory<>();
			final ImagePlus imp = FuzzImages.image(r, 3);
			final Map<String, Object> settings = settings(r, factory.getDefaultSettings(), imp);
			final String what = "case seed " + caseSeed + ": " + imp.getWidth() + " x " + imp.getHeight() + " x " + imp
				.getStackSize() + ", " + imp.getBitDepth() + "-bit, settings " + settings;
			final String error;
			try {
				error = factory.checkSettings(settings);
			}
			catch (final RuntimeException e) {
				throw new AssertionError("an exception escaped checkSettings: " + what, e);
			}
			if (error != null) {
				refusedSettings++;
				settingsMessage(error, what);
				if (Boolean.getBoolean("contact.tracker.fuzz.verbose")) System.out.println(error.strip() + "  <-  " + what);
				continue;
			}
			final String outcome = detect(r, imp, settings, what);
			if (outcome == null) detected++;
			else {
				refusedInput++;
				if (Boolean.getBoolean("contact.tracker.fuzz.verbose")) System.out.println(outcome + "  <-  " + what);
			}
		}
		FuzzCase.reach("TrackMate fuzz (" + refusedSettings + " settings refused, " + refusedInput +
			" images or intervals)", cases, detected, refusedSettings + refusedInput, REACH_FLOOR);
		assertTrue(refusedSettings > 0 && refusedInput > 0 || cases < 40, refusedSettings + " settings refused, " +
			refusedInput + " images or intervals refused");
	}

	/**
	 * Asserts that a message of invalid settings is TrackMate's: one line per setting at fault (as TrackMate's own
	 * factories list them), each naming the setting, no stack trace.
	 */
	private static void settingsMessage(final String error, final String what) {
		final List<String> lines = error.strip().lines().toList();
		assertFalse(lines.isEmpty(), "a refusal says why: " + what);
		for (final String line : lines)
			assertTrue(!line.contains("Exception") && (line.contains("UNKNOWN_KEY") || TrackMateSettings.keys().stream()
				.anyMatch(line::contains)), "one setting per line: '" + line + "' in " + error + "; " + what);
	}

	/**
	 * @return the settings a user would give for the movie (its threshold, r_out, particles' polarity; the others
	 *         TrackMate's defaults) with one or two values changed (in a third of the cases): a number of the other type, out of range,
	 *         not finite, text, null, missing; or an unknown key added
	 */
	private static Map<String, Object> settings(final SplittableRandom r, final Map<String, Object> defaults,
		final ImagePlus imp)
	{
		final Map<String, Object> s = new HashMap<>(defaults);
		s.put("GREY_THRESHOLD", FuzzImages.threshold(imp));
		s.put("R_OUT", (double) FuzzImages.rOut(imp));
		s.put("MIN_AREA", 5);
		s.put("PARTICLES", FuzzImages.dark(imp) ? "dark" : "bright");
		final List<String> keys = new ArrayList<>(s.keySet());
		keys.sort(null); // the order of a HashMap's keys is no seed's
		final Object[] odd = { -1, 0, 3, 1e9, -2.5, Double.NaN, Double.NEGATIVE_INFINITY, "x", "fit", "dark", "image",
			"", null, true, 7L, 0.5f, Integer.MAX_VALUE };
		// one or two odd values in a third of the cases: any odd value refuses the settings
		final int changes = r.nextInt(3) == 0 ? 1 + r.nextInt(2) : 0;
		for (int k = 0; k < changes; k++) {
			final String key = keys.get(r.nextInt(keys.size()));
			switch (r.nextInt(4)) {
				case 0 -> s.remove(key);
				case 1 -> s.put("UNKNOWN_KEY", odd[r.nextInt(odd.length)]);
				default -> s.put(key, odd[r.nextInt(odd.length)]);
			}
		}
		return s;
	}

	/** @return null when the detector found spots (checked), else its error message (checked) */
	private static String detect(final SplittableRandom r, final ImagePlus imp, final Map<String, Object> settings,
		final String what)
	{
		final int bits = imp.getBitDepth();
		if (bits == 8) return detect(r, imp, ArrayImgs.unsignedBytes(dims(imp)), settings, what);
		if (bits == 16) return detect(r, imp, ArrayImgs.unsignedShorts(dims(imp)), settings, what);
		return detect(r, imp, ArrayImgs.floats(dims(imp)), settings, what);
	}

	private static long[] dims(final ImagePlus imp) {
		return new long[] { imp.getWidth(), imp.getHeight(), imp.getStackSize() };
	}

	private static <T extends RealType<T> & NativeType<T>> String detect(final SplittableRandom r, final ImagePlus imp,
		final Img<T> img, final Map<String, Object> settings, final String what)
	{
		final Cursor<T> cursor = img.localizingCursor();
		while (cursor.hasNext()) {
			cursor.fwd();
			cursor.get().setReal(imp.getStack().getProcessor(cursor.getIntPosition(2) + 1).getf(cursor.getIntPosition(0),
				cursor.getIntPosition(1)));
		}
		// the stack's third axis as time, channel or Z (Z of 2 or more: refused), or the planes dropped to one
		final AxisType third = switch (r.nextInt(4)) {
			case 0 -> Axes.CHANNEL;
			case 1 -> Axes.Z;
			default -> Axes.TIME;
		};
		final double[] cal = { size(r), size(r), 1 };
		final ImgPlus<T> movie = new ImgPlus<>(img, "fuzz", new AxisType[] { Axes.X, Axes.Y, third }, cal);
		final Interval interval = interval(r, movie, third);
		final SpotGlobalDetector<T> detector;
		final boolean ok;
		final String where = what + ", axes X Y " + third + ", interval " + (interval == null ? "none" : interval
			.toString());
		try {
			@SuppressWarnings("unchecked")
			final ContactTrackerDetectorFactory<T> factory = new ContactTrackerDetectorFactory<>();
			detector = factory.getDetector(movie, settings, interval);
			((MultiThreaded) detector).setNumThreads(1 + r.nextInt(2));
			ok = detector.checkInput() && detector.process();
		}
		catch (final RuntimeException e) {
			throw new AssertionError("an exception escaped the detector: " + where, e);
		}
		if (!ok) {
			final String m = detector.getErrorMessage();
			assertTrue(m != null && !m.isBlank(), "a refusal says why: " + where);
			if (m.startsWith(SETTINGS_HEADER)) settingsMessage(m.substring(SETTINGS_HEADER.length()), where);
			else {
				assertEquals(1, m.strip().lines().count(), m + "; " + where);
				assertFalse(m.contains("Exception"), m + "; " + where);
			}
			return m;
		}
		final double dx = movie.averageScale(0), dy = movie.averageScale(1);
		final fiji.plugin.trackmate.SpotCollection spots = detector.getResult();
		for (final int frame : spots.keySet())
			for (final Spot s : spots.iterable(frame, false)) {
			final double x = s.getFeature(Spot.POSITION_X), y = s.getFeature(Spot.POSITION_Y);
			assertTrue(Double.isFinite(x) && Double.isFinite(y), "finite: " + s + "; " + where);
			boolean flagged = false;
			for (final Map.Entry<String, Double> f : s.getFeatures().entrySet())
				flagged |= f.getKey().startsWith("FLAG_") && !f.getKey().equals("FLAG_SECOND_PASS") && f.getValue() != null &&
					f.getValue() == 1;
			assertTrue(flagged || x >= -0.5 * dx && y >= -0.5 * dy, "inside unless flagged: " + s.getFeatures() + "; " +
				where);
			}
		return null;
	}

	/** @return a pixel size: mostly a positive one, sometimes 0, negative or not a number */
	private static double size(final SplittableRandom r) {
		final double[] odd = { 0, -0.1, Double.NaN, Double.POSITIVE_INFINITY };
		return r.nextInt(20) == 0 ? odd[r.nextInt(odd.length)] : 0.05 + r.nextDouble();
	}

	/**
	 * @return TrackMate's interval (the image's axes without channel): the whole movie, a range of frames, a crop
	 *         (down to one pixel wide), one outside the image, or none
	 */
	private static Interval interval(final SplittableRandom r, final ImgPlus<?> img, final AxisType third) {
		final int n = third == Axes.CHANNEL ? 2 : 3;
		final long[] min = new long[n], max = new long[n];
		for (int d = 0; d < n; d++)
			max[d] = img.max(d);
		switch (r.nextInt(6)) {
			case 0:
				return null;
			case 1: // one pixel wide
				min[0] = max[0] = r.nextInt((int) img.dimension(0));
				break;
			case 2: // a crop
				min[0] = r.nextInt((int) img.dimension(0));
				min[1] = r.nextInt((int) img.dimension(1));
				break;
			case 3: // outside the image
				min[0] = img.dimension(0) + 3;
				max[0] = min[0] + 4;
				break;
			case 4: // a range of frames
				if (n == 3) min[2] = r.nextInt((int) img.dimension(2));
				break;
			default:
				break;
		}
		return new FinalInterval(min, max);
	}
}
