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
package io.github.contacttracker.potential;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

class SpotSetTest {

	private static Map<String, double[]> table() {
		final Map<String, double[]> c = new LinkedHashMap<>();
		c.put("FRAME", new double[] { 0, 0, 1, 1, 2 });
		c.put("POSITION_X", new double[] { 1, 2, 3, 4, 5 });
		c.put("POSITION_Y", new double[] { 1, 1, 1, 1, 1 });
		c.put("FLAG_SECOND_PASS", new double[] { 1, 1, 1, 0, 0 }); // the normal case, not a warning
		c.put("FLAG_AT_BORDER", new double[] { 0, 1, 0, 0, 0 });
		c.put("FLAG_FELL_BACK", new double[] { 0, 0, 0, 0, 1 });
		return c;
	}

	@Test
	void warningFlagsLeaveSpotsOutButSecondPassDoesNot() {
		final SpotSet s = SpotSet.fromColumns(table(), SpotSet.Selection.DEFAULT);
		assertEquals(3, s.size());
		assertEquals(2, s.flaggedLeftOut());
		assertEquals(List.of(0, 1), s.frameNumbers());
		assertEquals(List.of("FLAG_AT_BORDER", "FLAG_FELL_BACK"), s.flagColumns());
		final SpotSet kept = SpotSet.fromColumns(table(), new SpotSet.Selection(0, false));
		assertEquals(5, kept.size());
		assertEquals(0, kept.flaggedLeftOut());
	}

	@Test
	void startFrameLeavesEarlierFramesOut() {
		final SpotSet s = SpotSet.fromColumns(table(), new SpotSet.Selection(1, false));
		assertEquals(3, s.size());
		assertEquals(2, s.earlyLeftOut());
		assertEquals(List.of(1, 2), s.frameNumbers());
	}

	@Test
	void missingColumnsAndBadValuesAreNamed() {
		final Map<String, double[]> noY = table();
		noY.remove("POSITION_Y");
		assertEquals("missing column POSITION_Y", assertThrows(IllegalArgumentException.class, () -> SpotSet
			.fromColumns(noY, SpotSet.Selection.DEFAULT)).getMessage());
		final Map<String, double[]> badFrame = table();
		badFrame.get("FRAME")[2] = 1.5;
		assertEquals("row 3: FRAME must be a whole number 0 or more, not 1.5", assertThrows(
			IllegalArgumentException.class, () -> SpotSet.fromColumns(badFrame, SpotSet.Selection.DEFAULT)).getMessage());
		final Map<String, double[]> emptyX = table();
		emptyX.get("POSITION_X")[4] = Double.NaN;
		assertEquals("row 5: POSITION_X and POSITION_Y must be numbers, not empty and 1.0", assertThrows(
			IllegalArgumentException.class, () -> SpotSet.fromColumns(emptyX, SpotSet.Selection.DEFAULT)).getMessage());
	}
}
