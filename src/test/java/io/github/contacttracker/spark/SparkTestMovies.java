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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.process.ImageProcessor;
import io.github.contacttracker.cli.ContactTrackerCli;
import io.github.contacttracker.lab.cli.ContactTrackerLab;

/**
 * The movies the Spark tests track, and the command line to compare with; free of Spark's classes, so that the
 * cluster test (on the packaged jars, without the job's classes) can use them.
 */
final class SparkTestMovies {

	private SparkTestMovies() {}

	/**
	 * @return in {@code dir}: padded.tif (12 frames of 1024 x 1024: the profile is measured on 3 of them, the 9 others
	 *         go to chunks), pair.tif (6 frames of 206 x 140, all of them profile frames), simulated touching pairs,
	 *         and nan.tif (padded.tif in 32-bit float, a NaN pixel in frame 10)
	 */
	static Path[] movies(final Path dir) throws IOException {
		final Path pair = dir.resolve("pair.tif");
		final Object[] r = cli("simulate", "--scenario", "pair", "--separation", "1.0", "--frames", "12", "--seed", "3",
			"--out", pair.toString(), "--truth", dir.resolve("truth.csv").toString());
		assertEquals(0, r[0], (String) r[2]);
		// the same frames on a large canvas of their background (ImageJ's writer, calibration kept)
		final ImagePlus small = new ImagePlus(pair.toString());
		final ImageStack big = new ImageStack(1024, 1024);
		for (int t = 1; t <= small.getStackSize(); t++) {
			final ImageProcessor ip = small.getStack().getProcessor(t);
			final ImageProcessor canvas = ip.createProcessor(1024, 1024);
			canvas.setValue(ip.getStatistics().median);
			canvas.fill();
			canvas.insert(ip, 300, 200);
			big.addSlice(canvas);
		}
		final ImagePlus movie = new ImagePlus("padded", big);
		movie.setCalibration(small.getCalibration());
		final Path padded = dir.resolve("padded.tif");
		assertTrue(new FileSaver(movie).saveAsTiffStack(padded.toString()));
		// pair.tif again, 6 frames
		final ImageStack six = new ImageStack(small.getWidth(), small.getHeight());
		for (int t = 1; t <= 6; t++)
			six.addSlice(small.getStack().getProcessor(t));
		final ImagePlus sixFrames = new ImagePlus("pair", six);
		sixFrames.setCalibration(small.getCalibration());
		assertTrue(new FileSaver(sixFrames).saveAsTiffStack(pair.toString()));
		// padded.tif as 32-bit float with a NaN pixel in frame 10: a chunk's frame, not a profile frame (1, 5, 9)
		final ImageStack floats = new ImageStack(1024, 1024);
		for (int t = 1; t <= big.getSize(); t++)
			floats.addSlice(big.getProcessor(t).convertToFloat());
		floats.getProcessor(10).putPixelValue(10, 10, Float.NaN);
		final ImagePlus nanMovie = new ImagePlus("nan", floats);
		nanMovie.setCalibration(small.getCalibration());
		final Path nan = dir.resolve("nan.tif");
		assertTrue(new FileSaver(nanMovie).saveAsTiffStack(nan.toString()));
		return new Path[] { padded, pair, nan };
	}

	static Object[] cli(final String... args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final int status = ContactTrackerLab.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
			new PrintStream(err, true, StandardCharsets.UTF_8));
		return new Object[] { status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8) };
	}


	/** @return the summary line of {@code movie}, its time left out */
	static String summary(final String out, final String movie) {
		return out.lines().filter(l -> l.startsWith(movie + ": ")).findFirst().orElseThrow(() -> new AssertionError(
			"no summary of " + movie + " in " + out)).replaceAll(", [0-9.]+ s \\([0-9.]+ frames/s\\)", "");
	}
}
