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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.io.TestMovies;

/**
 * Integration test on the PACKAGED command-line jar (failsafe): a movie several times larger than the heap is
 * tracked in a forked JVM with {@code -Xmx64m}; before streaming, the whole stack was read first and this ended in
 * "out of memory".
 */
class StreamingMemoryIT {

	@TempDir
	Path dir;

	private static final int SIZE = 512, FRAMES = 600; // 16-bit: 300 MB

	private static Path cliJar() throws IOException {
		try (Stream<Path> files = Files.list(Path.of(System.getProperty("basedir", ".")).resolve("target"))) {
			return files.filter(p -> p.getFileName().toString().endsWith("-cli.jar")).findFirst().orElseThrow();
		}
	}

	/** Four particles, moving by 0.1 px a frame. */
	private static float[] frame(final int t) {
		final float[] px = new float[SIZE * SIZE];
		java.util.Arrays.fill(px, 100);
		for (int k = 0; k < 4; k++) {
			final double cx = 100 + 100 * k + 0.1 * (t % 50), cy = 150 + 60 * k;
			for (int y = (int) cy - 20; y <= cy + 20; y++)
				for (int x = (int) cx - 20; x <= cx + 20; x++) {
					final double r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
					px[y * SIZE + x] += (float) Math.rint(3000 * Math.exp(-r2 / 32));
				}
		}
		return px;
	}

	@Test
	void aMovieFiveTimesTheHeapIsTrackedFrameByFrame() throws Exception {
		final Path tif = dir.resolve("large.tif");
		TestMovies.writeTiff(tif, false, 16, 1, FRAMES, SIZE, SIZE, StreamingMemoryIT::frame, null, 0);
		assertTrue(Files.size(tif) > 300_000_000L, "the movie is larger than 300 MB: " + Files.size(tif));
		final Path csv = dir.resolve("spots.csv");
		final List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
			.toString(), "-Xmx64m", "-Djava.awt.headless=true", "-jar", cliJar().toString(), "track", tif.toString(),
			"--threshold", "1000", "--r-out", "14", "--method", "paper", "--threads", "2", "--csv", csv.toString()));
		final Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
		final String output = new String(p.getInputStream().readAllBytes());
		assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
		assertEquals(0, p.exitValue(), output);
		assertTrue(output.contains("2400 spots in 600 frames of 'large.tif', 0 flagged"), output);
		assertEquals(2401, Files.readAllLines(csv).size());
	}
}
