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

import java.util.List;

import io.github.contacttracker.core.Connectivity;

import net.imglib2.img.array.ArrayImgs;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A threshold between two grey levels: integer planes compare with ceil(threshold), which must give exactly the
 * active pixels {@code v >= threshold} of the generic path, for thresholds just below, at and just above a level.
 */
class FractionalThresholdTest {

	@ParameterizedTest
	@ValueSource(doubles = { 99.0, 99.25, 99.5, 99.999, 100.0, 100.001, 100.5 })
	void integerFastPathsActivateExactlyThePixelsAtOrAboveAFractionalThreshold(final double threshold) {
		// a ramp of grey levels 95..104 along x, ten rows
		final int w = 10, h = 10;
		final byte[] bytes = new byte[w * h];
		final short[] shorts = new short[w * h];
		final float[] floats = new float[w * h];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				bytes[y * w + x] = (byte) (95 + x);
				shorts[y * w + x] = (short) (95 + x);
				floats[y * w + x] = 95 + x;
			}
		int expected = 0;
		for (int x = 0; x < w; x++)
			if (95 + x >= threshold) expected += h;
		for (final Plane plane : List.of(Plane.of(ArrayImgs.unsignedBytes(bytes, w, h)), Plane.of(ArrayImgs
			.unsignedShorts(shorts, w, h)), Plane.of(ArrayImgs.floats(floats, w, h)), Plane.generic(ArrayImgs
				.unsignedBytes(bytes, w, h))))
		{
			final List<Region> regions = ComponentLabeling.label(plane, threshold, Connectivity.EIGHT);
			assertEquals(1, regions.size(), plane.getClass().getSimpleName());
			assertEquals(expected, regions.get(0).area(), plane.getClass().getSimpleName() + " at " + threshold);
		}
	}
}
