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

import io.github.contacttracker.io.ImageFiles;

/**
 * Fuzzes the command line's real entry points, {@code track} (with and without values, so that the profile helper
 * measures them) and {@code profile}, with random images: every size from 1x1, 8, 16 and 32 bits, constant,
 * noisy or holding particles, floats with NaN and infinities, one to three frames; and random option strings. The
 * property: no internal error (no exception escapes), the exit status 0 or 2, a refusal one line naming the file
 * or the option, and no output file left behind a refusal.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases (a few seconds). A longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=EntryPointFuzzTest -Dcontact.tracker.fuzz.cases=5000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 * A case that fails prints its seed and arguments, to be kept as a named regression test.
 */
class EntryPointFuzzTest {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 150;
	/** The least share of cases that must track or measure (about 0.6 do, in long runs). */
	static final double REACH_FLOOR = 0.4;

	@TempDir
	Path dir;

	@Test
	void noInputEndsInAnInternalError() throws IOException {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int tracked = 0, refused = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final Path movie = dir.resolve("case" + c + ".tif");
			final ij.ImagePlus imp = FuzzImages.image(r, 3);
			ImageFiles.saveTiff(imp, movie);
			final Path csv = dir.resolve("case" + c + ".csv");
			final List<String> args = new ArrayList<>();
			if (r.nextInt(5) == 0) {
				args.add("profile");
				args.add(movie.toString());
			}
			else {
				args.add("track");
				args.add(movie.toString());
				options(r, args, imp);
				args.add("--csv");
				args.add(csv.toString());
				args.add("--no-progress");
			}
			final FuzzCase run = new FuzzCase(caseSeed, args);
			final String said = run.said, what = run.what;
			if (run.refused()) {
				// the line names the movie, or the option at fault
				assertTrue(said.contains("case" + c + ".tif") || said.contains("option ") || said.contains("--"), what);
				assertFalse(Files.exists(csv), "no output left behind a refusal: " + what);
			}
			if (!run.refused()) {
				tracked++;
				positionsInside(csv, what);
			}
			else refused++;
			Files.deleteIfExists(csv);
			Files.deleteIfExists(dir.resolve("case" + c + ".settings.txt"));
		}
		// the cases reach both ends: a fuzz that only ever refused (or only tracked) would test one path
		FuzzCase.reach("entry-point fuzz (track, profile)", cases, tracked, refused, REACH_FLOOR);
	}

	/**
	 * Every spot of a run's CSV has finite coordinates, within the image's extent (px, as the pixel centres' range
	 * widened by half a pixel) unless it is flagged.
	 */
	static void positionsInside(final Path csv, final String what) throws IOException {
		if (!Files.exists(csv)) return; // profile: no CSV
		final List<String> lines = Files.readAllLines(csv).stream().filter(l -> !l.startsWith("#")).toList();
		if (lines.size() < 2) return;
		final List<String> head = List.of(lines.get(0).split(","));
		final int x = head.indexOf("POSITION_X"), y = head.indexOf("POSITION_Y");
		final List<Integer> flags = new ArrayList<>();
		for (int i = 0; i < head.size(); i++)
			if (head.get(i).startsWith("FLAG_") && !head.get(i).equals("FLAG_SECOND_PASS")) flags.add(i);
		for (final String line : lines.subList(1, lines.size())) {
			final String[] v = line.split(",");
			final double px = Double.parseDouble(v[x]), py = Double.parseDouble(v[y]);
			assertTrue(Double.isFinite(px) && Double.isFinite(py), "finite: " + line + " " + what);
			boolean flagged = false;
			for (final int f : flags)
				flagged |= v[f].equals("1");
			assertTrue(flagged || px >= -0.5 && py >= -0.5, "inside unless flagged: " + line + " " + what);
		}
	}

	/**
	 * Random options, each given or left to the profile helper to measure: the values a user would give for the
	 * movie (a threshold between its background and its particles, its particles' polarity, diameter and r_out),
	 * but for none, one or two that are out of range, not numbers, or not the movie's.
	 */
	private static void options(final SplittableRandom r, final List<String> args, final ij.ImagePlus imp) {
		final String[][] choices = { { "--threshold", fmt(FuzzImages.threshold(imp)), "0", "-3", "1e9", "NaN", "x" }, {
			"--r-out", Long.toString(FuzzImages.rOut(imp)), "0.5", "0", "-1", "400", "2" }, { "--diameter", Long.toString(
				FuzzImages.diameter(imp)), "0", "30", "1e6", "-2" }, { "--method", "fit", "paper", "deblend", "first",
					"iterative", "nope" }, { "--detection", "auto", "threshold", "image", "other" }, { "--min-area", "1",
						"20", "0", "1000000" }, { "--kinds", "0", "1", "4", "9" }, { "--particles", FuzzImages.dark(imp)
							? "dark" : "bright", FuzzImages.dark(imp) ? "bright" : "dark", "grey" }, { "--connectivity", "8",
								"4", "6" } };
		FuzzCase.options(r, choices, 0, args);
	}

	private static String fmt(final double v) {
		return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
	}
}
