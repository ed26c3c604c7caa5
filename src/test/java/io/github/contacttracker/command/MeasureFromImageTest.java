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
package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.command.CommandService;
import org.scijava.module.Module;
import org.scijava.module.ModuleItem;
import org.scijava.module.ModuleService;
import org.scijava.widget.Button;
import java.util.SplittableRandom;

import ij.ImagePlus;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.ij.ShownImage;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ProfileScenes;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;

/**
 * The dialog's "Measure from the image" button, pressed the way Fiji's dialog presses it (the input's callback on
 * the module): it fills {@code threshold}, {@code r_out} and {@code diameter} with exactly what the profile helper
 * suggests for the frame on display, keeps a diameter that was given, and leaves the fields alone with a one-line
 * message when the frame has nothing to measure. The button is not a setting, not remembered and not a macro
 * option: a headless run ignores it.
 */
class MeasureFromImageTest extends WithContext {

	/** The command's module as the dialog holds it, on {@code imp}. */
	private static Module dialog(final ImagePlus imp) {
		final Module m = context.service(ModuleService.class).createModule(context.service(CommandService.class)
			.getCommand(ContactTrackerCommand.class));
		m.setInput("imp", imp);
		return m;
	}

	/** Presses the button: what SciJava's button widget does. @return what was written to the Log window */
	private static String press(final Module m) throws Exception {
		final ModuleItem<?> button = m.getInfo().getInput("measure");
		assertEquals(Button.class, button.getType());
		final PrintStream out = System.out;
		final ByteArrayOutputStream printed = new ByteArrayOutputStream();
		System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
		try {
			button.callback(m);
		}
		finally {
			System.setOut(out);
		}
		return printed.toString(StandardCharsets.UTF_8);
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static ProfileAnalysis.Result helper(final ImagePlus imp, final int t, final double diameter) {
		return ProfileAnalysis.analyse((RandomAccessibleInterval) ImagePlusFrames.of(imp, 1).frame(t), diameter, 0);
	}

	private static double value(final Module m, final String name) {
		return ((Number) m.getInput(name)).doubleValue();
	}

	/**
	 * Two blurred spheres standing apart, whose light at contact rises above their own peak: the helper's threshold
	 * lies above every pixel. The button then fills in what {@code track} measures on that frame (detection by the
	 * image, a threshold within the frame, the spheres' rim as the diameter), never a threshold outside the image.
	 */
	@Test
	void aThresholdAboveEveryPixelIsNeverFilledIn() throws Exception {
		final ImageSimulator sim = new ImageSimulator(r -> 120 / (1 + Math.exp((r - 6) * 1.702 / 1.5)), 3);
		final var frame = Quantiser.toUnsignedBytes(sim.render(java.util.List.of(new double[] { 38.3, 40.2 },
			new double[] { 62.3, 40.2 }), 100, 80, 37), NoiseModel.gaussian(3), new SplittableRandom(11)).image();
		final ImagePlus imp = TimeSeries.of("pair", java.util.List.of(frame), Calibration.PIXELS);
		double max = 0;
		for (final var v : frame)
			max = Math.max(max, v.getRealDouble());
		final Module m = dialog(imp);
		final String log = press(m);
		assertTrue(value(m, "threshold") <= max, "threshold " + value(m, "threshold") + ", brightest pixel " + max);
		assertEquals(TrackingSettings.IMAGE, m.getInput("detection"), log);
		assertEquals(12, value(m, "diameter"), 0.6, log);
		assertTrue(log.contains("tracked by the particles' image"), log);
	}

	@Test
	void fillsTheFieldsWithTheHelpersSuggestionsForTheFrameShown() throws Exception {
		final ImagePlus imp = ProfileScenes.particles("particles", 4, Calibration.PIXELS);
		imp.setPosition(1, 1, 3);
		final Module m = dialog(imp);
		m.setInput("min_area", 7);
		final String log = press(m);

		final ProfileAnalysis.Result r = helper(imp, 2, 0);
		assertTrue(r.diameterEstimated());
		assertEquals(r.suggestedThreshold(true), value(m, "threshold"), 0, "threshold, rounded up to a grey level");
		assertEquals(r.suggestedROut(), value(m, "r_out"), 0, "r_out, rounded up to whole pixels");
		assertEquals(Math.round(r.diameter() * 100) / 100.0, value(m, "diameter"), 0, "the estimate, to 0.01 px");
		assertEquals(ProfileScenes.SMALL.diameterPx(), value(m, "diameter"), 0.1 * ProfileScenes.SMALL.diameterPx());
		assertEquals(7, value(m, "min_area"), 0, "the other fields are left alone");
		// another frame measures otherwise: the one on display was taken
		assertFalse(r.threshold() == helper(imp, 0, 0).threshold() && r.rOut() == helper(imp, 0, 0).rOut());
		// wrapped for the Log window: continuation lines are indented
		final String flat = log.replace("\n    ", " ");
		assertTrue(flat.startsWith("Contact Tracker: measured 'particles', frame 3: threshold " + fmt(r
			.suggestedThreshold(true)) + ", r_out " + fmt(r.suggestedROut()) + " px, diameter "), log);
		assertTrue(flat.contains(" px (estimated)"), log);
		for (final String line : log.split("\n"))
			assertTrue(line.length() <= io.github.contacttracker.report.ShownFrameProfile.LOG_WIDTH, line);
		assertTrue(log.contains("  warning: the diameter"), "the helper's warnings follow: " + log);
		assertFalse(((Cancelable) m).isCanceled());
	}

	/**
	 * Dark particles (the frame inverted, 255 - v) with Particles left at bright: the button finds them dark, sets
	 * the setting and measures what it measures on the bright frame, and says so.
	 */
	@Test
	void darkParticlesAreFoundSetAndMeasuredInverted() throws Exception {
		final ImagePlus bright = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		final ProfileAnalysis.Result r = helper(bright, 0, 0);
		final ImagePlus dark = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		dark.getProcessor().invert();
		final Module m = dialog(dark);
		assertEquals("bright", m.getInput("particles"));
		final String log = press(m);
		assertEquals("dark", m.getInput("particles"));
		assertEquals(r.suggestedThreshold(true), value(m, "threshold"), 0);
		assertEquals(r.suggestedROut(), value(m, "r_out"), 0);
		assertTrue(log.replace("\n    ", " ").startsWith("Contact Tracker: measured 'particles': dark particles (the " +
			"frame looks so), threshold "), log);
		// said bright: the bright frame stays bright
		final Module b = dialog(bright);
		press(b);
		assertEquals("bright", b.getInput("particles"));
	}

	/**
	 * Particles a few pixels across: the button lowers Min area to the helper's (half the particles' active area), and
	 * says so; a lower one is kept.
	 */
	@Test
	void minAreaIsLoweredForSmallParticles() throws Exception {
		final ImagePlus imp = ProfileScenes.tiny("tiny");
		final Module m = dialog(imp);
		assertEquals(TrackingSettings.MIN_AREA.defaultValue(), value(m, "min_area"), 0);
		final String log = press(m);
		final ProfileAnalysis.Result r = helper(imp, 0, 0);
		final int minArea = r.suggestedMinArea(r.suggestedThreshold(true));
		assertTrue(minArea < TrackingSettings.MIN_AREA.defaultValue(), "small particles: " + minArea);
		assertEquals(minArea, value(m, "min_area"), 0);
		assertTrue(log.replace("\n    ", " ").contains(", min area " + minArea + " px (small particles)"), log);
		final Module lower = dialog(imp);
		lower.setInput("min_area", minArea - 1);
		press(lower);
		assertEquals(minArea - 1, value(lower, "min_area"), 0, "a lower min area is left alone");
	}

	/**
	 * With an area selection the button measures within it, as the command tracks: the values are the helper's on
	 * the selection's rectangle, a row of bright marks burned into the top of the frame (like a timestamp's digits)
	 * left out (with them the threshold reads 67, not 66), and the Log says so.
	 */
	@Test
	@SuppressWarnings({ "unchecked", "rawtypes" })
	void anAreaSelectionIsMeasuredWithin() throws Exception {
		final ImagePlus imp = ProfileScenes.particles("stamped", 1, Calibration.PIXELS);
		for (int k = 0; k < 12; k++)
			for (int y = 4; y < 11; y++)
				for (int x = 6 + 6 * k; x < 10 + 6 * k; x++)
					imp.getProcessor().set(x, y, 250);
		imp.setRoi(new ij.gui.Roi(0, 20, 200, 180));
		final Module m = dialog(imp);
		final String log = press(m);
		final net.imglib2.Interval region = ShownImage.selection(imp);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse((RandomAccessibleInterval) ImagePlusFrames.within(
			ImagePlusFrames.of(imp, 1).frame(0), region), 0, 0);
		assertEquals(r.suggestedThreshold(true), value(m, "threshold"), 0);
		assertEquals(r.suggestedROut(), value(m, "r_out"), 0);
		assertEquals(Math.round(r.diameter() * 100) / 100.0, value(m, "diameter"), 0);
		assertTrue(log.replace("\n    ", " ").startsWith("Contact Tracker: measured 'stamped' within the selection " +
			"(x 0-199, y 20-199): threshold"), log);
	}

	@Test
	void aGivenDiameterIsKeptAndUsed() throws Exception {
		final ImagePlus imp = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		final Module m = dialog(imp);
		m.setInput("diameter", 21.5);
		final String log = press(m);
		final ProfileAnalysis.Result r = helper(imp, 0, 21.5);
		assertEquals(21.5, value(m, "diameter"), 0);
		assertEquals(r.suggestedThreshold(true), value(m, "threshold"), 0);
		assertEquals(r.suggestedROut(), value(m, "r_out"), 0);
		// with the diameter given the helper does not estimate it, and the threshold depends on it
		assertFalse(r.diameterEstimated());
		assertTrue(r.threshold() != helper(imp, 0, 0).threshold());
		assertTrue(log.startsWith("Contact Tracker: measured 'particles': threshold"), log);
		assertTrue(log.contains("diameter 21.5 px (given)"), log);
	}

	@Test
	void aFrameWithNothingToMeasureLeavesTheFieldsAndSaysWhy() throws Exception {
		final Module m = dialog(ProfileScenes.empty("background only"));
		m.setInput("threshold", 123.0);
		m.setInput("r_out", 17.0);
		m.setInput("diameter", 0.0);
		final String log = press(m);
		assertEquals(123, value(m, "threshold"), 0);
		assertEquals(17, value(m, "r_out"), 0);
		assertEquals(0, value(m, "diameter"), 0);
		assertEquals("Contact Tracker: cannot measure from the image: no particle brighter than the noise in the " +
			"frame", log.trim(), "one line, no stack trace");
		assertFalse(((Cancelable) m).isCanceled(), "the dialog stays open");

		// an image the command refuses says so the same way
		final Module zt = dialog(Simulated.zAndT("zt"));
		assertTrue(press(zt).trim().startsWith("Contact Tracker: cannot measure from the image: 'zt' has 2 Z slices " +
			"and 2 time frames"));
		assertEquals(TrackingSettings.THRESHOLD.defaultValue(), value(zt, "threshold"), 0);
	}

	/** Headless and from scripts the button is an optional input nobody sets: the run ignores it. */
	@Test
	void theButtonIsNoSettingAndARunIgnoresIt() throws Exception {
		final ModuleItem<?> button = context.service(CommandService.class).getCommand(ContactTrackerCommand.class)
			.getInput("measure");
		assertFalse(button.isRequired());
		assertFalse(button.isPersisted());
		assertNull(TrackingSettings.named("measure"));
		final ImagePlus imp = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		final Module run = Simulated.run(context, ContactTrackerCommand.class, "imp", imp, "threshold", 100.0, "r_out",
			16.0, "overlay", false, "table", false);
		assertFalse(((Cancelable) run).isCanceled(), () -> ((Cancelable) run).getCancelReason());
		assertEquals(100, value(run, "threshold"), 0, "nothing was measured");
	}

	private static String fmt(final double v) {
		return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
	}
}
