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
package io.github.contacttracker.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;


/**
 * Fuzzes the {@code potential} subcommand with random spots tables (columns missing, shuffled or repeated; values
 * that are not numbers, NaN, infinite, negative, huge; empty tables, one spot, all spots flagged) and random option
 * strings. The property: no exception escapes, the exit status 0 or 2, a refusal one line, and no output file left
 * behind a refusal.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases (a few seconds). A longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=PotentialFuzzTest -Dcontact.tracker.fuzz.cases=5000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 * A case that fails prints its seed and arguments, to be kept as a named regression test.
 */
class PotentialFuzzTest {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 300;
	/** The least share of cases that must compute (about 0.35 do: half the tables and options are odd). */
	static final double REACH_FLOOR = 0.25;

	@TempDir
	Path dir;

	@Test
	void noTableEndsInAnInternalError() throws IOException {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int computed = 0, refused = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final Path spots = dir.resolve("case" + c + ".csv");
			Files.write(spots, table(r));
			final Path csv = dir.resolve("u" + c + ".csv"), png = dir.resolve("u" + c + ".png");
			final List<String> args = new ArrayList<>(List.of("potential", spots.toString()));
			options(r, args);
			args.add("--csv");
			args.add(csv.toString());
			if (r.nextInt(4) == 0) {
				args.add("--png");
				args.add(png.toString());
			}
			final FuzzCase run = new FuzzCase(caseSeed, args);
			final String what = run.what;
			if (run.refused()) {
				assertFalse(Files.exists(csv) || Files.exists(png), "no output left behind a refusal: " + what);
				refused++;
			}
			else {
				computed++;
				// every row of the table: r, a whole pair count, then g, U and its error (empty where no pair)
				for (final String line : Files.readAllLines(csv).subList(1, Files.readAllLines(csv).size())) {
					final String[] v = line.split(",", -1);
					assertEquals(5, v.length, line + " " + what);
					assertTrue(Double.isFinite(Double.parseDouble(v[0])), line + " " + what);
					assertTrue(Long.parseLong(v[1]) >= 0, line + " " + what);
				}
			}
			Files.deleteIfExists(csv);
			Files.deleteIfExists(png);
		}
		FuzzCase.reach("potential fuzz", cases, computed, refused, REACH_FLOOR);
	}

	/**
	 * @return a random spots table: half of them as {@code track} writes them (2 to 40 spots a frame, some flagged),
	 *         so that the computation is reached as often as a refusal; the others empty, with a column missing,
	 *         twice or swapped, few spots, a tiny field, or holding a value they should not
	 */
	static List<String> table(final SplittableRandom r) {
		final boolean hostile = r.nextBoolean();
		final List<String> lines = new ArrayList<>();
		if (hostile && r.nextInt(10) == 0) return lines; // empty
		final List<String> columns = new ArrayList<>(List.of("ID", "FRAME", "POSITION_X", "POSITION_Y",
			"FLAG_SECOND_PASS", "FLAG_AT_BORDER"));
		if (hostile && r.nextInt(5) == 0) columns.remove(1 + r.nextInt(3)); // a needed column missing
		if (hostile && r.nextInt(5) == 0) columns.add(columns.get(r.nextInt(columns.size()))); // a column twice
		if (r.nextInt(5) == 0) java.util.Collections.swap(columns, r.nextInt(columns.size()), r.nextInt(columns.size()));
		lines.add(String.join(",", columns));
		final int frames = 1 + r.nextInt(5);
		final int perFrame = hostile && r.nextInt(3) == 0 ? r.nextInt(3) : 2 + r.nextInt(39);
		final double side = hostile && r.nextInt(4) == 0 ? r.nextDouble() * 2 : 20 + r.nextDouble() * 100;
		// a hostile table in two holds a value it should not (a cell in fifty of it)
		final int oddEvery = hostile && r.nextBoolean() ? 50 : Integer.MAX_VALUE;
		int id = 0;
		for (int f = 0; f < frames; f++)
			for (int i = 0; i < perFrame; i++, id++) {
				final StringBuilder row = new StringBuilder();
				for (final String col : columns) {
					if (row.length() > 0) row.append(',');
					row.append(switch (col) {
						case "ID" -> Integer.toString(id);
						case "FRAME" -> r.nextInt(oddEvery) == 0 ? odd(r) : Integer.toString(r.nextInt(oddEvery) == 0 ? -1 : f);
						case "POSITION_X", "POSITION_Y" -> r.nextInt(oddEvery) == 0 ? odd(r) : Double.toString(r.nextDouble() *
							side);
						default -> r.nextInt(oddEvery) == 0 ? odd(r) : r.nextInt(8) == 0 ? "1" : "0";
					});
				}
				if (hostile && r.nextInt(100) == 0) row.append(",extra");
				lines.add(row.toString());
			}
		return lines;
	}

	/** @return a value a table should not hold */
	private static String odd(final SplittableRandom r) {
		final String[] odd = { "NaN", "Infinity", "-Infinity", "", "x", "1e308", "-1e308", "2.5", "9999999999999" };
		return odd[r.nextInt(odd.length)];
	}

	/**
	 * Random options: the sensible ones (a bin and r_max; the others left out or sensible) but for none, one or two
	 * that are out of range, not numbers or not a choice.
	 */
	private static void options(final SplittableRandom r, final List<String> args) {
		final String[][] choices = { { "--bin", "1", "0", "-1", "1e-9", "NaN", "Infinity", "x" }, { "--r-max", "10",
			"0", "-5", "1e9", "NaN", "0.1" }, { "--width", "60", "0", "-1", "NaN", "1e-300" }, { "--start-frame", "0",
				"-1", "3", "1000000" }, { "--flagged", "drop", "keep", "maybe" }, { "--zero", "5,10", "10,5", "a,b",
					"NaN,NaN", "0,1e9", "3" } };
		final List<Integer> odd = FuzzCase.oddOnes(r, choices.length);
		for (int i = 0; i < choices.length; i++) {
			final String[] c = choices[i];
			if (!odd.contains(i) && i > 1 && r.nextInt(3) > 0) continue;
			args.add(c[0]);
			args.add(c[odd.contains(i) ? 1 + r.nextInt(c.length - 1) : 1]);
			// the field of view's height mostly with its width (one alone is refused)
			if (c[0].equals("--width") && r.nextInt(8) > 0) {
				args.add("--height");
				args.add(r.nextInt(6) > 0 ? "60" : r.nextBoolean() ? "-1" : "Infinity");
			}
		}
	}
}
