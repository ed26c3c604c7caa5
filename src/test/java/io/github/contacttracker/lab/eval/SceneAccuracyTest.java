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
package io.github.contacttracker.lab.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scene;

/**
 * The default method in two of issue 12's scenes, on few images: before the fix the hexagonal cluster of the
 * flat-top particles carried a 16 nm bias and the unlike pair 24 nm; now every particle's bias must be within its
 * statistical error (about 0.4 nm on 10 images) plus 1 nm.
 */
class SceneAccuracyTest {

	private static void check(final SceneStudy.Result r, final double positionStdNm, final int images) {
		assertEquals(0, r.lost(), "lost");
		assertEquals(0, r.extra(), "extra spots");
		final double tolerance = 1 + 3 * positionStdNm / Math.sqrt(images);
		assertTrue(Math.abs(r.bias()) < tolerance, r.scene() + ": bias " + r.bias() + " nm at " + r.biasWhere());
		assertTrue(Math.abs(r.meanError()) < tolerance, r.scene() + ": distance error " + r.meanError() + " nm");
		assertTrue(r.worstStdOverCrb() < 2, r.scene() + ": std / CRB " + r.worstStdOverCrb());
	}

	@Test
	void hexagonalClusterIsUnbiased() {
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("hex7", Scene.flatTop()), 10, 3);
		check(r, r.crb(), 10);
	}

	@Test
	void unlikePairIsUnbiased() {
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("unlike13", PaperParticles.silica206()),
			10, 4);
		check(r, r.crb(), 10);
	}

	/**
	 * Long-range particles in a chain: each one's gradient lines are tilted by its neighbours' light, which the
	 * merge detection must not take for two particles in one area (it did: 41 of 160 spots flagged, -25 nm).
	 */
	@Test
	void chainOfLongRangeParticlesIsNotTakenForMerges() {
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("chain4", PaperParticles.silica206()),
			10, 5);
		assertEquals(0, r.flagged(), "no particle of the chain is a merge");
		check(r, r.crb(), 10);
	}

	/**
	 * Long-range particles twice as bright: the cores clip at 255 and the dark rings at 0. Fitting the pixels clipped
	 * at 0 as data pushed the pair 2.8 nm apart (1.4 nm per particle); leaving out only those, and the saturated ones,
	 * would still keep near each clip level just the pixels whose noise pulled them away from it.
	 */
	/**
	 * Photon noise on bright particles: the noise under them is far above the background's. With one variance for
	 * all of a group's pixels the reported sigma was 0.64 of the observed spread here; weighted by where the centres'
	 * information lies, it must be within a factor 1.5 of it. 160 images: the spread itself is known to about 6% (with
	 * 40, the least of the four ratios read 0.6668 and 0.6664 under two profile estimates equal to a few parts in
	 * 10^4: it sat on the bound by chance; with 160 it reads 0.72).
	 */
	@Test
	void reportedSigmaFollowsPhotonNoise() {
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("photon", PaperParticles.silica553()),
			160, 7);
		check(r, r.std(), 160);
		assertTrue(r.sigmaRatioMin() > 1 / 1.5 && r.sigmaRatioMax() < 1.5, "reported sigma / spread " + r
			.sigmaRatioMin() + " to " + r.sigmaRatioMax());
	}

	/**
	 * The same on a cluster too large to fit jointly ({@code hex37}, twice as bright, photon noise): its members are
	 * fitted in turn, and their reported sigma must follow the observed spread as a joint fit's does. Most members
	 * end on a refit that settles at its first step, and that path had reported one variance for all pixels: 0.53 to
	 * 0.94 of the spread here (now within 1.5 either way).
	 */
	@Test
	void reportedSigmaFollowsPhotonNoiseWhenFittedInTurn() {
		final ParticleType t = PaperParticles.silica553();
		final List<Scene.Particle> bright = new ArrayList<>();
		for (final Scene.Particle p : Scene.of("hex37", t).particles())
			bright.add(new Scene.Particle(p.x(), p.y(), 1, Scene.SATURATED_BRIGHTNESS));
		final Scene scene = new Scene("photon37", t, bright, 0, 0, Scene.PHOTON_GAIN, Scene.READ_NOISE, t.background() +
			Scene.SATURATED_BRIGHTNESS * (t.threshold() - t.background()));
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(scene, 40, 8);
		assertEquals(0, r.lost(), "lost");
		assertEquals(0, r.extra(), "extra spots");
		assertTrue(r.sigmaRatioMin() > 1 / 1.5 && r.sigmaRatioMax() < 1.5, "reported sigma / spread " + r
			.sigmaRatioMin() + " to " + r.sigmaRatioMax());
	}

	@Test
	void saturatedLongRangePairIsUnbiased() {
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("saturated", PaperParticles
			.silica206()), 10, 6);
		assertTrue(r.clipped() > 0, "the scene clips");
		assertEquals(0, r.lost(), "lost");
		assertEquals(0, r.extra(), "extra spots");
		assertEquals(0, r.flagged(), "flagged");
		// statistical error of a mean over 10 images: 0.1 nm
		assertEquals(0, r.bias(), 0.5, "bias at " + r.biasWhere());
		assertEquals(0, r.meanError(), 0.5, "distance error");
		assertTrue(r.worstStdOverCrb() < 1.5, "std / CRB " + r.worstStdOverCrb());
	}

	/**
	 * The long-range pair on a background of 5 (noise sigma 2.9): the dark rings clip at 0 and the whole background
	 * lies within the band the fit leaves out, so the profile rounds find no fixed point. The centres may then be
	 * off, but never silently: every spot is flagged, or the pair is unbiased.
	 */
	@Test
	void backgroundNearZeroIsFlaggedOrUnbiased() {
		final ParticleType t = PaperParticles.silica206();
		final double background = 5;
		final ParticleType dark = new ParticleType(t.name(), t.diameterMicrons(), t.pixelSizeNm(), t.profile(),
			background, background + t.threshold() - t.background(), t.rOut(), t.noise());
		final int images = 3;
		final SceneStudy.Result r = new SceneStudy(Method.FIT, 2).run(Scene.of("pair", dark), images, 7);
		assertEquals(0, r.lost(), "lost");
		assertEquals(0, r.extra(), "extra spots");
		final boolean unbiased = Math.abs(r.bias()) < 1 && Math.abs(r.meanError()) < 1;
		assertTrue(unbiased || r.flagged() == 2 * images, "bias " + r.bias() + " nm, distance error " + r.meanError() +
			" nm, yet only " + r.flagged() + " of " + 2 * images + " spots flagged");
	}
}
