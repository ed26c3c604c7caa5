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
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.lab.sim.DetectionScenes;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;
import io.github.contacttracker.lab.sim.SmallParticles;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.converter.Converters;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;
import net.imglib2.view.Views;

/** What {@code track} measures when values are not given: the polarity of the particles among them. */
class MeasuredSettingsTest {

	/**
	 * Bright-field-like particles as on the paper authors' 1.avi (a core saturating far above the 8-bit range, a dark
	 * ring reaching about as far below the background as the core above it, as 1.avi's do, a faint bright ring; D = 32
	 * px), 40 in 320 x 320 px, some touching, background 136, noise 3.
	 */
	private static RandomAccessibleInterval<UnsignedByteType> brightField() {
		final RadialProfile profile = r -> 200 * Math.exp(-r * r / 32) - 115 * Math.exp(-(r - 12) * (r - 12) / 32) + 12 *
			Math.exp(-(r - 27) * (r - 27) / 32);
		final SplittableRandom rnd = new SplittableRandom(3);
		final List<double[]> centres = new ArrayList<>();
		while (centres.size() < 40) {
			final double[] c = { 20 + rnd.nextDouble() * 280, 20 + rnd.nextDouble() * 280 };
			if (centres.stream().allMatch(o -> Math.hypot(c[0] - o[0], c[1] - o[1]) > 31.5)) centres.add(c);
		}
		return Quantiser.toUnsignedBytes(new ImageSimulator(profile, 3).render(centres, 320, 320, 136), NoiseModel
			.gaussian(3), rnd).image();
	}

	@SuppressWarnings("unchecked")
	private static RandomAccessibleInterval<UnsignedByteType> inverted(final RandomAccessibleInterval<UnsignedByteType> f) {
		return (RandomAccessibleInterval<UnsignedByteType>) Inversion.of(f);
	}

