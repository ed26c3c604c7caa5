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
package io.github.contacttracker.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.stream.Collectors;

import io.github.contacttracker.advisor.Finding;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.kind.Kinds;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import net.imglib2.RandomAccess;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.loops.LoopBuilder;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import org.junit.jupiter.api.Test;

/**
 * The profile helper's findings in words: the sentences users have read since the helper had warnings; and the
 * kinds of particle it reports.
 */
class ProfileReportTest {

	@Test
	void everyFindingHasItsSentence() {
		final Map<Finding, String> expected = new LinkedHashMap<>();
		expected.put(new Finding.DiameterFromImage(30.0213, 15.0107), "the diameter (30.02 px) is estimated as twice " +
			"the radius where the particles' image returns to the background (15.01 px): give it if you know it");
		expected.put(new Finding.DiameterFromHalfHeight(11.9871, 8.6014), "the diameter (11.99 px) is estimated as " +
			"twice the radius where the particles' profile falls to half its height, the rim of a blurred sphere (their " +
			"image returns to the background 8.600 px out): give it if you know it");
		expected.put(new Finding.DiameterFromSpacing(34.0589, 10, 85, 42.9791), "the diameter (34.06 px) is estimated " +
			"as the 10-th percentile of the 85 spots' nearest-neighbour distances, closer than the particles' image " +
			"reaches (42.98 px across): give it if you know it");
		expected.put(new Finding.SpotsTooClose(18, 17.5712), "18 spots lie closer to another than two such particles " +
			"can and still be told apart (17.57 px): left out of the spacing; bright marks in the frame (a timestamp, a " +
			"scale bar)? In Fiji, select the region to track");
		expected.put(new Finding.MergedAtPoint(), "the particle's active area looks merged with a neighbour's: pick an " +
			"isolated particle");
		expected.put(new Finding.FrameValuesAtPoint(11.5, true, 42.1634, 55.2, 6), "the particle lies 11.50 px from " +
			"the image's edge (beyond it neighbours go unseen), less than twice the frame's r_out (2 x 42.16 px): within " +
			"that reach its own profile is cut by the edge (its own r_out, 55.20 px, is not used), so the profile and " +
			"values given are the frame's, from its 6 most isolated particles: use them");
		expected.put(new Finding.FrameValuesAtPoint(52.3912, false, 42.1634, 68.6187, 6), "the particle's nearest " +
			"neighbour is 52.39 px away, less than twice the frame's r_out (2 x 42.16 px): within that reach its own " +
			"profile holds its neighbours' light (its own r_out, 68.62 px, is not used), so the profile and values " +
			"given are the frame's, from its 6 most isolated particles: use them");
		expected.put(new Finding.FrameValuesAtPoint(100, false, 42.1634, 68.6187, 1), "the particle's nearest " +
			"neighbour is 100 px away, less than twice the r_out its own profile gives (2 x 68.62 px), a reach the " +
			"frame's isolated particles do not show (the frame's r_out is 42.16 px): its own profile holds its " +
			"neighbours' light, so the profile and values given are the frame's, from its 1 most isolated particle: " +
			"use them");
		expected.put(new Finding.FrameValuesAtPoint(52.3912, false, 42.1634, Double.NaN, 6), "the particle's nearest " +
			"neighbour is 52.39 px away and its own profile could not be measured (the frame's r_out is 42.16 px), so " +
			"the profile and values given are the frame's, from its 6 most isolated particles: use them");
		expected.put(new Finding.NotRefined(), "could not refine the centre; the profile is taken around the point " +
			"given");
		expected.put(new Finding.NotIsolated(93.0844, 52.44), "no particle is isolated: the most isolated has a " +
			"neighbour at 93.08 px (1.780 diameters); the profile's outer part may show neighbours");
		expected.put(new Finding.NeighboursMaskedCloser(22.1376, 27.672), "the field is dense: pixels within 27.67 px " +
			"of a neighbour left no background around the particles, so neighbours were masked within 22.14 px only; " +
			"their light may show in the profile's outer part");
		expected.put(new Finding.NotBackToBackground(12.8), "the profile has not returned to the background by 12.80 " +
			"px: increase max_radius (r_out is a lower bound)");
		expected.put(new Finding.BackgroundTexture(61.4321, 10, 13.9789, 123.98), "at 61.43, 10 bright spots of the " +
			"background (halos, rings; up to 13.98 above it) would be taken for particles, whose cores rise at least " +
			"124.0 above it: the threshold is raised to the middle of that gap");
		expected.put(new Finding.RaisedUntilRound(154.8012, 67, 159), "at 154.8, 67 of the frame's 159 active areas " +
			"have the shape of no single particle (bright fringes between touching particles, or particles merged): the " +
			"threshold is raised until they are round");
		expected.put(new Finding.NotRound(3, 120, 131.456), "3 of the frame's 120 active areas have the shape of no " +
			"single particle up to 131.5 (half the cores' height): they will be flagged MERGED, or dropped when smaller " +
			"than two particles' active areas (fringes, marks)");
		expected.put(new Finding.ThresholdAboveCentre(), "the suggested threshold is above the particle's centre: at " +
			"contact no threshold separates two such particles (the profile is too long-ranged for the method)");
		for (final Map.Entry<Finding, String> e : expected.entrySet())
			assertEquals(e.getValue(), ProfileReport.sentence(e.getKey()), e.getKey().toString());
		// a new kind of finding needs its sentence here too
		final Set<Class<?>> kinds = Arrays.stream(Finding.class.getPermittedSubclasses()).collect(Collectors.toSet());
		assertEquals(kinds, expected.keySet().stream().map(Object::getClass).collect(Collectors.toSet()));
	}

