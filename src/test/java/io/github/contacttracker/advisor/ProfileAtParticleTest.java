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

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import org.junit.jupiter.api.Test;

/**
 * The profile at a clicked particle and the profile of the frame (Measure) on one real-like frame: bright-field
 * particles whose faint halo reaches further than a diameter, many at contact, a few with neighbours one and a half
 * diameters away, one isolated. A particle whose neighbours lie within its image gives the frame's values and says
 * why; an isolated one gives its own, equal to the frame's within their errors and to the truth.
 */
class ProfileAtParticleTest {

	/**
	 * A bright-field particle with a long tail, as on the authors' 1.avi (about 34 px across): a core clipped at 255,
	 * a dark ring at 13 px, a bright halo at 26 px and a faint tail out to about 40 px.
	 */
	static final RadialProfile LONG_HALO = r -> 250 * Math.exp(-r * r / 24) - 85 * Math.exp(-(r - 13) * (r - 13) / 30) +
		15 * Math.exp(-(r - 26) * (r - 26) / 30) + 4 * Math.exp(-(r - 36) * (r - 36) / 80);
	static final double BACKGROUND = 120, NOISE = 2.5;
	/** The particle with neighbours 50-56 px away (about 1.5 diameters, as 1.avi's most isolated). */
	static final double[] CROWDED = { 250.3, 250.6 };
	/** The particle with no neighbour within 110 px. */
	static final double[] ISOLATED = { 560.4, 250.2 };
	static final int W = 681, H = 501;

	/** The centres: the two particles above, the crowded one's five neighbours, and clusters at contact. */
	static List<double[]> field(final SplittableRandom rnd) {
		final List<double[]> c = new ArrayList<>(List.of(CROWDED, ISOLATED));
		for (int k = 0; k < 5; k++) {
			final double a = k * 2 * Math.PI / 5 + 0.3 * rnd.nextDouble(), d = 50 + 6 * rnd.nextDouble();
			c.add(new double[] { CROWDED[0] + d * Math.cos(a), CROWDED[1] + d * Math.sin(a) });
		}
		final int placed = c.size();
		for (int tries = 0; c.size() < 70 && tries < 100000; tries++) {
			final double[] p;
			if (c.size() > placed && rnd.nextBoolean()) { // at contact with one placed before
				final double[] o = c.get(placed + rnd.nextInt(c.size() - placed));
				final double a = 2 * Math.PI * rnd.nextDouble(), d = 34 + rnd.nextDouble();
				p = new double[] { o[0] + d * Math.cos(a), o[1] + d * Math.sin(a) };
			}
			else p = new double[] { 10 + 430 * rnd.nextDouble(), 10 + 481 * rnd.nextDouble() };
			boolean free = Math.hypot(p[0] - CROWDED[0], p[1] - CROWDED[1]) > 80 && p[0] > 10 && p[1] > 10 && p[0] < 440 &&
				p[1] < H - 10;
			for (final double[] o : c)
				free &= Math.hypot(p[0] - o[0], p[1] - o[1]) > 33.9;
			if (free) c.add(p);
		}
		return c;
	}

	static RandomAccessibleInterval<UnsignedByteType> frame(final long seed) {
		final SplittableRandom rnd = new SplittableRandom(seed);
		return Quantiser.toUnsignedBytes(new ImageSimulator(LONG_HALO, 3).render(field(rnd), W, H, BACKGROUND),
			NoiseModel.gaussian(NOISE), rnd).image();
	}

	/**
	 * Clicked on the particle with neighbours at 1.5 diameters: alone, its background annulus holds the neighbours'
	 * halos, its reach reads about twice the true one and the neighbours' masks, widened to it, cover the particle
	 * itself (on 1.avi no ring inside 40 px; here a threshold of 380, above every pixel). The helper says its profile
	 * cannot return to the background there and gives the frame's profile and values, centred on the particle clicked.
	 */
	@Test
	void aParticleAmongNeighboursGivesTheFramesValuesAndSaysWhy() {
		final RandomAccessibleInterval<UnsignedByteType> frame = frame(1);
		final ProfileAnalysis.Result all = ProfileAnalysis.analyse(frame, 0, 0);
		final ProfileAnalysis.Result one = ProfileAnalysis.analyse(frame, Math.round(CROWDED[0] + 1), Math.round(
			CROWDED[1] - 1), 0, 0);
		assertEquals(CROWDED[0], one.x(), 0.2, "centred on the particle clicked");
		assertEquals(CROWDED[1], one.y(), 0.2);
		final Finding.FrameValuesAtPoint why = one.findings().stream().filter(f -> f instanceof Finding.FrameValuesAtPoint)
			.map(f -> (Finding.FrameValuesAtPoint) f).findFirst().orElseThrow(() -> new AssertionError(one.findings()));
		assertEquals(all.suggestedThreshold(true), one.suggestedThreshold(true), "threshold");
		assertEquals(all.suggestedROut(), one.suggestedROut(), "r_out");
		// the finding names the r_out given, the frame's, and keeps the particle's own apart
		assertEquals(one.rOut(), why.frameROut(), 1e-9, "the finding's r_out is the one given");
		assertEquals(all.suggestedDiameter(), one.suggestedDiameter(), "diameter");
		assertTrue(one.count()[1] > 0 && one.level()[1] > 250, "the profile holds the cores: " + one.level()[1]);
	}

