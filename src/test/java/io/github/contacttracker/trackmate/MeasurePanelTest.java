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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.util.List;
import java.util.Map;

import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JSpinner;
import javax.swing.SwingUtilities;

import org.junit.jupiter.api.Test;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import ij.ImagePlus;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ProfileScenes;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * The panel's "Measure from the image" button: it fills the threshold, {@code r_out} and the diameter with exactly
 * what the profile helper suggests for the frame on display of TrackMate's image (lengths shown in the image's
 * units, returned in pixels), keeps a diameter that was given, and leaves the fields alone with a one-line message
 * when there is nothing to measure.
 */
class MeasurePanelTest {

	/** 0.1 um pixels, so that lengths on the panel differ from pixels. */
	private static final Calibration MICRONS = new Calibration(0.1, 0.1, "micron", 1, "s");

	/** Each test starts from the documented defaults, not the values another test's panel left. */
	@org.junit.jupiter.api.BeforeEach
	void freshSession() {
		LastSettings.forget();
	}

	private static <T extends RealType<T> & NativeType<T>> ContactTrackerConfigurationPanel panel(final ImagePlus imp) {
		return (ContactTrackerConfigurationPanel) new ContactTrackerDetectorFactory<T>().getDetectorConfigurationPanel(
			new Settings(imp), new Model());
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static ProfileAnalysis.Result helper(final ImagePlus imp, final int t, final double diameter) {
		return ProfileAnalysis.analyse((RandomAccessibleInterval) ImagePlusFrames.of(imp, 1).frame(t), diameter, 0);
	}

	private static double number(final Map<String, Object> settings, final String key) {
		return ((Number) settings.get(key)).doubleValue();
	}

	@Test
	void fillsTheFieldsWithTheHelpersSuggestionsForTheFrameShown() {
		final ImagePlus imp = ProfileScenes.particles("particles", 3, MICRONS);
		imp.setPosition(1, 1, 2);
		final ContactTrackerConfigurationPanel panel = panel(imp);
		final Map<String, Object> before = panel.getSettings();
		final String message = panel.measureFromImage();

		final ProfileAnalysis.Result r = helper(imp, 1, 0);
		final Map<String, Object> after = panel.getSettings();
		assertEquals(r.suggestedThreshold(true), number(after, "GREY_THRESHOLD"), 0);
		assertEquals(r.suggestedROut(), number(after, "R_OUT"), 0, "in pixels, whatever the panel shows");
		assertEquals(Math.round(r.diameter() * 100) / 100.0, number(after, "DIAMETER"), 0);
		for (final String key : List.of("MIN_AREA", "MIN_SECOND_AREA", "CONNECTIVITY", "METHOD", "TARGET_CHANNEL"))
			assertEquals(before.get(key), after.get(key), key);
		// r_out is shown in microns, its pixels beside it
		assertTrue(all(panel).stream().anyMatch(c -> c instanceof JSpinner && Math.abs(((Number) ((JSpinner) c)
			.getValue()).doubleValue() - 0.1 * r.suggestedROut()) < 1e-9), "r_out in microns");
		assertTrue(all(panel).stream().anyMatch(c -> c instanceof JLabel && ("micron (" + (long) r.suggestedROut() +
			" px)").equals(((JLabel) c).getText())));
		assertTrue(message.startsWith("Measured 'particles', frame 2: threshold " + (long) r.suggestedThreshold(true) +
			", r_out " + (long) r.suggestedROut() + " px, diameter "), message);
		final int warnings = r.findings().size();
		assertTrue(warnings > 0, "the diameter was estimated: a warning says so");
		assertTrue(message.endsWith("(estimated); " + warnings + " warning" + (warnings == 1 ? "" : "s") +
			" in the Log window"), message);
		assertTrue(shown(panel).contains(message.substring(0, 20)), "the message is on the panel");
	}

	/** Dark particles with PARTICLES at bright: the button finds them dark, sets it, and measures the inverted frame. */
	@Test
	void darkParticlesAreFoundSetAndMeasuredInverted() {
		final ImagePlus bright = ProfileScenes.particles("particles", 1, MICRONS);
		final ProfileAnalysis.Result r = helper(bright, 0, 0);
		final ImagePlus dark = ProfileScenes.particles("particles", 1, MICRONS);
		dark.getProcessor().invert();
		final ContactTrackerConfigurationPanel panel = panel(dark);
		assertEquals("bright", panel.getSettings().get("PARTICLES"));
		final String message = panel.measureFromImage();
		assertEquals("dark", panel.getSettings().get("PARTICLES"));
		assertEquals(r.suggestedThreshold(true), number(panel.getSettings(), "GREY_THRESHOLD"), 0);
		assertEquals(r.suggestedROut(), number(panel.getSettings(), "R_OUT"), 0);
		assertTrue(message.startsWith("Measured 'particles': dark particles (the frame looks so), threshold "), message);
	}

	/**
	 * Two blurred spheres standing apart, whose light at contact rises above their own peak: the helper's threshold
	 * lies above every pixel, and the panel gets what {@code track} measures (detection by the image, a threshold
	 * within the frame, the spheres' rim as the diameter), never a threshold outside the image.
	 */
	@Test
	void aThresholdAboveEveryPixelIsNeverFilledIn() {
		final ImageSimulator sim = new ImageSimulator(r -> 120 / (1 + Math.exp((r - 6) * 1.702 / 1.5)), 3);
		final var frame = Quantiser.toUnsignedBytes(sim.render(List.of(new double[] { 38.3, 40.2 }, new double[] { 62.3,
			40.2 }), 100, 80, 37), NoiseModel.gaussian(3), new java.util.SplittableRandom(11)).image();
		double max = 0;
		for (final var v : frame)
			max = Math.max(max, v.getRealDouble());
		final ContactTrackerConfigurationPanel panel = panel(TimeSeries.of("pair", List.of(frame), MICRONS));
		final String message = panel.measureFromImage();
		final Map<String, Object> after = panel.getSettings();
		assertTrue(number(after, "GREY_THRESHOLD") <= max, after + ", brightest pixel " + max);
		assertEquals(TrackingSettings.IMAGE, after.get("DETECTION"), message);
		assertEquals(12, number(after, "DIAMETER"), 0.6, "in pixels: " + message);
		assertTrue(message.contains("found by their image"), message);

		// detection by the threshold chosen: nothing to fall back to, and the fields stay as they were
		final ContactTrackerConfigurationPanel chosen = panel(TimeSeries.of("pair", List.of(frame), MICRONS));
		final Map<String, Object> byThreshold = new java.util.LinkedHashMap<>(chosen.getSettings());
		byThreshold.put("DETECTION", TrackingSettings.BY_THRESHOLD);
		chosen.setSettings(byThreshold);
		final String refused = chosen.measureFromImage();
		assertTrue(refused.startsWith("Not measured: ") && refused.contains(" lies above its every pixel"), refused);
		assertEquals(byThreshold, chosen.getSettings());
	}

	/** Particles a few pixels across: the button lowers MIN_AREA to the helper's, and says so. */
	@Test
	void minAreaIsLoweredForSmallParticles() {
		final ImagePlus imp = ProfileScenes.tiny("tiny");
		final ContactTrackerConfigurationPanel panel = panel(imp);
		assertEquals(TrackingSettings.MIN_AREA.defaultValue(), number(panel.getSettings(), "MIN_AREA"), 0);
		final String message = panel.measureFromImage();
		final ProfileAnalysis.Result r = helper(imp, 0, 0);
		final int minArea = r.suggestedMinArea(r.suggestedThreshold(true));
		assertTrue(minArea < TrackingSettings.MIN_AREA.defaultValue(), "small particles: " + minArea);
		assertEquals(minArea, number(panel.getSettings(), "MIN_AREA"), 0);
		assertTrue(message.contains(", min area " + minArea + " px (small particles)"), message);
	}

	@Test
	void aGivenDiameterIsKeptAndUsed() {
		final ImagePlus imp = ProfileScenes.particles("particles", 1, MICRONS);
		final ContactTrackerConfigurationPanel panel = panel(imp);
		final Map<String, Object> s = panel.getSettings();
		s.put("DIAMETER", 21.5);
		panel.setSettings(s);
		panel.measureFromImage();
		final ProfileAnalysis.Result r = helper(imp, 0, 21.5);
		assertFalse(r.diameterEstimated());
		assertEquals(21.5, number(panel.getSettings(), "DIAMETER"), 0);
		assertEquals(r.suggestedThreshold(true), number(panel.getSettings(), "GREY_THRESHOLD"), 0);
		assertEquals(r.suggestedROut(), number(panel.getSettings(), "R_OUT"), 0);
	}

	/**
	 * A diameter left in the fields from another image (TrackMate hands the panel the last values) that the helper
	 * cannot measure with: seen in the real wizard, 65.29 px from a simulated movie, then on the real 1-1.tif (34 px
	 * particles, a dense monolayer) the button said "Not measured: only 0 background pixels ... use a larger
	 * max_radius", an option the panel does not have. Now the diameter is estimated instead, and the message says so.
	 */
	@Test
	void aGivenDiameterThatDoesNotFitIsEstimatedInsteadAndSaidSo() {
		final ImagePlus imp = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		final double tooLarge = 5 * ProfileScenes.SMALL.diameterPx();
		final ContactTrackerConfigurationPanel panel = panel(imp);
		final Map<String, Object> s = panel.getSettings();
		s.put("DIAMETER", tooLarge);
		panel.setSettings(s);
		org.junit.jupiter.api.Assertions.assertThrows(io.github.contacttracker.core.InvalidInputException.class,
			() -> helper(imp, 0, tooLarge), "the helper cannot measure with it");
		final String message = panel.measureFromImage();
		final ProfileAnalysis.Result r = helper(imp, 0, 0);
		assertEquals(Math.round(r.diameter() * 100) / 100.0, number(panel.getSettings(), "DIAMETER"), 0);
		assertEquals(r.suggestedThreshold(true), number(panel.getSettings(), "GREY_THRESHOLD"), 0);
		assertEquals(r.suggestedROut(), number(panel.getSettings(), "R_OUT"), 0);
		assertTrue(message.contains("(estimated: 100 px given did not fit)"), message);
		final int warnings = r.findings().size() + 1;
		assertTrue(message.endsWith(warnings + " warnings in the Log window"), message);
	}

	@Test
	void nothingToMeasureLeavesTheFieldsAndSaysWhy() {
		final ContactTrackerConfigurationPanel panel = panel(ProfileScenes.empty("background only"));
		final Map<String, Object> s = panel.getSettings();
		s.put("GREY_THRESHOLD", 123.0);
		s.put("R_OUT", 17.0);
		panel.setSettings(s);
		final String message = panel.measureFromImage();
		assertEquals("Not measured: no particle brighter than the noise in the frame", message);
		assertEquals(s, panel.getSettings());
		assertTrue(shown(panel).contains(message));
	}

	/** The button itself: on the event thread it measures in the background and fills the fields when done. */
	@Test
	void theButtonMeasuresOffTheEventThread() throws Exception {
		final ImagePlus imp = ProfileScenes.particles("particles", 1, Calibration.PIXELS);
		final ContactTrackerConfigurationPanel panel = panel(imp);
		final JButton button = all(panel).stream().filter(c -> c instanceof JButton && ContactTrackerConfigurationPanel.MEASURE
			.equals(((JButton) c).getText())).map(c -> (JButton) c).findFirst().orElse(null);
		assertNotNull(button);
		assertTrue(button.isEnabled());
		SwingUtilities.invokeAndWait(button::doClick);
		final long deadline = System.currentTimeMillis() + 20_000;
		while (!shown(panel).contains("Measured") && System.currentTimeMillis() < deadline)
			Thread.sleep(20);
		SwingUtilities.invokeAndWait(() -> {}); // the fields are filled in the same event as the message
		assertEquals(helper(imp, 0, 0).suggestedThreshold(true), number(panel.getSettings(), "GREY_THRESHOLD"), 0);
		assertTrue(button.isEnabled(), "ready for another measurement");

		// without an image there is nothing to measure on
		final JButton none = all(panel(null)).stream().filter(c -> c instanceof JButton && ContactTrackerConfigurationPanel.MEASURE
			.equals(((JButton) c).getText())).map(c -> (JButton) c).findFirst().orElseThrow();
		assertFalse(none.isEnabled());
	}

	/** @return the texts of the panel's labels */
	private static String shown(final Container panel) {
		final StringBuilder b = new StringBuilder();
		for (final Component c : all(panel))
			if (c instanceof JLabel && ((JLabel) c).getText() != null) b.append(((JLabel) c).getText()).append('\n');
		return b.toString();
	}

	private static List<Component> all(final Container root) {
		return ContactTrackerDetectorFactoryTest.allComponents(root);
	}
}
