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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

/** The local background plane: exact on a plane, robust to a neighbour's light, a constant on a line. */
class BackgroundPlaneTest {

	private static final double A = 57.3, B = 0.41, C = -0.27;

	/**
	 * An annulus of a tilted background with a sector of it lit by a neighbour (40 grey levels up): the refit without
	 * the lit pixels gives the background's own plane back.
	 */
	@Test
	void tiltedAnnulusWithANeighbourGivesThePlaneBack() {
		final DoubleList x = new DoubleList(), y = new DoubleList(), v = new DoubleList();
		for (int j = -20; j <= 20; j++)
			for (int i = -20; i <= 20; i++) {
				final double r = Math.hypot(i, j);
				if (r < 16 || r > 20) continue;
				x.add(i);
				y.add(j);
				v.add(A + B * i + C * j + (i > 0 && 4 * Math.abs(j) < i ? 40 : 0));
			}
		assertArrayEquals(new double[] { A, B, C }, BackgroundPlane.robust(x, y, v), 1e-9);
	}

	/** Points on one column (an annulus cut to a sliver by the border): no plane, their mean. */
	@Test
	void pointsOnALineGiveTheirMean() {
		final DoubleList x = new DoubleList(), y = new DoubleList(), v = new DoubleList();
		double sum = 0;
		for (int j = -15; j <= 15; j++) {
			x.add(12);
			y.add(j);
			v.add(A + C * j + (j % 3));
			sum += A + C * j + (j % 3);
		}
		assertArrayEquals(new double[] { sum / 31, 0, 0 }, BackgroundPlane.robust(x, y, v), 1e-9);
	}
}
