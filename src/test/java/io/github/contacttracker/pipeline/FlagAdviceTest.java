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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;

/** What a run that flags most of its spots advises depends on what the run did, and never repeats it. */
class FlagAdviceTest {

	private static TrackerParameters used(final Method method, final Detection detection, final double diameter,
		final int kinds)
	{
		return new TrackerParameters(100, 43, 20, Connectivity.EIGHT, 10, method, diameter, kinds, detection);
	}

	/** Calls {@code check} with every warning flag under every method, detection, diameter given or not and kinds. */
	private static void forEveryWarning(final java.util.function.BiConsumer<Flag, TrackerParameters> check) {
		for (final Method method : Method.values())
			for (final Detection detection : Detection.values())
				for (final double diameter : new double[] { 0, 34.06 })
					for (final int kinds : new int[] { 0, 1, 2 })
						for (final Flag flag : Flag.values())
							if (flag.isWarning()) check.accept(flag, used(method, detection, diameter, kinds));
	}

	/** @return two frames of a pair of {@code type} touching */
	private static FrameSource pair(final ParticleType type) {
		final SimulatedStack<?> pair = SimulatedStack.simulate(type, Scenario.PAIR, 1.0, 2, 3, 8);
		return FrameSource.of(pair.frameCount(), t -> pair.frames().get(t), Calibration.PIXELS, "pair", null);
	}

	/** @return the last warning of a run of {@code source} with {@code settings} in front end {@code ui} */
	private static String lastWarning(final SettingValues settings, final FrameSource source, final FrontEnd ui) {
		final List<String> warnings = new TrackingPipeline(settings, ui).run(source, false).warnings();
		return warnings.get(warnings.size() - 1);
	}

	/** @return the advice as the command line words it */
	private static String cli(final Flag flag, final TrackerParameters used) {
		return FlagAdvice.advice(flag, used, FrontEnd.COMMAND_LINE);
	}

	/**
	 * Every warning flag under every method, detection, diameter given or not and kinds: the advice never names the
	 * method the run used, the detection by the image when the run already found its particles so, a diameter to
	 * give when one was given, nor a number of kinds to give when one was.
	 */
	@Test
	void noAdviceRepeatsWhatTheRunDid() {
		forEveryWarning((flag, used) -> {
			final Method method = used.method();
			final String advice = cli(flag, used);
			final String where = flag + " under " + used;
			assertFalse(advice.isBlank(), where);
			assertFalse(advice.contains("--method " + method.key()), () -> where + ": " + advice);
			if (used.detectsByImage()) assertFalse(advice.contains("--detection image"), () -> where + ": " + advice);
			if (used.diameter() > 0) assertFalse(advice.matches(".*(give|with the particles') --diameter.*"),
				() -> where + ": " + advice);
			if (used.kinds() > 1) assertFalse(advice.contains("--kinds"), () -> where + ": " + advice);
		});
	}

	/**
	 * FELL_BACK has two causes: the paper's second pass (once or iterated) left too few pixels outside the
	 * neighbours' discs, which the advice says with the run's r_out and min_second_area and mends with a method that
	 * models the neighbours; a profile method's fit could not be made, mended by the iterative second pass.
	 */
	@Test
	void fellBackIsExplainedByTheMethodUsed() {
		for (final Method m : List.of(Method.PAPER, Method.ITERATIVE)) {
			final String a = cli(Flag.FELL_BACK, used(m, Detection.THRESHOLD, 34.06, 0));
			assertTrue(a.contains("r_out = 43 px") && a.contains("fewer than 10 pixels") && a.contains(
				"--min-second-area"), a);
			assertTrue(a.contains("r_out is at least the diameter, 34.06 px"), a);
			assertTrue(a.contains("--method fit"), a);
			assertFalse(a.contains("--method iterative"), a);
		}
		// a diameter above r_out: the neighbour's disc does not reach the centre, and the advice does not say it does
		assertFalse(cli(Flag.FELL_BACK, used(Method.PAPER, Detection.THRESHOLD, 50, 0)).contains(
			"at least the diameter"));
		for (final Method m : List.of(Method.FIT, Method.DEBLEND))
			assertTrue(cli(Flag.FELL_BACK, used(m, Detection.THRESHOLD, 0, 0)).contains(
				"--method iterative"), m::key);
		// merges under the paper's method: the detection by the image comes with a method that uses it
		assertTrue(cli(Flag.MERGED, used(Method.PAPER, Detection.THRESHOLD, 34.06, 0)).contains(
			"--method fit --detection image"));
		assertTrue(cli(Flag.MERGED, used(Method.FIT, Detection.THRESHOLD, 0, 0)).contains(
			"use --detection image and give --diameter"));
	}