	/** Each kind's line: its count, sizes, contrast and dark ring, numbered as in the KIND column. */
	@Test
	void everyKindHasItsLine() {
		final Kinds.Kind inFocus = new Kinds.Kind(1, 46, 4.7312, 116.8, 81.5, 14, 4.8951, new double[] { 117 });
		final Kinds.Kind outOfFocus = new Kinds.Kind(2, 37, 8.0967, 117.2, 70.4, 14.5, 8.2811, new double[] { 117 });
		assertEquals(List.of("kind 1 of 2: 46 particles, core radius 4.7 px, active radius 4.9 px, central contrast 117, " +
			"dark ring 82 deep at 14 px", "kind 2 of 2: 37 particles, core radius 8.1 px, active radius 8.3 px, central " +
				"contrast 117, dark ring 70 deep at 14.5 px", "2 particles of no kind (KIND 0: no bright core, e.g. cut by " +
					"the border)"), ProfileReport.kinds(new ProfileAnalysis.ParticleKinds(1, 85, List.of(inFocus,
						outOfFocus))));
		// one kind, found on five frames, without a dark ring (a Gaussian spot) and without an active area known
		final Kinds.Kind spot = new Kinds.Kind(1, 100, 2.35, 40, 0, Double.NaN, Double.NaN, new double[] { 40 });
		assertEquals(List.of("kind 1 of 1 (all particles alike): 100 particles in 5 frames, core radius 2.4 px, " +
			"central contrast 40, no dark ring"), ProfileReport.kinds(new ProfileAnalysis.ParticleKinds(5, 100, List.of(
				spot))));
		assertEquals(List.of("kinds: none (no particle with a bright core at this threshold)"), ProfileReport.kinds(
			new ProfileAnalysis.ParticleKinds(1, 3, List.of())));
	}

	/** The particles' diameter at contact (px, about the larger kind's) and their spacing in the simulated frames. */
	private static final int DIAMETER = 30, SPACING = 100;

