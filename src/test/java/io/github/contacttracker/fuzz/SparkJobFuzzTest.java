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

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ij.ImagePlus;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.spark.SparkTrack;

/**
 * Fuzzes the Spark job's entry point ({@link SparkTrack#run}, a local master) as {@link EntryPointFuzzTest} does
 * {@code track}: each run tracks one to five random movies (the shared {@link FuzzImages}, now and then a file that
 * is no TIFF or no file at all) with random tracking and job options, into an output folder that exists, does not
 * exist yet, or is a file. The property, per movie: its CSV (finite positions, inside the image unless flagged), or
 * one error line naming it and no file of it left behind; per run: no exception escapes, the exit status 0 when
 * every movie was written and 2 otherwise, an option refused in one line, no file but the movies' and the Parquet
 * table in the folder, and a folder the run made removed again when it wrote nothing.
 * <p>
 * A Spark run starts and stops its own local context (the job stops the session it ran in), about a second or two:
 * the suite runs {@value #SHORT_RUN} movies (in runs of up to five). A longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=SparkJobFuzzTest -Dcontact.tracker.fuzz.cases=400 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 */
class SparkJobFuzzTest {

	/** Movies in the suite's run. */
	static final int SHORT_RUN = 15;
	/**
	 * The least share of movies that must be tracked and written (0.34 do in a long run: a run's threshold is the
	 * first movie's, outside some other movies' data).
	 */
	static final double REACH_FLOOR = 0.25;

	@TempDir
	Path dir;

	@Test
	void noInputEndsInAnExceptionOrAStrayFile() throws IOException {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int movies = 0, written = 0, refused = 0, run = 0;
		while (movies < cases) {
			final long runSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(runSeed);
			final Path in = Files.createDirectories(dir.resolve("in" + run));
			final int n = Math.min(cases - movies, 1 + r.nextInt(5));
			final List<Path> paths = new ArrayList<>();
			final List<ImagePlus> images = new ArrayList<>();
			for (int m = 0; m < n; m++) {
				final Path movie = in.resolve("r" + run + "m" + m + ".tif");
				final int kind = r.nextInt(20);
				if (kind == 0) Files.writeString(movie, "II*\0 not really a TIFF");
				else if (kind > 1) {
					final ImagePlus imp = FuzzImages.image(r, 3);
					ImageFiles.saveTiff(imp, movie);
					images.add(imp);
				}
				// kind 1: no such file
				paths.add(movie);
			}
			final ImagePlus first = images.isEmpty() ? FuzzImages.trackable(r, 3) : images.get(0);
			final Path outDir = outDir(r, run);
			final boolean existed = Files.exists(outDir);
			final List<String> args = new ArrayList<>();
			paths.forEach(p -> args.add(p.toString()));
			args.add("--out-dir");
			args.add(outDir.toString());
			final boolean optionOdd = options(r, args, first);
			final String what = "run seed " + runSeed + " " + args;
			final Object[] result = spark(args, what);
			final int status = (Integer) result[0];
			final String said = (String) result[1];
			final String whatSaid = what + ":\n" + said;
			assertFalse(said.contains("Exception") || said.contains("internal error"), whatSaid);
			assertTrue(status == 0 || status == SparkTrack.EXIT_BAD_INPUT, "exit " + status + ": " + whatSaid);
			final List<String> errors = said.lines().filter(l -> l.contains("error")).toList();
			if (status == 0) assertTrue(errors.isEmpty(), whatSaid);
			final Set<String> expected = new HashSet<>();
			boolean any = false;
			for (final Path movie : paths) {
				final String name = movie.getFileName().toString().replace(".tif", "");
				final Path csv = outDir.resolve(name + ".csv");
				final boolean named = errors.stream().anyMatch(l -> l.contains(movie.toString()));
				if (Files.exists(csv)) {
					assertFalse(named, "a movie written is named in no error: " + whatSaid);
					EntryPointFuzzTest.positionsInside(csv, whatSaid);
					expected.add(name + ".csv");
					expected.add(name + ".settings.txt");
					expected.add(name + ".xml");
					written++;
					any = true;
				}
				else {
					assertEquals(SparkTrack.EXIT_BAD_INPUT, status, "a movie not written fails the run: " + whatSaid);
					// the movie named in its own line, or the run refused before any movie in one line
					assertTrue(named || errors.size() == 1, "a movie not written is named: " + movie + "; " + whatSaid);
					refused++;
				}
				movies++;
			}
			if (status == SparkTrack.EXIT_BAD_INPUT && !any) {
				final long movieLines = errors.stream().filter(l -> paths.stream().anyMatch(p -> l.contains(p
					.toString()))).count();
				// refused before any work: one line (an option, the folder); else one line per movie and the count
				assertTrue(movieLines == 0 && errors.size() == 1 || movieLines == paths.size() && errors.size() == paths
					.size(), "one line per refusal: " + whatSaid);
				if (optionOdd && movieLines == 0) assertTrue(errors.get(0).contains("--") || errors.get(0).contains(
					"option"), "an option refused names it: " + whatSaid);
			}
			if (Files.isDirectory(outDir)) {
				expected.add("spots.parquet");
				try (Stream<Path> files = Files.list(outDir)) {
					files.forEach(f -> assertTrue(expected.contains(f.getFileName().toString()), "a stray file " + f + ": " +
						whatSaid));
				}
			}
			if (!existed && !any) assertFalse(Files.exists(outDir) && Files.isDirectory(outDir),
				"no folder left behind a run that wrote nothing: " + whatSaid);
			if (!existed && any) assertTrue(Files.isDirectory(outDir), "the folder made: " + whatSaid);
			if (Boolean.getBoolean("contact.tracker.fuzz.verbose")) System.out.println(whatSaid);
			run++;
		}
		FuzzCase.reach("Spark job fuzz (" + run + " runs)", movies, written, refused, REACH_FLOOR);
	}

