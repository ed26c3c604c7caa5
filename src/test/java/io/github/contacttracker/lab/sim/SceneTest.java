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
package io.github.contacttracker.lab.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class SceneTest {

	@Test
	void poissonHasItsMeanAndVariance() {
		final SplittableRandom r = new SplittableRandom(3);
		for (final double mean : new double[] { 2.5, 40, 900 }) {
			double s = 0, s2 = 0;
			final int n = 40000;
			for (int i = 0; i < n; i++) {
				final double k = Poisson.sample(mean, r);
				s += k;
				s2 += k * k;
			}
			final double m = s / n, v = s2 / n - m * m;
			// standard errors: sqrt(mean / n) for the mean, about mean sqrt(2 / n) for the variance
			assertEquals(mean, m, 5 * Math.sqrt(mean / n), "mean " + mean);
			assertEquals(mean, v, 5 * mean * Math.sqrt(2.0 / n) + 0.05, "variance at mean " + mean);
		}
	}

	@Test
	void scaledParticleIsTheProfileStretched() {
		final RadialProfile p = GaussianBesselProfile.gaussian(100, 5);
		final ImageSimulator sim = new ImageSimulator(p, 1);
		final NoiseFreeImage img = NoiseFreeImage.uniform(61, 61, 0);
		sim.addParticle(img, 30, 30, 1.3, 1.1);
		for (final int dx : new int[] { 0, 3, 7, 12 })
			assertEquals(110 * Math.exp(-dx * dx / (2 * 6.5 * 6.5)), img.get(30 + dx, 30), 0.02, "r = " + dx);
	}

	@Test
	void scenesAreTouchingClustersOfTheirSize() {
		final ParticleType t = PaperParticles.silica553();
		assertEquals(6 + 6, Scene.of("hex7", t).touchingPairs().size());
		assertEquals(3, Scene.of("chain4", t).touchingPairs().size());
		assertEquals(3, Scene.of("triple", t).touchingPairs().size());
		assertEquals(1, Scene.of("unlike13", t).touchingPairs().size());
		final Scene ramp = Scene.of("ramp", t);
		final SimulatedStack<?> s = ramp.simulate(2, 1);
		assertEquals(2, s.frameCount());
		final List<double[]> c = s.truth().get(0);
		assertEquals(t.diameterPx(), Math.hypot(c.get(0)[0] - c.get(1)[0], c.get(0)[1] - c.get(1)[1]), 1e-9);
		assertTrue(Scene.of("saturated", t).simulate(1, 1).clippedPixels() > 50, "cores clip");
		assertEquals(0, Scene.of("pair", t).simulate(1, 1).clippedPixels());
	}
}
