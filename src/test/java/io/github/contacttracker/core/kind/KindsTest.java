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
package io.github.contacttracker.core.kind;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;

/**
 * Kinds found on simulated monolayers of known kinds: dense fields of touching particles (each placed at contact
 * with one already there where it fits, as in a real monolayer), 8-bit with uniform noise, measured at the first
 * pass's centres. Each particle found is matched to the true centre within {@value #MATCH_PX} px, whose kind it
 * must be given; kinds are numbered by size, so the true kinds are listed from the smallest.
 */
class KindsTest {

	/** A bright core (half its contrast at about 4.8 px), a dark ring at about 13 px, a faint halo. */
	static final RadialProfile PROFILE = new GaussianBesselProfile(100, 0.3, 10);
	static final double BACKGROUND = 60, THRESHOLD = BACKGROUND + 45, NOISE = 5, REACH = 40;
	/** Distance from a particle's centre at which another touches it, at scale 1 (px). */
	static final double CONTACT_RADIUS = 12;
	static final int SIZE = 400, FRAMES = 3, PER_FRAME = 70;
	static final double MATCH_PX = 3;

	/** A true particle: centre and kind (1 the smallest). */
	record Truth(double x, double y, int kind) {}

	/** One frame: the particles' features and their true kinds (0: matched to no true particle). */
	record Found(List<KindFeatures> features, int[] truth) {}

	/** Kinds of unlike size and brightness, the "unlike" scene's ratios: 1.2 times larger, 1.1 times brighter. */
	@Test
	void twoKindsOfUnlikeSize() {
		final List<Found> frames = simulate(new double[] { 1, 1.2 }, new double[] { 1, 1.1 }, 11);
		final Kinds kinds = Kinds.find(sample(frames));
		assertEquals(2, kinds.count(), "kinds found: " + kinds.describe());
		assertTrue(correct(kinds, frames) >= 0.98, "correctly assigned: " + correct(kinds, frames));
	}

	/** Three kinds as in the authors' 6.avi: the larger, the dimmer. */
	@Test
	void threeKindsOfUnlikeSizeAndBrightness() {
		final List<Found> frames = simulate(new double[] { 1, 1.4, 1.9 }, new double[] { 1, 0.85, 0.7 }, 12);
		final Kinds kinds = Kinds.find(sample(frames));
		assertEquals(3, kinds.count(), "kinds found: " + kinds.describe());
		assertTrue(correct(kinds, frames) >= 0.98, "correctly assigned: " + correct(kinds, frames));
		final List<Kinds.Kind> described = kinds.describe();
		int total = 0;
		for (int k = 0; k < 3; k++) {
			assertEquals(k + 1, described.get(k).kind());
			if (k > 0) assertTrue(described.get(k).coreRadius() > described.get(k - 1).coreRadius(), "numbered by size");
			total += described.get(k).count();
		}
		assertEquals(sample(frames).size(), total, "every particle of the sample in one kind");
		// the core radius scales with the particle: 1.4 and 1.9 times the smallest's, within 5%
		assertEquals(1.4, described.get(1).coreRadius() / described.get(0).coreRadius(), 0.07);
		assertEquals(1.9, described.get(2).coreRadius() / described.get(0).coreRadius(), 0.095);
	}

	/**
	 * Kinds of the same size told apart by brightness alone (the second feature): 1.6 times brighter. Of one size,
	 * kinds are numbered in order of brightness.
	 */
	@Test
	void twoKindsOfEqualSizeUnlikeBrightness() {
		final List<Found> frames = simulate(new double[] { 1, 1 }, new double[] { 1, 1.6 }, 13);
		final Kinds kinds = Kinds.find(sample(frames));
		assertEquals(2, kinds.count(), "kinds found: " + kinds.describe());
		assertTrue(correct(kinds, frames) >= 0.98, "correctly assigned: " + correct(kinds, frames));
	}

