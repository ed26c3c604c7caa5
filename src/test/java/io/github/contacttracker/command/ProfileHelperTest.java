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
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.module.Module;

import ij.ImagePlus;
import ij.gui.Plot;
import ij.gui.PointRoi;
import io.github.contacttracker.advisor.Finding;
import io.github.contacttracker.advisor.Margins;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.report.ProfileReport;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.QuantisedFrame;
import io.github.contacttracker.lab.sim.RadialProfile;
import io.github.contacttracker.lab.sim.SimulatedStack;
import net.imglib2.img.array.ArrayImg;

/**
 * The parameter helper on a simulated isolated particle of known profile: its suggestions land within 2 px
 * ({@code r_out}) and within the noise margin (threshold) of the same rule applied to the true profile.
 * <p>
 * The particles are defined here (not taken from the paper presets, which may be retuned): a short-range one
 * whose dark first ring stays below the background at contact, and a long-range one whose bright second ring
 * lies beyond {@code D/2} and so sets the threshold.
 */
class ProfileHelperTest extends WithContext {

	/** Short range, the 5.53 um kind: D = 65 px. */
	static final ParticleType SHORT = new ParticleType("short range", 6.5, 100, new GaussianBesselProfile(120, 0.1,
		18), 60, 100, 52, NoiseModel.uniform(5));
	/** Long range, the 2.06 um kind: D = 56 px, second bright ring at 44 px. */
	static final ParticleType LONG = new ParticleType("long range", 5.6, 100, new GaussianBesselProfile(100, 0.16, 40),
		80, 115, 80, NoiseModel.uniform(5));

	/** One particle at (cx, cy) in a frame with room for 2.5 diameters around it. */
	record Scene(ParticleType type, ArrayImg<?, ?> frame, double cx, double cy) {}

	static Scene scene(final ParticleType type, final long seed) {
		final int size = (int) Math.ceil(2 * Margins.AUTO_RADIUS_DIAMETERS * type.diameterPx()) + 12;
		final double cx = size / 2.0 + 0.31, cy = size / 2.0 - 0.27;
		final QuantisedFrame<?> q = SimulatedStack.renderFrame(type, List.of(new double[] { cx, cy }), size, size, type
			.noise(), new SplittableRandom(seed), 8);
		return new Scene(type, q.image(), cx, cy);
	}

	/** The rule on the true profile: pixel noise = the noise model's plus rounding to integers. */
	static double trueSigma(final ParticleType type) {
		return Math.sqrt(type.noise().sigma() * type.noise().sigma() + 1.0 / 12);
	}

	static double trueROut(final ParticleType type) {
		return type.profile().reach(trueSigma(type)) + Margins.R_OUT_MARGIN_PX;
	}

	static double trueThreshold(final ParticleType type) {
		final RadialProfile p = type.profile();
		final double reach = p.reach(trueSigma(type));
		double brightest = 0;
		for (double r = type.diameterPx() / 2; r <= reach; r += 0.01)
			brightest = Math.max(brightest, p.value(r));
		return type.background() + 2 * brightest + Margins.THRESHOLD_MARGIN_SIGMAS * trueSigma(type);
	}

	static Stream<Arguments> particles() {
		return Stream.of(Arguments.of(SHORT, 11L), Arguments.of(LONG, 12L));
	}

	@ParameterizedTest
	@MethodSource("particles")
	void suggestionsMatchTheRuleOnTheTrueProfile(final ParticleType type, final long seed) {
		final Scene s = scene(type, seed);
		// the user clicks a couple of pixels off the centre
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(rai(s), Math.round(s.cx() + 2), Math.round(s.cy() - 1),
			type.diameterPx(), 0);
		final double sigma = trueSigma(type);
		assertTrue(r.refined());
		assertEquals(s.cx(), r.x(), 0.1, "centre x");
		assertEquals(s.cy(), r.y(), 0.1, "centre y");
		assertEquals(type.background(), r.background(), 0.5, "background");
		assertEquals(sigma, r.noise(), 0.1 * sigma, "noise");
		assertEquals(trueROut(type), r.rOut(), 2, "r_out within 2 px");
		assertEquals(trueThreshold(type), r.threshold(), Margins.THRESHOLD_MARGIN_SIGMAS * sigma,
			"threshold within the noise margin");
		// the measured profile is the true one
		for (int k = 1; k < r.radius().length; k += 7)
			assertEquals(type.background() + type.profile().value(r.radius()[k]), r.level()[k], 1.5, "ring " + k);
	}

