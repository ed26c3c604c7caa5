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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.scijava.plugin.SciJavaPlugin;

import fiji.plugin.trackmate.detection.SpotGlobalDetectorFactory;
import fiji.plugin.trackmate.features.spot.SpotAnalyzerFactory;

/**
 * Pins the compile-only TrackMate mirror (src/trackmate-mirror) to the RELEASED API. The expected shapes are in
 * {@code released-api.txt}, recorded with {@link ApiSignatures} from the jars built from the release tags it
 * names; the mirror is read by reflection in the same format. For every mirrored class:
 * <ul>
 * <li>its kind, type parameters and generic supertypes equal the release's;</li>
 * <li>every public or protected member it declares exists in the release with the same erased signature and the
 * same abstract / default / static / concrete status (a difference links here and fails inside Fiji with
 * NoSuchMethodError, AbstractMethodError or IncompatibleClassChangeError);</li>
 * <li>every abstract method of the release is in the mirror, so the compiler makes us implement it.</li>
 * </ul>
 * Every class under src/trackmate-mirror is checked, so a new mirror class cannot escape.
 */
class MirrorContractTest {

	private static final Path MIRROR = Path.of(System.getProperty("basedir", ".")).resolve("src/trackmate-mirror/java");

	private static List<String> released() throws IOException {
		try (InputStream in = MirrorContractTest.class.getResourceAsStream("released-api.txt")) {
			assertTrue(in != null, "released-api.txt missing");
			return new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().filter(l -> !l.isBlank() && !l
				.startsWith("#")).collect(Collectors.toList());
		}
	}

	private static List<String> mirroredClassNames() throws IOException {
		try (Stream<Path> files = Files.walk(MIRROR)) {
			return files.filter(p -> p.toString().endsWith(".java")).map(p -> MIRROR.relativize(p).toString().replace(
				'\\', '/').replace(".java", "").replace('/', '.')).sorted().collect(Collectors.toList());
		}
	}

	/**
	 * Where the mirror's type line may differ from the release's, and why that cannot break linkage. Nothing else
	 * may differ.
	 */
	private static final java.util.Map<String, String> KNOWN_TYPE_DIFFERENCES = java.util.Map.of("net.imagej.ImgPlus",
		"the real ImgPlus extends AbstractCalibratedRealInterval and implements ImgPlusMetadata (imagej-common types we "
			+ "do not mirror); we only construct it in tests and call its methods with invokevirtual, which resolves "
			+ "through whatever hierarchy the real class has");

	/**
	 * Lines about class {@code name} itself (not its nested classes). For a concrete class "default" and "concrete"
	 * are one status: callers link to either alike, and nobody implements a concrete class's methods.
	 */
	private static List<String> linesOf(final List<String> lines, final String name) {
		final List<String> of = lines.stream().filter(l -> l.startsWith("type " + name + " ") || l.startsWith("ctor " +
			name + "(") || l.startsWith("method " + name + ".") || l.startsWith("field " + name + ".")).collect(
				Collectors.toList());
		if (!of.isEmpty() && (of.get(0).contains(" class ") && !of.get(0).contains(" abstract class ")))
			of.replaceAll(l -> l.endsWith(" default") ? l.substring(0, l.length() - "default".length()) + "concrete" : l);
		return of;
	}

	@Test
	void everyMirroredClassHasTheReleasedShape() throws Exception {
		final List<String> released = released();
		final List<String> names = mirroredClassNames();
		assertTrue(names.size() >= 20, "mirror classes not found under " + MIRROR + ": " + names);
		final List<String> problems = new ArrayList<>();
		final Set<String> checked = new LinkedHashSet<>();
		for (final String top : names) {
			final List<String> mirrorLines = ApiSignatures.describe(Class.forName(top));
			final Set<String> classes = mirrorLines.stream().filter(l -> l.startsWith("type ")).map(l -> l.split(" ")[1])
				.collect(Collectors.toCollection(LinkedHashSet::new));
			for (final String name : classes) {
				checked.add(name);
				final List<String> mine = linesOf(mirrorLines, name);
				final List<String> theirs = linesOf(released, name);
				if (theirs.isEmpty()) {
					problems.add(name + ": not in the released API record");
					continue;
				}
				if (!mine.get(0).equals(theirs.get(0)) && !KNOWN_TYPE_DIFFERENCES.containsKey(name)) problems.add("kind/supertypes differ:\n  mirror:   " + mine.get(0) +
					"\n  released: " + theirs.get(0));
				final Set<String> releasedSet = new HashSet<>(theirs);
				for (final String line : mine.subList(1, mine.size()))
					if (!releasedSet.contains(line)) problems.add("not in the release: " + line);
				final Set<String> mineSet = new HashSet<>(mine);
				for (final String line : theirs)
					if (line.endsWith(" abstract") && !mineSet.contains(line)) problems.add("abstract in the release, " +
						"missing from the mirror: " + line);
			}
		}
		assertEquals(List.of(), problems, "mirror drifted from the release; checked " + checked);
	}

	/** The record itself must be what it says: the released Spot is a class, and SpotBase does not exist. */
	@Test
	void releasedRecordIsOfTheRelease() throws IOException {
		final List<String> released = released();
		assertTrue(released.contains("type fiji.plugin.trackmate.Spot class extends net.imglib2.AbstractEuclideanSpace " +
			"implements java.lang.Comparable<fiji.plugin.trackmate.Spot>, net.imglib2.RealLocalizable"), "Spot's line");
		assertTrue(released.contains("ctor fiji.plugin.trackmate.Spot(double,double,double,double,double)"));
		assertFalse(released.stream().anyMatch(l -> l.contains("SpotBase")), "SpotBase is not released");
		assertThrowsClassNotFound("fiji.plugin.trackmate.SpotBase");
	}

	private static void assertThrowsClassNotFound(final String name) {
		try {
			Class.forName(name);
			throw new AssertionError(name + " must not be mirrored: it exists only on unreleased TrackMate branches");
		}
		catch (final ClassNotFoundException expected) {
			// fine
		}
	}

	/**
	 * Our factory and feature declarer implement every method of TrackMate's interfaces but {@code copy()}, so they
	 * link whether a release declares one abstract or default.
	 */
	@Test
	void ourPluginsImplementEveryInterfaceMethodExceptCopy() {
		for (final Class<?>[] pair : new Class<?>[][] { { ContactTrackerDetectorFactory.class,
			SpotGlobalDetectorFactory.class }, { ContactTrackerSpotFeatures.class, SpotAnalyzerFactory.class } })
		{
			final Class<?> ours = pair[0];
			assertTrue(pair[1].isAssignableFrom(ours));
			final List<String> missing = new ArrayList<>();
			final Set<Class<?>> seen = new HashSet<>();
			final List<Class<?>> todo = new ArrayList<>(List.of(pair[1]));
			while (!todo.isEmpty()) {
				final Class<?> i = todo.remove(0);
				if (!seen.add(i) || i == SciJavaPlugin.class) continue;
				todo.addAll(List.of(i.getInterfaces()));
				for (final Method m : i.getDeclaredMethods()) {
					if (m.isSynthetic() || Modifier.isStatic(m.getModifiers()) || m.getName().equals("copy")) continue;
					try {
						ours.getDeclaredMethod(m.getName(), m.getParameterTypes());
					}
					catch (final NoSuchMethodException e) {
						missing.add(i.getSimpleName() + "." + m.getName());
					}
				}
			}
			assertEquals(List.of(), missing, "not implemented by " + ours.getSimpleName());
			assertTrue(Modifier.isPublic(ours.getModifiers()));
		}
	}
}