	/**
	 * Clicked on the isolated particle, the helper profiles it alone; its values are the frame's within their errors
	 * (threshold within the noise margin, r_out within 3 px, diameter within 5%) and its r_out is the truth's (where
	 * the true profile falls within the noise, plus the margin) within 2 px.
	 */
	@Test
	void anIsolatedParticleGivesTheFramesValuesWithinTheirErrors() {
		final RandomAccessibleInterval<UnsignedByteType> frame = frame(1);
		final ProfileAnalysis.Result all = ProfileAnalysis.analyse(frame, 0, 0);
		final ProfileAnalysis.Result one = ProfileAnalysis.analyse(frame, Math.round(ISOLATED[0]), Math.round(
			ISOLATED[1]), 0, 0);
		assertEquals(ISOLATED[0], one.x(), 0.2, "centred on the particle clicked");
		assertEquals(ISOLATED[1], one.y(), 0.2);
		assertEquals(1, one.particles(), "alone: " + one.findings());
		final double sigma = Math.sqrt(NOISE * NOISE + 1.0 / 12);
		final double trueROut = reach(sigma) + Margins.R_OUT_MARGIN_PX;
		assertEquals(trueROut, one.rOut(), 2, "r_out at the particle, truth " + trueROut);
		// the frame's particles have neighbours closer than twice r_out: their tails overlap, and its r_out is the
		// rougher one (measured: the particle 43.78, the frame 41.26, the truth 44.09 px)
		assertEquals(all.rOut(), one.rOut(), 3, "r_out: the frame's, truth " + trueROut);
		assertEquals(all.threshold(), one.threshold(), Margins.THRESHOLD_MARGIN_SIGMAS * sigma, "threshold");
		assertEquals(all.diameter(), one.diameter(), 0.05 * all.diameter(), "diameter");
	}

	/** @return where the true profile last lies more than {@code s} off the background (px) */
	static double reach(final double s) {
		double r = 100;
		while (Math.abs(LONG_HALO.value(r)) <= s)
			r -= 0.01;
		return r;
	}

	/**
	 * A point on no particle: on a particle's bright halo, the frame's values (before, the spots were found at the
	 * point's own height, and the halos' fringes taken for particles halved the diameter); on the bare background, a
	 * refusal in one line that says no particle is there.
	 */
	@Test
	void aPointOnNoParticleGivesTheFramesValuesOrSaysNoneIsThere() {
		final RandomAccessibleInterval<UnsignedByteType> frame = frame(1);
		final ProfileAnalysis.Result all = ProfileAnalysis.analyse(frame, 0, 0);
		final long hx = Math.round(ISOLATED[0] + 26), hy = Math.round(ISOLATED[1]);
		final ProfileAnalysis.Result halo = ProfileAnalysis.analyse(frame, hx, hy, 0, 0);
		assertEquals(all.diameter(), halo.diameter(), 1e-9, "the frame's diameter");
		assertEquals(all.threshold(), halo.threshold(), 1e-9, "the frame's threshold");
		assertEquals(all.rOut(), halo.rOut(), 1e-9, "the frame's r_out");
		final List<double[]> centres = field(new SplittableRandom(1));
		long bx = -1, by = -1;
		for (int y = 20; y < H - 20 && bx < 0; y += 5)
			for (int x = 20; x < W - 20 && bx < 0; x += 5) {
				boolean far = true;
				for (final double[] c : centres)
					far &= Math.hypot(c[0] - x, c[1] - y) > 80;
				if (far) {
					bx = x;
					by = y;
				}
			}
		assertTrue(bx >= 0, "a background point exists in the frame");
		final long px = bx, py = by;
		final io.github.contacttracker.core.InvalidInputException e = org.junit.jupiter.api.Assertions.assertThrows(
			io.github.contacttracker.core.InvalidInputException.class, () -> ProfileAnalysis.analyse(frame, px, py, 0, 0));
		assertTrue(e.getMessage().startsWith("no bright particle at (" + px + ", " + py + ")"), e.getMessage());
	}
}
