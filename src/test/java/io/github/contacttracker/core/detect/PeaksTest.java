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

import org.junit.jupiter.api.Test;

class PeaksTest {

	private static Peaks heights(final double... h) {
		return new Peaks(new double[h.length], new double[h.length], h, h.clone());
	}

	@Test
	void theHighestStandApartWhereTheHeightsFallByTheRatio() {
		// a tweezer's bead among the background's bumps, band-passed (a public stack's first frame)
		assertEquals(1, heights(51.2, 3.5, 3.1, 2.7, 1.3).standingApart(5));
		assertEquals(2, heights(60, 48, 9, 8).standingApart(5));
		// particles of one kind, however many: no fall that deep
		assertEquals(4, heights(10, 9, 5, 2.1).standingApart(5));
		assertEquals(2, heights(10, 2.1).standingApart(5));
		assertEquals(1, heights(10).standingApart(5));
		assertEquals(0, heights().standingApart(5));
	}
}
