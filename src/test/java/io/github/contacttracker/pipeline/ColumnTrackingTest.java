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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * Frames handed over as pixel arrays ({@link PixelPlanes}) tracked into columns ({@link ColumnTracking}) and
 * profiled ({@link ProfileSummary}): the centres against the truth, the same spots as the pipeline on the same
 * pixels read as images, and one-line refusals of bad input.
 */
class ColumnTrackingTest {

	private static final int W = 240, H = 200, FRAMES = 3;
	/** A bright core on a background of 40; active area about 9 px across at the helper's threshold. */
	private static final RadialProfile PROFILE = r -> 160 * Math.exp(-r * r / 50);
	private static final double DIAMETER = 22;

	/** The true centres of frame {@code t}: twelve particles, two of the pairs touching, none near the border. */
	private static List<double[]> truth(final int t) {
		final List<double[]> c = new ArrayList<>();
		for (int i = 0; i < 4; i++)
			for (int j = 0; j < 2; j++)
				c.add(new double[] { 40.3 + 50 * i + 0.37 * t, 50.6 + 90 * j + 0.21 * t });
		c.add(new double[] { 60.2 + 0.3 * t, 95.1 });
		c.add(new double[] { 60.2 + 0.3 * t + DIAMETER, 95.4 });
		c.add(new double[] { 150.7, 96.3 - 0.2 * t });
		c.add(new double[] { 150.7 + DIAMETER, 96.3 });
		return c;
	}

	private static byte[][] planes() {
		final SplittableRandom rnd = new SplittableRandom(11);
		final ImageSimulator sim = new ImageSimulator(PROFILE, 3);
		final byte[][] planes = new byte[FRAMES][];
		for (int t = 0; t < FRAMES; t++) {
			final RandomAccessibleInterval<UnsignedByteType> f = Quantiser.toUnsignedBytes(sim.render(truth(t), W, H, 40),
				NoiseModel.gaussian(2), rnd).image();
			final byte[] p = new byte[W * H];
			final var cursor = f.localizingCursor();
			while (cursor.hasNext()) {
				final int v = cursor.next().get();
				p[cursor.getIntPosition(1) * W + cursor.getIntPosition(0)] = (byte) v;
			}
			planes[t] = p;
		}
		return planes;
	}

	private static double[] column(final ColumnTracking.Table table, final SpotColumn c) {
		return table.columns()[Arrays.asList(table.keys()).indexOf(c.key())];
	}

	/** Every particle found once, within 0.05 px of its true centre, the settings measured as track measures them. */
	@Test
	void centresMatchTheTruthWithMeasuredSettings() {
		final ColumnTracking.Table table = ColumnTracking.track(new PixelPlanes(planes(), W, H), "sim", Map.of(), 1);
		final double[] x = column(table, SpotColumn.POSITION_X), y = column(table, SpotColumn.POSITION_Y), frame = column(
			table, SpotColumn.FRAME);
		assertEquals(FRAMES * truth(0).size(), x.length, "spots");
		for (int t = 0; t < FRAMES; t++)
			for (final double[] c : truth(t)) {
				double best = Double.POSITIVE_INFINITY;
				for (int i = 0; i < x.length; i++)
					if (frame[i] == t) best = Math.min(best, Math.hypot(x[i] - c[0], y[i] - c[1]));
				assertTrue(best < 0.05, "frame " + t + " particle at " + Arrays.toString(c) + ": nearest spot " + best +
					" px away");
			}
		assertEquals(List.of("threshold", "r_out", "diameter"), table.measured());
		assertEquals(DIAMETER, Double.parseDouble(table.settings().get("diameter")), 0.1 * DIAMETER);
		for (final double m : table.mass())
			assertTrue(m > 0, "mass " + m);
	}

	/** The same pixels as ImgLib2 images through the pipeline with the same settings: the same spots, bit for bit. */
	@Test
	void sameSpotsAsThePipeline() {
		final byte[][] planes = planes();
		final ColumnTracking.Table table = ColumnTracking.track(new PixelPlanes(planes, W, H), "sim", Map.of("threshold",
			"100", "r_out", "30", "method", "paper"), 0);
		final SettingValues settings = SettingValues.defaults().withText(TrackingSettings.THRESHOLD, "100").withText(
			TrackingSettings.R_OUT, "30").withText(TrackingSettings.METHOD, "paper");
		final MeasuredSettings.Result m = MeasuredSettings.of("sim", ArrayImgs.unsignedBytes(planes[0], W, H), true,
			settings, Set.of(TrackingSettings.THRESHOLD, TrackingSettings.R_OUT, TrackingSettings.METHOD), FrontEnd.COMMAND_LINE);
		final List<Localization> spots = new TrackingPipeline(m.settings()).run(FrameSource.of(FRAMES,
			t -> ArrayImgs.unsignedBytes(planes[t], W, H), Calibration.PIXELS, "sim", null),
			false).spots();
		assertEquals(spots.size(), column(table, SpotColumn.POSITION_X).length);
		for (final SpotColumn c : SpotColumn.values()) {
			final double[] expected = new double[spots.size()];
			for (int i = 0; i < spots.size(); i++)
				expected[i] = c.value(spots.get(i), i, Calibration.PIXELS);
			assertArrayEquals(expected, column(table, c), c.key());
		}
		assertEquals(List.of("diameter"), table.measured());
		assertEquals("paper", table.settings().get("method"));
	}

