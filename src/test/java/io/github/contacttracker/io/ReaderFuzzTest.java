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

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Coverage-guided fuzzing of the readers with Jazzer: any bytes, as a file, are read or refused in one line naming
 * the file ({@link ReaderContract}); an out-of-memory, a stray exception, ImageJ printing or a hang is a finding.
 * <p>
 * In the suite this runs in Jazzer's regression mode: once on each file of the seed corpus,
 * {@code src/test/resources/io/github/contacttracker/io/ReaderFuzzTestInputs/readers/} (valid files of every
 * format, {@link SeedFiles}; a finding's reproducer is added there too), in well under a second. To fuzz:
 * <pre>
 * JAZZER_FUZZ=1 mvn -B test -Dtest='ReaderFuzzTest#readers' -Djazzer.instrument='io.github.contacttracker.**,ij.**'
 * </pre>
 * for 10 minutes or to the first finding (see src/site/markdown/manual.md, Broken files).
 */
class ReaderFuzzTest {

	/** Where a fuzzed input is written, one file reused. */
	private static Path scratch;

	/** Any input taking over 10 s is a finding: a hang (Jazzer passes JUnit's timeout to the fuzzer per input). */
	@Timeout(10)
	@FuzzTest(maxDuration = "10m")
	void readers(final byte[] data) throws IOException {
		if (scratch == null) scratch = Files.createTempDirectory("reader-fuzz");
		final Path file = scratch.resolve("fuzzed.tif");
		Files.write(file, data);
		ReaderContract.check(file, 4);
	}

	/**
	 * The corpus holds the seed files, every one read, and the reproducers of the fuzzer's findings
	 * ({@code finding-*}), each now read or refused; rewrite the seeds with {@code -Dcontact.tracker.writeSeeds=true}.
	 */
	@Test
	void theSeedCorpusHoldsAValidFileOfEveryFormat(@TempDir final Path dir) throws IOException {
		final Path corpus = Path.of(System.getProperty("basedir", ".")).resolve(
			"src/test/resources/io/github/contacttracker/io/ReaderFuzzTestInputs/readers");
		final Map<String, byte[]> seeds = SeedFiles.all(dir);
		if (Boolean.getBoolean("contact.tracker.writeSeeds")) for (final Map.Entry<String, byte[]> s : seeds.entrySet())
			Files.write(corpus.resolve(s.getKey()), s.getValue());
		final Map<String, ReaderContract.Outcome> read = new TreeMap<>();
		try (Stream<Path> files = Files.list(corpus)) {
			for (final Path f : files.toList()) {
				final ReaderContract.Outcome outcome = ReaderContract.check(f, 4);
				if (!f.getFileName().toString().startsWith("finding-")) read.put(f.getFileName().toString(), outcome);
			}
		}
		final Map<String, ReaderContract.Outcome> expected = new TreeMap<>();
		for (final String name : seeds.keySet())
			expected.put(name, ReaderContract.Outcome.READ);
		assertEquals(expected, read);
	}
}
