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
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.SimulatedStack;

/** {@code contact-tracker profile}: the table, the PNG, the CSV and the line to copy; help and bad options. */
class ProfileCliTest {

	record Run(int status, String out, String err) {}

	static Run run(final String... args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final int status = ContactTrackerCli.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
			new PrintStream(err, true, StandardCharsets.UTF_8));
		return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
	}

	@Test
	void profileOfAMovieSuggestsTheSettings(@TempDir final Path dir) throws Exception {
		final ParticleType type = PaperParticles.silica553();
		final double d = type.diameterPx();
		final List<double[]> centres = new ArrayList<>();
		for (final double[] c : new double[][] { { 2.5, 2.5 }, { 7.5, 2.5 }, { 2.5, 7.5 }, { 7, 7 }, { 8, 7 } })
			centres.add(new double[] { c[0] * d + 0.3, c[1] * d - 0.2 });
		final int size = (int) Math.ceil(10 * d);
		final var frame = SimulatedStack.renderFrame(type, centres, size, size, type.noise(), new SplittableRandom(1), 8)
			.image();
		final Path tif = dir.resolve("movie.tif");
		ImageFiles.saveTiff(TimeSeries.of("movie", List.of(frame), Calibration.PIXELS), tif);
		final Path png = dir.resolve("profile.png"), csv = dir.resolve("profile.csv");
		final Run r = run("profile", tif.toString(), "--png", png.toString(), "--csv", csv.toString());
		assertEquals(0, r.status(), r.err());
		assertTrue(r.out().contains("   r_px    level  above_bg  pixels"), r.out());
		final String last = r.out().strip().lines().reduce((a, b) -> b).orElseThrow();
		assertTrue(last.matches("suggested: --threshold \\d+ --r-out \\d+ --diameter [0-9.]+"), last);
		final double diameter = Double.parseDouble(last.replaceAll(".*--diameter ", ""));
		assertEquals(d, diameter, 0.02 * d, "diameter from the pair at contact");
		assertTrue(ImageIO.read(png.toFile()).getWidth() > 100, "a PNG plot");
		final List<String> rows = Files.readAllLines(csv);
		assertEquals("r_px,level,above_background,pixels", rows.get(0));
		assertTrue(rows.size() > 100);

		// at a point, given the diameter
		final Run at = run("profile", tif.toString(), "--at", Math.round(centres.get(0)[0]) + "," + Math.round(centres
			.get(0)[1]), "--diameter", "65.3");
		assertEquals(0, at.status(), at.err());
		assertTrue(at.out().contains("profile of 1 particle around"), at.out());
		assertTrue(at.out().strip().endsWith("--diameter 65.3"), at.out());
	}

	/**
	 * Two blurred spheres standing apart, whose light at contact would rise above their own peak: no threshold keeps
	 * two of them apart, and the helper's threshold lies above every pixel. The line to copy is then what 'track'
	 * measures (detection by the image, a threshold within the frame), never a value outside the frame.
	 */
	@Test
	void aThresholdAboveEveryPixelIsNeverSuggested(@TempDir final Path dir) throws Exception {
		final ImageSimulator sim = new ImageSimulator(r -> 120 / (1 + Math.exp((r - 6) * 1.702 / 1.5)), 3);
		final var frame = Quantiser.toUnsignedBytes(sim.render(List.of(new double[] { 38.3, 40.2 }, new double[] { 62.3,
			40.2 }), 100, 80, 37), NoiseModel.gaussian(3), new SplittableRandom(11)).image();
		final Path tif = dir.resolve("pair.tif");
		ImageFiles.saveTiff(TimeSeries.of("pair", List.of(frame), Calibration.PIXELS), tif);
		double max = 0;
		for (final var v : frame)
			max = Math.max(max, v.getRealDouble());
		final Run r = run("profile", tif.toString());
		assertEquals(0, r.status(), r.err());
		assertTrue(r.out().contains("warning: the threshold ") && r.out().contains(" lies above every pixel of the " +
			"frame (" + (int) max + ")"), r.out());
		final String last = r.out().strip().lines().reduce((a, b) -> b).orElseThrow();
		assertTrue(last.matches("suggested: --detection image --threshold [0-9.]+ --r-out [0-9.]+ --diameter [0-9.]+"),
			last);
		final double threshold = Double.parseDouble(last.replaceAll(".*--threshold ([0-9.]+).*", "$1"));
		assertTrue(threshold <= max, last);
		assertEquals(12, Double.parseDouble(last.replaceAll(".*--diameter ", "")), 0.6, "the spheres' rim: " + last);
	}

	@Test
	void helpAndBadOptions(@TempDir final Path dir) {
		final Run help = run("profile", "--help");
		assertEquals(0, help.status());
		assertTrue(help.out().contains("--at=X,Y"), help.out());
		final Run bad = run("profile", "movie.tif", "--frame", "two");
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, bad.status());
		assertTrue(bad.err().startsWith("contact-tracker: error: Invalid value for option '--frame'"), bad.err());
		assertTrue(bad.err().contains("(see contact-tracker profile --help)"), bad.err());
		assertEquals(1, bad.err().strip().lines().count(), "one line");
		final Run missing = run("profile", dir.resolve("none.tif").toString());
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, missing.status());
		assertTrue(missing.err().contains("file not found"), missing.err());
		final Run usage = run("--help");
		assertEquals(0, usage.status());
		assertTrue(usage.out().contains("profile"), "the subcommand is listed: " + usage.out());
	}
}
