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
package io.github.contacttracker.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Integration test on the PACKAGED command-line jar (failsafe): the broken and hostile files of issue 24, and a TIFF
 * of two million chained directories, through {@code track} in a 256 MB heap, each in a process of its own as a user
 * runs it: exit status 2, exactly one line on standard error naming the file, within a few seconds. (Before: ImageJ's messages on 2-4 lines, out of memory for
 * a looping directory chain or a huge declared size, runs past 30 s.)
 */
class BrokenFilesIT {

	@TempDir
	Path dir;

	/** A case's process may take at most this long (the JVM's start included). */
	private static final long BOUND_MS = 10_000;

	private static Path cliJar() throws IOException {
		try (Stream<Path> files = Files.list(Path.of(System.getProperty("basedir", ".")).resolve("target"))) {
			return files.filter(p -> p.getFileName().toString().endsWith("-cli.jar")).findFirst().orElseThrow();
		}
	}

	/** @return the kinds of broken file, by name (also written by scripts/reader-comparison) */
	static Map<String, byte[]> cases(final Map<String, byte[]> seeds) {
		final Map<String, byte[]> cases = new LinkedHashMap<>();
		cases.put("empty.tif", new byte[0]);
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			final byte[] valid = seeds.get(seed);
			final String base = seed.replace(".tif", "-");
			final int first = new SeedFiles.Tiff(valid).ifd;
			cases.put(base + "loop-to-first.tif", new SeedFiles.Tiff(valid).next(0, first).bytes);
			cases.put(base + "last-loops-to-first.tif", new SeedFiles.Tiff(valid).next(99, first).bytes);
			cases.put(base + "huge-width.tif", new SeedFiles.Tiff(valid).set(256, 0x7fff_fff0L).bytes);
			cases.put(base + "huge-both.tif", new SeedFiles.Tiff(valid).set(256, 60000).set(257, 60000).bytes);
			cases.put(base + "zero-height.tif", new SeedFiles.Tiff(valid).set(257, 0).bytes);
			cases.put(base + "strip-past-end.tif", new SeedFiles.Tiff(valid).set(273, valid.length + 10).bytes);
			cases.put(base + "bits-128.tif", new SeedFiles.Tiff(valid).set(258, 128).bytes);
			cases.put(base + "entries-huge.tif", new SeedFiles.Tiff(valid).entries(65535).bytes);
			cases.put(base + "truncated.tif", Arrays.copyOf(valid, valid.length / 2));
		}
		final byte[] avi = seeds.get("movie.avi");
		final byte[] list = avi.clone();
		ByteBuffer.wrap(list).order(ByteOrder.LITTLE_ENDIAN).putInt(16, 0x7fff_ff00);
		cases.put("avi-list-length.avi", list);
		cases.put("avi-truncated-header.avi", Arrays.copyOf(avi, 300));
		cases.put("avi-truncated.avi", Arrays.copyOf(avi, avi.length / 2));
		return cases;
	}

	/**
	 * @return a classic TIFF of {@code n} chained directories of one entry each and no image: describing them all
	 *         would take more than the heap's share
	 */
	private static byte[] chain(final int n) {
		final ByteBuffer b = ByteBuffer.allocate(8 + 18 * n).order(ByteOrder.LITTLE_ENDIAN);
		b.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt(8);
		for (int i = 0; i < n; i++)
			b.putShort((short) 1).putShort((short) 305).putShort((short) 2).putInt(1).putInt(0).putInt(i + 1 < n ? 8 +
				18 * (i + 1) : 0);
		return b.array();
	}

	/**
	 * A strip whose stated size overstates it (2^31 - 1 bytes) while the file holds its rows is no broken file: it
	 * is read as ImageJ reads it, as far as its rows need (a public monolayer's TIFF states 4 MiB for its 512 KiB
	 * strip), by the command line, in a 256 MB heap.
	 */
	@Test
	void aStripWhoseStatedSizeIsHugeIsReadAsFarAsItsRowsNeed() throws Exception {
		final Map<String, byte[]> seeds = SeedFiles.all(Files.createDirectories(dir.resolve("seeds-huge")));
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			final Path file = dir.resolve(seed.replace(".tif", "-strip-bytes-huge.tif"));
			Files.write(file, new SeedFiles.Tiff(seeds.get(seed)).set(279, 0x7fff_ffffL).bytes);
			final Path csv = dir.resolve(file.getFileName() + ".csv");
			final Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
				"-Xmx256m", "-Djava.awt.headless=true", "-jar", cliJar().toString(), "track", file.toString(),
				"--threshold", "100", "--r-out", "5", "--csv", csv.toString()).redirectOutput(ProcessBuilder.Redirect
					.DISCARD).start();
			final String err = new String(p.getErrorStream().readAllBytes()).strip();
			assertTrue(p.waitFor(BOUND_MS, TimeUnit.MILLISECONDS), seed + ": still running");
			assertEquals(0, p.exitValue(), seed + ": " + err);
			assertTrue(Files.exists(csv), seed + ": its CSV");
		}
	}

	@Test
	void everyBrokenFileIsOneLineAndExitTwoInA256MegabyteHeap() throws Exception {
		final Map<String, byte[]> cases = cases(SeedFiles.all(Files.createDirectories(dir.resolve("seeds"))));
		cases.put("many-directories.tif", chain(2_000_000));
		final List<String> report = new ArrayList<>();
		for (final Map.Entry<String, byte[]> c : cases.entrySet()) {
			final Path file = dir.resolve(c.getKey());
			Files.write(file, c.getValue());
			final List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
				"-Xmx256m", "-Djava.awt.headless=true", "-jar", cliJar().toString(), "track", file.toString(),
				"--threshold", "100", "--r-out", "5", "--csv", dir.resolve(c.getKey() + ".csv").toString());
			final long start = System.nanoTime();
			final Process p = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
			final String err = new String(p.getErrorStream().readAllBytes()).strip();
			final boolean ended = p.waitFor(BOUND_MS, TimeUnit.MILLISECONDS);
			if (!ended) p.destroyForcibly();
			final long ms = (System.nanoTime() - start) / 1_000_000;
			assertTrue(ended, c.getKey() + ": still running after " + BOUND_MS + " ms");
			report.add(String.format("%-32s exit %d %5d ms  %s", c.getKey(), p.exitValue(), ms, err));
			assertEquals(2, p.exitValue(), c.getKey() + ": " + err);
			assertEquals(1, err.lines().count(), c.getKey() + ": one line: " + err);
			assertTrue(err.startsWith("contact-tracker: error: ") && err.contains(file.toString()), err);
			assertTrue(ms < BOUND_MS, c.getKey() + ": " + ms + " ms");
			assertTrue(Files.notExists(dir.resolve(c.getKey() + ".csv")), "no CSV left behind");
		}
		System.out.println("BrokenFilesIT, " + cases.size() + " cases, -Xmx256m:\n" + String.join("\n", report));
	}
}