	/**
	 * Inverted, such a frame is dark cores in bright rings, and its darkest pixel lies about as far below its median
	 * as its brightest above it (as on 1.avi inverted): the levels do not tell, its blobs do (the cores stand out more
	 * than the rings), and it is measured as the bright frame is, inverted. Said to be bright, the helper takes the
	 * rings for cores and its threshold lies above every pixel; that is said, with what to do, instead of a refusal of
	 * the threshold later. Told dark, the values are those of the bright frame.
	 */
	@Test
	void aThresholdAboveEveryPixelSaysWhatToTry() {
		final RandomAccessibleInterval<UnsignedByteType> bright = brightField(), dark = inverted(bright);
		assertFalse(Contrast.looksDark(bright));
		assertTrue(Contrast.looksDark(dark), "1.avi inverted is dark cores in bright rings");
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result seen = MeasuredSettings.of("bf.tif", dark, true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result measured = MeasuredSettings.of("bf.tif", bright, true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		assertEquals(measured.settings().withText(TrackingSettings.PARTICLES, TrackingSettings.DARK), seen.settings());
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> MeasuredSettings.of("bf.tif",
			dark, true, defaults.withText(TrackingSettings.PARTICLES, "bright"), Set.of(
				TrackingSettings.PARTICLES), FrontEnd.COMMAND_LINE));
		assertTrue(e.getMessage().startsWith("cannot measure --threshold on the first frame of bf.tif: the helper's "),
			e.getMessage());
		assertTrue(e.getMessage().contains(" lies above its every pixel ("), e.getMessage());
		assertTrue(e.getMessage().contains("; if the particles are darker than the background, give --particles dark;"),
			e.getMessage());
		// what else the frame shows: its blobs' size, and the options that track them by their image
		assertTrue(e.getMessage().contains("; its blobs are about ") && e.getMessage().contains(
			" px across: --detection image --diameter "), e.getMessage());

		final MeasuredSettings.Result fromBright = MeasuredSettings.of("bf.tif", bright, true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result told = MeasuredSettings.of("bf.tif", dark, true, defaults.withText(
			TrackingSettings.PARTICLES, TrackingSettings.DARK), Set.of(TrackingSettings.PARTICLES), FrontEnd.COMMAND_LINE);
		assertEquals(fromBright.settings().withText(TrackingSettings.PARTICLES, TrackingSettings.DARK), told.settings());
		assertEquals(fromBright.notice(), told.notice(), "nothing measured about the polarity: it was given");
	}

	/**
	 * The same frame, dark cores in bright rings, where the user says what the particles are: bright, of a diameter
	 * given. The inverted frame's blobs stand out more, which with nothing said refuses the run (above); told both the
	 * contrast and the diameter, the run is tracked as told, by the particles' image (a tweezer's bead, dark inside a
	 * bright rim, given --particles dark and its diameter, was refused because its rim's pieces stood out more). Told the
	 * contrast alone, it is still refused.
	 */
	@Test
	void theContrastAndDiameterGivenAreTrackedAsTold() {
		final RandomAccessibleInterval<UnsignedByteType> dark = inverted(brightField());
		final SettingValues bright = SettingValues.defaults().withText(TrackingSettings.PARTICLES, "bright");
		assertThrows(InvalidInputException.class, () -> MeasuredSettings.of("bf.tif", dark, true, bright, Set.of(
			TrackingSettings.PARTICLES), FrontEnd.COMMAND_LINE));
		final MeasuredSettings.Result told = MeasuredSettings.of("bf.tif", dark, true, bright.with(
			TrackingSettings.DIAMETER, 24.0), Set.of(TrackingSettings.PARTICLES, TrackingSettings.DIAMETER),
			FrontEnd.COMMAND_LINE);
		assertEquals(TrackingSettings.IMAGE, told.settings().get(TrackingSettings.DETECTION), told.notice());
		assertEquals(24.0, told.settings().diameter(), told.notice());
		assertTrue(told.notice().contains("tracked by the particles' image"), told.notice());
	}

	/**
	 * Two particles dark inside a bright ring (a core 700 grey levels deep, a ring 350 high at the radius of 12 px),
	 * two diameters apart (a tweezer pair's first frame), on a 16-bit ramp of light (3,000 to 4,500 across, 300 down), noise 80; {@code sign} -1 gives the same
	 * particles inverted about the background: bright cores in dark rings.
	 */
	private static RandomAccessibleInterval<UnsignedShortType> ringsOnARamp(final double sign) {
		return ringsOnARamp(sign, 48);
	}

	/** As {@link #ringsOnARamp(double)}, the pair's centres {@code apart} px apart (its diameter is about 24 px). */
	private static RandomAccessibleInterval<UnsignedShortType> ringsOnARamp(final double sign, final double apart) {
		final RadialProfile profile = r -> sign * (-700 * Math.exp(-r * r / (2 * 4.2 * 4.2)) + 350 * Math.exp(-(r - 12) *
			(r - 12) / (2 * 2.2 * 2.2)));
		final int w = 200, h = 140;
		final NoiseFreeImage image = new ImageSimulator(profile, 3).render(List.of(new double[] { 100 - apart / 2, 70 }, new double[] {
			100 + apart / 2, 70 }), w, h, 0);
		final double[] p = image.pixels();
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				p[y * w + x] += 3000 + 1500.0 * x / w + 300.0 * y / h;
		return Quantiser.toUnsignedShorts(image, NoiseModel.gaussian(80), new SplittableRandom(9)).image();
	}

	/**
	 * Particles dark inside a bright ring reach further below the background than above it, 1.3 to 1.6 times as far,
	 * and the inverted frame's blobs (their cores) stand out more: taken for dark, read relative to the light, which
	 * on a ramp puts the frame's darkest pixel in its dark corner (the pair was taken for bright, the helper measured
	 * noise's bumps 1.9 px across, and the run found 2 spots in 40 frames; with --particles dark, both in each).
	 * Inverted (bright cores in dark rings, as a bright-field movie's), they stay bright.
	 */
	@Test
	void darkCoresInBrightRingsOnARampAreTakenForDark() {
		assertTrue(Contrast.looksDark(ringsOnARamp(1)));
		assertFalse(Contrast.looksDark(ringsOnARamp(-1)));
		final MeasuredSettings.Result r = MeasuredSettings.of("pair.tif", ringsOnARamp(1), true, SettingValues.defaults(),
			Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(r.settings().dark() && r.notice().contains("--particles dark"), r.notice());
		assertEquals(24, r.settings().diameter(), 4, r.notice());
	}

	/**
	 * Pushed into contact, a tweezer pair of such particles puts its two rings' light together where they cross, as
	 * bright there as the cores are dark: the frame's extremes no longer tell (its darkest pixel 1.0 to 1.1 times as
	 * far below as its brightest above), and its blobs decide (the cores stand out about twice as much as the rings at
	 * the particles' scale). This pair was taken for bright below 1.17 diameters apart, and a single frame of the
	 * detection study's ring pair at 1.08 and 0.96 diameters refused ("no single particle away from the border");
	 * with the blobs deciding, it is dark down to contact, and both of the study's particles are found. Inverted,
	 * still bright.
	 */
	@Test
	void darkCoresInBrightRingsAtContactAreTakenForDark() {
		for (final double apart : new double[] { 26, 24 }) {
			assertTrue(Contrast.looksDark(ringsOnARamp(1, apart)), "apart " + apart);
			assertFalse(Contrast.looksDark(ringsOnARamp(-1, apart)), "apart " + apart);
		}
		final MeasuredSettings.Result r = MeasuredSettings.of("pair.tif", ringsOnARamp(1, 24), true, SettingValues
			.defaults(), Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(r.settings().dark() && r.notice().contains("--particles dark"), r.notice());
	}

	/**
	 * Spheres as a dense confocal slice shows them: bright cores 8 px across, about 12 px apart, 40 grey levels above a
	 * background of 30, under photon noise of 15.
	 */
	private static RandomAccessibleInterval<UnsignedByteType> noisyPacked() {
		final RadialProfile profile = r -> 40 / (1 + Math.exp((r - 4) / 0.7));
		final SplittableRandom rnd = new SplittableRandom(5);
		final List<double[]> centres = new ArrayList<>();
		for (int attempt = 0; attempt < 4000; attempt++) {
			final double[] c = { 6 + rnd.nextDouble() * 148, 6 + rnd.nextDouble() * 148 };
			if (centres.stream().allMatch(o -> Math.hypot(c[0] - o[0], c[1] - o[1]) > 11)) centres.add(c);
		}
		return Quantiser.toUnsignedBytes(new ImageSimulator(profile, 3).render(centres, 160, 160, 30), NoiseModel
			.gaussian(15), rnd).image();
	}

	/**
	 * Where the noise hides where the particles' profile returns to the background, the helper's own diameter is far
	 * too small and its threshold lies above every pixel; it measures again at the diameter of the frame's blobs, and
	 * says so (a confocal stack of polydisperse spheres: 3.2 px, then 8.0 px, and its spots 29% flagged instead of all).
	 */
	@Test
	void whereTheHelpersOwnThresholdLiesOutsideTheFrameItMeasuresAtTheBlobs() {
		final RandomAccessibleInterval<UnsignedByteType> frame = noisyPacked();
		final double own = ProfileAnalysis.analyse(frame, 0, 0).suggestedThreshold(true);
		int brightest = 0;
		for (final UnsignedByteType p : Views.iterable(frame))
			brightest = Math.max(brightest, p.get());
		assertTrue(own > brightest, "the helper's own threshold " + own + ", the brightest pixel " + brightest);
		final MeasuredSettings.Result r = MeasuredSettings.of("c.tif", frame, true, SettingValues.defaults(), Set.of(),
			FrontEnd.COMMAND_LINE);
		assertTrue(r.notice().contains("by the profile helper at the diameter of the frame's blobs"), r.notice());
		assertEquals(8, r.settings().diameter(), 2, r.notice());
		final double t = r.settings().get(TrackingSettings.THRESHOLD);
		assertTrue(t > 30 && t <= brightest, "a threshold above the background, within the frame: " + r.notice());
	}

	/**
	 * What the helper says, where it measures and where it cannot, is said in the words of the front end it runs in: a
	 * Fiji user is pointed to the dialog's fields and their macro keys, and to the Profile command, never to an
	 * option of the command line; a TrackMate user to the panel's fields. The command line's words are its options.
	 */
	@Test
	void theHelperSpeaksTheFrontEndsWords() {
		// (dark cores in bright rings said to be bright)
		final RandomAccessibleInterval<UnsignedByteType> dark = inverted(brightField());
		final SettingValues bright = SettingValues.defaults().withText(TrackingSettings.PARTICLES,
			"bright");
		final Set<Setting<?>> said = Set.of(TrackingSettings.PARTICLES);
		final InvalidInputException fiji = assertThrows(InvalidInputException.class, () -> MeasuredSettings.of("bf.tif",
			dark, true, bright, said, FrontEnd.FIJI));
		assertFalse(fiji.getMessage().contains("--"), fiji.getMessage());
		assertTrue(fiji.getMessage().startsWith("cannot measure 'Threshold' (macro threshold) on the first frame"), fiji
			.getMessage());
		assertTrue(fiji.getMessage().contains("give 'Particles' dark (macro particles=dark)"), fiji.getMessage());
		assertTrue(fiji.getMessage().contains("(Plugins > Tracking > Contact Tracker Profile, a click on the particle, " +
			"measures one particle)"), fiji.getMessage());
		final InvalidInputException cli = assertThrows(InvalidInputException.class, () -> MeasuredSettings.of("bf.tif",
			dark, true, bright, said, FrontEnd.COMMAND_LINE));
		assertTrue(cli.getMessage().contains("give --particles dark") && cli.getMessage().contains(
			"(contact-tracker profile MOVIE --at X,Y measures one particle)"), cli.getMessage());

		final RandomAccessibleInterval<UnsignedByteType> packed = firstFrame(DetectionScenes.dense(1, 3));
		final MeasuredSettings.Result trackMate = MeasuredSettings.of("dense.tif", packed, true, SettingValues
			.defaults(), Set.of(), FrontEnd.TRACKMATE);
		assertFalse(trackMate.notice().contains("--"), trackMate.notice());
		assertTrue(trackMate.notice().contains("tracked by the particles' image: 'Detection' image, 'Particle diameter' "),
			trackMate.notice());
		final MeasuredSettings.Result line = MeasuredSettings.of("dense.tif", packed, true, SettingValues.defaults(), Set
			.of(), FrontEnd.COMMAND_LINE);
		assertEquals(trackMate.settings(), line.settings(), "the words change, not the values");
		assertTrue(line.notice().contains("tracked by the particles' image: --detection image --diameter "), line
			.notice());
	}

	/**
	 * On float data the threshold is suggested as the helper writes a number, four significant digits (a change far
	 * below the noise), and that is the value tracked with, by the helper's profile and by the image's fall-back
	 * alike: a user copies what the notice says and gets the same run.
	 */
	@Test
	void aThresholdMeasuredOnFloatDataReadsAsWrittenAndIsTheOneUsed() {
		final RandomAccessibleInterval<FloatType> isolated = floats(brightField());
		final RandomAccessibleInterval<FloatType> packed = floats(firstFrame(DetectionScenes.dense(1, 3)));
		for (final RandomAccessibleInterval<FloatType> frame : List.of(isolated, packed)) {
			final MeasuredSettings.Result r = MeasuredSettings.of("f.tif", frame, false, SettingValues.defaults(), Set
				.of(), FrontEnd.COMMAND_LINE);
			final double t = r.settings().get(TrackingSettings.THRESHOLD);
			final String written = MeasuredSettings.optionValue(t);
			assertTrue(written.replace("-", "").replace(".", "").replaceFirst("^0+", "").length() <= 4, written);
			assertTrue(r.notice().contains("--threshold " + written + " "), r.notice());
		}
	}

	/** @return {@code frame}'s values times 1.37 plus 0.3, as 32-bit floats: grey levels that are not whole */
	private static RandomAccessibleInterval<FloatType> floats(final RandomAccessibleInterval<UnsignedByteType> frame) {
		return Converters.convert(frame, (i, o) -> o.setReal(1.37 * i.getRealDouble() + 0.3), new FloatType());
	}

	/**
	 * A dense monolayer of two sizes (D 10 and 14 px, area fraction 0.7): the helper's level cuts it into spots nearly
	 * all closer together than two particles can be told apart, and none of the rest stands alone. Before, the helper
	 * measured its profile on the few spots left (4 particles on the study's first movie), suggested r_out 19 px for
	 * particles 10 and 14 px across. It now says it cannot measure, why, and what to give; {@code track} finds the
	 * particles by their image with the frame's blob scale, between the two diameters, and an r_out within one.
	 */
	@Test
	void aLevelThatPartsNoParticlesIsNotMeasuredOn() {
		final RandomAccessibleInterval<UnsignedByteType> packed = firstFrame(DetectionScenes.denseBidisperse(1, 6000));
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> ProfileAnalysis.analyse(packed, 0,
			0));
		assertTrue(e.getMessage().contains(" lie closer to another than two particles of their profile can (") && e
			.getMessage().endsWith("and no other stands alone: that level does not part these particles into one spot " +
				"each; give their diameter"),
			e.getMessage());
		final MeasuredSettings.Result r = MeasuredSettings.of("bidisperse.tif", packed, true, SettingValues.defaults(),
			Set.of(), FrontEnd.COMMAND_LINE);
		assertEquals(TrackingSettings.IMAGE, r.settings().get(TrackingSettings.DETECTION), r.notice());
		assertTrue(r.settings().diameter() > 10 && r.settings().diameter() < 14, r.notice());
		assertTrue(r.settings().get(TrackingSettings.R_OUT) <= 10, r.notice());
		assertTrue(r.notice().contains("could not measure (") && r.notice().contains("does not part these particles"), r
			.notice());
	}

	/**
	 * Bright particles packed edge to edge cover most of the frame, so its median lies on them and the small dark gaps
	 * between them reach far below it: the levels alone would call them dark. Their blobs say otherwise (the inverted
	 * frame's gaps stand no higher than the particles do), and they are taken for what they are. Dark discs standing
	 * apart on a bright background are still taken for dark.
	 */
	@Test
	void aPackedMonolayerOfBrightParticlesIsNotTakenForDark() {
		assertFalse(Contrast.looksDark(firstFrame(DetectionScenes.dense(1, 3))));
		assertTrue(Contrast.looksDark(firstFrame(DetectionScenes.dark(1, 3))));
	}

	@SuppressWarnings("unchecked")
	private static RandomAccessibleInterval<UnsignedByteType> firstFrame(final DetectionScene scene) {
		return (RandomAccessibleInterval<UnsignedByteType>) (Object) scene.frames().get(0);
	}

	/**
	 * Particles darker than a bright background (the inverse of bright ones on a dark one): taken for dark when neither
	 * the threshold nor the polarity was given, and said; with the threshold given, never (it is the user's grey
	 * level).
	 */
	@Test
	void darkParticlesAreMeasuredAsSuchUnlessTheThresholdIsGiven() {
		final RadialProfile profile = r -> 150 * Math.exp(-r * r / 18);
		final SplittableRandom rnd = new SplittableRandom(7);
		final List<double[]> centres = new ArrayList<>();
		for (int k = 0; k < 9; k++)
			centres.add(new double[] { 40 + 60 * (k % 3) + rnd.nextDouble(), 40 + 60 * (k / 3) + rnd.nextDouble() });
		final RandomAccessibleInterval<UnsignedByteType> bright = Quantiser.toUnsignedBytes(new ImageSimulator(profile, 3)
			.render(centres, 200, 200, 40), NoiseModel.gaussian(2), rnd).image(), dark = inverted(bright);
		assertTrue(Contrast.looksDark(dark));
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result fromBright = MeasuredSettings.of("m.tif", bright, true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result fromDark = MeasuredSettings.of("m.tif", dark, true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertEquals(fromBright.settings().withText(TrackingSettings.PARTICLES, TrackingSettings.DARK), fromDark
			.settings());
		assertEquals(fromBright.notice().replace("profile helper:", "profile helper: --particles dark"), fromDark
			.notice());
		final SettingValues given = defaults.with(TrackingSettings.THRESHOLD, 100.0).with(TrackingSettings.R_OUT, 20.0);
		assertFalse(MeasuredSettings.of("m.tif", dark, true, given, Set.of(TrackingSettings.THRESHOLD,
			TrackingSettings.R_OUT), FrontEnd.COMMAND_LINE).settings().dark());
	}
	/**
	 * Particles a few pixels across: their active areas come near the default {@code min_area}, so a smaller one is
	 * measured with the other values and said; one given is kept, and so is the default for large particles.
	 */
	@Test
	void aSmallerMinAreaIsMeasuredForSmallParticlesUnlessGiven() {
		final RandomAccessibleInterval<UnsignedByteType> small = SmallParticles.simulate(1, 11).frames().get(0);
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result measured = MeasuredSettings.of("s.tif", small, true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final int minArea = measured.settings().get(TrackingSettings.MIN_AREA);
		assertTrue(minArea < TrackingSettings.MIN_AREA.defaultValue(), "lowered: " + minArea);
		assertEquals(ProfileAnalysis.analyse(small, 0, 0).suggestedMinArea(measured.settings().get(
			TrackingSettings.THRESHOLD)), minArea, "the helper's, at the threshold used");
		assertTrue(measured.notice().contains(" --min-area " + minArea + " (given values win"), measured.notice());
		final MeasuredSettings.Result given = MeasuredSettings.of("s.tif", small, true, defaults.with(
			TrackingSettings.MIN_AREA, 20), Set.of(TrackingSettings.MIN_AREA), FrontEnd.COMMAND_LINE);
		assertEquals(20, given.settings().get(TrackingSettings.MIN_AREA));
		assertFalse(given.notice().contains("--min-area"), given.notice());
		final MeasuredSettings.Result large = MeasuredSettings.of("bf.tif", brightField(), true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertEquals(TrackingSettings.MIN_AREA.defaultValue(), large.settings().get(TrackingSettings.MIN_AREA));
		assertFalse(large.notice().contains("--min-area"), large.notice());
	}

	/**
	 * Found by the entry-point fuzz: detection by the image on a frame the helper cannot measure, with a diameter of
	 * 1e6 px given, sought seeds at that scale (a filter a million pixels wide) for minutes. The diameter is left to
	 * the tracker, which refuses it in one line.
	 */
	@Test
	void aDiameterBeyondTheFrameIsNotUsedToSeekSeeds() {
		final byte[] flat = new byte[40 * 30];
		java.util.Arrays.fill(flat, (byte) 20);
		final RandomAccessibleInterval<UnsignedByteType> frame = net.imglib2.img.array.ArrayImgs.unsignedBytes(flat, 40,
			30);
		final SettingValues given = SettingValues.defaults().withText(TrackingSettings.DETECTION, TrackingSettings.IMAGE)
			.with(TrackingSettings.DIAMETER, 1e6);
		org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(10), () -> {
			try {
				MeasuredSettings.of("flat.tif", frame, true, given, Set.of(TrackingSettings.DETECTION,
					TrackingSettings.DIAMETER), FrontEnd.COMMAND_LINE);
			}
			catch (final InvalidInputException e) {
				// a refusal in one line is as good as values
			}
		});
	}

	/**
	 * A movie whose first frame is blank (the shutter not yet open, the slices below the coverslip): the helper
	 * measures on the middle frame, says which, and gives the values it gives on that frame alone; it does not track
	 * the blank frame's noise by its image.
	 */
	@Test
	void aBlankFirstFrameIsMeasuredOnTheMiddleOne() {
		final RandomAccessibleInterval<UnsignedByteType> particles = brightField();
		final RandomAccessibleInterval<UnsignedByteType> blank = net.imglib2.img.array.ArrayImgs.unsignedBytes(320, 320);
		for (final UnsignedByteType t : net.imglib2.view.Views.flatIterable(blank))
			t.set(136);
		final List<RandomAccessibleInterval<UnsignedByteType>> movie = List.of(blank, particles, particles, particles);
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result onMovie = MeasuredSettings.of("movie.tif", movie::get, movie.size(), true,
			defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result onFrame = MeasuredSettings.of("movie.tif", particles, true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(onMovie.notice().contains("measured on frame 3 by the profile helper"), onMovie.notice());
		assertEquals(onFrame.notice().replace("frame 1", "frame 3").replace("profile movie.tif", "profile --frame 3 movie.tif"),
			onMovie.notice());
		assertEquals(onFrame.settings(), onMovie.settings());
		assertEquals(TrackingSettings.AUTO, onMovie.settings().get(TrackingSettings.DETECTION), "not sent to the image");
		// one frame, blank: nothing to measure on, said (a constant frame holds no blob either)
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> MeasuredSettings.of("blank.tif",
			List.of(blank)::get, 1, true, defaults, Set.of(), FrontEnd.COMMAND_LINE));
		assertTrue(e.getMessage().startsWith("cannot measure the particles on the first frame of blank.tif"), e
			.getMessage());
	}

	/**
	 * A tweezer pair that starts overlapping and is pulled apart: on the first frame the helper finds no particle
	 * standing alone, so it measures on the middle frame, where the two stand apart, and says which; the values are
	 * those of that frame alone (dark cores in bright rings, their diameter). Before, the first frame's fallback
	 * tracked the whole movie by the image as bright particles: on the detection study's ring pair played backwards,
	 * 64% of the particles were found, none closer than 0.75 diameters; now all, unflagged.
	 */
	@Test
	void aPairOverlappingOnTheFirstFrameIsMeasuredWhereItStandsApart() {
		final List<RandomAccessibleInterval<UnsignedShortType>> movie = List.of(ringsOnARamp(1, 12), ringsOnARamp(1, 30),
			ringsOnARamp(1, 40), ringsOnARamp(1, 48));
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result first = MeasuredSettings.of("pair.tif", movie.get(0), true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		assertTrue(first.notice().contains("the profile helper could not measure"), first.notice());
		final MeasuredSettings.Result onMovie = MeasuredSettings.of("pair.tif", movie::get, movie.size(), true, defaults,
			Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result onFrame = MeasuredSettings.of("pair.tif", movie.get(2), true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		assertTrue(onMovie.notice().contains("measured on frame 3 by the profile helper: --particles dark"), onMovie
			.notice());
		assertEquals(onFrame.notice().replace("frame 1", "frame 3").replace("profile pair.tif", "profile --frame 3 pair.tif"),
			onMovie.notice());
		assertEquals(onFrame.settings(), onMovie.settings());
	}

	/**
	 * A packed field the helper cannot measure on keeps the first frame's fallback (detection by the image, at the
	 * diameter of its blobs): another frame of the same field gives no better values.
	 */
	@Test
	void aPackedFirstFrameKeepsItsFallback() {
		final RandomAccessibleInterval<UnsignedByteType> packed = firstFrame(DetectionScenes.dense(1, 3));
		final List<RandomAccessibleInterval<UnsignedByteType>> movie = List.of(packed, packed, packed);
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result onMovie = MeasuredSettings.of("dense.tif", movie::get, movie.size(), true,
			defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result onFrame = MeasuredSettings.of("dense.tif", packed, true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		assertTrue(onMovie.notice().contains("tracked by the particles' image"), onMovie.notice());
		assertEquals(onFrame.notice(), onMovie.notice());
		assertEquals(onFrame.settings(), onMovie.settings());
	}

	/**
	 * A pair of blurred discs held overlapping on the first frame (0.5 diameters) and pulled apart to 2: the helper
	 * measures the first frame's overlap as one particle nearly twice as wide, and the middle frame's pair, 1.27
	 * diameters apart, sets its spacing; the last frame, where the pair stands apart, gives the particles' size, and
	 * its values are taken, and said (on another movie of the scene, the last frame's rim, where the helper measures
	 * no threshold). The movie played forwards keeps its first frame's values.
	 */
	@Test
	void aPairOverlappingOnTheFirstFrameIsSizedWhereItStandsApart() {
		final List<RandomAccessibleInterval<?>> forward = new ArrayList<>(DetectionScenes.pairSweep(40, 1).frames());
		final List<RandomAccessibleInterval<?>> backward = new ArrayList<>(forward);
		java.util.Collections.reverse(backward);
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result first = MeasuredSettings.of("pair.tif", backward.get(0), true, defaults, Set.of(),
			FrontEnd.COMMAND_LINE);
		assertTrue(first.settings().diameter() > 18, first.notice());
		final MeasuredSettings.Result onMovie = MeasuredSettings.of("pair.tif", backward::get, backward.size(), true,
			defaults, Set.of(), FrontEnd.COMMAND_LINE);
		final MeasuredSettings.Result onLast = MeasuredSettings.of("pair.tif", backward.get(39), true, defaults, Set
			.of(), FrontEnd.COMMAND_LINE);
		assertEquals(onLast.notice().replace("frame 1", "frame 40").replace("profile pair.tif", "profile --frame 40 pair.tif"),
			onMovie.notice());
		assertEquals(onLast.settings(), onMovie.settings());
		assertEquals(12, onMovie.settings().diameter(), 1, onMovie.notice());
		final MeasuredSettings.Result played = MeasuredSettings.of("pair.tif", forward::get, forward.size(), true,
			defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(played.notice().contains("measured on frame 1 by the profile helper"), played.notice());
		// another movie of the scene: on its last frame the helper measures the rim but no threshold, whose size counts
		final List<RandomAccessibleInterval<?>> third = new ArrayList<>(DetectionScenes.pairSweep(40, 3).frames());
		java.util.Collections.reverse(third);
		final MeasuredSettings.Result rim = MeasuredSettings.of("pair.tif", third::get, third.size(), true, defaults,
			Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(rim.notice().contains("the profile helper measured the particles' rim on frame 40 but no threshold"),
			rim.notice());
		assertEquals(12, rim.settings().diameter(), 1, rim.notice());
	}

	/**
	 * A packed field of particles of many sizes (the detection study's dense-polydisperse scene, D 7 to 13.3 px): where
	 * the helper's r_out reaches less than its margin past the particles' radius, the notice says so and what to try
	 * (on this movie, r_out 5 at D 7.7 px: 88% of the particles found; with r_out 6, 99.2%). Where it reaches far
	 * enough (another movie of the scene: r_out 6 at D 7.77 px), or where r_out was given, it says nothing of it.
	 */
	@Test
	void aReachShortOfTheParticlesEdgeSaysWhatToTry() {
		final SettingValues defaults = SettingValues.defaults();
		final MeasuredSettings.Result short_ = MeasuredSettings.of("p.tif", DetectionScenes.densePolydisperse(2, 3)
			.frames().get(0), true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertEquals(5, short_.settings().get(TrackingSettings.R_OUT), short_.notice());
		assertTrue(short_.notice().contains("its --r-out reaches less than 2 px past the particles' radius") && short_
			.notice().endsWith("try --r-out 6 and check the flags"), short_.notice());
		final MeasuredSettings.Result given = MeasuredSettings.of("p.tif", DetectionScenes.densePolydisperse(2, 3)
			.frames().get(0), true, defaults.with(TrackingSettings.R_OUT, 5.0), Set.of(TrackingSettings.R_OUT),
			FrontEnd.COMMAND_LINE);
		assertFalse(given.notice().contains("try --r-out"), given.notice());
		final MeasuredSettings.Result far = MeasuredSettings.of("p.tif", DetectionScenes.densePolydisperse(2, 1)
			.frames().get(0), true, defaults, Set.of(), FrontEnd.COMMAND_LINE);
		assertEquals(6, far.settings().get(TrackingSettings.R_OUT), far.notice());
		assertFalse(far.notice().contains("try --r-out"), far.notice());
	}

	/**
	 * A tweezer's bead a third of the frame across, dark inside a bright rim that reaches the 8-bit ceiling, its core
	 * textured with bright specks (as sanger-matteo/Bead_Tracker's {@code Stack_BoaB}): with its diameter given and not
	 * its contrast, it is taken for dark, judged by the blobs at that diameter (the frame's extremes say bright: the
	 * rim lies 1.6 times as far above the background as the core below).
	 */
	@Test
	void aBeadDarkInsideABrightRimIsDarkAtTheDiameterGiven() {
		final SettingValues given = SettingValues.defaults().with(TrackingSettings.DIAMETER, 62.0);
		final MeasuredSettings.Result r = MeasuredSettings.of("bead.tif", texturedBead(), true, given, Set.of(
			TrackingSettings.DIAMETER), FrontEnd.COMMAND_LINE);
		assertTrue(r.settings().dark(), r.notice());
		assertTrue(r.notice().contains("--particles dark"), r.notice());
	}

	/** 184 x 181 px, 8-bit: a bead of 62 px around (95.3, 91.6), its core 75 below a background of 135, its rim 120 above. */
	private static RandomAccessibleInterval<UnsignedByteType> texturedBead() {
		final int w = 184, h = 181;
		final double cx = 95.3, cy = 91.6;
		final SplittableRandom random = new SplittableRandom(5);
		final double[][] specks = new double[14][];
		for (int i = 0; i < specks.length; i++) {
			final double r = 18 * Math.sqrt(random.nextDouble()), t = 2 * Math.PI * random.nextDouble();
			specks[i] = new double[] { cx + r * Math.cos(t), cy + r * Math.sin(t) };
		}
		final byte[] pixels = new byte[w * h];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				final double d = Math.hypot(x - cx, y - cy);
				double v = 135 + 0.05 * (x - w / 2) - 75 / (1 + Math.exp((d - 26) / 1.2)) + 120 * Math.exp(-(d - 29) * (d -
					29) / 8.0);
				for (final double[] s : specks)
					v += 90 * Math.exp(-((x - s[0]) * (x - s[0]) + (y - s[1]) * (y - s[1])) / (2 * 2.2 * 2.2)) / (1 + Math
						.exp(d - 24));
				v += 2 * random.nextGaussian();
				pixels[y * w + x] = (byte) Math.round(Math.max(0, Math.min(255, v)));
			}
		return net.imglib2.img.array.ArrayImgs.unsignedBytes(pixels, w, h);
	}
}
