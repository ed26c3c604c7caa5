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
package io.github.contacttracker.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.SparkSession;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;


/**
 * The Spark job on {@code local[2]} against the command line: each movie's CSV and TrackMate XML byte for byte
 * {@code track}'s (the default method {@code fit}, its profile measured once per movie and broadcast, and the
 * settings measured on frame 1), with tasks that fail on their first attempt retried to the same files; an
 * unreadable movie named in one line, the others written, exit 2; the Parquet table holds the CSVs' spots.
 */
class SparkTrackTest {

	@TempDir
	static Path dir;

	/** 12 frames of 1024 x 1024: the profile is measured on 3 of them (PROFILE_PIXELS), the 9 others in chunks. */
	static Path padded;
	/** 6 frames of 206 x 140: all of them are profile frames. */
	static Path pair;
	/** padded.tif in float with a NaN pixel in frame 10, which a chunk task meets. */
	static Path nan;

	@BeforeAll
	static void movies() throws IOException {
		final Path[] movies = SparkTestMovies.movies(dir);
		padded = movies[0];
		pair = movies[1];
		nan = movies[2];
	}

	static Object[] spark(final String... args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final int status = SparkTrack.run(args, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(
			err, true, StandardCharsets.UTF_8));
		return new Object[] { status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8) };
	}

	@Test
	void equalsTheCommandLineByteForByteThroughRetriesAndABadMovie() throws IOException {
		final Path cliDir = Files.createDirectories(dir.resolve("cli")), sparkDir = Files.createDirectories(dir.resolve(
			"spark"));
		final Object[] c = SparkTestMovies.cli("track", padded.toString(), pair.toString(), "--out-dir", cliDir.toString());
		assertEquals(0, c[0], (String) c[2]);
		final Object[] x = SparkTestMovies.cli("track", pair.toString(), "--csv", cliDir.resolve("pair-xml.csv").toString(),
			"--trackmate-xml", cliDir.resolve("pair.xml").toString());
		assertEquals(0, x[0], (String) x[2]);
		final Path broken = dir.resolve("broken.avi");
		Files.writeString(broken, "RIFF....AVI not really");
		final Object[] n = SparkTestMovies.cli("track", nan.toString(), pair.toString(), "--out-dir", Files
			.createDirectories(dir.resolve("cli-nan")).toString());
		final String nanError = ((String) n[2]).lines().filter(l -> l.startsWith("contact-tracker: error: " + nan))
			.findFirst().orElseThrow(() -> new AssertionError((String) n[2])).substring("contact-tracker: ".length());
		assertTrue(nanError.contains("frame 10"), nanError);

		// local[2] with two attempts per task; the first attempt of the first chunk and of the first movie's writing
		// fails (the writing one after its files are written)
		final SparkSession session = SparkSession.builder().master("local[2,2]").appName("test").config(
			SparkTrack.FAIL_FIRST_ATTEMPT, "track,write").getOrCreate();
		final AtomicInteger failedTasks = new AtomicInteger(), tasks = new AtomicInteger();
		session.sparkContext().addSparkListener(new SparkListener() {
			@Override
			public void onTaskEnd(final SparkListenerTaskEnd e) {
				tasks.incrementAndGet();
				if (e.taskInfo().failed()) failedTasks.incrementAndGet();
			}
		});
		final Object[] s = spark(padded.toString(), broken.toString(), nan.toString(), pair.toString(), "--out-dir",
			sparkDir.toString(), "--chunk", "4", "--trackmate-xml");
		assertEquals(SparkTrack.EXIT_BAD_INPUT, s[0], (String) s[2]);
		final List<String> errors = ((String) s[2]).lines().filter(l -> l.startsWith("contact-tracker-spark: error:"))
			.toList();
		assertEquals(2, errors.size(), (String) s[2]);
		// a NaN met by a chunk task: the command line's message, the movie not written, no task retried for it
		assertEquals("contact-tracker-spark: " + nanError, errors.get(1));
		assertTrue(errors.get(0).startsWith("contact-tracker-spark: error: " + broken + ": cannot read " + broken +
			": not a TIFF") && errors.get(0).contains("Save As > Tiff"), errors.get(0));
		assertTrue(((String) s[2]).contains("2 of 4 movies failed"), (String) s[2]);
		assertEquals(3, failedTasks.get(), "the injected failures (the first chunk of padded.tif and of nan.tif, the " +
			"first movie's writing), each retried once");
		// stage 1: 4 movies; stage 2: 9 frames of padded.tif and of nan.tif in chunks of 4; stage 3: 3 movies
		assertTrue(tasks.get() >= 4 + 6 + 3, tasks + " tasks");

		for (final String name : List.of("padded.csv", "pair.csv"))
			assertArrayEquals(Files.readAllBytes(cliDir.resolve(name)), Files.readAllBytes(sparkDir.resolve(name)), name);
		assertArrayEquals(Files.readAllBytes(cliDir.resolve("pair.xml")), Files.readAllBytes(sparkDir.resolve(
			"pair.xml")));
		assertArrayEquals(Files.readAllBytes(cliDir.resolve("pair-xml.csv")), Files.readAllBytes(sparkDir.resolve(
			"pair.csv")));
		// the summaries are the command line's, but for the time
		for (final String m : List.of(padded.toString(), pair.toString()))
			assertEquals(SparkTestMovies.summary((String) c[1], m), SparkTestMovies.summary((String) s[1], m));
		// nothing else in the folder: no partial file of a failed attempt, no file of the broken movie
		final Set<String> files = new TreeSet<>();
		try (Stream<Path> list = Files.list(sparkDir)) {
			list.forEach(p -> files.add(p.getFileName().toString()));
		}
		assertEquals(Set.of("padded.csv", "padded.settings.txt", "padded.xml", "pair.csv", "pair.settings.txt",
			"pair.xml", "spots.parquet"), files);
		for (final String m : List.of("padded", "pair"))
			assertArrayEquals(Files.readAllBytes(cliDir.resolve(m + ".settings.txt")), Files.readAllBytes(sparkDir.resolve(
				m + ".settings.txt")), m + "'s settings, measured on frame 1 as the command line does");

		// the Parquet table: the CSVs' spots, partitioned by movie
		final SparkSession reader = SparkSession.builder().master("local[1]").appName("read").getOrCreate();
		try {
			final List<Row> rows = reader.read().parquet(sparkDir.resolve("spots.parquet").toString()).orderBy("MOVIE",
				"ID").select("MOVIE", "ID", "FRAME", "POSITION_X", "POSITION_Y").collectAsList();
			final List<String> csv = Stream.concat(Files.readAllLines(cliDir.resolve("padded.csv")).stream().skip(1).map(
				l -> "padded," + l), Files.readAllLines(cliDir.resolve("pair.csv")).stream().skip(1).map(l -> "pair," +
					l)).toList();
			assertEquals(csv.size(), rows.size());
			for (int i = 0; i < rows.size(); i++) {
				final String[] f = csv.get(i).split(",");
				final Row r = rows.get(i);
				assertEquals(f[0], r.getString(0));
				assertEquals(Long.parseLong(f[1]), r.getLong(1));
				assertEquals(Long.parseLong(f[2]), r.getLong(2));
				assertEquals(Double.parseDouble(f[3]), r.getDouble(3), 1e-12);
				assertEquals(Double.parseDouble(f[4]), r.getDouble(4), 1e-12);
			}
			assertTrue(Files.isDirectory(sparkDir.resolve("spots.parquet/MOVIE=padded")));
		}
		finally {
			reader.stop();
		}
	}

	/**
	 * A field of 16 bright and 9 dark discs (D 10 px, 80 above and below a background of 100), tracked bright: the job
	 * says, as the command line does, that the first frame also holds 9 dark blobs (its executors read that frame once
	 * more to count them).
	 */
	@Test
	void aFieldOfBothContrastsIsWarnedAboutAsTheCommandLineDoes() throws IOException {
		final int w = 160, h = 160;
		final ij.ImageStack stack = new ij.ImageStack(w, h);
		final java.util.Random noise = new java.util.Random(3);
		for (int t = 0; t < 2; t++) {
			final byte[] px = new byte[w * h];
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					double v = 100;
					for (int i = 0; i < 25; i++) {
						final double r = Math.hypot(x - 18.3 - 30.1 * (i % 5), y - 17.6 - 30.4 * (i / 5));
						v += (i % 3 == 0 ? -80 : 80) / (1 + Math.exp((r - 5) / 0.7));
					}
					px[y * w + x] = (byte) Math.max(0, Math.min(255, Math.round(v + 3 * noise.nextGaussian())));
				}
			stack.addSlice(new ij.process.ByteProcessor(w, h, px));
		}
		final Path mixed = dir.resolve("mixed.tif");
		assertTrue(new ij.io.FileSaver(new ij.ImagePlus("mixed", stack)).saveAsTiffStack(mixed.toString()));
		final Object[] c = SparkTestMovies.cli("track", mixed.toString(), "--diameter", "10", "--out-dir", Files
			.createDirectories(dir.resolve("mixed-cli")).toString());
		assertEquals(0, c[0], (String) c[2]);
		final Object[] s = spark(mixed.toString(), "--diameter", "10", "--out-dir", dir.resolve("mixed-spark").toString());
		assertEquals(0, s[0], (String) s[2]);
		final String summary = SparkTestMovies.summary((String) s[1], mixed.toString());
		assertEquals(SparkTestMovies.summary((String) c[1], mixed.toString()), summary);
		assertTrue(summary.contains("warning: frame 1 also holds 9 blobs darker than the background"), summary);
	}

	/** A refused run leaves no output folder it made behind (two movies that would write one CSV). */
	@Test
	void aRefusedRunRemovesTheFolderItMade() throws IOException {
		final Path other = Files.createDirectories(dir.resolve("elsewhere")).resolve(pair.getFileName());
		Files.copy(pair, other, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
		final Path out = dir.resolve("new").resolve("folder");
		final Object[] r = spark(pair.toString(), other.toString(), "--out-dir", out.toString(), "--threshold", "100",
			"--r-out", "10");
		org.junit.jupiter.api.Assertions.assertEquals(2, r[0], () -> "refused: " + r[2]);
		org.junit.jupiter.api.Assertions.assertTrue(r[2].toString().contains("would both be written"), () -> r[2]
			.toString());
		org.junit.jupiter.api.Assertions.assertFalse(Files.exists(dir.resolve("new")), "no folder left behind");
	}
}
