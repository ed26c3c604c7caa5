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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import org.junit.jupiter.api.Test;

/**
 * Simulations of what failed on real bright-field footage (the paper authors' movies and a movie of isolated
 * particles no one here made): the profile helper's values, taken without any value given, must give one spot per
 * particle, no spot on the background and no false merge.
 */
class RealFootageFailuresTest {

	/**
	 * A small bright-field particle: a bright core, a dark ring, a faint halo; its image ends (the dark ring's outer
	 * edge) about 8 px from the centre.
	 */
	static final RadialProfile SMALL = r -> 120 * Math.exp(-r * r / 12.5) - 40 * Math.exp(-(r - 5) * (r - 5) / 4.5) +
		8 * Math.exp(-(r - 9) * (r - 9) / 8);

	/** Renders particles on a background, with Gaussian noise, stored as JPEG of the given quality. */
	static ArrayImg<UnsignedByteType, ByteArray> frame(final int w, final int h, final RadialProfile profile, final List<double[]> centres,
		final java.util.function.DoubleBinaryOperator background, final double noise, final long seed) throws IOException
	{
		final NoiseFreeImage img = new ImageSimulator(profile, 3).render(centres, w, h, 0);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				img.pixels()[y * w + x] += background.applyAsDouble(x, y);
		return fromBytes(img, noise, seed, w, h);
	}

	static ArrayImg<UnsignedByteType, ByteArray> fromBytes(final NoiseFreeImage img, final double noise, final long seed, final int w, final int h)
		throws IOException
	{
		final byte[] noisy = ((ByteArray) Quantiser.toUnsignedBytes(img, NoiseModel.gaussian(noise),
			new SplittableRandom(seed)).image().update(null)).getCurrentStorageArray();
		return ArrayImgs.unsignedBytes(ProfileSuggestionTest.jpeg(noisy, w, h, 0.5f), w, h);
	}

	/**
	 * Isolated particles, five a frame, 15-16 px across, on a background with a slow illumination texture: the
	 * helper took their spacing (over 100 px) as the diameter, so its threshold fell 12 grey levels above the
	 * background and 17 spots a frame were found for 5 particles. Now the diameter is the particles' own (twice the
	 * outer edge of the dark ring of the true profile, within 2 px), and tracking with the suggestions finds exactly
	 * the five particles in every frame, within 0.15 px, none flagged.
	 */
	@Test
	void isolatedBrightFieldParticlesGetTheirOwnSizeAndOneSpotEach() throws IOException {
		final int w = 320, h = 320;
		final SplittableRandom rnd = new SplittableRandom(4);
		for (int t = 0; t < 3; t++) {
			final List<double[]> centres = ProfileSuggestionTest.scattered(5, w, h, 40, 90, rnd);
			final ArrayImg<UnsignedByteType, ByteArray> image = frame(w, h, SMALL, centres, (x, y) -> 100 + 6 * Math.sin(x / 23.0) * Math.cos(y / 31.0) +
				4 * Math.sin((x + 2 * y) / 9.0), 2, 10 + t);
			final Plane plane = Plane.of(image);
			final ProfileAnalysis.Result r = ProfileAnalysis.analyse(image, 0, 0);
			final double s = r.noise();
			double deepest = 0, at = 0;
			for (double x = 0; x < 20; x += 0.01)
				if (SMALL.value(x) < deepest) {
					deepest = SMALL.value(x);
					at = x;
				}
			double edge = at;
			while (SMALL.value(edge) < -s)
				edge += 0.01;
			assertEquals(2 * edge, r.diameter(), 2, "the particles' own size, not their spacing: " + r.findings() +
				java.util.Arrays.toString(r.level()));
			final TrackerParameters p = TrackerParameters.of(r.suggestedThreshold(true), r.suggestedROut()).withDiameter(r
				.diameter());
			for (final Method m : new Method[] { Method.PAPER, Method.FIT }) {
				final List<Localization> spots = new ContactTracker(p.withMethod(m)).analyse(plane, 0, false).spots();
				assertEquals(5, spots.size(), m + ": one spot per particle, none on the background: threshold " +
					r.threshold() + ", " + r.findings());
				for (final Localization l : spots) {
					assertEquals(0, l.flags() & ~Flag.SECOND_PASS.bit(), m + ": no flag " + Flag.decode(l.flags()));
					double best = Double.POSITIVE_INFINITY;
					for (final double[] c : centres)
						best = Math.min(best, Math.hypot(c[0] - l.x(), c[1] - l.y()));
					assertTrue(best < 0.15, m + ": centre within 0.15 px of a particle: " + best);
				}
			}
		}
	}