	/**
	 * A simulated frame of two known kinds, 12 small particles and 8 larger and dimmer ones (as in the authors'
	 * movies), apart from each other: the helper reports two kinds, numbered by size, with their counts.
	 */
	@Test
	void aFrameOfTwoKindsReportsTwoKinds() {
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(frame(12, 8, 41), DIAMETER, 0);
		final List<Kinds.Kind> kinds = r.kinds().kinds();
		assertEquals(2, kinds.size(), kinds.toString());
		assertEquals(12, kinds.get(0).count(), kinds.toString());
		assertEquals(8, kinds.get(1).count(), kinds.toString());
		assertEquals(1.4, kinds.get(1).coreRadius() / kinds.get(0).coreRadius(), 0.07, "sizes 1.4 times apart");
		assertEquals(0, r.kinds().unclassified());
		final List<String> lines = ProfileReport.lines(r, true);
		assertTrue(lines.stream().anyMatch(l -> l.startsWith("  kind 1 of 2: 12 particles, core radius ")), lines
			.toString());
		assertTrue(lines.stream().anyMatch(l -> l.startsWith("  kind 2 of 2: 8 particles, core radius ")), lines
			.toString());
		// alike particles: one kind, and the report says so
		final ProfileAnalysis.Result alike = ProfileAnalysis.analyse(frame(20, 0, 42), DIAMETER, 0);
		assertEquals(1, alike.kinds().kinds().size(), alike.kinds().toString());
		assertTrue(ProfileReport.lines(alike, true).stream().anyMatch(l -> l.startsWith("  kind 1 of 1 (all particles " +
			"alike): 20 particles, ")), ProfileReport.lines(alike, true).toString());
	}

	/**
	 * The kinds are found on all the frames given; one that cannot be tracked (a NaN pixel) is left out, and the
	 * profile is measured all the same.
	 */
	@Test
	void kindsOnSeveralFramesLeaveOutOneThatCannotBeTracked() {
		final ArrayImg<FloatType, ?> first = floats(frame(12, 8, 41)), second = floats(frame(12, 8, 43)), broken =
			floats(frame(12, 8, 44));
		final RandomAccess<FloatType> pixel = broken.randomAccess();
		pixel.setPosition(new int[] { 0, 0 });
		pixel.get().set(Float.NaN);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(first, DIAMETER, 0, List.of(first, second, broken));
		assertEquals(2, r.kinds().frames(), "the broken frame left out");
		assertEquals(List.of(24, 16), r.kinds().kinds().stream().map(Kinds.Kind::count).toList());
		assertTrue(ProfileReport.kinds(r.kinds()).get(0).startsWith("kind 1 of 2: 24 particles in 2 frames, core " +
			"radius "), ProfileReport.kinds(r.kinds()).toString());
		assertEquals(ProfileAnalysis.analyse(first, DIAMETER, 0).threshold(), r.threshold(), 0);
	}

	private static ArrayImg<FloatType, ?> floats(final ArrayImg<UnsignedByteType, ?> bytes) {
		final ArrayImg<FloatType, ?> out = ArrayImgs.floats(bytes.dimension(0), bytes.dimension(1));
		LoopBuilder.setImages(bytes, out).forEachPixel((a, b) -> b.setReal(a.getRealDouble()));
		return out;
	}

	/**
	 * {@code small} particles of scale 1 and {@code large} ones of scale 1.4 and 0.85 times the contrast, in random
	 * places of a grid {@value #SPACING} px apart, on a background of 60 with uniform noise of amplitude 5.
	 */
	private static ArrayImg<UnsignedByteType, ?> frame(final int small, final int large, final long seed) {
		final SplittableRandom random = new SplittableRandom(seed);
		final ImageSimulator simulator = new ImageSimulator(new GaussianBesselProfile(100, 0.3, 10));
		final int columns = 5, spacing = SPACING;
		final NoiseFreeImage image = NoiseFreeImage.uniform(columns * spacing, ((small + large + columns - 1) /
			columns) * spacing, 60);
		final List<Boolean> isLarge = new ArrayList<>();
		for (int i = 0; i < small + large; i++)
			isLarge.add(i >= small);
		Collections.shuffle(isLarge, new java.util.Random(seed));
		for (int i = 0; i < isLarge.size(); i++) {
			final double x = spacing * (i % columns + 0.5) + random.nextDouble(-3, 3);
			final double y = spacing * (i / columns + 0.5) + random.nextDouble(-3, 3);
			if (isLarge.get(i)) simulator.addParticle(image, x, y, 1.4, 0.85);
			else simulator.addParticle(image, x, y);
		}
		return Quantiser.toUnsignedBytes(image, NoiseModel.uniform(5), random).image();
	}
}
