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
package io.github.contacttracker.lab.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;

class ScenarioTest {

	private static final double D = 65.29;

	private static double distance(final double[] a, final double[] b) {
		return Math.hypot(a[0] - b[0], a[1] - b[1]);
	}

	@Test
	void pairIsSymmetricAtTheRequestedDistance() {
		final List<double[]> c = Scenario.PAIR.centres(1.37, D, 100, 50);
		assertEquals(2, c.size());
		assertEquals(1.37 * D, distance(c.get(0), c.get(1)), 1e-12);
		assertEquals(100, 0.5 * (c.get(0)[0] + c.get(1)[0]), 1e-12);
		assertEquals(50, c.get(0)[1], 0);
		assertEquals(50, c.get(1)[1], 0);
		assertEquals(100 - 0.685 * D, c.get(0)[0], 1e-12);
		assertArrayEquals(new int[] { 0, 1 }, Scenario.PAIR.measuredPair());
	}

	@Test
	void tripleStartsAsATouchingEquilateralTriangle() {
		final List<double[]> c = Scenario.TRIPLE.centres(1, D, 100, 80);
		assertEquals(3, c.size());
		assertEquals(D, distance(c.get(0), c.get(1)), 1e-9);
		assertEquals(D, distance(c.get(0), c.get(2)), 1e-9);
		assertEquals(D, distance(c.get(1), c.get(2)), 1e-9);
		assertArrayEquals(new int[] { 0, 1 }, Scenario.TRIPLE.measuredPair());
	}

	@Test
	void tripleMovesTheOuterPairApartAndKeepsTheMiddleFixed() {
		final List<double[]> contact = Scenario.TRIPLE.centres(1, D, 100, 80);
		final List<double[]> apart = Scenario.TRIPLE.centres(1.5, D, 100, 80);
		assertEquals(1.5 * D, distance(apart.get(0), apart.get(1)), 1e-9);
		assertArrayEquals(contact.get(2), apart.get(2), 0);
		// the pair's midpoint stays put and the pair moves along its own line
		assertEquals(100, 0.5 * (apart.get(0)[0] + apart.get(1)[0]), 1e-12);
		assertEquals(contact.get(0)[1], apart.get(0)[1], 0);
		// the middle particle is now further than D from both
		assertEquals(Math.hypot(0.75 * D, Math.sqrt(3) / 2 * D), distance(apart.get(0), apart.get(2)), 1e-9);
		assertEquals(distance(apart.get(0), apart.get(2)), distance(apart.get(1), apart.get(2)), 1e-9);
	}

	@Test
	void rejectsNonPositiveSeparation() {
		assertThrows(IllegalArgumentException.class, () -> Scenario.PAIR.centres(0, D, 0, 0));
		assertThrows(IllegalArgumentException.class, () -> Scenario.TRIPLE.centres(1, -D, 0, 0));
	}
}
