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

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The smoothing of the band-pass: a Gaussian, and for wide ones three boxes of the same variance. */
class BandPassTest {

	/** The three boxes' widths give the Gaussian's variance to within one box step. */
	@ParameterizedTest
	@ValueSource(doubles = { 16.5, 20, 37.3, 187.5 })
	void theBoxesHaveTheGaussiansVariance(final double sigma) {
		double variance = 0;
		for (final int r : BandPass.boxRadii(sigma)) {
			final int b = 2 * r + 1;
			variance += (b * (double) b - 1) / 12;
		}
		// one box two pixels wider or narrower changes the variance by (b + 1) / 3
		assertEquals(sigma * sigma, variance, (2 * Math.sqrt(4 * sigma * sigma) + 2) / 3, "sigma " + sigma);
	}

	/**
	 * An impulse blurred by the boxes against the Gaussian kernel itself: the same second moment to 2%, and within 6%
	 * of the Gaussian's peak everywhere.
	 */
	@ParameterizedTest
	@ValueSource(doubles = { 17, 24 })
	void anImpulseBlurredByTheBoxesIsAlmostTheGaussian(final double sigma) {
		final int w = 301, h = 301, c = 150;
		final float[] impulse = new float[w * h];
		impulse[c * w + c] = 1;
		final float[] blurred = BandPass.blur(impulse, w, h, sigma);
		double sum = 0, moment = 0, worst = 0;
		final double peak = 1 / (2 * Math.PI * sigma * sigma);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				final double v = blurred[y * w + x], r2 = (x - c) * (x - c) + (y - c) * (y - c);
				sum += v;
				moment += v * r2;
				worst = Math.max(worst, Math.abs(v - peak * Math.exp(-r2 / (2 * sigma * sigma))));
			}
		assertEquals(1, sum, 1e-4, "the boxes keep the light");
		assertEquals(2 * sigma * sigma, moment / sum, 0.02 * 2 * sigma * sigma, "second moment");
		assertTrue(worst < 0.06 * peak, "largest difference " + worst / peak + " of the peak");
	}
}
