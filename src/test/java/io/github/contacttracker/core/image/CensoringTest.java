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

	@Test
	void eightBitClipsAtBothEnds() {
		final byte[] pixels = new byte[100];
		java.util.Arrays.fill(pixels, (byte) 50);
		pixels[0] = 0; // a dark ring's pixel clipped, the background not
		pixels[1] = (byte) 255;
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10));
		assertEquals(0, plane.floor());
		assertEquals(255, plane.saturation());
		final Censoring c = Censoring.of(plane, 2);
		assertTrue(c.clipped(0));
		assertTrue(c.clipped(255));
		assertFalse(c.clipped(1));
		// the band: within 3 sigma (6 grey levels) of a clip level, by the model
		assertFalse(c.usable(6));
		assertTrue(c.usable(6.5));
		assertTrue(c.usable(248.5));
		assertFalse(c.usable(249));
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
		assertTrue(c.clipped(0));
		assertFalse(c.usable(6), "the band stays");
		pixels[0] = pixels[1] = pixels[2] = pixels[3] = 50;
		assertFalse(Censoring.of(Plane.of(ArrayImgs.unsignedBytes(pixels, 10, 10)), 2).backgroundClipped());
	}

	@Test
	void floatingPointNeverClips() {
		final Plane plane = Plane.of(ArrayImgs.floats(new float[4], 2, 2));
		final Censoring c = Censoring.of(plane, 2);
		assertFalse(c.active());
		assertFalse(c.clipped(-1e30));
		assertTrue(c.usable(1e30));
	}
}
