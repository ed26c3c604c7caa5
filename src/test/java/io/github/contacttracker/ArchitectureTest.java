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
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The house (src/site/markdown/contributing.md, "The house"): each package uses only the packages below it, so there is no cycle and
 * the front ends never import each other. Read from the sources' references to our packages.
 */
class ArchitectureTest {

	/** Which of our packages each package may use. */
	private static final Map<String, Set<String>> ALLOWED = Map.ofEntries( //
		Map.entry("core", Set.of()), //
		Map.entry("sim", Set.of("core")), //
		Map.entry("potential", Set.of("core")), //
		Map.entry("settings", Set.of("core")), //
		Map.entry("io", Set.of("core", "settings", "potential")), //
		Map.entry("eval", Set.of("core", "sim", "potential")), //
		Map.entry("pipeline", Set.of("core", "io", "settings")), //
		Map.entry("cli", Set.of("core", "sim", "potential", "settings", "io", "eval", "pipeline")), //
		Map.entry("command", Set.of("core", "sim", "potential", "settings", "io", "eval", "pipeline")), //
		Map.entry("trackmate", Set.of("core", "settings", "io", "pipeline")), //
		Map.entry("spark", Set.of("core", "potential", "settings", "io", "pipeline")));

	private static final Pattern REFERENCE = Pattern.compile("io\\.github\\.contacttracker\\.([a-z]+)\\.");

	@Test
	void everyPackageUsesOnlyThePackagesBelowIt() throws IOException {
		final Path root = Path.of(System.getProperty("basedir", ".")).resolve("src/main/java/io/github/contacttracker");
		final List<String> violations = new ArrayList<>();
		final Set<String> seen = new TreeSet<>();
		try (Stream<Path> files = Files.walk(root)) {
			for (final Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
				final String pkg = root.relativize(f).getName(0).toString();
				seen.add(pkg);
				final Set<String> allowed = ALLOWED.get(pkg);
				if (allowed == null) {
					violations.add(pkg + ": a package the house does not know (add it to ALLOWED and to contributing.md)");
					continue;
				}
				final Matcher m = REFERENCE.matcher(Files.readString(f));
				while (m.find()) {
					final String used = m.group(1);
					if (!used.equals(pkg) && !allowed.contains(used)) violations.add(root.relativize(f) + " uses " + used);
				}
			}
		}
		assertEquals(ALLOWED.keySet(), seen, "packages");
		assertTrue(violations.isEmpty(), String.join("\n", violations));
	}
}
