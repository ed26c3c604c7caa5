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
import java.util.HashSet;
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
 * the front ends never import each other; the lab ({@code lab.*}) stands on top, used by nothing outside it. The core is built of rooms ({@code core} and {@code core.*}) that stand in
 * the same kind of order, and holds no ImageJ, SciJava or Fiji type. Read from the sources' references to our packages.
 */
class ArchitectureTest {

	/** The core's rooms, bottom first; each uses only rooms to its left. The packages outside see the core as one. */
	private static final List<String> CORE = List.of("core", "core.math", "core.image", "core.profile", "core.radial",
		"core.kind", "core.fit", "core.detect", "core.track");

	/** Which of our packages each package may use ({@code core} standing for all of the core's rooms). */
	private static final Map<String, Set<String>> ALLOWED = Map.ofEntries( //
		Map.entry("core", Set.of()), //
		Map.entry("core.math", Set.of()), //
		Map.entry("core.image", Set.of("core", "core.math")), //
		Map.entry("core.profile", Set.of("core", "core.math", "core.image")), //
		Map.entry("core.radial", Set.of("core", "core.math", "core.image", "core.profile")), //
		Map.entry("core.kind", Set.of("core", "core.math", "core.image", "core.profile", "core.radial")), //
		Map.entry("core.fit", Set.of("core", "core.math", "core.image", "core.profile", "core.radial", "core.kind")), //
		Map.entry("core.detect", Set.of("core", "core.math", "core.image", "core.profile", "core.radial", "core.kind",
			"core.fit")), //
		Map.entry("core.track", Set.of("core", "core.math", "core.image", "core.profile", "core.radial", "core.kind",
			"core.fit", "core.detect")), //
		Map.entry("advisor", Set.of("core")), //
		Map.entry("potential", Set.of("core")), //
		Map.entry("settings", Set.of("core")), //
		// io reads and writes file formats: not the helper's words, nor the potential's tables and plots, nor ImageJ
		// glue (ioHoldsNoImageJGlue)
		Map.entry("io", Set.of("core", "settings")), //
		// ImageJ glue shared by front ends: an ImageJ image's frames as ImgLib2 planes, the image on display, frames
		// as an ImageJ time series
		Map.entry("ij", Set.of("core", "io")), //
		Map.entry("report", Set.of("core", "advisor", "potential", "io", "ij")), //
		Map.entry("plot", Set.of("core", "advisor", "potential", "io")), //
		Map.entry("ui", Set.of()), //
		Map.entry("pipeline", Set.of("core", "advisor", "io", "ij", "settings", "report")), //
		Map.entry("cli", Set.of("core", "advisor", "potential", "settings", "io", "ij", "report", "plot", "pipeline")), //
		Map.entry("command", Set.of("core", "advisor", "potential", "settings", "io", "ij", "report", "plot", "ui",
			"pipeline")), //
		Map.entry("trackmate", Set.of("core", "settings", "io", "report", "ui", "pipeline")), //
		Map.entry("spark", Set.of("core", "potential", "settings", "io", "ij", "report", "pipeline")), //
		// the lab: the simulator, the studies and the research subcommands; nothing outside it uses it
		Map.entry("lab.sim", Set.of("core")), //
		Map.entry("lab.eval", Set.of("core", "lab.sim", "potential")), //
		Map.entry("lab.cli", Set.of("core", "advisor", "potential", "settings", "io", "ij", "report", "plot",
			"pipeline", "cli", "lab.sim", "lab.eval")));

	/** A reference to a type of ours: the package (a core room with its name) followed by a type or a wildcard. */
	private static final Pattern REFERENCE = Pattern.compile(
		"io\\.github\\.contacttracker\\.((?:core\\.|lab\\.)?[a-z]+)\\.(?=[A-Z*])");

	/** ImageJ 1, ImageJ2/SciJava and Fiji packages: none of them in the core. */
	private static final Pattern FRONT_END_TYPE = Pattern.compile("(?<![\\w.])(ij|net\\.imagej|org\\.scijava|fiji)\\.[a-zA-Z]");