	@Test
	void theLongRangeRingSetsTheThresholdAndItsReachIsExplained() {
		final ProfileAnalysis.Result r = atCentre(scene(LONG, 3L));
		assertTrue(r.bridge() > LONG.background() + 20, "the second ring beyond D/2 is bright: " + r.bridge());
		assertTrue(r.rOut() > LONG.diameterPx());
		// r_out beyond D is where this particle's light ends: no warning against the helper's own value, and the report
		// says what it means for the paper's second pass at contact
		assertEquals(List.of(), ProfileReport.warnings(r).stream().filter(w -> w.contains("r_out")).toList());
		assertTrue(ProfileReport.lines(r, true).stream().anyMatch(l -> l.contains("--method paper keeps the first " +
			"pass")), ProfileReport.lines(r, true).toString());
		final ProfileAnalysis.Result s = atCentre(scene(SHORT, 3L));
		assertEquals(List.of(), s.findings());
		assertTrue(s.activeRadius() > 0.25 * SHORT.diameterPx(), "a usable active area: " + s.activeRadius());
	}

	/**
	 * A particle alone (no neighbour to measure a distance to): the diameter is where its own image ends (here the
	 * reach of its true profile: a dark ring shallower than 3 noise sigmas does not count), not an error.
	 */
	@Test
	void aLoneParticlesDiameterIsWhereItsImageEnds() {
		final Scene s = scene(SHORT, 5L);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(rai(s), s.cx(), s.cy(), 0, 0);
		final double sigma = trueSigma(SHORT);
		double deepest = 0, atDeepest = 0;
		for (double x = 0; x < 3 * SHORT.diameterPx(); x += 0.01)
			if (SHORT.profile().value(x) < deepest) {
				deepest = SHORT.profile().value(x);
				atDeepest = x;
			}
		// its dark ring (-8 grey levels) is shallower than 3 noise sigmas: the image ends at the reach, where the
		// profile stays within the noise
		assertTrue(deepest > -3 * sigma && deepest < -sigma, "a shallow dark ring: " + deepest);
		final double edge = SHORT.profile().reach(sigma);
		assertEquals(2 * edge, r.diameter(), 2.0, "twice the reach of the true profile " + edge);
		assertTrue(r.diameterEstimated());
		assertTrue(r.findings().stream().anyMatch(f -> f instanceof Finding.DiameterFromImage), r.findings().toString());
		assertTrue(ProfileReport.warnings(r).stream().anyMatch(w -> w.contains("where the particles' image returns to " +
			"the background")), ProfileReport.warnings(r).toString());
	}

	@Test
	void badInputsAreRefused() {
		final Scene s = scene(SHORT, 5L);
		assertEquals("diameter must be the particle diameter in pixels (> 0; 0 = estimate it), not -1", assertThrows(
			IllegalArgumentException.class, () -> ProfileAnalysis.analyse(rai(s), s.cx(), s.cy(), -1, 0)).getMessage());
		assertTrue(assertThrows(IllegalArgumentException.class, () -> ProfileAnalysis.analyse(rai(s), -5, 3, 65, 0))
			.getMessage().contains("is outside the image"));
		// a point on the background
		assertTrue(assertThrows(IllegalArgumentException.class, () -> ProfileAnalysis.analyse(rai(s), 3, 3, 65, 0))
			.getMessage().startsWith("no bright particle at (3, 3)"));
	}