	/**
	 * A run that tracks touching particles with the iterative second pass and an r_out above their diameter (no
	 * pixel of either is outside the other's disc) flags every spot FELL_BACK; its warning says so with the
	 * run's own values and advises the joint fit, not the method it used.
	 */
	@Test
	void anIterativeRunOnTouchingParticlesIsAdvisedTheFit() {
		final ParticleType type = PaperParticles.silica206();
		assertTrue(type.rOut() > type.diameterPx(), "the preset's r_out reaches past a touching neighbour's centre");
		final FrameSource source = pair(type);
		final SettingValues settings = SettingValues.defaults().with(TrackingSettings.THRESHOLD, type.threshold()).with(
			TrackingSettings.R_OUT, type.rOut()).with(TrackingSettings.DIAMETER, type.diameterPx()).with(
				TrackingSettings.METHOD, Method.ITERATIVE.key());
		final TrackingResult r = new TrackingPipeline(settings).run(source, false);
		assertEquals(4, r.spots().size(), r.spots().toString());
		assertTrue(r.spots().stream().allMatch(s -> s.has(Flag.FELL_BACK)), r.spots().toString());
		final String warning = r.warnings().get(r.warnings().size() - 1);
		assertTrue(warning.startsWith("4 of 4 spots (100%) are flagged, most FELL_BACK (4): "), warning);
		assertTrue(warning.contains("r_out is at least the diameter"), warning);
		assertTrue(warning.contains("--method fit"), warning);
		assertFalse(warning.contains("--method iterative"), warning);

		// the same run in Fiji names the dialog's fields and the macro keys, in TrackMate the panel's fields
		final String inFiji = lastWarning(settings, source, FrontEnd.FIJI);
		assertTrue(inFiji.startsWith("4 of 4 spots (100%) are flagged, most FELL_BACK (4): "), inFiji);
		assertTrue(inFiji.contains("set 'Method' to fit (macro method=fit)"), inFiji);
		assertTrue(inFiji.contains("'Min second area' (macro min_second_area)"), inFiji);
		assertTrue(inFiji.contains("Contact Tracker Profile"), inFiji);
		assertFalse(inFiji.contains("--"), inFiji);
		final String inPanel = lastWarning(settings, source, FrontEnd.TRACKMATE);
		assertTrue(inPanel.contains("set 'Method' to fit"), inPanel);
		assertFalse(inPanel.contains("--") || inPanel.contains("macro"), inPanel);
		for (final String line : List.of(warning, inFiji, inPanel))
			assertPlain(line, "the run's warning");
	}

