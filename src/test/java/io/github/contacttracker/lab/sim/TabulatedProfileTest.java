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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TabulatedProfileTest {

	@TempDir
	Path dir;

	private final TabulatedProfile ring = new TabulatedProfile(new double[] { 0, 5, 10 }, new double[] { 10, -10,
		0 });

	@Test
	void interpolatesLinearlyAndIsZeroBeyondTheTable() {
		final TabulatedProfile uneven = new TabulatedProfile(new double[] { 0, 1, 3 }, new double[] { 4, 2, 1 });
		assertEquals(4, uneven.value(0), 1e-12);
		assertEquals(3, uneven.value(0.5), 1e-12);
		assertEquals(2, uneven.value(1), 1e-12);
		assertEquals(1.25, uneven.value(2.5), 1e-12);
		assertEquals(1, uneven.value(3), 1e-12);
		assertEquals(0, uneven.value(3.0001), 0);
		assertEquals(-8, ring.value(6), 1e-12);
		assertEquals(-2, ring.value(9), 1e-12);
		assertEquals(2, ring.value(2), 1e-12);
	}

	@Test
	void reachIsExactOnTheTable() {
		assertEquals(9, ring.reach(2), 1e-12);
		assertEquals(9.75, ring.reach(0.5), 1e-12);
		// the table ends at a non-zero value: the profile jumps to 0 there
		final TabulatedProfile cut = new TabulatedProfile(new double[] { 0, 2 }, new double[] { 5, 3 });
		assertEquals(2, cut.reach(1), 0);
		assertEquals(1, cut.reach(4), 1e-12);
	}

	@Test
	void sampleReproducesTheProfile() {
		final GaussianBesselProfile p = new GaussianBesselProfile(120, 0.1, 18);
		final TabulatedProfile t = TabulatedProfile.sample(p, 0.01, 60);
		assertTrue(t.maxRadius() >= 60);
		double worst = 0;
		for (double r = 0; r <= 60; r += 0.0037)
			worst = Math.max(worst, Math.abs(t.value(r) - p.value(r)));
		assertEquals(0, worst, 2e-5);
	}

	@Test
	void parsesCsvWithHeaderCommentsAndBlankLines() throws IOException {
		final Path file = dir.resolve("profile.csv");
		Files.writeString(file, "# measured profile\nr_px,value\n0,100\n\n 1.5 , 40\n# ring\n3,-10\n");
		final TabulatedProfile p = TabulatedProfile.fromCsv(file);
		assertEquals(3, p.size());
		assertEquals(100, p.value(0), 1e-12);
		assertEquals(70, p.value(0.75), 1e-12);
		assertEquals(15, p.value(2.25), 1e-12);
		assertEquals(3, p.maxRadius(), 0);
	}

	@Test
	void csvErrorsNameTheFileAndLine() throws IOException {
		final Path bad = dir.resolve("bad.csv");
		Files.writeString(bad, "r_px,value\n0,100\n1,forty\n");
		final IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TabulatedProfile
			.fromCsv(bad));
		assertTrue(e.getMessage().contains("bad.csv line 3"), e.getMessage());
		assertTrue(!e.getMessage().contains("\n"), "one line: " + e.getMessage());

		final Path fields = dir.resolve("fields.csv");
		Files.writeString(fields, "0,100,7\n");
		assertTrue(assertThrows(IllegalArgumentException.class, () -> TabulatedProfile.fromCsv(fields)).getMessage()
			.contains("fields.csv line 1"));

		final Path order = dir.resolve("order.csv");
		Files.writeString(order, "0,100\n2,50\n1,10\n");
		assertTrue(assertThrows(IllegalArgumentException.class, () -> TabulatedProfile.fromCsv(order)).getMessage()
			.contains("order.csv line 3"));

		final Path start = dir.resolve("start.csv");
		Files.writeString(start, "0.5,100\n2,50\n");
		assertTrue(assertThrows(IllegalArgumentException.class, () -> TabulatedProfile.fromCsv(start)).getMessage()
			.contains("start.csv"));

		assertThrows(IOException.class, () -> TabulatedProfile.fromCsv(dir.resolve("missing.csv")));
	}

	@Test
	void rejectsInvalidTables() {
		assertThrows(IllegalArgumentException.class, () -> new TabulatedProfile(new double[] { 0, 1 },
			new double[] { 1 }));
		assertThrows(IllegalArgumentException.class, () -> new TabulatedProfile(new double[] { 0, 1, 1 },
			new double[] { 1, 2, 3 }));
		assertThrows(IllegalArgumentException.class, () -> new TabulatedProfile(new double[] { 1, 2 },
			new double[] { 1, 2 }));
	}
}
