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
package io.github.contacttracker.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.StringWriter;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.potential.SpotSet;

class SpotTableCsvTest {

	@Test
	void readsOurOneHeaderTable() {
		final SpotTableCsv.Table t = SpotTableCsv.parse(List.of("ID,FRAME,POSITION_X,POSITION_Y,FLAG_MERGED",
			"0,0,1.5,2.5,0", "1,0,3.5,4.5,1", ""), SpotSet::reads, "s.csv");
		assertEquals(2, t.rows());
		assertEquals(1, t.headerRows());
		assertEquals("", t.unit());
		assertEquals(List.of("FRAME", "POSITION_X", "POSITION_Y", "FLAG_MERGED"), List.copyOf(t.columns().keySet()));
		assertArrayEquals(new double[] { 1.5, 3.5 }, t.columns().get("POSITION_X"));
		assertArrayEquals(new double[] { 0, 1 }, t.columns().get("FLAG_MERGED"));
	}

	/** The KIND column is written last and read back as written; spots never classified are of kind 0. */
	@Test
	void readsBackTheKindOfEverySpot() throws Exception {
		final Localization plain = new Localization(0, 1.5, 2.5, 1.5, 2.5, 30, 30, 1, 3.1, 0, 2, 0.01, 0.01, Double.NaN,
			Double.NaN, 0);
		final Localization moved = new Localization(0, 5.5, 2.5, 5.5, 2.5, 30, 30, 1, 3.1, 0, 2, 0.01, 0.01, Double.NaN,
			Double.NaN, 3);
		final List<Localization> spots = List.of(plain, plain.withFrame(1).withKind(2), moved);
		final StringWriter csv = new StringWriter();
		SpotCsvWriter.write(csv, spots, Calibration.PIXELS);
		final List<String> lines = csv.toString().lines().toList();
		assertEquals("KIND", lines.get(0).substring(lines.get(0).lastIndexOf(',') + 1));
		final SpotTableCsv.Table t = SpotTableCsv.parse(lines, key -> key.equals(SpotColumn.KIND.key()) || SpotSet
			.reads(key), "k.csv");
		assertArrayEquals(new double[] { 0, 2, 3 }, t.columns().get("KIND"));
		assertArrayEquals(new double[] { 0, 1, 0 }, t.columns().get("FRAME"));
		assertArrayEquals(new double[] { 1.5, 1.5, 5.5 }, t.columns().get("POSITION_X"));
	}

	@Test
	void readsTrackMatesExportWithFourHeaderRowsQuotesAndUnits() {
		final SpotTableCsv.Table t = SpotTableCsv.parse(List.of( //
			"LABEL,ID,TRACK_ID,QUALITY,POSITION_X,POSITION_Y,POSITION_Z,POSITION_T,FRAME", //
			"Label,Spot ID,Track ID,Quality,X,Y,Z,T,Frame", //
			"Label,Spot ID,Track ID,Quality,X,Y,Z,T,Frame", //
			",,,(quality),(micron),(micron),(micron),(sec),", //
			"\"ID0, first\",0,0,12.0,1.25,2.5,0,0,0", //
			"ID1,1,0,11.0,3.75,4.5,0,0,0"), SpotSet::reads, "export.csv");
		assertEquals(4, t.headerRows());
		assertEquals("micron", t.unit());
		assertEquals(2, t.rows());
		assertArrayEquals(new double[] { 1.25, 3.75 }, t.columns().get("POSITION_X"));
		assertArrayEquals(new double[] { 0, 0 }, t.columns().get("FRAME"));
	}

	@Test
	void badInputNamesFileLineAndColumn() {
		assertEquals("e.csv is empty", assertThrows(IllegalArgumentException.class, () -> SpotTableCsv.parse(List
			.of("", " "), SpotSet::reads, "e.csv")).getMessage());
		assertEquals("h.csv has a header but no data row", assertThrows(IllegalArgumentException.class,
			() -> SpotTableCsv.parse(List.of("FRAME,POSITION_X,POSITION_Y"), SpotSet::reads, "h.csv")).getMessage());
		assertEquals("b.csv line 3: POSITION_Y is not a number: 'abc'", assertThrows(IllegalArgumentException.class,
			() -> SpotTableCsv.parse(List.of("FRAME,POSITION_X,POSITION_Y", "0,1,2", "0,1,abc"), SpotSet::reads, "b.csv"))
				.getMessage());
		assertEquals("s.csv line 2: 2 cells, but column POSITION_Y is number 3", assertThrows(
			IllegalArgumentException.class, () -> SpotTableCsv.parse(List.of("FRAME,POSITION_X,POSITION_Y", "0,1"),
				SpotSet::reads, "s.csv")).getMessage());
	}
}
