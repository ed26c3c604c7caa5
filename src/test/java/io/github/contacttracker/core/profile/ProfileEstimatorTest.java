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
package io.github.contacttracker.core.profile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.function.DoubleUnaryOperator;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.DoublePlane;

class ProfileEstimatorTest {

	/** Overlapping particles (no undistorted side): the joint model still recovers the profile. */
	@Test
	void recoversProfileFromOverlappingParticles() {
		final DoubleUnaryOperator profile = r -> 100 * Math.exp(-r * r / 50) - 20 * Math.exp(-(r - 12) * (r - 12) / 8);
		final int w = 120, h = 90;
		final double[][] c = { { 45.3, 44.8 }, { 63.1, 46.2 }, { 54.0, 30.4 } };
		final double[] img = TestImages.render(w, h, 30, profile, c);
		final ProfileEstimator est = new ProfileEstimator(30);
		est.add(new DoublePlane(img, w, h), new double[] { c[0][0], c[1][0], c[2][0] }, new double[] { c[0][1], c[1][1],
			c[2][1] }, new boolean[3]);
		final EmpiricalProfile p = est.estimate();
		assertEquals(30, p.background(), 0.05);
		// Pixel integration blurs the profile slightly: compare with the pixel-averaged truth.
		for (double r = 0; r < 20; r += 0.7) {
			double avg = 0;
			for (int i = 0; i < 8; i++)
				for (int j = 0; j < 8; j++)
					avg += profile.applyAsDouble(Math.hypot(r + (i + 0.5) / 8 - 0.5, (j + 0.5) / 8 - 0.5));
			assertEquals(avg / 64, p.value(r), 0.3, "at r = " + r);
		}
		assertEquals(0, p.value(p.radius() + 1), 0);
	}

	@Test
	void tooLittleDataIsRefused() {
		final ProfileEstimator est = new ProfileEstimator(30);
		assertThrows(IllegalStateException.class, est::estimate);
	}
}
