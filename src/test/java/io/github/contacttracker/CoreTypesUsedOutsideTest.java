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
package io.github.contacttracker;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The contributors' page lists which types of the core's inner rooms the packages outside the core use, and by
 * whom; this reads the same from the sources' references and holds the two equal, so the list cannot go stale.
 * {@code core} and {@code core.track} are the core's API and are not listed.
 */
class CoreTypesUsedOutsideTest {

	private static final Path SOURCES = Path.of(System.getProperty("basedir", ".")).resolve(
		"src/main/java/io/github/contacttracker");
	private static final Path PAGE = Path.of(System.getProperty("basedir", ".")).resolve(
		"src/site/markdown/contributing.md");

	/** A reference to a type of an inner room of the core ({@code core.image.Region}), or a wildcard of one. */
	private static final Pattern INNER = Pattern.compile(
		"io\\.github\\.contacttracker\\.(core\\.(?!track\\.)[a-z]+)\\.([A-Z]\\w*|\\*)");

	/** The table's header, which starts the rows read. */
	private static final String HEADER = "| type used outside the core |";

	/** A row: the type, then the packages using it, each in backticks. */
	private static final Pattern ROW = Pattern.compile("^\\| `([\\w.]+)` \\| ([^|]+) \\|");

	private static final Pattern QUOTED = Pattern.compile("`([\\w.]+)`");

	@Test
	void theContributorsTableIsWhatTheSourcesUse() throws IOException {
		assertEquals(fromSources(), fromPage(), "contributing.md's table of core types used outside the core " +
			"(type -> packages using it), against the sources' references");
	}

	/** @return each inner-room type referenced outside the core, with the packages (lab.* by room) that do */
	private static Map<String, Set<String>> fromSources() throws IOException {
		final Map<String, Set<String>> used = new TreeMap<>();
		final List<String> wildcards = new ArrayList<>();
		try (Stream<Path> files = Files.walk(SOURCES)) {
			for (final Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
				final String pkg = SOURCES.relativize(f.getParent()).toString().replace('/', '.').replace('\\', '.');
				if (pkg.equals("core") || pkg.startsWith("core.")) continue;
				final Matcher m = INNER.matcher(Files.readString(f));
				while (m.find()) {
					if (m.group(2).equals("*")) wildcards.add(SOURCES.relativize(f) + " imports " + m.group(1) + ".*");
					else used.computeIfAbsent(m.group(1) + "." + m.group(2), k -> new TreeSet<>()).add(pkg);
				}
			}
		}
		assertTrue(wildcards.isEmpty(), "name the core types used, so that the table can list them: " + wildcards);
		return used;
	}

	/** @return the page's table: each type with the packages it names */
	private static Map<String, Set<String>> fromPage() throws IOException {
		final List<String> lines = Files.readAllLines(PAGE);
		int i = 0;
		while (i < lines.size() && !lines.get(i).startsWith(HEADER))
			i++;
		assertTrue(i < lines.size(), "contributing.md has no table starting '" + HEADER + "'");
		final Map<String, Set<String>> listed = new TreeMap<>();
		for (i += 2; i < lines.size() && lines.get(i).startsWith("|"); i++) {
			final Matcher row = ROW.matcher(lines.get(i));
			assertTrue(row.find(), "not a row of type and packages: " + lines.get(i));
			final Set<String> by = new TreeSet<>();
			final Matcher q = QUOTED.matcher(row.group(2));
			while (q.find())
				by.add(q.group(1));
			listed.put(row.group(1), by);
		}
		return listed;
	}
}
