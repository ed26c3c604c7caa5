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
package io.github.contacttracker.core.track;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;

/**
 * QUALITY ranks real particles above noise: every particle, bright or faint, gets 1, components of noise less, so
 * that a histogram threshold (TrackMate's automatic one) that keeps the top group keeps every particle.
 */
class QualityTest {

	@Test
	void theSignificanceOfTheSummedExcessCappedAtOne() {
		// z = 400 / (4 sqrt(25)) = 20, of 50
		assertEquals(20.0 / ContactTracker.FULL_SIGNIFICANCE, ContactTracker.quality(400, 25, 4), 1e-15);
		assertEquals(1, ContactTracker.quality(1e6, 25, 4), 0);
		assertEquals(1, ContactTracker.quality(10, 25, 0), 0, "a noiseless image: every spot is certain");
	}

	@Test
	void particlesOfTwoBrightnessesAllGetOneNoiseComponentsLess() {
		final int w = 220, h = 160;
		final double[][] bright = { { 50, 50 }, { 160, 45 } }, faint = { { 55, 115 }, { 165, 112 } };
		final double[] b = TestImages.render(w, h, 20, TestImages.gaussian(150, 8), bright);
		final double[] f = TestImages.render(w, h, 0, TestImages.gaussian(45, 8), faint);
		final double[] img = new double[w * h];
		for (int i = 0; i < img.length; i++)
			img[i] = b[i] + f[i];
		// white noise and a threshold 6 grey levels above the background: small components of noise pass min_area 3
		final double[] noisy = TestImages.withUniformNoise(img, 10, 20261202L);
		final List<Localization> spots = new ContactTracker(TrackerParameters.of(26, 30).withMinArea(3).withMethod(
			Method.values()[0])).track(TestImages.floats(noisy, w, h), 0);
		final List<double[]> truth = new ArrayList<>(List.of(bright));
		truth.addAll(List.of(faint));
		int particles = 0, noise = 0;
		double brightArea = 0, faintArea = Double.POSITIVE_INFINITY;
		for (final Localization s : spots) {
			final double[] nearest = truth.stream().min((p, q) -> Double.compare(Math.hypot(p[0] - s.x(), p[1] - s.y()),
				Math.hypot(q[0] - s.x(), q[1] - s.y()))).get();
			if (Math.hypot(nearest[0] - s.x(), nearest[1] - s.y()) < 3) {
				particles++;
				assertEquals(1, s.quality(), 0, "a particle at " + s.x() + ", " + s.y());
				// the two kinds differ in size and brightness (the summed excess, which QUALITY was, split them)
				if (nearest[1] < 80) brightArea = Math.max(brightArea, s.activeArea());
				else faintArea = Math.min(faintArea, s.activeArea());
			}
			else {
				noise++;
				assertTrue(s.quality() < 0.5, "noise at " + s.x() + ", " + s.y() + ": " + s.quality());
			}
		}
		assertEquals(4, particles, "every particle found");
		assertTrue(noise >= 3, "the scene must hold components of noise: " + noise);
		assertTrue(brightArea > faintArea, "two kinds of particles");
	}
}
