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
package io.github.contacttracker.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PotentialCliTest {

	@TempDir
	Path dir;

	private static Object[] run(final String... args) {
		return ContactTrackerCliTest.run(args);
	}

	/** Uniform random spots, 20 per frame in 40 x 30, 200 frames; every 10th spot flagged at the border. */
	private Path uniformSpots() throws IOException {
		final SplittableRandom random = new SplittableRandom(4);
		final List<String> lines = new ArrayList<>();
		lines.add("ID,FRAME,POSITION_X,POSITION_Y,FLAG_SECOND_PASS,FLAG_AT_BORDER");
		int id = 0;
		for (int f = 0; f < 200; f++)
			for (int i = 0; i < 20; i++, id++)
				lines.add(id + "," + f + "," + random.nextDouble(40) + "," + random.nextDouble(30) + ",1," + (id % 10 == 0
					? 1 : 0));
		final Path csv = dir.resolve("spots.csv");
		Files.write(csv, lines);
		return csv;
	}

	@Test
	void writesTheTableAndThePlot() throws IOException {
		final Path spots = uniformSpots(), csv = dir.resolve("u.csv"), png = dir.resolve("u.png");
		final Object[] r = run("potential", spots.toString(), "--bin", "1", "--r-max", "20", "--width", "40",
			"--height", "30", "--zero", "10,20", "--csv", csv.toString(), "--png", png.toString());
		assertEquals(0, r[0], (String) r[2]);
		final String report = (String) r[1];
		assertTrue(report.contains("3600 spots in 200 frames used (of 4000 rows; left out: 400 flagged by " +
			"FLAG_AT_BORDER, 0 before the start frame)"), report);
		assertTrue(report.contains("field of view 40 x 30, as given"), report);
		final List<String> lines = Files.readAllLines(csv);
		assertEquals("R,PAIRS,G,U_KT,U_KT_ERR", lines.get(0));
		assertEquals(21, lines.size());
		assertTrue(lines.get(1).startsWith("0.5,"), lines.get(1));
		for (int i = 1; i < lines.size(); i++) {
			final String[] c = lines.get(i).split(",", -1);
			assertEquals(5, c.length);
			final long pairs = Long.parseLong(c[1]);
			// uniform spots: g = 1 within the counting statistics, U = 0 within its error bar
			if (pairs > 0) {
				assertEquals(1, Double.parseDouble(c[2]), 4 / Math.sqrt(pairs), lines.get(i));
				assertEquals(0, Double.parseDouble(c[3]), 4 * Double.parseDouble(c[4]) + 0.02, lines.get(i));
			}
		}
		assertEquals(720 + 2 * 80, ImageIO.read(png.toFile()).getWidth(), 200); // a plot was drawn
	}

	@Test
	void emptyBinsHaveEmptyCellsAndTheInferredFieldIsSaid() throws IOException {
		final Path spots = dir.resolve("two.csv");
		Files.write(spots, List.of("FRAME,POSITION_X,POSITION_Y", "0,0,0", "0,3,4", "1,10,10"));
		final Object[] r = run("potential", spots.toString(), "--bin", "1", "--r-max", "6");
		assertEquals(0, r[0], (String) r[2]);
		final String[] lines = ((String) r[1]).split("\n");
		assertEquals("R,PAIRS,G,U_KT,U_KT_ERR", lines[0]);
		assertEquals("0.5,0,0,,", lines[1]);
		assertTrue(lines[6].startsWith("5.5,1,"), lines[6]);
		assertTrue(((String) r[2]).contains("INFERRED from the spots"), (String) r[2]);
		assertTrue(((String) r[2]).contains("note: field of view inferred from the spots"), (String) r[2]);
	}

	@Test
	void badInputIsOneLineWithStatusTwoAndNoOutput() throws IOException {
		final Path out = dir.resolve("out.csv");
		final Path noY = dir.resolve("noy.csv"), empty = dir.resolve("empty.csv"), bad = dir.resolve("bad.csv");
		Files.write(noY, List.of("FRAME,POSITION_X", "0,1"));
		Files.write(empty, List.of());
		Files.write(bad, List.of("FRAME,POSITION_X,POSITION_Y", "0,1,2", "0,x1,2"));
		final String[][] cases = { { noY.toString(), "missing column POSITION_Y" }, { empty.toString(), "is empty" },
			{ bad.toString(), "line 3: POSITION_X is not a number: 'x1'" }, { dir.resolve("none.csv").toString(),
				"no such file" } };
		for (final String[] c : cases) {
			final Object[] r = run("potential", c[0], "--bin", "1", "--r-max", "5", "--csv", out.toString());
			assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0], c[0]);
			final String err = (String) r[2];
			assertTrue(err.startsWith("contact-tracker: error: ") && err.contains(c[1]), err);
			assertEquals(1, err.strip().split("\n").length, err);
			assertFalse(Files.exists(out));
		}
		final Object[] far = run("potential", uniformSpots().toString(), "--bin", "1", "--r-max", "35", "--width", "40",
			"--height", "30", "--csv", out.toString());
		assertEquals(2, far[0]);
		assertTrue(((String) far[2]).contains("r_max 35 exceeds the smaller side of the field of view (40 x 30)"),
			(String) far[2]);
		assertEquals(2, run("potential", uniformSpots().toString(), "--bin", "1", "--r-max", "5", "--width", "40")[0]);
		assertEquals(2, run("potential", uniformSpots().toString(), "--bin", "1", "--r-max", "5", "--flagged", "maybe")[0]);
		assertEquals(2, run("potential", uniformSpots().toString(), "--bin", "1", "--r-max", "5", "--zero", "3")[0]);
		assertFalse(Files.exists(out));
	}
}
