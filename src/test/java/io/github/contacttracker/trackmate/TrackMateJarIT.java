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

import io.github.contacttracker.settings.TrackMateSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

import org.jdom2.Document;
import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.TrackMateXmlWriter;
import io.github.contacttracker.settings.SettingsOf;

/**
 * Integration test on the PACKAGED jar (failsafe, phase {@code integration-test}, after {@code package}): the
 * TrackMate mirror must not ship, and the SciJava plugin index must list the detector factory under the type
 * TrackMate's DetectorProvider asks for ({@code fiji.plugin.trackmate.detection.SpotDetectorFactoryBase}) and the
 * spot features under {@code fiji.plugin.trackmate.features.spot.SpotAnalyzerFactory}.
 * <p>
 * Failsafe puts the built jar, not {@code target/classes}, on the class path, so this test also shows that the
 * TrackMate-free parts (XML writer, detector settings) run without any TrackMate class. It must therefore not
 * refer to a TrackMate or mirror type itself.
 */
class TrackMateJarIT {

	private static final List<String> FORBIDDEN = List.of("fiji/plugin/trackmate/", "net/imagej/",
		"net/imglib2/algorithm/");
	private static final String FACTORY = "io.github.contacttracker.trackmate.ContactTrackerDetectorFactory";
	private static final String FEATURES = "io.github.contacttracker.trackmate.ContactTrackerSpotFeatures";
	private static final String INDEX = "META-INF/json/org.scijava.plugin.Plugin";

	private static Path target() {
		return Path.of(System.getProperty("basedir", ".")).resolve("target");
	}

	/** @return the plain jar (no classifier) */
	private static Path pluginJar() throws IOException {
		final List<Path> jars = new ArrayList<>();
		try (Stream<Path> files = Files.list(target())) {
			files.filter(p -> {
				final String n = p.getFileName().toString();
				return n.endsWith(".jar") && !n.startsWith("original-") && !n.matches(".*-(sources|tests|test-sources|javadoc|cli|spark|lab)\\.jar");
			}).forEach(jars::add);
		}
		assertEquals(1, jars.size(), "expected exactly one plugin jar in " + target() + ": " + jars);
		return jars.get(0);
	}

	private static List<String> forbiddenEntries(final Path jar) throws IOException {
		final List<String> bad = new ArrayList<>();
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			for (final ZipEntry e : Collections.list(zip.entries()))
				for (final String f : FORBIDDEN)
					if (e.getName().startsWith(f)) bad.add(e.getName());
		}
		return bad;
	}

	@Test
	void pluginJarShipsNoMirrorAndOnlyOurClasses() throws IOException {
		final Path jar = pluginJar();
		assertEquals(List.of(), forbiddenEntries(jar), "the TrackMate mirror leaked into " + jar);
		final List<String> foreign = new ArrayList<>();
		int ours = 0;
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			for (final ZipEntry e : Collections.list(zip.entries()))
				if (e.getName().endsWith(".class")) {
					if (e.getName().startsWith("io/github/contacttracker/")) ours++;
					else foreign.add(e.getName());
				}
			for (final String c : List.of(FACTORY, "io.github.contacttracker.trackmate.ContactTrackerDetector",
				"io.github.contacttracker.trackmate.ContactTrackerConfigurationPanel",
				"io.github.contacttracker.settings.TrackMateSettings"))
				assertNotNull(zip.getEntry(c.replace('.', '/') + ".class"), c + " missing from " + jar);
		}
		assertTrue(ours > 10, "too few classes in " + jar);
		assertEquals(List.of(), foreign, "classes outside io/github/contacttracker in " + jar);
	}

	@Test
	void pluginIndexListsTheFactoryAndTheSpotFeaturesUnderTrackMatesTypes() throws IOException {
		final Path jar = pluginJar();
		final String index;
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			final ZipEntry e = zip.getEntry(INDEX);
			assertNotNull(e, INDEX + " missing from " + jar);
			try (InputStream in = zip.getInputStream(e)) {
				index = new String(in.readAllBytes(), StandardCharsets.UTF_8);
			}
		}
		// the index is a run of JSON objects {"class":"..","values":{"type":"..",...}}
		final Matcher m = Pattern.compile("\\{\"class\":\"([^\"]+)\",\"values\":\\{([^{}]*)\\}\\}").matcher(index);
		final java.util.Map<String, String> types = new java.util.HashMap<>();
		int entries = 0;
		while (m.find()) {
			entries++;
			final Matcher t = Pattern.compile("\"type\":\"([^\"]+)\"").matcher(m.group(2));
			assertTrue(t.find(), "no type in " + m.group());
			types.put(m.group(1), t.group(1));
		}
		assertTrue(entries > 0, "unreadable plugin index: " + index);
		assertEquals("fiji.plugin.trackmate.detection.SpotDetectorFactoryBase", types.get(FACTORY), "factory entry in " + index);
		assertEquals("fiji.plugin.trackmate.features.spot.SpotAnalyzerFactory", types.get(FEATURES), "features entry in " + index);
	}

	@Test
	void commandLineJarShipsNoMirrorEither() throws IOException {
		try (Stream<Path> files = Files.list(target())) {
			for (final Path cli : (Iterable<Path>) files.filter(p -> p.getFileName().toString().endsWith("-cli.jar"))::iterator)
				assertEquals(List.of(), forbiddenEntries(cli), "the TrackMate mirror leaked into " + cli);
		}
	}

	/** On the jar's class path there is no TrackMate, yet the XML writer and the settings work. */
	@Test
	void xmlWriterRunsWithoutTrackMate() {
		assertThrows(ClassNotFoundException.class, () -> Class.forName("fiji.plugin.trackmate.Spot"),
			"the mirror is on the integration-test class path: is the test running against target/classes?");
		final Document doc = TrackMateXmlWriter.document(
			List.of(new Localization(0, 3, 4, 3, 4, 30, 30, 100, 3.1, 0, 1, 0.01, 0.01, Double.NaN, Double.NaN,
				0)), Calibration.PIXELS,
			new ImageSource("a.tif", "", 16, 16, 1, 1), SettingsOf.values(TrackerParameters.of(50, 8), 1));
		assertEquals(TrackMateSettings.DETECTOR_KEY, doc.getRootElement().getChild("Settings").getChild("DetectorSettings")
			.getAttributeValue("DETECTOR_NAME"));
		assertFalse(TrackMateSettings.defaults().isEmpty());
	}
}