	/** 16-bit and float pixels give the same centres as 8-bit ones of the same values. */
	@Test
	void pixelTypesAgree() {
		final byte[][] bytes = planes();
		final short[][] shorts = new short[FRAMES][W * H];
		final float[][] floats = new float[FRAMES][W * H];
		for (int t = 0; t < FRAMES; t++)
			for (int i = 0; i < W * H; i++) {
				shorts[t][i] = (short) (bytes[t][i] & 0xff);
				floats[t][i] = bytes[t][i] & 0xff;
			}
		final Map<String, String> given = Map.of("threshold", "100", "r_out", "30", "diameter", "22");
		final double[] x8 = column(ColumnTracking.track(new PixelPlanes(bytes, W, H), "a", given, 1), SpotColumn.POSITION_X);
		assertArrayEquals(x8, column(ColumnTracking.track(new PixelPlanes(shorts, W, H), "b", given, 1),
			SpotColumn.POSITION_X));
		assertArrayEquals(x8, column(ColumnTracking.track(new PixelPlanes(floats, W, H), "c", given, 1),
			SpotColumn.POSITION_X));
	}

	/** The helper's report: the diameter and the settings track would measure. */
	@Test
	void profileSuggestsWhatTrackMeasures() {
		final PixelPlanes frames = new PixelPlanes(planes(), W, H);
		final Map<String, Object> report = ProfileSummary.of(frames, 0, 0, 0, null);
		final ColumnTracking.Table table = ColumnTracking.track(frames, "sim", Map.of(), 1);
		assertEquals(Double.parseDouble(table.settings().get("threshold")), (double) report.get("threshold"));
		assertEquals(Double.parseDouble(table.settings().get("r_out")), (double) report.get("r_out"));
		assertEquals(DIAMETER, (double) report.get("diameter"), 0.1 * DIAMETER);
		assertEquals("bright", report.get("particles"));
		assertTrue(((String[]) report.get("lines")).length > 3);
	}

	@Test
	void badInputIsOneLineNamingIt() {
		final byte[][] planes = planes();
		assertEquals("unknown setting 'r-out': the settings are threshold, r_out, min_area, min_second_area, " +
			"connectivity, method, diameter, kinds, particles, detection, channel", assertThrows(InvalidInputException.class,
				() -> ColumnTracking.track(new PixelPlanes(planes, W, H), "sim", Map.of("r-out", "3"), 1)).getMessage());
		assertEquals("r_out must be a positive number of pixels, not -1.0", assertThrows(InvalidInputException.class,
			() -> ColumnTracking.track(new PixelPlanes(planes, W, H), "sim", Map.of("r_out", "-1"), 1)).getMessage());
		assertEquals("frame 1 has 48000 pixels, not 100 x 100 = 10000", assertThrows(InvalidInputException.class,
			() -> new PixelPlanes(planes, 100, 100)).getMessage());
		assertEquals("frame 2 is not of the first frame's pixel type (byte[])", assertThrows(InvalidInputException.class,
			() -> new PixelPlanes(new Object[] { planes[0], new float[W * H] }, W, H)).getMessage());
		assertEquals("pixels must be 8-bit or 16-bit unsigned integers or 32-bit floats, not int[]", assertThrows(
			InvalidInputException.class, () -> new PixelPlanes(new Object[] { new int[4] }, 2, 2)).getMessage());
		assertEquals("threshold 300 is outside the data range [0, 237] of 'sim'", assertThrows(
			InvalidInputException.class, () -> ColumnTracking.track(new PixelPlanes(planes, W, H), "sim", Map.of(
				"threshold", "300", "r_out", "30", "diameter", "22"), 1)).getMessage().replaceAll("\\[\\d+, \\d+\\]",
					"[0, 237]"));
		final float[] nan = new float[W * H];
		nan[5] = Float.NaN;
		assertTrue(assertThrows(InvalidInputException.class, () -> ColumnTracking.track(new PixelPlanes(new Object[] {
			nan }, W, H), "sim", Map.of("threshold", "0.5", "r_out", "30", "diameter", "22"), 1)).getMessage().contains(
				"pixel (5, 0) is NaN"));
		assertEquals("frame 3 does not exist: there are 3 frames (counted from 0)", assertThrows(
			InvalidInputException.class, () -> ProfileSummary.of(new PixelPlanes(planes, W, H), 3, 0, 0, null))
				.getMessage());
	}
}