	@Test
	void everyPackageUsesOnlyThePackagesBelowIt() throws IOException {
		final Path root = Path.of(System.getProperty("basedir", ".")).resolve("src/main/java/io/github/contacttracker");
		final List<String> violations = new ArrayList<>();
		final Set<String> seen = new TreeSet<>();
		try (Stream<Path> files = Files.walk(root)) {
			for (final Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
				final String pkg = root.relativize(f.getParent()).toString().replace('/', '.').replace('\\', '.');
				seen.add(pkg);
				final Set<String> allowed = ALLOWED.get(pkg);
				if (allowed == null) {
					violations.add(pkg + ": a package the house does not know (add it to ALLOWED and to contributing.md)");
					continue;
				}
				final String text = Files.readString(f);
				final Matcher m = REFERENCE.matcher(text);
				while (m.find()) {
					final String used = m.group(1);
					final String seenAs = CORE.contains(pkg) || !CORE.contains(used) ? used : "core";
					if (!used.equals(pkg) && !allowed.contains(seenAs)) violations.add(root.relativize(f) + " uses " + used);
				}
				if (CORE.contains(pkg) && FRONT_END_TYPE.matcher(text).find())
					violations.add(root.relativize(f) + " uses an ImageJ, SciJava or Fiji type: the core is pure ImgLib2");
			}
		}
		assertEquals(ALLOWED.keySet(), seen, "packages");
		assertTrue(violations.isEmpty(), String.join("\n", violations));
	}

	/** ImageJ 1's types, named in an import or in full. */
	private static final Pattern IMAGEJ_TYPE = Pattern.compile("(?<![\\w.])ij\\.[a-zA-Z]");

	/** ImgLib2's types, named in an import or in full. */
	private static final Pattern IMGLIB2_TYPE = Pattern.compile("(?<![\\w.])net\\.imglib2\\.");

	/**
	 * {@code io} reads and writes files: where it uses ImageJ, it is to read a movie into an ImageJ image or to save
	 * one. Turning an ImageJ image into ImgLib2 frames or back is ImageJ glue that the front ends share, and stands
	 * in {@code ij} ({@code ImagePlusFrames}, {@code TimeSeries}), which uses {@code io}, never the other way round.
	 * So no file of {@code io} uses both ImageJ's and ImgLib2's types.
	 */
	@Test
	void ioHoldsNoImageJGlue() throws IOException {
		final Path io = Path.of(System.getProperty("basedir", ".")).resolve("src/main/java/io/github/contacttracker/io");
		final List<String> glue = new ArrayList<>();
		try (Stream<Path> files = Files.list(io)) {
			for (final Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java")).sorted()::iterator) {
				final String text = Files.readString(f);
				if (IMAGEJ_TYPE.matcher(text).find() && IMGLIB2_TYPE.matcher(text).find()) glue.add(f.getFileName()
					.toString());
			}
		}
		assertTrue(glue.isEmpty(), "ImageJ glue in io (ImageJ images as ImgLib2 frames, or back: it belongs in ij): " +
			glue);
	}

	/**
	 * The lab (simulator, studies, research subcommands) stays out of what users run: no front end, no pipeline, no
	 * package outside the lab may use it, so the Fiji plugin's jar can leave it out.
	 */
	@Test
	void nothingOutsideTheLabUsesIt() {
		for (final Map.Entry<String, Set<String>> e : ALLOWED.entrySet())
			if (!e.getKey().startsWith("lab.")) for (final String used : e.getValue())
				assertTrue(!used.startsWith("lab."), e.getKey() + " may use " + used);
	}

	/** The rules themselves have no cycle: following "may use" from any package never comes back to it. */
	@Test
	void theRulesHaveNoCycle() {
		for (final String start : ALLOWED.keySet()) {
			final Set<String> reached = new HashSet<>();
			final List<String> todo = new ArrayList<>(ALLOWED.get(start));
			while (!todo.isEmpty()) {
				final String p = todo.remove(todo.size() - 1);
				assertTrue(!p.equals(start), start + " reaches itself");
				if (reached.add(p)) todo.addAll(ALLOWED.get(p));
			}
		}
	}

	/** The core's rooms stand in the order {@link #CORE} lists: each may use only rooms listed before it. */
	@Test
	void coreRoomsStandInOrder() {
		for (int i = 0; i < CORE.size(); i++)
			for (final String used : ALLOWED.get(CORE.get(i)))
				assertTrue(CORE.indexOf(used) >= 0 && CORE.indexOf(used) < i, CORE.get(i) + " may use " + used);
	}
}