	/**
	 * A run that finds no spot says so, with what it left out and what to try in the front end's terms: here every
	 * area of a pair is smaller than the min area asked for. A run that finds spots, or has no frame, says nothing of
	 * the kind.
	 */
	@Test
	void aRunThatFindsNothingSaysWhy() {
		final ParticleType type = PaperParticles.silica206();
		final FrameSource source = pair(type);
		final SettingValues settings = SettingValues.defaults().with(TrackingSettings.THRESHOLD, type.threshold()).with(
			TrackingSettings.R_OUT, type.rOut()).with(TrackingSettings.DIAMETER, type.diameterPx()).with(
				TrackingSettings.DETECTION, TrackingSettings.BY_THRESHOLD).with(TrackingSettings.MIN_AREA, 100_000);
		final TrackingResult r = new TrackingPipeline(settings).run(source, false);
		assertEquals(0, r.spots().size());
		final String warning = r.warnings().get(r.warnings().size() - 1);
		assertTrue(warning.startsWith("no spot found in 2 frames: no area at or above --threshold "), warning);
		assertTrue(warning.contains("(4 smaller than --min-area 100000"), warning);
		assertTrue(warning.contains("--particles dark"), warning);
		final String inFiji = lastWarning(settings, source, FrontEnd.FIJI);
		assertTrue(inFiji.contains("'Min area' (macro min_area)"), inFiji);
		assertFalse(inFiji.contains("--"), inFiji);
		assertPlain(warning, "the run's warning");

		final TrackerParameters byImage = used(Method.FIT, Detection.IMAGE, 34.06, 1);
		final String image = FlagAdvice.nothingFound(0, 5, 12, byImage, true, FrontEnd.COMMAND_LINE);
		assertTrue(image.startsWith("no spot found in 5 frames: no peak of the image filtered at the particles' " +
			"diameter was kept as a particle (12 seeds left out: too faint, or not needed by the fit): check --diameter, " +
			"now 34.06 px"), image);
		assertFalse(image.contains("--particles dark"), "the run already inverted the frames: " + image);
		assertEquals(null, FlagAdvice.nothingFound(1, 5, 12, byImage, false, FrontEnd.COMMAND_LINE));
		assertEquals(null, FlagAdvice.nothingFound(0, 0, 0, byImage, false, FrontEnd.COMMAND_LINE));
	}

	/**
	 * A field of 16 bright and 9 dark soft-edged discs (D 10 px, 80 above and below a background of 100, noise 3), tracked
	 * bright: the run finds the bright ones and says that frame 1 also holds 9 dark blobs, naming the setting that
	 * tracks them, in each front end's words; tracked dark, it finds the dark ones and names the bright ones. A field of
	 * bright discs alone says nothing of the kind, and neither do fewer than 5 such blobs or fewer than a fifth as many
	 * as the spots.
	 */
	@Test
	void aFieldOfBothContrastsSaysWhatTheRunLeftOut() {
		final SettingValues settings = SettingValues.defaults().with(TrackingSettings.THRESHOLD, 140.0).with(
			TrackingSettings.R_OUT, 9.0).with(TrackingSettings.DIAMETER, 10.0).with(TrackingSettings.DETECTION,
				TrackingSettings.IMAGE);
		final TrackingResult bright = new TrackingPipeline(settings).run(mixed(3), false);
		assertEquals(16, bright.spots().size(), "the bright ones");
		final String said = bright.warnings().get(bright.warnings().size() - 1);
		assertTrue(said.startsWith("frame 1 also holds 9 blobs darker than the background, at least half as strong as the 16 " +
			"particles tracked there"), said);
		assertTrue(said.endsWith("track them in a second run: use --particles dark"), said);
		assertPlain(said, "the run's warning");
		final String inFiji = lastWarning(settings, mixed(3), FrontEnd.FIJI);
		assertTrue(inFiji.contains("'Particles' (macro particles=dark)") || inFiji.contains("set 'Particles' to dark"),
			inFiji);
		assertFalse(inFiji.contains("--"), inFiji);
		final TrackingResult dark = new TrackingPipeline(settings.withText(TrackingSettings.PARTICLES,
			TrackingSettings.DARK).with(TrackingSettings.THRESHOLD, 255 - 60.0)).run(mixed(3), false);
		assertEquals(9, dark.spots().size(), "the dark ones");
		assertTrue(dark.warnings().stream().anyMatch(w -> w.startsWith("frame 1 also holds 16 blobs brighter") && w
			.endsWith("--particles bright")), dark.warnings().toString());
		final TrackingResult alone = new TrackingPipeline(settings).run(mixed(0), false);
		assertEquals(25, alone.spots().size());
		assertTrue(alone.warnings().stream().noneMatch(w -> w.contains("also holds")), alone.warnings().toString());
		assertEquals(null, FlagAdvice.otherContrast(4, 10, false, FrontEnd.COMMAND_LINE));
		assertEquals(null, FlagAdvice.otherContrast(9, 50, false, FrontEnd.COMMAND_LINE));
	}

