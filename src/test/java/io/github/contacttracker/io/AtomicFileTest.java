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
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.core.InvalidInputException;

/** Files appear whole or not at all, and several files all or none, also when a write fails half-way. */
class AtomicFileTest {

	@TempDir
	Path dir;

	private List<String> names() throws IOException {
		try (Stream<Path> s = Files.list(dir)) {
			return s.map(p -> p.getFileName().toString()).sorted().toList();
		}
	}

	@Test
	void allFilesAppearTogether() throws IOException {
		final Path a = dir.resolve("a.csv"), b = dir.resolve("b.xml");
		AtomicFile.writeAll(List.of(a, b), List.of(out -> out.write("A".getBytes(StandardCharsets.UTF_8)),
			out -> out.write("B".getBytes(StandardCharsets.UTF_8))));
		assertEquals(List.of("a.csv", "b.xml"), names());
		assertEquals("A", Files.readString(a));
		assertEquals("B", Files.readString(b));
	}

	/** The second file fails after its temporary file was opened and partly written: nothing is left. */
	@Test
	void aFailureAfterTheFilesAreOpenLeavesNoFileBehind() throws IOException {
		final Path a = dir.resolve("a.csv"), b = dir.resolve("b.xml");
		final IOException e = assertThrows(IOException.class, () -> AtomicFile.writeAll(List.of(a, b), List.of(
			out -> out.write(new byte[100_000]), out -> {
				out.write(new byte[1000]);
				throw new IOException("disk full");
			})));
		assertEquals("disk full", e.getMessage());
		assertEquals(List.of(), names(), "no target and no temporary file may remain");
	}

	/** A failed write leaves an existing file as it was. */
	@Test
	void aFailedWriteKeepsTheOldFile() throws IOException {
		final Path a = dir.resolve("a.csv");
		Files.writeString(a, "old");
		assertThrows(IOException.class, () -> AtomicFile.write(a, out -> {
			out.write("new, half".getBytes(StandardCharsets.UTF_8));
			throw new IOException("interrupted");
		}));
		assertEquals("old", Files.readString(a));
		assertEquals(List.of("a.csv"), names());
	}

	@Test
	void checkFolderNamesTheMissingFolder() {
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> AtomicFile.checkFolder("csv",
			dir.resolve("nope/a.csv")));
		assertTrue(e.getMessage().startsWith("cannot write csv ") && e.getMessage().endsWith("nope does not exist"), e
			.getMessage());
		AtomicFile.checkFolder("csv", dir.resolve("fine.csv"));
		assertFalse(Files.exists(dir.resolve("fine.csv")), "a check writes nothing");
	}
}
