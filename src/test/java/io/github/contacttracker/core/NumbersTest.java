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
package io.github.contacttracker.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class NumbersTest {

	@Test
	void significantKeepsWholeNumbersWholeAndTrailingZerosOtherwise() {
		assertEquals("85", Numbers.significant(85, 4));
		assertEquals("-3", Numbers.significant(-3, 4));
		assertEquals("13.98", Numbers.significant(13.98, 4));
		assertEquals("124.0", Numbers.significant(123.98, 4));
		assertEquals("1.750", Numbers.significant(1.75, 4));
		assertEquals("0.001235", Numbers.significant(0.0012345, 4));
	}

	@Test
	void fmtWritesExactlyOrRounded() {
		assertEquals("85", Numbers.fmt(85));
		assertEquals("61.5", Numbers.fmt(61.5));
		assertEquals("2.887", Numbers.fmt(2.88675, 3));
		assertEquals("12.5", Numbers.fmt(12.5, 3));
	}
}
