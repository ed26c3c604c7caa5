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
package io.github.contacttracker.core.radial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.core.track.FrameResult;

class CentreUncertaintyTest {

	/** The propagated variance equals the sum of squared finite-difference derivatives dc/dI_p. */
	@Test
	void propagationEqualsFiniteDifferences() {
		final int w = 60, h = 56;
		final double[] img = TestImages.render(w, h, 20, TestImages.gaussian(150, 7), new double[] { 29.3, 27.8 });
		for (final Method m : new Method[] { Method.FIRST }) {
			final ContactTracker t = new ContactTracker(TrackerParameters.of(60, 30).withMethod(m));
			final Plane base = Plane.of(TestImages.floats(img, w, h));
			final FrameResult r0 = t.analyse(base, 0, false);
			final Localization s0 = r0.spots().get(0);
			final double eps = 1e-3;
			double vx = 0, vy = 0;
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					final double[] bumped = img.clone();
					bumped[y * w + x] += eps;
					final Localization s = t.analyse(Plane.of(TestImages.floats(bumped, w, h)), 0, false).spots().get(0);
					if (s.activeArea() != s0.activeArea()) continue; // the mask moved: not part of the linear model
					final double dx = (s.x() - s0.x()) / eps, dy = (s.y() - s0.y()) / eps;
					vx += dx * dx;
					vy += dy * dy;
				}
			// sigmaX = noise * sqrt(var per unit noise): compare per unit noise.
			final double noise = r0.noiseSigma();
			assertTrue(noise > 0);
			assertEquals(Math.sqrt(vx), s0.sigmaX() / noise, 0.02 * Math.sqrt(vx));
			assertEquals(Math.sqrt(vy), s0.sigmaY() / noise, 0.02 * Math.sqrt(vy));
		}
	}

	/** On noisy images, the reported standard error matches the observed spread of the centres. */
	@Test
	void reportedErrorMatchesObservedSpread() {
		final int w = 70, h = 70, n = 300;
		final double[] clean = TestImages.render(w, h, 40, TestImages.gaussian(150, 8), new double[] { 35.2, 34.6 });
		final ContactTracker t = new ContactTracker(TrackerParameters.of(100, 35));
		double sx = 0, sxx = 0, sigma = 0;
		for (int k = 0; k < n; k++) {
			final List<Localization> spots = t.track(TestImages.bytes(TestImages.withUniformNoise(clean, 5, 100 + k), w,
				h), 0);
			assertEquals(1, spots.size());
			sx += spots.get(0).x();
			sxx += spots.get(0).x() * spots.get(0).x();
			sigma += spots.get(0).sigmaX();
		}
		final double observed = Math.sqrt((sxx - sx * sx / n) / (n - 1));
		final double reported = sigma / n;
		final double ratio = reported / observed;
		assertTrue(ratio > 0.8 && ratio < 1.25, "reported/observed = " + ratio + " (" + reported + " vs " +
			observed + ")");
	}
}
