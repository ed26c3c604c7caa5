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
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import net.imglib2.img.array.ArrayImgs;

class CensoringTest {

	/**
	 * Where the background is not clipped, the floor is linked with the frame's noise (a dark ring's pixel at 0 is
	 * kept, fitted through the link) and the saturation banded: within 3 sigma (6 grey levels) of it, by the model.
	 */
	@Test
	void eightBitLinksTheFloorAndBandsTheSaturation() {
		final byte[] pixels = new byte[100];
		java.util.Arrays.fill(pixels, (byte) 50);
		pixels[0] = 0; // a dark ring's pixel clipped, the background not
		pixels[1] = (byte) 255;
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10));
		assertEquals(0, plane.floor());
		assertEquals(255, plane.saturation());
		final Censoring c = Censoring.of(plane, 2);
		assertFalse(c.backgroundClipped());
		assertTrue(c.linked());
		assertEquals(2, c.floorNoise());
		assertFalse(c.clipped(0), "linked: kept");
		assertTrue(c.clipped(255));
		assertFalse(c.clipped(1));
		assertTrue(c.usable(0));
		assertTrue(c.usable(-20), "linked: any model near the floor is fitted through the link");
		assertTrue(c.usable(248.5));
		assertFalse(c.usable(249));
		assertEquals(0.5 + 6 * 2, c.linkTop(), 1e-12);
	}

	/**
	 * The link is the mean of normal noise added to the model, rounded and clipped at the floor: checked against
	 * 2 million draws at models below, at and above the floor; its slope against the mean's numerical derivative; far
	 * above the floor (at the link's top) both are the model's own to 1e-7.
	 */
	@Test
	void theLinkIsTheMeanOfRoundedClippedNoise() {
		final byte[] pixels = new byte[100];
		java.util.Arrays.fill(pixels, (byte) 50);
		final double sigma = 4;
		final Censoring c = Censoring.of(Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10)), sigma);
		final java.util.SplittableRandom random = new java.util.SplittableRandom(5);
		final int draws = 2_000_000;
		for (final double m : new double[] { -3, 0, 2, 5.5, 12 }) {
			double sum = 0;
			for (int i = 0; i < draws; i++) {
				final double g = gaussian(random);
				sum += Math.max(0, Math.rint(m + sigma * g));
			}
			// the draws' mean to its standard error (under sigma / sqrt(draws) = 0.003), and the link's values above
			// the floor taken as unrounded (0.010 grey levels off at a model of 2 with noise 4: a quarter of a percent
			// of the noise)
			assertEquals(sum / draws, c.mean(m), 0.02, "model " + m);
			final double h = 1e-4, numerical = (c.mean(m + h) - c.mean(m - h)) / (2 * h);
			assertEquals(numerical, c.slope(m), 1e-6, "slope at " + m);
		}
		final double top = c.linkTop();
		assertEquals(top, c.mean(top), 1e-7 * sigma);
		assertEquals(1, c.slope(top), 1e-7);
	}

	private static double gaussian(final java.util.SplittableRandom random) {
		double u, v, s;
		do {
			u = 2 * random.nextDouble() - 1;
			v = 2 * random.nextDouble() - 1;
			s = u * u + v * v;
		}
		while (s >= 1 || s == 0);
		return u * Math.sqrt(-2 * Math.log(s) / s);
	}

	/**
	 * A background clipped at the floor (more than 5% of the pixels at it, as confocal slices with the offset
	 * subtracted) is said, so that a fit holds its background instead of fitting it from pixels the band leaves out;
	 * a dark ring's few clipped pixels are not.
	 */
	@Test
	void aClippedBackgroundIsSaid() {
		final byte[] pixels = new byte[100];
		java.util.Arrays.fill(pixels, (byte) 50);
		java.util.Arrays.fill(pixels, 0, 6, (byte) 0);
		final Censoring c = Censoring.of(Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10)), 2);
		assertTrue(c.backgroundClipped());
		// the frame's noise is not the clipped background's: banded until the profile measures that
		assertFalse(c.linked());
		assertTrue(c.clipped(0));
		assertFalse(c.usable(6), "the band stays");
		assertTrue(c.usable(6.5));
		final Censoring linked = c.withFloorNoise(3);
		assertTrue(linked.linked());
		assertEquals(3, linked.floorNoise());
		assertFalse(linked.clipped(0));
		assertTrue(linked.usable(6));
		assertTrue(linked.backgroundClipped());
		assertFalse(c.withFloorNoise(Double.NaN).linked(), "not measured (a background of structure): the band");
		pixels[0] = pixels[1] = pixels[2] = pixels[3] = 50;
		final Censoring not = Censoring.of(Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10)), 2);
		assertFalse(not.backgroundClipped());
		assertEquals(2, not.withFloorNoise(3).floorNoise(), "a background not clipped keeps the frame's noise");
	}

	@Test
	void floatingPointNeverClips() {
		final Plane plane = Plane.of(ArrayImgs.floats(new float[4], 2, 2));
		final Censoring c = Censoring.of(plane, 2);
		assertFalse(c.active());
		assertFalse(c.linked());
		assertFalse(c.clipped(-1e30));
		assertTrue(c.usable(1e30));
	}
}