	/**
	 * An optical trap's one bead at low signal, as a public tweezer movie compressed as video shows it (a bright core
	 * 22 grey levels above the background, a dark ring 3 deep, noise of 3 smoothed between neighbouring pixels by the
	 * codec). The frame's noise, read from neighbouring pixels, is a fraction of the true one there, and the bead's
	 * round area at half height is flagged merged by its gradient lines, which that noise tilts; the helper found no
	 * single particle and refused every such movie. It now measures the bead (the only spot, its outline round), and
	 * tracking with its values finds the bead, unflagged, within 0.5 px.
	 */
	@Test
	void aLoneBeadOnCompressedVideoIsMeasured() throws IOException {
		final int w = 120, h = 120, frames = 5;
		final RadialProfile bead = r -> 22 * Math.exp(-Math.pow(r / 9, 4)) - 3 * Math.exp(-(r - 19) * (r - 19) / 50);
		final List<double[]> truth = new ArrayList<>();
		final List<ArrayImg<UnsignedByteType, ByteArray>> movie = new ArrayList<>();
		final SplittableRandom rnd = new SplittableRandom(2);
		for (int t = 0; t < frames; t++) {
			final double[] c = { 56.3 + 0.4 * t, 61.6 - 0.3 * t };
			truth.add(c);
			final NoiseFreeImage img = new ImageSimulator(bead, 3).render(List.of(c), w, h, 29);
			final byte[] noisy = ((ByteArray) Quantiser.toUnsignedBytes(img, NoiseModel.gaussian(3), rnd).image().update(
				null)).getCurrentStorageArray();
			movie.add(ArrayImgs.unsignedBytes(ProfileSuggestionTest.jpeg(noisy, w, h, 0.3f), w, h));
		}
		// (why it was refused: the frame's noise read as a hundredth of the true 3, the bead's area flagged merged)
		final Plane first = Plane.of(movie.get(0));
		assertTrue(NoiseEstimate.sigma(first) < 0.3, "noise read " + NoiseEstimate.sigma(first));
		final List<Localization> half = FrameSpots.find(first, null, null, 0).spots();
		assertTrue(half.size() == 1 && half.get(0).has(Flag.MERGED), "the bead alone, flagged merged: " + half);
		final MeasuredSettings.Result m = MeasuredSettings.of("trap.tif", movie.get(0), true, SettingValues.defaults(),
			Set.of(), FrontEnd.COMMAND_LINE);
		final List<Localization> spots = new TrackingPipeline(m.settings()).run(FrameSource.of(frames, movie::get,
			Calibration.PIXELS, "trap.tif", null), false).spots();
		assertEquals(frames, spots.size(), "one spot a frame: " + m.notice());
		for (final Localization l : spots) {
			assertEquals(0, l.flags() & ~Flag.SECOND_PASS.bit(), "no flag: " + Flag.decode(l.flags()));
			final double[] c = truth.get(l.frame());
			assertTrue(Math.hypot(l.x() - c[0], l.y() - c[1]) < 0.5, "on the bead in frame " + l.frame() + ": " + l.x() +
				", " + l.y() + " for " + c[0] + ", " + c[1]);
		}
	}