	/**
	 * {@code --out-dir} names a folder that does not exist yet: the job makes it (and its parents), as
	 * {@code track} does, and writes the movie's files into it (issue 36, deliverable 5).
	 */
	@Test
	void aMissingOutputFolderIsMade() throws IOException {
		final ImagePlus imp = FuzzImages.trackable(new SplittableRandom(3), 3);
		final Path movie = dir.resolve("one.tif");
		ImageFiles.saveTiff(imp, movie);
		final Path out = dir.resolve("not").resolve("yet");
		final List<String> args = List.of(movie.toString(), "--out-dir", out.toString(), "--master", "local[1]",
			"--threshold", Double.toString(FuzzImages.threshold(imp)), "--r-out", Long.toString(FuzzImages.rOut(imp)));
		final Object[] r = spark(args, args.toString());
		assertEquals(0, r[0], (String) r[1]);
		assertTrue(Files.isRegularFile(out.resolve("one.csv")), "the CSV in the folder made");
		assertTrue(Files.isDirectory(out.resolve("spots.parquet")), "the Parquet table in it");
	}

	/**
	 * Found by this fuzz (seed 20261205, 150 movies): a {@code --master} Spark cannot parse ({@code nowhere://x}) ended
	 * the job in Spark's {@code SparkException} and its stack trace (exit 1), and left the output folder it had made.
	 * Now refused in one line naming the master, exit 2, no folder left behind.
	 */
	@Test
	void aMasterSparkCannotUseIsRefusedInOneLine() throws IOException {
		final Path movie = dir.resolve("one.tif");
		ImageFiles.saveTiff(FuzzImages.trackable(new SplittableRandom(3), 3), movie);
		final Path out = dir.resolve("made").resolve("out");
		final List<String> args = List.of(movie.toString(), "--out-dir", out.toString(), "--master", "nowhere://x");
		final Object[] r = spark(args, args.toString());
		final String said = (String) r[1];
		assertEquals(SparkTrack.EXIT_BAD_INPUT, r[0], said);
		final List<String> errors = said.lines().filter(l -> l.contains("error")).toList();
		assertEquals(1, errors.size(), said);
		assertTrue(errors.get(0).startsWith("contact-tracker-spark: error: Spark cannot start with master nowhere://x: ") &&
			errors.get(0).contains("Could not parse Master URL"), said);
		assertFalse(Files.exists(dir.resolve("made")), "no folder left behind");
	}

	/** @return the output folder: one that exists, one that does not (nested), or a file */
	private Path outDir(final SplittableRandom r, final int run) throws IOException {
		switch (r.nextInt(8)) {
			case 0:
				return Files.writeString(dir.resolve("file" + run), "a file, not a folder");
			case 1, 2, 3:
				return dir.resolve("new" + run).resolve("out");
			default:
				return Files.createDirectories(dir.resolve("out" + run));
		}
	}

	/**
	 * Random options: the tracking options of {@code track} (a user's values for the first movie, but for none, one
	 * or two odd ones), and the job's own ({@code --chunk}, {@code --master}, {@code --trackmate-xml},
	 * {@code --conf}).
	 *
	 * @return whether an odd value was given
	 */
	private static boolean options(final SplittableRandom r, final List<String> args, final ImagePlus imp) {
		final String[][] choices = { { "--threshold", Double.toString(FuzzImages.threshold(imp)), "0", "-3", "1e9", "NaN",
			"x" }, { "--r-out", Long.toString(FuzzImages.rOut(imp)), "0.5", "0", "-1", "400" }, { "--diameter", Long
				.toString(FuzzImages.diameter(imp)), "0", "1e6", "-2" }, { "--method", "fit", "paper", "deblend", "first",
					"iterative", "nope" }, { "--min-area", "1", "20", "0" }, { "--particles", FuzzImages.dark(imp) ? "dark"
						: "bright", FuzzImages.dark(imp) ? "bright" : "dark", "grey" }, { "--chunk", "1", "2", "500", "0",
							"x" }, { "--master", "local[2]", "local[1]", "local[0]", "nowhere://x" }, { "--conf",
								"spark.ui.enabled=false", "novalue", "spark.executor.memory=lots", "spark.default.parallelism=x" } };
		// the master and the Spark UI off always given, for the tests' speed
		final boolean odd = FuzzCase.options(r, choices, 2, args);
		if (r.nextInt(4) == 0) args.add("--trackmate-xml");
		return odd;
	}

	/**
	 * @return the job's exit status and what it wrote to its error stream; an exception that escaped, or no answer in
	 *         {@link FuzzCase#timeout()} seconds, is an assertion error naming the run
	 */
	static Object[] spark(final List<String> args, final String what) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final FutureTask<Integer> run = new FutureTask<>(() -> SparkTrack.run(args.toArray(String[]::new),
			new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)));
		final Thread thread = new Thread(run, "fuzz spark run");
		thread.setDaemon(true);
		thread.start();
		try {
			return new Object[] { run.get(FuzzCase.timeout(), TimeUnit.SECONDS), err.toString(StandardCharsets.UTF_8) };
		}
		catch (final ExecutionException e) {
			throw new AssertionError(what + ": an exception escaped", e.getCause());
		}
		catch (final TimeoutException e) {
			run.cancel(true);
			throw new AssertionError(what + ": no answer in " + FuzzCase.timeout() + " s (a hang?)");
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new AssertionError("interrupted", e);
		}
	}
}
