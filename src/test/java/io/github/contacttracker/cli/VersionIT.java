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