	/**
	 * A dense bright-field monolayer whose touching particles show a bright fringe between them (brighter than the
	 * sum of their profiles, as on the authors' movie): at the contact rule's threshold the fringes are active areas
	 * of no particle's shape. The helper raises the threshold until the active areas are round; at a lower threshold
	 * given by hand the fringes are dropped as no particle (not flagged as merges): either way one spot per particle
	 * and no MERGED flag.
	 */
	@Test
	void brightFringesBetweenTouchingParticlesAreNoParticles() throws IOException {
		final int w = 360, h = 300;
		final double d = 32;
		final List<double[]> centres = new ArrayList<>();
		final SplittableRandom rnd = new SplittableRandom(8);
		for (int row = 0; row < 6; row++)
			for (int col = 0; col < 7; col++)
				if ((row + col) % 3 != 0) // a lattice with holes: pairs, chains, triangles at contact
					centres.add(new double[] { 50 + col * d + (row % 2) * d / 2 + 0.3 * rnd.nextDouble(), 50 + row * d * Math
						.sqrt(3) / 2 + 0.3 * rnd.nextDouble() });
		final NoiseFreeImage img = new ImageSimulator(ProfileSuggestionTest.BRIGHT_FIELD, 3).render(centres, w, h, 0);
		int fringes = 0;
		for (int i = 0; i < centres.size(); i++)
			for (int j = i + 1; j < centres.size(); j++) {
				final double[] a = centres.get(i), b = centres.get(j);
				final double dist = Math.hypot(a[0] - b[0], a[1] - b[1]);
				if (dist > 1.1 * d) continue;
				fringes++;
				final double mx = (a[0] + b[0]) / 2, my = (a[1] + b[1]) / 2, ux = (b[0] - a[0]) / dist, uy = (b[1] - a[1]) /
					dist;
				for (int y = (int) my - 10; y <= (int) my + 10; y++)
					for (int x = (int) mx - 10; x <= (int) mx + 10; x++) {
						final double along = (x - mx) * ux + (y - my) * uy, across = -(x - mx) * uy + (y - my) * ux;
						img.pixels()[y * w + x] += 190 * Math.exp(-along * along / 2.5 - across * across / 18);
					}
			}
		for (int i = 0; i < img.pixels().length; i++)
			img.pixels()[i] += 136;
		final ArrayImg<UnsignedByteType, ByteArray> image = fromBytes(img, 3, 5, w, h);
		final Plane plane = Plane.of(image);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(image, d, 0);
		assertTrue(r.threshold() > r.atContact(), "raised above the contact rule's " + r.atContact() + ": " + r
			.threshold());
		final TrackerParameters p = TrackerParameters.of(r.suggestedThreshold(true), r.suggestedROut()).withDiameter(d)
			.withMethod(Method.PAPER);
		assertOneSpotPerParticle(new ContactTracker(p).analyse(plane, 0, false), centres, "suggested");
		// by hand, at 185: the fringes (their peaks near 230) are active areas, dropped as no particle. (Lower, at the
		// contact rule's 162, the faint outer rings of the six particles around a hole in the lattice add up to round
		// spots of 170-180 there: round, they are spots, as at any threshold a user picks below them; the helper's
		// threshold is clear of them.)
		assertTrue(r.suggestedThreshold(true) > 185, "the helper is above the fringes' feet: " + r.threshold());
		final FrameResult low = new ContactTracker(TrackerParameters.of(185, p.rOut()).withDiameter(d).withMethod(
			Method.PAPER)).analyse(plane, 0, false);
		assertOneSpotPerParticle(low, centres, "at 185");
		assertTrue(low.discarded() >= fringes / 2, "fringes dropped: " + low.discarded() + " of " + fringes);
	}

	private static void assertOneSpotPerParticle(final FrameResult result, final List<double[]> centres,
		final String what)
	{
		int matched = 0;
		for (final Localization l : result.spots()) {
			assertTrue(!l.has(Flag.MERGED), what + ": no false merge at " + l.x() + ", " + l.y());
			for (final double[] c : centres)
				if (Math.hypot(c[0] - l.x(), c[1] - l.y()) < 2) matched++;
		}
		final StringBuilder extra = new StringBuilder();
		for (final Localization l : result.spots()) {
			double best = Double.POSITIVE_INFINITY;
			for (final double[] c : centres)
				best = Math.min(best, Math.hypot(c[0] - l.x(), c[1] - l.y()));
			if (best >= 2) extra.append(String.format(" (%.1f, %.1f) area %d %s;", l.x(), l.y(), l.activeArea(), Flag
				.decode(l.flags())));
		}
		assertEquals(centres.size(), result.spots().size(), what + ": one spot per particle; not on one:" + extra);
		assertEquals(centres.size(), matched, what + ": each spot on a particle");
	}
}
