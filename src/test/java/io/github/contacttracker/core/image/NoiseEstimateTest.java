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
package io.github.contacttracker.core.image;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;

/** {@link NoiseEstimate}: the noise of a frame with smooth signal, and the same value from every kind of plane. */
class NoiseEstimateTest {

	/** Two particles on a background, Gaussian noise of sigma 4 rounded to whole grey levels. */
	private static double[] frame() {
		final double[] img = TestImages.render(300, 200, 40, TestImages.gaussian(120, 6), new double[] { 80.3, 90.7 },
			new double[] { 200.6, 110.2 });
		final Random random = new Random(17);
		for (int i = 0; i < img.length; i++)
			img[i] = Math.round(img[i] + 4 * random.nextGaussian());
		return img;
	}

	@Test
	void measuresGaussianNoiseUnderSmoothSignal() {
		// rounding adds 1/12 to the variance: sqrt(16 + 1/12) = 4.01
		assertEquals(4.01, NoiseEstimate.sigma(Plane.of(TestImages.bytes(frame(), 300, 200))), 0.2);
	}

	/** The 8-bit path reads the array in integers; the others through Plane.read: the same sum, bit for bit. */
	@Test
	void everyPlaneTypeGivesTheSameValue() {
		final double[] img = frame();
		final double bytes = NoiseEstimate.sigma(Plane.of(TestImages.bytes(img, 300, 200)));
		assertEquals(bytes, NoiseEstimate.sigma(Plane.generic(TestImages.bytes(img, 300, 200))), 0);
		assertEquals(bytes, NoiseEstimate.sigma(Plane.of(TestImages.shorts(img, 300, 200))), 0);
		assertEquals(bytes, NoiseEstimate.sigma(Plane.of(TestImages.floats(img, 300, 200))), 0);
	}
}