	/** Alike particles, dense and touching, in noise: one kind, on several fields. */
	@Test
	void alikeParticlesAreOneKind() {
		for (final long seed : new long[] { 21, 22, 23 }) {
			final List<Found> frames = simulate(new double[] { 1 }, new double[] { 1 }, seed);
			final Kinds kinds = Kinds.find(sample(frames));
			assertEquals(1, kinds.count(), "seed " + seed + ": " + kinds.describe());
			assertTrue(correct(kinds, frames) >= 0.98, "of kind 1: " + correct(kinds, frames));
		}
	}

	/** Alike particles of a natural spread, 5% in size and brightness, are one kind too; so are two kinds 5% apart. */
	@Test
	void aSpreadIsNoKind() {
		for (final long seed : new long[] { 31, 32 }) {
			final Kinds kinds = Kinds.find(sample(simulate(new double[] { 1 }, new double[] { 1 }, 0.05, seed)));
			assertEquals(1, kinds.count(), "seed " + seed + ": " + kinds.describe());
		}
		assertEquals(1, Kinds.find(sample(simulate(new double[] { 1, 1.05 }, new double[] { 1, 1 }, 0.03, 33)))
			.count());
	}

	/** Two kinds of particles spread 5% about their kinds' sizes 1.3 times apart: still two, told apart. */
	@Test
	void twoSpreadKinds() {
		final List<Found> frames = simulate(new double[] { 1, 1.3 }, new double[] { 1, 1.15 }, 0.05, 34);
		final Kinds kinds = Kinds.find(sample(frames));
		assertEquals(2, kinds.count(), "kinds found: " + kinds.describe());
		assertTrue(correct(kinds, frames) >= 0.98, "correctly assigned: " + correct(kinds, frames));
	}

	/** The classifier travels (to a distributed job's workers) and classifies there as here. */
	@Test
	void kindsSurviveSerialization() throws Exception {
		final List<Found> frames = simulate(new double[] { 1, 1.4, 1.9 }, new double[] { 1, 0.85, 0.7 }, 12);
		final Kinds kinds = Kinds.find(sample(frames));
		final java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
		try (java.io.ObjectOutputStream out = new java.io.ObjectOutputStream(bytes)) {
			out.writeObject(kinds);
		}
		final Kinds copy;
		try (java.io.ObjectInputStream in = new java.io.ObjectInputStream(new java.io.ByteArrayInputStream(bytes
			.toByteArray())))
		{
			copy = (Kinds) in.readObject();
		}
		assertEquals(3, copy.count());
		for (final KindFeatures f : sample(frames))
			assertEquals(kinds.kindOf(f), copy.kindOf(f));
		assertArrayEquals(kinds.describe().get(2).profile(), copy.describe().get(2).profile());
	}

	/** The number given is the number of kinds, however many there are; 1 puts every particle in kind 1. */
	@Test
	void aGivenNumberOfKinds() {
		final List<Found> frames = simulate(new double[] { 1, 1.4, 1.9 }, new double[] { 1, 0.85, 0.7 }, 12);
		final List<KindFeatures> sample = sample(frames);
		final Kinds two = Kinds.find(sample, 2);
		assertEquals(2, two.count());
		final Kinds one = Kinds.find(sample, 1);
		assertEquals(1, one.count());
		assertEquals(sample.size(), one.describe().get(0).count());
		for (final KindFeatures f : sample)
			assertEquals(1, one.kindOf(f));
		// four asked of three kinds: four, the one left over splitting a kind
		assertEquals(4, Kinds.find(sample, 4).count());
		// more asked than there are particles: at most one kind per particle
		assertEquals(1, Kinds.find(sample.subList(0, 1), 3).count());
		assertEquals(1, Kinds.find(sample.subList(0, 1), 3).kindOf(sample.get(0)));
		assertEquals("the number of kinds must be 0 (automatic) or more, not -1", org.junit.jupiter.api.Assertions
			.assertThrows(InvalidInputException.class, () -> Kinds.find(sample, -1)).getMessage());
	}

