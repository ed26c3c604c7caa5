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

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Integration test on the PACKAGED command-line jar (failsafe): {@code --version} prints the version number the jar
 * was built with (the one in its file name), not only the name.
 */
class VersionIT {

	@Test
	void versionPrintsTheJarsVersion() throws IOException, InterruptedException {
		final Path jar;
		try (Stream<Path> files = Files.list(Path.of(System.getProperty("basedir", ".")).resolve("target"))) {
			jar = files.filter(p -> p.getFileName().toString().endsWith("-cli.jar")).findFirst().orElseThrow();
		}
		final String name = jar.getFileName().toString(); // Contact_Tracker-0.1.0-SNAPSHOT-cli.jar
		final String version = name.substring("Contact_Tracker-".length(), name.length() - "-cli.jar".length());
		final Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
			.toString(), "-Djava.awt.headless=true", "-jar", jar.toString(), "--version")).redirectErrorStream(true)
				.start();
		final String output = new String(p.getInputStream().readAllBytes());
		p.waitFor(60, TimeUnit.SECONDS);
		assertEquals(0, p.exitValue(), output);
		assertEquals("Contact Tracker " + version, output.strip());
	}
}
