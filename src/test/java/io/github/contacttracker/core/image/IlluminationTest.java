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

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;

/** A frame's pixels relative to its light: a ramp and a vignette taken out, the particles left. */
class IlluminationTest {

	private static final int W = 160, H = 120;

	/** @return light of a ramp and a fall-off to the corners, with {@code discs} discs 400 above it, radius 6 */
	private static double[] frame(final int discs) {
		final double[] img = new double[W * H];
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				final double u = (x - 80) / 80.0, v = (y - 60) / 60.0;
				img[y * W + x] = 2000 + 900 * u - 300 * v - 500 * (u * u + v * v);
				for (int k = 0; k < discs; k++)
					if (Math.hypot(x - 20 - 30 * k, y - 30 - 15 * (k % 3)) <= 6) img[y * W + x] += 400;
			}
		return img;
	}

	@Test
	void theLightIsTakenOutAndTheParticlesAreLeft() {
		final double[] img = frame(5);
		final double[] light = frame(0);
		final double[] r = Illumination.residuals(Plane.of(TestImages.floats(img, W, H)));
		assertEquals(W * H, r.length);
		// the particles' pixels are outliers of the fit, which the light alone determines
		for (int i = 0; i < r.length; i++)
			assertEquals(img[i] - light[i], r[i], 1e-3, "at " + i % W + ", " + i / W);
	}

	/** A frame too small for a surface is read as it is. */
	@Test
	void aFrameTooSmallIsReadAsItIs() {
		final double[] img = { 1, 2, 3, 4 };
		final double[] r = Illumination.residuals(Plane.of(TestImages.floats(img, 2, 2)));
		for (int i = 0; i < img.length; i++)
			assertEquals(img[i], r[i], 0);
	}
}
