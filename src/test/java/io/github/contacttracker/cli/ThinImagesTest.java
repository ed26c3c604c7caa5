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
import java.util.SplittableRandom;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import ij.ImagePlus;
import ij.process.ByteProcessor;
import io.github.contacttracker.io.ImageFiles;

/**
 * Images 1 to 3 pixels in one dimension (a thin selection, a line-scan camera) reach the profile helper on every
 * {@code track}: they once ended in an internal error (the helper asked for the 20th brightest of fewer pixels).
 * Every one either tracks or ends with exit 2 and one line naming the file, with and without values given.
 */
class ThinImagesTest {

	@TempDir
	Path dir;

	/**
	 * Found by the entry-point fuzz: an r_out of 1e6 px (or such a diameter with detection by the image) sized the
	 * profile's arrays beyond the heap, an internal error; now one line naming the movie and the value.
	 */
	@org.junit.jupiter.api.Test
	void aReachBeyondTheFrameIsRefusedInOneLine() throws IOException {
		final ByteProcessor ip = new ByteProcessor(40, 30);
		ip.setValue(200);
		ip.fillOval(10, 10, 8, 8);
		final Path tif = dir.resolve("small.tif");
		ImageFiles.saveTiff(new ImagePlus("small", ip), tif);
		for (final String[] args : new String[][] { { "--threshold", "100", "--r-out", "1e6" }, { "--threshold", "100",
			"--r-out", "5", "--diameter", "1e6", "--detection", "image" } })
		{
			final String[] all = new String[args.length + 4];
			all[0] = "track";
			all[1] = tif.toString();
			System.arraycopy(args, 0, all, 2, args.length);
			all[args.length + 2] = "--csv";
			all[args.length + 3] = dir.resolve("o.csv").toString();
			final Object[] out = ContactTrackerCliTest.run(all);
			final String err = ((String) out[2]).strip();
			assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, out[0], err);
			assertEquals(1, err.lines().count(), err);
			assertTrue(err.contains("small.tif") && err.contains("twice the frame's diagonal"), err);
			assertFalse(Files.exists(dir.resolve("o.csv")));
		}
	}

	@ParameterizedTest
	@CsvSource({ "1,1", "1,17", "17,1", "2,9", "3,5", "2,50", "50,2", "3,40", "40,3" })
	void thinImagesTrackOrEndInOneLine(final int w, final int h) throws IOException {
		final ByteProcessor ip = new ByteProcessor(w, h);
		final SplittableRandom r = new SplittableRandom(w * 100L + h);
		for (int i = 0; i < w * h; i++)
			ip.set(i, 20 + r.nextInt(200));
		final Path tif = dir.resolve("thin.tif");
		ImageFiles.saveTiff(new ImagePlus("thin", ip), tif);
		for (final String[] values : new String[][] { {}, { "--threshold", "100", "--r-out", "5" } }) {
			final Path csv = dir.resolve("out.csv");
			final String[] args = new String[3 + values.length + 2];
			args[0] = "track";
			args[1] = tif.toString();
			System.arraycopy(values, 0, args, 2, values.length);
			args[2 + values.length] = "--csv";
			args[3 + values.length] = csv.toString();
			args[4 + values.length] = "--no-progress";
			final Object[] out = ContactTrackerCliTest.run(args);
			final String err = (String) out[2];
			assertFalse(err.contains("internal error"), err);
			assertTrue((int) out[0] == 0 || (int) out[0] == 2, "exit " + out[0] + ": " + err);
			if ((int) out[0] == 2) {
				assertEquals(1, err.strip().lines().filter(l -> l.contains("error")).count(), err);
				assertTrue(err.contains("thin.tif"), "the error names the file: " + err);
				assertFalse(Files.exists(csv), "nothing half-written");
			}
			Files.deleteIfExists(csv);
		}
	}
}
