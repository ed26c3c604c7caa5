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
package io.github.contacttracker.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;

/** RADIUS from the diameter given: one value for one kind, each kind its own when several were found. */
class KindRadiiTest {

	private static Localization spot(final double activeRadius, final int kind) {
		return new Localization(0, 10, 10, 10, 10, (int) Math.round(Math.PI * activeRadius * activeRadius), 0, 1,
			activeRadius, 0, 2, 0.01, 0.01, Double.NaN, Double.NaN, kind);
	}

	@Test
	void oneKindGetsHalfTheDiameter() {
		final List<Localization> spots = List.of(spot(5, 0), spot(6, 0), spot(7, 0));
		assertArrayEquals(new double[] { 10 }, KindRadii.of(spots, 20), 0);
		assertArrayEquals(new double[] { 10, 10 }, KindRadii.of(List.of(spot(5, 1), spot(6, 1)), 20), 0);
	}

	/**
	 * Two kinds, the small one most numerous: it gets half the diameter, the large one that scaled by the ratio of
	 * their median active-area radii (8 / 5), whatever the outliers.
	 */
	@Test
	void eachKindItsOwnRadius() {
		final List<Localization> spots = new ArrayList<>();
		for (int i = 0; i < 6; i++)
			spots.add(spot(i == 0 ? 2 : 5, 1));
		for (int i = 0; i < 3; i++)
			spots.add(spot(i == 0 ? 30 : 8, 2));
		spots.add(spot(3, 0)); // no kind: the main kind's
		assertArrayEquals(new double[] { 10, 10, 16 }, KindRadii.of(spots, 20), 1e-12);
	}
}
