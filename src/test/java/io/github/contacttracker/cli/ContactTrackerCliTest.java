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

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ij.ImagePlus;
import ij.process.ColorProcessor;
import ij.process.FloatProcessor;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.cli.ContactTrackerLab;

class ContactTrackerCliTest {

	@TempDir
	Path dir;

	/** Runs the CLI; returns {exit status, stdout, stderr}. */
	static Object[] run(final String... args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final int status = ContactTrackerLab.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
			new PrintStream(err, true, StandardCharsets.UTF_8));
		return new Object[] { status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8) };
	}

	private Path simulated() {
		final Path tif = dir.resolve("pair.tif"), truth = dir.resolve("truth.csv");
		final Object[] r = run("simulate", "--scenario", "pair", "--separation", "1.0", "--frames", "4", "--seed",
			"3", "--out", tif.toString(), "--truth", truth.toString());
		assertEquals(0, r[0], (String) r[2]);
		return tif;
	}

	@Test
	void simulateThenTrackFindsTheTruthInCalibratedUnits() throws IOException {
		final Path tif = simulated();
		final Path csv = dir.resolve("spots.csv");
		final Object[] r = run("track", tif.toString(), "--threshold", "85", "--r-out", "61", "--csv", csv.toString());
		assertEquals(0, r[0], (String) r[2]);
		assertTrue(((String) r[1]).contains("8 spots in 4 frames of 'pair.tif', 0 flagged"), (String) r[1]);
		final List<String> lines = Files.readAllLines(csv);
		assertEquals(9, lines.size());
		assertTrue(lines.get(0).startsWith("ID,FRAME,POSITION_X,POSITION_Y,POSITION_Z,POSITION_T,RADIUS,QUALITY," +
			"VISIBILITY,"), lines.get(0));
		assertEquals(SpotColumn.values().length, lines.get(0).split(",").length);
		// Truth (px) times the pixel size (um) equals the tracked positions within 0.01 um.
		final List<String> truth = Files.readAllLines(dir.resolve("truth.csv"));
		final double um = PaperParticles.silica553().pixelSizeMicrons();
		for (int i = 1; i < truth.size(); i++) {
			final String[] t = truth.get(i).split(",");
			final double tx = Double.parseDouble(t[2]) * um, ty = Double.parseDouble(t[3]) * um;
			boolean found = false;
			for (int j = 1; j < lines.size(); j++) {
				final String[] s = lines.get(j).split(",");
				if (s[1].equals(t[0]) && Math.hypot(Double.parseDouble(s[2]) - tx, Double.parseDouble(s[3]) - ty) < 0.01)
					found = true;
			}
			assertTrue(found, "truth " + truth.get(i));
		}
	}

	/**
	 * {@code simulate --detection-scene}: the study's scene as a movie and its truth, the same particles the study
	 * renders with that seed; a name it does not know, or a scene option beside it, is a one-line error and writes
	 * nothing.
	 */
	@Test
	void simulateWritesADetectionSceneAndItsTruth() throws IOException {
		final Path tif = dir.resolve("clipped.tif"), truth = dir.resolve("clipped.csv");
		final Object[] r = run("simulate", "--detection-scene", "clipped", "--frames", "2", "--seed", "7", "--out", tif
			.toString(), "--truth", truth.toString());
		assertEquals(0, r[0], (String) r[2]);
		final io.github.contacttracker.lab.sim.DetectionScene scene = io.github.contacttracker.lab.sim.DetectionScenes
			.of("clipped", 2, 7);
		final ij.ImagePlus imp = ImageFiles.open(tif);
		assertEquals(2, imp.getStackSize());
		assertEquals(scene.width(), imp.getWidth());
		final List<String> lines = Files.readAllLines(truth);
		assertEquals("frame,particle,x_px,y_px,diameter_px,band", lines.get(0));
		final int n = scene.scene().particles().size();
		assertEquals(1 + 2 * n, lines.size());
		for (int i = 1; i < lines.size(); i++) {
			final String[] t = lines.get(i).split(",");
			final double[] c = scene.truth().get(Integer.parseInt(t[0])).get(Integer.parseInt(t[1]));
			assertEquals(c[0], Double.parseDouble(t[2]), 1e-6);
			assertEquals(c[1], Double.parseDouble(t[3]), 1e-6);
			assertEquals(scene.band(Integer.parseInt(t[0]), Integer.parseInt(t[1])), t[5]);
		}
		final Path other = dir.resolve("none.tif");
		final Object[] bad = run("simulate", "--detection-scene", "crowd", "--out", other.toString(), "--truth", dir
			.resolve("none.csv").toString());
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, bad[0]);
		assertTrue(((String) bad[2]).contains("--detection-scene must be one of"), (String) bad[2]);
		final Object[] both = run("simulate", "--detection-scene", "dim", "--scenario", "pair", "--out", other
			.toString(), "--truth", dir.resolve("none.csv").toString());
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, both[0]);
		assertTrue(((String) both[2]).contains("takes no --scenario"), (String) both[2]);
		assertFalse(Files.exists(other));
	}

	/**
	 * {@code --kinds N}: in the help; a value outside the core's limits, or no number, is a one-line error naming
	 * it; a valid one reaches the core's parameters (the TrackMate file records the parameters tracked with).
	 */
	@Test
	void kindsIsCheckedAgainstTheCoresLimitsAndReachesTheCore() throws IOException {
		final String help = (String) run("track", "--help")[1];
		assertTrue(help.contains("[--kinds=N]") && help.contains("--kinds=N  "), help);
		final Path tif = simulated();
		for (final String[] bad : new String[][] { { "5", "kinds must be 0 (found automatically), 1 (all alike) or " +
			"up to 4, not 5" }, { "-1", "kinds must be 0 (found automatically), 1 (all alike) or up to 4, not -1" }, {
				"two", "kinds must be a whole number, not 'two'" } })
		{
			final Object[] r = run("track", tif.toString(), "--threshold", "85", "--r-out", "61", "--kinds", bad[0]);
			assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0], (String) r[2]);
			assertEquals("contact-tracker: error: option --kinds: " + bad[1], ((String) r[2]).strip());
			assertEquals("", r[1]);
		}
		final Path csv = dir.resolve("kinds.csv"), xml = dir.resolve("kinds.xml");
		final Object[] r = run("track", tif.toString(), "--threshold", "85", "--r-out", "61", "--kinds", "1", "--csv",
			csv.toString(), "--trackmate-xml", xml.toString());
		assertEquals(0, r[0], (String) r[2]);
		assertTrue(Files.readString(xml).contains(" KINDS=\"1\" "), "KINDS=\"1\" in the detector settings");
		assertTrue(Files.readAllLines(csv).get(0).endsWith(",KIND"), "the KIND column");
	}

	@Test
	void csvGoesToStdoutWithoutCsvOption() {
		final Path tif = simulated();
		final Object[] r = run("track", tif.toString(), "--threshold", "85", "--r-out", "61");
		assertEquals(0, r[0]);
		assertTrue(((String) r[1]).startsWith("ID,FRAME,POSITION_X"));
		assertTrue(((String) r[2]).contains("8 spots"));
	}

	/**
	 * One command: {@code track MOVIE} with no values measures them as {@code profile} suggests, says so on stderr,
	 * and tracks exactly as a run given those values; a value given wins over the measured one.
	 */
	@Test
	void trackWithoutValuesMeasuresThemAsProfileSuggests() throws IOException {
		final Path tif = simulated();
		final Object[] p = run("profile", tif.toString());
		assertEquals(0, p[0], (String) p[2]);
		final String suggested = ((String) p[1]).lines().filter(l -> l.startsWith("suggested:")).findFirst().orElseThrow()
			.substring("suggested:".length()).trim();
		final Path measured = dir.resolve("measured.csv"), given = dir.resolve("given.csv");
		final Object[] r = run("track", tif.toString(), "--csv", measured.toString());
		assertEquals(0, r[0], (String) r[2]);
		assertTrue(((String) r[2]).contains("measured on frame 1 by the profile helper: " + suggested), r[2] + " vs " +
			suggested);
		final List<String> args = new java.util.ArrayList<>(List.of("track", tif.toString(), "--csv", given.toString()));
		args.addAll(List.of(suggested.split(" ")));
		final Object[] g = run(args.toArray(String[]::new));
		assertEquals(0, g[0], (String) g[2]);
		assertEquals("", g[2], "nothing measured when everything is given");
		assertEquals(Files.readString(given), Files.readString(measured));
		// a given threshold wins; the rest is still measured
		final Object[] t = run("track", tif.toString(), "--threshold", "90", "--csv", given.toString());
		assertEquals(0, t[0], (String) t[2]);
		assertFalse(((String) t[2]).contains("--threshold"), (String) t[2]);
		assertTrue(((String) t[2]).contains("--r-out "), (String) t[2]);
	}

	private void assertBadInput(final String expected, final Path mustNotExist, final String... args) {
		final Object[] r = run(args);
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0]);
		final String err = ((String) r[2]).trim();
		assertEquals(1, err.lines().count(), "one line: " + err);
		assertTrue(err.contains(expected), err);
		if (mustNotExist != null) assertFalse(Files.exists(mustNotExist), "no partial output");
	}

	@Test
	void badInputGivesOneLineAndStatusTwoAndNoOutput() throws IOException {
		final Path csv = dir.resolve("out.csv");
		assertBadInput("file not found", csv, "track", dir.resolve("missing.tif").toString(), "--threshold", "1",
			"--r-out", "5", "--csv", csv.toString());
		final Path tif = simulated();
		assertBadInput("r_out must be a positive", csv, "track", tif.toString(), "--threshold", "85", "--r-out", "0",
			"--csv", csv.toString());
		assertBadInput("threshold 300 is outside the data range", csv, "track", tif.toString(), "--threshold", "300",
			"--r-out", "61", "--csv", csv.toString());
		assertBadInput("must be a number", csv, "track", tif.toString(), "--threshold", "high", "--r-out", "61");
		final Path rgb = dir.resolve("rgb.tif");
		final ColorProcessor colour = new ColorProcessor(20, 20);
		colour.set(3, 4, 0xc80000); // one red pixel: a colour image of three channels
		ImageFiles.saveTiff(new ImagePlus("rgb", colour), rgb);
		assertBadInput("channel 4 does not exist: 'rgb.tif' has 3 channels", csv, "track", rgb.toString(),
			"--channel", "4", "--threshold", "1", "--r-out", "5", "--csv", csv.toString());
		final Path nan = dir.resolve("nan.tif");
		final FloatProcessor fp = new FloatProcessor(20, 20);
		fp.setf(3, 4, Float.NaN);
		ImageFiles.saveTiff(new ImagePlus("nan", fp), nan);
		assertBadInput("pixel (3, 4) is NaN", csv, "track", nan.toString(), "--threshold", "0", "--r-out", "5",
			"--csv", csv.toString());
		final Path notImage = dir.resolve("text.tif");
		Files.writeString(notImage, "not an image");
		assertBadInput("as an image", csv, "track", notImage.toString(), "--threshold", "1", "--r-out", "5", "--csv",
			csv.toString());
		// (the 1 after it reads as a second movie: track takes several)
		assertBadInput("Unknown option: '--bogus'", null, "track", tif.toString(), "--threshold",
			"85", "--r-out", "61", "--bogus", "1");
		assertBadInput("Invalid value for option '--threads': 'two' is not an int", csv, "track", tif.toString(),
			"--threshold", "85", "--r-out", "61", "--threads", "two", "--csv", csv.toString());
		assertBadInput("unknown command", null, "frobnicate");
		try (var files = Files.list(dir)) {
			assertTrue(files.noneMatch(p -> p.getFileName().toString().endsWith(".part")), "no temporary files left");
		}
	}

	/**
	 * Several movies in one run: each movie's CSV in the output folder, byte for byte what a run of that movie alone
	 * writes; a movie that cannot be tracked is named, the others are still written, and the status says so.
	 */
	@Test
	void severalMoviesGoToOneCsvEachInTheOutputFolder() throws IOException {
		final Path a = simulated(), b = dir.resolve("pair15.tif");
		assertEquals(0, run("simulate", "--scenario", "pair", "--separation", "1.5", "--frames", "3", "--out", b
			.toString(), "--truth", dir.resolve("truth15.csv").toString())[0]);
		final Path outDir = Files.createDirectory(dir.resolve("out"));
		final Object[] r = run("track", a.toString(), b.toString(), "--threshold", "85", "--r-out", "61", "--out-dir",
			outDir.toString());
		assertEquals(0, r[0], (String) r[2]);
		assertTrue(((String) r[1]).contains("8 spots in 4 frames of 'pair.tif'") && ((String) r[1]).contains(
			"6 spots in 3 frames of 'pair15.tif'"), (String) r[1]);
		for (final Path movie : List.of(a, b)) {
			final Path alone = dir.resolve("alone.csv");
			assertEquals(0, run("track", movie.toString(), "--threshold", "85", "--r-out", "61", "--csv", alone
				.toString())[0]);
			final String name = movie.getFileName().toString().replace(".tif", ".csv");
			assertEquals(Files.readString(alone), Files.readString(outDir.resolve(name)), name);
		}

		final Path bad = dir.resolve("bad.tif");
		Files.writeString(bad, "not an image");
		final Path again = Files.createDirectory(dir.resolve("again"));
		final Object[] partly = run("track", a.toString(), bad.toString(), b.toString(), "--threshold", "85", "--r-out",
			"61", "--diameter", "65.3", "--out-dir", again.toString());
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, partly[0]);
		final List<String> err = ((String) partly[2]).lines().toList();
		assertEquals(2, err.size(), String.join("\n", err));
		assertTrue(err.get(0).startsWith("contact-tracker: error: " + bad) && err.get(0).contains("as an image"), err
			.get(0));
		assertTrue(err.get(1).contains("1 of 3 movies failed"), err.get(1));
		assertTrue(Files.exists(again.resolve("pair.csv")) && Files.exists(again.resolve("pair15.csv")));
		assertFalse(Files.exists(again.resolve("bad.csv")));

		// refused before any work: several movies without a folder, --out-dir with --csv, two movies of one name
		assertBadInput("2 movies need --out-dir", null, "track", a.toString(), b.toString(), "--threshold", "85",
			"--r-out", "61");
		assertBadInput("without --csv", null, "track", a.toString(), "--threshold", "85", "--r-out", "61", "--out-dir",
			outDir.toString(), "--csv", dir.resolve("x.csv").toString());
		final Path twin = Files.createDirectory(dir.resolve("twin")).resolve("pair.tif");
		Files.copy(a, twin);
		final Path fresh = Files.createDirectory(dir.resolve("fresh"));
		assertBadInput("would both be written to", null, "track", a.toString(), twin.toString(), "--threshold", "85",
			"--r-out", "61", "--out-dir", fresh.toString());
		try (var files = Files.list(fresh)) {
			assertEquals(0, files.count(), "nothing written");
		}

		// a folder that does not exist yet is made (its parents too); a file given as the folder is refused
		final Path made = dir.resolve("new").resolve("spots");
		assertEquals(0, run("track", a.toString(), "--threshold", "85", "--r-out", "61", "--out-dir", made.toString())[0]);
		assertTrue(Files.isRegularFile(made.resolve("pair.csv")));
		assertBadInput("is a file, not a folder", null, "track", a.toString(), "--threshold", "85", "--r-out", "61",
			"--out-dir", bad.toString());
		// a refused run leaves no folder behind: neither the one it made nor its parents, nor several movies that all
		// fail; a folder that existed stays
		final Path notYet = dir.resolve("later").resolve("spots");
		assertBadInput("threshold", null, "track", a.toString(), "--threshold", "1e9", "--r-out", "61", "--out-dir",
			notYet.toString());
		assertFalse(Files.exists(dir.resolve("later")), "no folder left behind a refusal");
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, run("track", bad.toString(), dir.resolve("missing.tif").toString(), "--threshold",
			"85", "--r-out", "61", "--out-dir", notYet.toString())[0]);
		assertFalse(Files.exists(dir.resolve("later")), "no folder left behind movies that all failed");
		assertBadInput("threshold", null, "track", a.toString(), "--threshold", "1e9", "--r-out", "61", "--out-dir",
			fresh.toString());
		assertTrue(Files.isDirectory(fresh), "a folder that existed stays");
	}
}