	@Test
	void theCommandPlotsAndReturnsTheRoundedSuggestions() throws Exception {
		final Scene s = scene(SHORT, 7L);
		final ImagePlus imp = TimeSeries.of("one particle", List.of(s.frame()), Calibration.PIXELS);
		imp.setRoi(new PointRoi((int) Math.round(s.cx()) + 1, (int) Math.round(s.cy())));
		final Module m = Simulated.run(context, ContactTrackerProfileCommand.class, "imp", imp, "diameter", Double
			.toString(SHORT.diameterPx()), "max_radius", "0", "plot", "false");
		assertFalse(((Cancelable) m).isCanceled(), () -> ((Cancelable) m).getCancelReason());
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(rai(s), Math.round(s.cx()) + 1, Math.round(s.cy()),
			SHORT.diameterPx(), 0);
		assertEquals(Math.ceil(r.threshold()), (double) m.getOutput("suggested_threshold"), 1e-9);
		assertEquals(Math.ceil(r.rOut()), (double) m.getOutput("suggested_r_out"), 1e-9);
		assertEquals(r.background(), (double) m.getOutput("background"), 1e-9);
		assertEquals(r.noise(), (double) m.getOutput("noise"), 1e-9);
		assertEquals(s.cx(), (double) m.getOutput("centre_x"), 0.1);
		final Plot plot = (Plot) m.getOutput("profile");
		assertNotNull(plot);
		assertNotNull(plot.getProcessor(), "the plot renders headless");
		// the noise band's two lines (objects 2 and 3, after the profile and the background) can be told apart
		assertTrue(plot.getPlotObjectStyle(2).startsWith(ij.plugin.Colors.colorToString(
			io.github.contacttracker.plot.ProfilePlots.NOISE_BAND) + ","), plot.getPlotObjectStyle(2));
		assertTrue(plot.getPlotObjectStyle(3).startsWith(ij.plugin.Colors.colorToString(
			io.github.contacttracker.plot.ProfilePlots.NOISE_BAND_LOW) + ","), plot.getPlotObjectStyle(3));
		assertFalse(plot.getPlotObjectStyle(2).split(",")[0].equals(plot.getPlotObjectStyle(3).split(",")[0]));
		// the legend (top right) has the top of the plot to itself: the profile, the threshold and the noise band
		// all lie in the lower 60%
		final double[] limits = plot.getLimits();
		final double top = limits[2] + 0.6 * (limits[3] - limits[2]);
		for (final double v : r.level())
			if (Double.isFinite(v)) assertTrue(v <= top, v + " above " + top);
		assertTrue((double) m.getOutput("suggested_threshold") <= top);
		assertTrue(r.background() + r.noise() <= top);

		// without a point: a clear message
		imp.deleteRoi();
		final Module none = Simulated.run(context, ContactTrackerProfileCommand.class, "imp", imp, "diameter", 65.0);
		assertTrue(((Cancelable) none).isCanceled());
		assertTrue(((Cancelable) none).getCancelReason().startsWith("no point on the image: click on an isolated " +
			"particle with the point tool"), ((Cancelable) none).getCancelReason());
	}

	private static ProfileAnalysis.Result atCentre(final Scene s) {
		return ProfileAnalysis.analyse(rai(s), Math.round(s.cx()), Math.round(s.cy()), s.type().diameterPx(), 0);
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static net.imglib2.RandomAccessibleInterval rai(final Scene s) {
		return (net.imglib2.RandomAccessibleInterval) s.frame();
	}

	@Test
	void logLinesAreWrappedToTheLogWindowsWidth() {
		final String warning = "  warning: the profile has not returned to background within max_radius = 80 px; " +
			"give a larger max_radius or check that the particle is isolated";
		final String wrapped = io.github.contacttracker.report.ShownFrameProfile.wrap(warning, 50, "    ");
		assertEquals(warning.trim().replaceAll(" +", " "), wrapped.trim().replaceAll("\\s+", " "), "no word lost");
		assertTrue(wrapped.startsWith("  warning: the"), wrapped);
		for (final String line : wrapped.split("\n"))
			assertTrue(line.length() <= 50, line);
		assertTrue(wrapped.split("\n")[1].startsWith("    "), "continuation lines are indented");
		assertEquals("short", io.github.contacttracker.report.ShownFrameProfile.wrap("short", 50, "  "));
	}
}
