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
package io.github.contacttracker.core.detect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.Plane;

/**
 * The particles' diameter read from the frame's blobs, without an isolated particle: sparse, touching and densely
 * packed discs of known diameter, with noise (measured: within 1% sparse, 10-22% small at area fraction 0.5, where
 * neighbours narrow each blob's response); a frame without blobs gives none.
 */
class ParticleScaleTest {

	/** Discs of diameter {@code d} at area fraction {@code fraction} (touching from about 0.5 on), on 20, noise 3. */
	private static double measured(final double d, final double fraction, final long seed) {
		return measured(d, fraction, 150, 3, seed);
	}

	/** Discs as above, {@code amplitude} above the background, with pixel noise {@code noise}. */
	private static double measured(final double d, final double fraction, final double amplitude, final double noise,
		final long seed)
	{
		final int w = 256, h = 256;
		final List<Scenes.Truth> truth = new ArrayList<>();
		for (final double[] p : Scenes.packing(w, h, new double[] { d / 2 }, fraction, 0, seed))
			truth.add(new Scenes.Truth(p[0], p[1], amplitude, p[2]));
		final double[] img = Scenes.noisy(Scenes.render(w, h, (x, y) -> 20, truth, Scenes.blurredDisc(1, 0.15), 2), noise,
			0, 255, seed);
		return ParticleScale.diameter(Plane.of(TestImages.bytes(img, w, h)));
	}

	@Test
	void sparseTouchingAndDenseDiscsAreMeasuredWithinAQuarter() {
		for (final double d : new double[] { 6, 12, 24 })
			for (final double fraction : new double[] { 0.1, 0.3, 0.5 }) {
				final double m = measured(d, fraction, 7 + (long) d);
				assertEquals(d, m, 0.25 * d, "diameter " + d + " at area fraction " + fraction);
			}
	}

	/**
	 * Strong pixel noise against the particles (a confocal slice's speckle: noise 15 on discs 40 above the background)
	 * makes small blobs inside every particle that answer as strongly as the particles; only those standing out from
	 * the noise are counted (without that rule, 12 px discs measured 5.8 px).
	 */
	@Test
	void discsUnderStrongNoiseAreMeasuredByTheBlobsThatStandOut() {
		for (final double d : new double[] { 8, 12 }) {
			final double m = measured(d, 0.5, 40, 15, 11 + (long) d);
			assertEquals(d, m, 0.25 * d, "diameter " + d + " under noise 15 against 40");
		}
	}

	@Test
	void aFrameWithoutBlobsHasNoDiameter() {
		final double[] flat = new double[64 * 64];
		java.util.Arrays.fill(flat, 40);
		assertTrue(Double.isNaN(ParticleScale.diameter(Plane.of(TestImages.bytes(flat, 64, 64)))));
		assertTrue(Double.isNaN(ParticleScale.diameter(Plane.of(TestImages.bytes(new double[] { 1, 2, 3 }, 3, 1)))));
	}
}