	/**
	 * @return one 8-bit frame of 160 x 160 px, 25 soft-edged discs of D 10 px on a grid, every {@code darkEvery}-th dark
	 *         (80 below a background of 100) and the others bright (80 above), Gaussian noise 3
	 */
	private static FrameSource mixed(final int darkEvery) {
		final List<double[]> bright = new java.util.ArrayList<>(), dark = new java.util.ArrayList<>();
		int i = 0;
		for (int gy = 0; gy < 5; gy++)
			for (int gx = 0; gx < 5; gx++, i++)
				(darkEvery > 0 && i % darkEvery == 0 ? dark : bright).add(new double[] { 18.3 + 30.1 * gx, 17.6 + 30.4 *
					gy });
		final java.util.function.DoubleUnaryOperator disc = r -> 80 / (1 + Math.exp((r - 5) / 0.7));
		final double[] up = io.github.contacttracker.core.TestImages.render(160, 160, 100, disc, bright.toArray(
			double[][]::new));
		final double[] down = io.github.contacttracker.core.TestImages.render(160, 160, 0, disc, dark.toArray(
			double[][]::new));
		final java.util.Random noise = new java.util.Random(3);
		final byte[] px = new byte[up.length];
		for (int k = 0; k < px.length; k++)
			px[k] = (byte) Math.max(0, Math.min(255, Math.round(up[k] - down[k] + 3 * noise.nextGaussian())));
		return FrameSource.of(1, t -> net.imglib2.img.array.ArrayImgs.unsignedBytes(px, 160, 160), Calibration.PIXELS,
			"mixed", null);
	}

	/**
	 * Every advice, in every front end, names each setting as its users meet it: no command-line option outside the
	 * command line, and in Fiji each field's label (the start of the dialog's) with its macro key.
	 */
	@Test
	void eachFrontEndNamesTheSettingsItsOwnWay() {
		forEveryWarning((flag, used) -> {
			final String cli = cli(flag, used);
			final String fiji = FlagAdvice.advice(flag, used, FrontEnd.FIJI);
			final String panel = FlagAdvice.advice(flag, used, FrontEnd.TRACKMATE);
			for (final String a : List.of(fiji, panel))
				assertFalse(a.contains("--") || a.contains("contact-tracker "), flag + ": " + a);
			for (final Setting<?> s : TrackingSettings.ALL)
				if (Pattern.compile(Pattern.quote(s.cliOption()) + "(?![\\w-])").matcher(cli).find()) {
					assertTrue(fiji.contains("'" + s.label() + "'") && Pattern.compile("\\(macro [^)]*\\b" + s.name() +
						"\\b").matcher(fiji).find(), () -> s.name() + " in " + fiji);
					assertTrue(panel.contains("'" + s.label()), () -> s.name() + " in " + panel);
				}
		});
	}

	/**
	 * Every advice, in every front end, reads once as a sentence: a setting's name is followed by at most one bracket
	 * (its macro key), never by a second with its value, and no bracket is empty or holds another.
	 */
	@Test
	void everyAdviceIsPlainText() {
		forEveryWarning((flag, used) -> {
			for (final FrontEnd ui : FrontEnd.values())
				assertPlain(FlagAdvice.advice(flag, used, ui), flag + " under " + used + " in " + ui);
		});
	}

	/** Two bracket groups in a row, an empty one, or one inside another fail; so do unbalanced brackets. */
	private static void assertPlain(final String line, final String where) {
		assertFalse(Pattern.compile("\\)\\s*\\(").matcher(line).find(), () -> where + ", two brackets in a row: " +
			line);
		assertFalse(Pattern.compile("\\(\\s*\\)").matcher(line).find(), () -> where + ", empty brackets: " + line);
		int depth = 0;
		for (int i = 0; i < line.length(); i++) {
			if (line.charAt(i) == '(') depth++;
			else if (line.charAt(i) == ')') depth--;
			final int d = depth;
			assertTrue(d == 0 || d == 1, () -> where + ", brackets nested or unbalanced at " + d + ": " + line);
		}
		assertEquals(0, depth, () -> where + ", an unclosed bracket: " + line);
	}
}
