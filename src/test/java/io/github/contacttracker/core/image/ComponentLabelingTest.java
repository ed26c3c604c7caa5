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

import java.util.ArrayDeque;
import java.util.List;
import java.util.Random;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.TestImages;

import net.imglib2.img.array.ArrayImgs;
import net.imglib2.view.Views;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class ComponentLabelingTest {

	/** Reference: breadth-first flood fill, components numbered in raster order of their first pixel. */
	private static int[] floodFill(final boolean[] mask, final int w, final int h, final Connectivity c) {
		final int[] label = new int[w * h];
		java.util.Arrays.fill(label, -1);
		int next = 0;
		final ArrayDeque<Integer> queue = new ArrayDeque<>();
		for (int start = 0; start < w * h; start++) {
			if (!mask[start] || label[start] >= 0) continue;
			label[start] = next;
			queue.add(start);
			while (!queue.isEmpty()) {
				final int p = queue.poll(), px = p % w, py = p / w;
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++) {
						if (dx == 0 && dy == 0) continue;
						if (c == Connectivity.FOUR && dx != 0 && dy != 0) continue;
						final int x = px + dx, y = py + dy;
						if (x < 0 || y < 0 || x >= w || y >= h) continue;
						final int q = y * w + x;
						if (mask[q] && label[q] < 0) {
							label[q] = next;
							queue.add(q);
						}
					}
			}
			next++;
		}
		return label;
	}

	private static void assertSameLabels(final int[] expected, final List<Region> regions, final int w,
		final int h)
	{
		final int[] got = new int[w * h];
		java.util.Arrays.fill(got, -1);
		for (int k = 0; k < regions.size(); k++) {
			final int label = k;
			regions.get(k).forEachPixel((x, y) -> got[y * w + x] = label);
		}
		int max = -1;
		for (final int e : expected)
			max = Math.max(max, e);
		assertEquals(max + 1, regions.size(), "number of components");
		for (int i = 0; i < w * h; i++)
			assertEquals(expected[i], got[i], "label at pixel " + i);
	}

	@ParameterizedTest
	@EnumSource(Connectivity.class)
	void equalsFloodFillOnRandomMasks(final Connectivity c) {
		final Random rnd = new Random(42);
		for (int trial = 0; trial < 200; trial++) {
			final int w = 1 + rnd.nextInt(40), h = 1 + rnd.nextInt(40);
			final double density = rnd.nextDouble();
			final boolean[] mask = new boolean[w * h];
			final byte[] pixels = new byte[w * h];
			for (int i = 0; i < w * h; i++) {
				mask[i] = rnd.nextDouble() < density;
				pixels[i] = (byte) (mask[i] ? 1 : 0);
			}
			assertSameLabels(floodFill(mask, w, h, c), ComponentLabeling.label(Plane.of(ArrayImgs.unsignedBytes(pixels, w,
				h)), 1, c), w, h);
		}
	}

	@ParameterizedTest
	@EnumSource(Connectivity.class)
	void thresholdedImageEqualsFloodFillInThePlanesOwnCoordinates(final Connectivity c) {
		final Random rnd = new Random(7);
		final int w = 64, h = 48;
		final double[] img = new double[w * h];
		final boolean[] mask = new boolean[w * h];
		for (int i = 0; i < img.length; i++) {
			img[i] = rnd.nextInt(256);
			mask[i] = img[i] >= 140;
		}
		final int[] expected = floodFill(mask, w, h, c);
		assertSameLabels(expected, ComponentLabeling.label(Plane.of(TestImages.bytes(img, w, h)), 140, c), w, h);
		// Same image translated: the plane keeps the offset, the regions are in its own coordinates (from 0, 0).
		final Plane translated = Plane.of(Views.translate(TestImages.floats(img, w, h), 10, -3));
		assertEquals(10, translated.minX());
		assertEquals(-3, translated.minY());
		assertSameLabels(expected, ComponentLabeling.label(translated, 140, c), w, h);
	}

	@Test
	void diagonalPixelsJoinOnlyWithEightConnectivity() {
		final byte[] px = { 1, 0, 0, //
			0, 1, 0, //
			0, 0, 1 };
		final Plane img = Plane.of(ArrayImgs.unsignedBytes(px, 3, 3));
		assertEquals(1, ComponentLabeling.label(img, 1, Connectivity.EIGHT).size());
		assertEquals(3, ComponentLabeling.label(img, 1, Connectivity.FOUR).size());
		assertEquals(3, ComponentLabeling.label(img, 1, Connectivity.EIGHT).get(0).area());
	}
}
