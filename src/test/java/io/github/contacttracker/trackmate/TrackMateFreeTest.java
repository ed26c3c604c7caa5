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
package io.github.contacttracker.trackmate;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;

/**
 * Only the TrackMate adapter (this package) may refer to TrackMate, ImageJ2 or
 * imglib2-algorithm types: the command line and the ImageJ 1 command run without them, and the mirror of those
 * types never ships. Checked on the compiled classes' constant pools.
 */
class TrackMateFreeTest {

	private static final List<String> FORBIDDEN = List.of("fiji/plugin/trackmate/", "net/imagej/",
		"net/imglib2/algorithm/");

	@Test
	void everythingButTheAdapterIsFreeOfTrackMateTypes() throws IOException, URISyntaxException {
		final Path root = Path.of(Localization.class.getProtectionDomain().getCodeSource().getLocation().toURI());
		assertTrue(Files.isDirectory(root), "expected compiled classes in a folder, not " + root);
		final Path adapter = root.resolve("io/github/contacttracker/trackmate");
		final List<String> offenders = new ArrayList<>();
		int checked = 0;
		try (Stream<Path> classes = Files.walk(root.resolve("io/github/contacttracker"))) {
			for (final Path p : (Iterable<Path>) classes.filter(f -> f.toString().endsWith(".class"))::iterator) {
				final boolean inAdapter = p.getParent().equals(adapter);
				if (inAdapter) continue;
				checked++;
				final String pool = new String(Files.readAllBytes(p), StandardCharsets.ISO_8859_1);
				for (final String f : FORBIDDEN)
					if (pool.contains(f)) offenders.add(root.relativize(p) + " refers to " + f);
			}
		}
		assertTrue(checked > 10, "too few classes checked: " + checked);
		assertTrue(offenders.isEmpty(), String.join("\n", offenders));
	}
}
