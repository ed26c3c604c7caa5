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

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.module.Module;
import org.scijava.prefs.PrefService;

import ij.measure.ResultsTable;
import io.github.contacttracker.command.ContactTrackerPotentialCommand;
import io.github.contacttracker.command.WithContext;

/**
 * Fuzzes the Pair Potential command headless, as a script runs it: its spots from a random spots CSV or from the
 * Results table filled with one (columns missing or repeated, NaN, infinite and other odd values, empty, one spot,
 * all flagged), or from a table title that names none, and random inputs. The property: no exception escapes the
 * command's run; a refusal is the command's own error, one line; a run that computes gives its potential table.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases; a longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=PotentialCommandFuzzTest -Dcontact.tracker.fuzz.cases=3000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 */
class PotentialCommandFuzzTest extends WithContext {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 200;
	/** The least share of cases that must compute. */
	static final double REACH_FLOOR = 0.3;

	@TempDir
	Path dir;


	@Test
	void noSpotsTableEndsInAnException() throws Exception {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int computed = 0, refused = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final List<String> lines = PotentialFuzzTest.table(r);
			final Map<String, Object> inputs = inputs(r);
			final String source;
			ResultsTable.getResultsTable().reset();
			switch (r.nextInt(8) == 0 ? 2 : r.nextInt(2)) { // a title no table has: one case in eight
				case 0: {
					final Path csv = dir.resolve("case" + c + ".csv");
					Files.write(csv, lines);
					inputs.put("csv", csv.toFile());
					source = "a spots CSV";
					break;
				}
				case 1:
					fill(ResultsTable.getResultsTable(), lines);
					inputs.put("table", r.nextBoolean() ? "Results" : "");
					source = "the Results table";
					break;
				default:
					inputs.put("table", "no such table " + c);
					source = "a title no table has";
			}
			final String what = "case seed " + caseSeed + ": " + source + " of " + Math.max(0, lines.size() - 1) +
				" rows, " + (lines.isEmpty() ? "no header" : lines.get(0)) + ", inputs " + inputs;
			context.service(PrefService.class).clearAll();
			final Module m = CommandRuns.run(context, ContactTrackerPotentialCommand.class, inputs, what);
			if (CommandRuns.refused(m, what)) refused++;
			else {
				computed++;
				final ResultsTable u = (ResultsTable) m.getOutput("potential");
				assertTrue(u != null && u.size() > 0, "a run that computes gives its table: " + what);
			}
		}
		FuzzCase.reach("Pair Potential command fuzz", cases, computed, refused, REACH_FLOOR);
	}

	/**
	 * Fills a results table from a CSV's lines as ImageJ opens one: a cell that is no number kept as text (ImageJ
	 * then reads it as NaN).
	 */
	private static void fill(final ResultsTable rt, final List<String> lines) {
		if (lines.isEmpty()) return;
		final String[] head = lines.get(0).split(",", -1);
		for (int i = 1; i < lines.size(); i++) {
			final String[] cells = lines.get(i).split(",", -1);
			rt.incrementCounter();
			for (int k = 0; k < Math.min(head.length, cells.length); k++) {
				try {
					rt.addValue(head[k], Double.parseDouble(cells[k]));
				}
				catch (final NumberFormatException e) {
					rt.addValue(head[k], cells[k]);
				}
			}
		}
	}

	/**
	 * @return random inputs: sensible ones (the bin, r_max and field of view measured) but for none, one or two
	 *         that are out of range or odd; some left out. A field's width comes with its height three times in four.
	 */
	private static Map<String, Object> inputs(final SplittableRandom r) {
		final Object[][] choices = { { "bin", 0.0, 1.0, 1e-9, -1.0, Double.NaN, Double.POSITIVE_INFINITY, 1e9 }, {
			"r_max", 0.0, 10.0, 1e-6, -3.0, Double.NaN, 1e12 }, { "width", 0.0, 100.0, 1.0, -5.0, Double.NaN }, {
				"height", 0.0, 100.0, 1.0, -5.0 }, { "start_frame", 0, 1, 3, -1, 1000 }, { "skip_flagged", true,
					false }, { "zero_from", 0.0, 5.0, 50.0, -1.0, Double.NaN }, { "zero_to", 0.0, 8.0, 2.0, -1.0 }, {
						"show", false, true }, { "results", true, false } };
		final List<Integer> odd = FuzzCase.oddOnes(r, choices.length);
		final Map<String, Object> in = new LinkedHashMap<>();
		for (int i = 0; i < choices.length; i++) {
			final Object[] c = choices[i];
			if (odd.contains(i)) in.put((String) c[0], c[1 + r.nextInt(c.length - 1)]);
			else if (r.nextBoolean()) in.put((String) c[0], c[1]);
		}
		if (in.get("width") instanceof Double w && w > 0 && r.nextInt(4) > 0) in.put("height", 100.0);
		return in;
	}
}
