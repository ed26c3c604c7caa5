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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;

/** The plane's pixel access (moved here from {@code FitPixelsTest} with the split of the core into rooms). */
class PlaneTest {

	/**
	 * The 8-bit threshold scan, which skips eight dark pixels at once by a word test, finds the runs the general
	 * scan finds: bright pixels at every position within a word, values on both sides of 128, thresholds at the
	 * test's edges (1, 128, 129, 255) and between.
	 */
	@Test
	void byteScanFindsTheRunsOfTheGeneralScan() {
		final int w = 203, h = 40; // not a multiple of eight: words end inside the row
		final Random random = new Random(9);
		final double[] img = new double[w * h];
		for (int i = 0; i < img.length; i++) {
			final int kind = random.nextInt(10);
			img[i] = kind < 6 ? random.nextInt(60) : kind < 8 ? 100 + random.nextInt(60) : random.nextInt(256);
		}
		img[0] = 255; // a bright first pixel of a row, and a bright last one
		img[w - 1] = 200;
		final Plane bytes = Plane.of(TestImages.bytes(img, w, h)), generic = Plane.generic(TestImages.bytes(img, w, h));
		for (final double t : new double[] { 0, 0.5, 1, 2, 59.5, 60, 85, 127, 128, 128.5, 129, 130, 200, 254, 255 }) {
			int found = 0;
			for (int y = 0; y < h; y++) {
				final RunList a = new RunList(), b = new RunList();
				bytes.scanRow(y, t, a);
				generic.scanRow(y, t, b);
				assertEquals(b.size, a.size, "threshold " + t + ", row " + y);
				for (int r = 0; r < a.size; r++) {
					assertEquals(b.x0[r], a.x0[r], "threshold " + t + ", row " + y + ", run " + r);
					assertEquals(b.x1[r], a.x1[r], "threshold " + t + ", row " + y + ", run " + r);
				}
				found += a.size;
			}
			assertTrue(found > 0, "threshold " + t + " finds runs");
		}
	}
}