	/**
	 * A few stray blobs (faint, small: a halo's bright spot) among two kinds are no third kind: the kinds stay two,
	 * and their particles are assigned as without the blobs.
	 */
	@Test
	void afewStrayBlobsAreNoKind() {
		final List<Found> frames = simulate(new double[] { 1, 1.3 }, new double[] { 1, 1.15 }, 11);
		final List<KindFeatures> sample = new ArrayList<>(sample(frames));
		for (int i = 0; i < 4; i++)
			sample.add(new KindFeatures(2 + 0.1 * i, 12, 0, Double.NaN, 1.5, new double[] { 12, 6, 1 }));
		final Kinds kinds = Kinds.find(sample);
		assertEquals(2, kinds.count(), "kinds found: " + kinds.describe());
		assertTrue(correct(kinds, frames) >= 0.98, "correctly assigned: " + correct(kinds, frames));
	}

	/** A place without a bright core is of no kind (0), and so is everything when no kind could be found. */
	@Test
	void aParticleWithoutABrightCoreIsOfKindZero() {
		final NoiseFreeImage flat = NoiseFreeImage.uniform(60, 60, BACKGROUND);
		new ImageSimulator(r -> -30 * Math.exp(-r * r / 50)).addParticle(flat, 30, 30); // a dark spot
		final Plane plane = Plane.of(Quantiser.toUnsignedBytes(flat, NoiseModel.none(), new SplittableRandom(1))
			.image());
		final KindFeatures dark = KindFeatures.measure(plane, 30, 30, 0, BACKGROUND, 20);
		assertFalse(dark.usable());
		assertEquals(-30, dark.peak(), 1);
		final List<Found> frames = simulate(new double[] { 1 }, new double[] { 1 }, 21);
		assertEquals(0, Kinds.find(sample(frames)).kindOf(dark));
		final Kinds none = Kinds.find(List.of(dark));
		assertEquals(0, none.count());
		assertEquals(0, none.kindOf(sample(frames).get(0)));
	}

	/** The features of an isolated particle without noise: its profile and the numbers read off it. */
	@Test
	void featuresOfAnIsolatedParticle() {
		final NoiseFreeImage image = NoiseFreeImage.uniform(101, 101, BACKGROUND);
		new ImageSimulator(PROFILE).addParticle(image, 50, 50);
		final Plane plane = Plane.of(Quantiser.toUnsignedBytes(image, NoiseModel.none(), new SplittableRandom(1))
			.image());
		assertEquals(BACKGROUND, KindFeatures.background(plane), 0, "most of the frame is background");
		final KindFeatures f = KindFeatures.measure(plane, 50, 50, 81, BACKGROUND, REACH);
		assertTrue(f.usable());
		// the pixel-integrated profile: 100 at the centre less the pixel's blur, half of that near 4.8 px
		assertEquals(99, f.peak(), 1.5);
		assertEquals(halfRadius(PROFILE), f.coreRadius(), 0.25);
		// the dark ring where the profile is lowest (about 11.8 px: the envelope pulls it in from J0's 12.8 px)
		double lowest = 0;
		for (double r = 8; r < 16; r += 0.01)
			if (PROFILE.value(r) < PROFILE.value(lowest)) lowest = r;
		assertEquals(-PROFILE.value(lowest), f.ringDepth(), 1.5);
		assertEquals(lowest, f.ringRadius(), 1);
		assertEquals(Math.sqrt(81 / Math.PI), f.activeRadius(), 1e-12);
		assertEquals((int) Math.floor(REACH + 0.5) + 1, f.profile().length);
		// each ring's median within the profile's change over half a pixel (and 1 grey level of rounding)
		for (int r = 2; r < f.profile().length; r++)
			assertEquals(PROFILE.value(r), f.profile()[r], 1 + Math.abs(PROFILE.value(r + 0.5) - PROFILE.value(r - 0.5)) /
				2, "radius " + r);
	}

