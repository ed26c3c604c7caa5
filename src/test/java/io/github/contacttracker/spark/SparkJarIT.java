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
package io.github.contacttracker.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarFile;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;

import org.junit.jupiter.api.Test;

/**
 * The PACKAGED jars (failsafe, after {@code package}): the Fiji plugin jar and the {@code -cli.jar} hold nothing of
 * Spark (neither Spark's, Scala's or Hadoop's classes nor our Spark job), so nothing of Spark loads in Fiji; the
 * {@code -spark.jar} holds the job and our dependencies, and leaves Spark to the cluster.
 */
class SparkJarIT {

	/** Whose classes the cluster provides: never in our jars. */
	static final List<String> PROVIDED = List.of("org/apache/spark/", "scala/", "org/apache/hadoop/",
		"org/apache/parquet/");

	static Path jar(final String classifier) throws IOException {
		final Path target = Path.of(System.getProperty("basedir", ".")).resolve("target");
		try (Stream<Path> files = Files.list(target)) {
			final List<Path> jars = files.filter(p -> {
				final String n = p.getFileName().toString();
				return n.startsWith("Contact_Tracker-") && (classifier.isEmpty() ? !n.matches(".*-(sources|tests|" +
					"test-sources|javadoc|cli|spark|lab)\\.jar") : n.endsWith("-" + classifier + ".jar")) && n.endsWith(".jar");
			}).toList();
			assertEquals(1, jars.size(), classifier + " jar in " + target + ": " + jars);
			return jars.get(0);
		}
	}

	private static List<String> entries(final Path jar, final List<String> prefixes) throws IOException {
		final List<String> found = new ArrayList<>();
		try (JarFile zip = new JarFile(jar.toFile())) {
			zip.stream().map(ZipEntry::getName).filter(n -> prefixes.stream().anyMatch(n::startsWith)).forEach(
				found::add);
		}
		return found;
	}

	@Test
	void pluginAndCommandLineJarsHoldNothingOfSpark() throws IOException {
		final List<String> banned = new ArrayList<>(PROVIDED);
		banned.add("io/github/contacttracker/spark/");
		for (final String classifier : List.of("", "cli")) {
			final Path jar = jar(classifier);
			assertEquals(List.of(), entries(jar, banned), jar.toString());
			// the command line is in both (a sanity check that the right jars were read)
			assertTrue(!entries(jar, List.of("io/github/contacttracker/cli/TrackCommand.class")).isEmpty(), jar
				.toString());
		}
	}

	@Test
	void sparkJarHoldsTheJobAndOurDependenciesButNotSpark() throws IOException {
		final Path jar = jar("spark");
		assertEquals(List.of(), entries(jar, PROVIDED), jar.toString());
		assertEquals(List.of(), entries(jar, List.of("fiji/plugin/trackmate/")), "the TrackMate mirror leaked");
		for (final String needed : List.of("io/github/contacttracker/spark/SparkTrack.class",
			"io/github/contacttracker/pipeline/TrackingPipeline.class", "net/imglib2/RandomAccessibleInterval.class",
			"ij/ImagePlus.class"))
			assertEquals(List.of(needed), entries(jar, List.of(needed)), needed + " in " + jar);
		try (JarFile zip = new JarFile(jar.toFile())) {
			assertNotNull(zip.getManifest());
			assertEquals("io.github.contacttracker.spark.SparkTrack", zip.getManifest().getMainAttributes().getValue("Main-Class"));
		}
	}
}
