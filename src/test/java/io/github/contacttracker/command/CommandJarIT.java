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
package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

import org.junit.jupiter.api.Test;
import org.scijava.annotations.Index;
import org.scijava.annotations.IndexItem;
import org.scijava.command.Command;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.Plugin;

/**
 * Integration test on the PACKAGED plugin jar (failsafe, after {@code package}): its SciJava plugin index lists
 * both commands with their menu paths, as Fiji reads it, and the macro-options check as a preprocessor.
 */
class CommandJarIT {

	private static final String INDEX = "META-INF/json/org.scijava.plugin.Plugin";

	private static Path pluginJar() throws IOException {
		final Path target = Path.of(System.getProperty("basedir", ".")).resolve("target");
		final List<Path> jars = new ArrayList<>();
		try (Stream<Path> files = Files.list(target)) {
			files.filter(p -> {
				final String n = p.getFileName().toString();
				return n.endsWith(".jar") && !n.startsWith("original-") && !n.matches(
					".*-(sources|tests|test-sources|javadoc|cli|spark|lab)\\.jar");
			}).forEach(jars::add);
		}
		assertEquals(1, jars.size(), "expected exactly one plugin jar in " + target + ": " + jars);
		return jars.get(0);
	}

	/**
	 * The plugin jar carries none of the lab (simulator, studies, research subcommands): Fiji users install only what
	 * tracks their movies. The lab's jar holds it, with its entry point, and names the command line's jar it runs on.
	 */
	@Test
	void pluginJarCarriesNoLabAndTheLabJarRunsBesideTheCommandLine() throws Exception {
		final Path jar = pluginJar();
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			final List<String> lab = zip.stream().map(ZipEntry::getName).filter(n -> n.startsWith(
				"io/github/contacttracker/lab/")).toList();
			assertEquals(List.of(), lab, "the lab in " + jar);
			assertNotNull(zip.getEntry("io/github/contacttracker/cli/ContactTrackerCli.class"));
		}
		final String name = jar.getFileName().toString();
		final Path labJar = jar.resolveSibling(name.substring(0, name.length() - 4) + "-lab.jar");
		try (ZipFile zip = new ZipFile(labJar.toFile())) {
			assertNotNull(zip.getEntry("io/github/contacttracker/lab/cli/ContactTrackerLab.class"));
			assertNotNull(zip.getEntry("io/github/contacttracker/lab/sim/ImageSimulator.class"));
			assertEquals(List.of(), zip.stream().map(ZipEntry::getName).filter(n -> n.endsWith(".class") && !n
				.startsWith("io/github/contacttracker/lab/")).toList(), "only the lab in " + labJar);
			final java.util.jar.Manifest m = new java.util.jar.Manifest(zip.getInputStream(zip.getEntry(
				"META-INF/MANIFEST.MF")));
			assertEquals("io.github.contacttracker.lab.cli.ContactTrackerLab", m.getMainAttributes().getValue(
				"Main-Class"));
			assertEquals(name.substring(0, name.length() - 4) + "-cli.jar", m.getMainAttributes().getValue("Class-Path"));
		}
	}

	@Test
	void pluginIndexListsBothCommandsWithTheirMenuPaths() throws Exception {
		// failsafe tests the packaged jar: our classes come from it (surefire, e.g. with -Dtest, has target/classes)
		final Path loadedFrom = Path.of(ContactTrackerCommand.class.getProtectionDomain().getCodeSource().getLocation()
			.toURI());
		assumeTrue(loadedFrom.getFileName().toString().endsWith(".jar"), "not run on the packaged jar (mvn verify)");
		final Path jar = pluginJar();
		assertEquals(jar.toRealPath(), loadedFrom.toRealPath(), "the classes under test are the jar's");
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			final ZipEntry index = zip.getEntry(INDEX);
			assertNotNull(index, jar + " has no " + INDEX);
			for (final String cls : List.of(ContactTrackerCommand.class, ContactTrackerProfileCommand.class,
				ContactTrackerPotentialCommand.class).stream().map(Class::getName).toList())
				assertNotNull(zip.getEntry(cls.replace('.', '/') + ".class"), cls + " is not in the jar");
		}
		// read the index the way SciJava does, from the jar alone: resources come only from the jar (no parent), the
		// classes the annotations name (Command, PreprocessorPlugin) from the test class path
		final ClassLoader classes = CommandJarIT.class.getClassLoader();
		final Map<String, Plugin> plugins = new HashMap<>();
		try (URLClassLoader jarOnly = new URLClassLoader(new URL[] { jar.toUri().toURL() }, null) {
			@Override
			protected Class<?> findClass(final String name) throws ClassNotFoundException {
				return classes.loadClass(name);
			}
		})
		{
			for (final IndexItem<Plugin> item : Index.load(Plugin.class, jarOnly))
				plugins.put(item.className(), item.annotation());
		}
		final Plugin tracker = plugins.get(ContactTrackerCommand.class.getName());
		final Plugin profile = plugins.get(ContactTrackerProfileCommand.class.getName());
		assertNotNull(tracker, "index: " + plugins.keySet());
		assertNotNull(profile, "index: " + plugins.keySet());
		// no pre- or postprocessor: they would run for every command Fiji executes (read as text: the index also
		// names TrackMate's plugin types, which are not on this class path)
		try (ZipFile zip = new ZipFile(jar.toFile())) {
			final String index = new String(zip.getInputStream(zip.getEntry(INDEX)).readAllBytes(),
				java.nio.charset.StandardCharsets.UTF_8);
			assertTrue(index.contains(Command.class.getName()), index);
			for (final String type : List.of(PreprocessorPlugin.class.getName(),
				org.scijava.module.process.PostprocessorPlugin.class.getName()))
				assertFalse(index.contains(type), type + " in the plugin index: it would run for every command");
		}
		assertEquals("Plugins>Tracking>Contact Tracker", tracker.menuPath());
		assertEquals(Command.class, tracker.type());
		assertTrue(tracker.headless());
		assertEquals("Plugins>Tracking>Contact Tracker Profile", profile.menuPath());
		assertEquals(Command.class, profile.type());
		assertTrue(profile.headless());
	}
}