	/**
	 * What places a particle among kinds, measured out to the core alone ({@link KindFeatures#measureCore}), is what
	 * the whole profile gives: the same core radius and central contrast to the last bit, hence the same kind, for
	 * particles of three sizes in a noisy dense 32-bit field (no two pixels alike: a ring read in part would have
	 * another median), at its borders too, whatever active area is given (none, or any from 1 to 400 px: the first
	 * rings read end anywhere from 6 to 25 px, before the core's edge or after it).
	 */
	@Test
	void theCoreAloneGivesTheWholeProfilesKind() {
		final List<Found> frames = simulate(new double[] { 0.8, 1, 1.4 }, new double[] { 1, 1.1, 1.2 }, 0.05, 23);
		final Kinds kinds = Kinds.find(sample(frames));
		assertEquals(3, kinds.count());
		final SplittableRandom random = new SplittableRandom(5);
		final ImageSimulator simulator = new ImageSimulator(PROFILE);
		final NoiseFreeImage image = NoiseFreeImage.uniform(SIZE, SIZE, BACKGROUND);
		final List<double[]> centres = new ArrayList<>();
		for (final Truth p : layout(new double[] { 0.8, 1, 1.4 }, random)) {
			final double scale = new double[] { 0.8, 1, 1.4 }[p.kind() - 1];
			simulator.addParticle(image, p.x(), p.y(), scale, 1);
			centres.add(new double[] { p.x() + 0.3 * gaussian(random), p.y() + 0.3 * gaussian(random) });
		}
		for (final double[] edge : new double[][] { { 2.5, 150 }, { 0.2, 0.4 }, { SIZE - 1.5, 200 }, { 100, SIZE - 4 } }) {
			simulator.addParticle(image, edge[0], edge[1], 1.4, 1);
			centres.add(edge);
		}
		final float[] data = new float[SIZE * SIZE];
		for (int i = 0; i < data.length; i++)
			data[i] = (float) (image.pixels()[i] + NOISE * gaussian(random));
		final Plane plane = Plane.of(net.imglib2.img.array.ArrayImgs.floats(data, SIZE, SIZE));
		final double background = KindFeatures.background(plane);
		int usable = 0;
		for (final double[] c : centres)
			for (int area = 0; area <= 400; area += area < 20 ? 1 : 7) {
				final KindFeatures whole = KindFeatures.measure(plane, c[0], c[1], area, background, REACH);
				final KindFeatures core = KindFeatures.measureCore(plane, c[0], c[1], area, background, REACH);
				final String at = "at " + c[0] + ", " + c[1] + ", area " + area;
				assertEquals(whole.coreRadius(), core.coreRadius(), 0, at);
				assertEquals(whole.peak(), core.peak(), 0, at);
				assertEquals(whole.activeRadius(), core.activeRadius(), 0, at);
				assertEquals(kinds.kindOf(whole), kinds.kindOf(core), at);
				if (whole.usable()) usable++;
			}
		assertTrue(usable > 0.9 * 75 * centres.size(), "most have a core: " + usable);
	}

	/** Where the profile first falls to half its value at the centre. */
	private static double halfRadius(final RadialProfile p) {
		double lo = 0, hi = 20;
		while (hi - lo > 1e-6) {
			final double mid = 0.5 * (lo + hi);
			if (p.value(mid) > 0.5 * p.value(0)) lo = mid;
			else hi = mid;
		}
		return lo;
	}

	/** All particles of all frames. */
	static List<KindFeatures> sample(final List<Found> frames) {
		final List<KindFeatures> all = new ArrayList<>();
		for (final Found f : frames)
			all.addAll(f.features());
		return all;
	}

	/** The share of the particles matched to a true one that are given its kind. */
	static double correct(final Kinds kinds, final List<Found> frames) {
		int right = 0, matched = 0;
		for (final Found f : frames)
			for (int i = 0; i < f.truth().length; i++) {
				if (f.truth()[i] == 0) continue;
				matched++;
				if (kinds.kindOf(f.features().get(i)) == f.truth()[i]) right++;
			}
		return (double) right / matched;
	}

	/**
	 * Simulates {@value #FRAMES} frames of particles of the given kinds (scales in increasing order, each kind
	 * equally likely), finds their active areas, runs the first pass and measures each particle at its centre.
	 */
	static List<Found> simulate(final double[] scales, final double[] amplitudes, final long seed) {
		return simulate(scales, amplitudes, 0, seed);
	}

	/**
	 * As {@link #simulate(double[], double[], long)}, each particle's scale and brightness scattered about its kind's
	 * by a relative standard deviation {@code spread} (polydisperse particles, a little out of focus).
	 */
	static List<Found> simulate(final double[] scales, final double[] amplitudes, final double spread,
		final long seed)
	{
		final SplittableRandom random = new SplittableRandom(seed);
		final ImageSimulator simulator = new ImageSimulator(PROFILE);
		final List<Found> frames = new ArrayList<>();
		for (int t = 0; t < FRAMES; t++) {
			final List<Truth> truth = layout(scales, random);
			final NoiseFreeImage image = NoiseFreeImage.uniform(SIZE, SIZE, BACKGROUND);
			for (final Truth p : truth)
				simulator.addParticle(image, p.x(), p.y(), scales[p.kind() - 1] * (1 + spread * gaussian(random)),
					amplitudes[p.kind() - 1] * (1 + spread * gaussian(random)));
			final Plane plane = Plane.of(Quantiser.toUnsignedBytes(image, NoiseModel.uniform(NOISE), random).image());
			final List<Particle> ps = new ArrayList<>();
			for (final Region r : ComponentLabeling.label(plane, THRESHOLD, Connectivity.EIGHT)) {
				final Particle p = r.area() >= 20 ? Particle.firstPass(plane, r, THRESHOLD) : null;
				if (p != null) ps.add(p);
			}
			final Particle[] particles = ps.toArray(new Particle[0]);
			final Estimate[] centres = Arrays.stream(particles).map(p -> p.first()).toArray(Estimate[]::new);
			final KindFeatures[] features = KindFeatures.measure(plane, particles, centres, REACH);
			final int[] kinds = new int[particles.length];
			for (int k = 0; k < particles.length; k++)
				for (final Truth p : truth)
					if (Math.hypot(p.x() - centres[k].x(), p.y() - centres[k].y()) < MATCH_PX) kinds[k] = p.kind();
			assertTrue(Arrays.stream(kinds).filter(k -> k > 0).count() >= 0.9 * truth.size(), "most particles found");
			frames.add(new Found(Arrays.asList(features), kinds));
		}
		return frames;
	}

	/** A standard normal deviate (Box-Muller). */
	private static double gaussian(final SplittableRandom random) {
		return Math.sqrt(-2 * Math.log(1 - random.nextDouble())) * Math.cos(2 * Math.PI * random.nextDouble());
	}

	/**
	 * Up to {@value #PER_FRAME} particles of random kinds, each placed touching one placed before (at a random
	 * angle, 0 to 2 px apart) where it overlaps none, or anywhere when that fails, and no nearer the frame's edge
	 * than its contact radius.
	 */
	private static List<Truth> layout(final double[] scales, final SplittableRandom random) {
		final List<Truth> placed = new ArrayList<>();
		for (int attempt = 0; attempt < 20 * PER_FRAME && placed.size() < PER_FRAME; attempt++) {
			final int kind = 1 + random.nextInt(scales.length);
			final double radius = CONTACT_RADIUS * scales[kind - 1];
			double x, y;
			if (!placed.isEmpty() && attempt % 4 != 0) {
				final Truth next = placed.get(random.nextInt(placed.size()));
				final double a = random.nextDouble(2 * Math.PI);
				final double d = CONTACT_RADIUS * scales[next.kind() - 1] + radius + random.nextDouble(2);
				x = next.x() + d * Math.cos(a);
				y = next.y() + d * Math.sin(a);
			}
			else {
				x = random.nextDouble(radius, SIZE - radius);
				y = random.nextDouble(radius, SIZE - radius);
			}
			if (x < radius || y < radius || x > SIZE - radius || y > SIZE - radius) continue;
			boolean free = true;
			for (final Truth p : placed)
				if (Math.hypot(p.x() - x, p.y() - y) < CONTACT_RADIUS * scales[p.kind() - 1] + radius - 1e-9) free = false;
			if (free) placed.add(new Truth(x, y, kind));
		}
		return placed;
	}
}
