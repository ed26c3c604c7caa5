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
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.script.ScriptEngine;
import javax.script.ScriptEngineManager;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.Context;
import org.scijava.module.Module;
import org.scijava.script.ScriptService;

import ij.ImagePlus;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.SpotCsvWriter;

/**
 * The batch scripts of {@code scripts/}. The Groovy one runs headless through SciJava's script service, as
 * {@code ImageJ --headless --run} does; it needs a Groovy script engine on the test class path
 * ({@code org.apache.groovy:groovy-jsr223}, test scope) and is skipped without one. The macro's parsing and
 * argument handling are tested here, in plain ImageJ's macro interpreter; {@link MacroTest} runs it on images
 * through a stand-in for Fiji's bridge.
 */
class BatchScriptsTest extends WithContext {

	/** @return what the macro printed (headless, ImageJ prints to standard output) */
	private static String runMacro(final String argument) throws Exception {
		final String code = Files.readString(Path.of(System.getProperty("basedir", ".")).resolve(
			"scripts/contact-tracker-batch.ijm"));
		return MacroTest.macro(code, argument);
	}

	@Test
	void macroParsesItsArgumentsAndSkipsWhatIsNotATiff(@TempDir final Path dir) throws Exception {
		final Path in = Files.createDirectories(dir.resolve("in folder")), out = Files.createDirectories(dir.resolve(
			"out"));
		Files.writeString(in.resolve("notes.txt"), "not an image");
		final String printed = runMacro("input=[" + in + "] output=[" + out + "] threshold=110 r_out=55");
		assertTrue(printed.contains("Contact Tracker batch: 0 image(s) done, 0 failed"), printed);
		final String missing = runMacro("input=[" + dir.resolve("nowhere") + "] output=[" + out + "]");
		assertTrue(missing.contains("Contact Tracker batch: input folder not found"), missing);
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	@Test
	void groovyBatchWritesOneCsvPerTiff(@TempDir final Path dir) throws Exception {
		final ScriptService scripts = context.service(ScriptService.class);
		if (scripts.getLanguageByExtension("groovy") == null) {
			// Fiji has SciJava's Groovy language plugin; here, adapt the plain javax.script engine (the #@ lines are
			// parsed and stripped by SciJava either way)
			final ScriptEngine groovy = new ScriptEngineManager().getEngineByExtension("groovy");
			assumeTrue(groovy != null, "no Groovy script engine (org.apache.groovy:groovy-jsr223) on the class path");
			scripts.getIndex().add(groovy.getFactory(), false);
		}
		final Path script = Path.of(System.getProperty("basedir", ".")).resolve("scripts/contact-tracker-batch.groovy");
		final Path in = Files.createDirectories(dir.resolve("in")), out = Files.createDirectories(dir.resolve("out"));
		final ImagePlus movie = Simulated.image();
		ImageFiles.saveTiff(movie, in.resolve("movie.tif"));
		ImageFiles.saveTiff(Simulated.zAndT("volume"), in.resolve("volume.tiff"));
		Files.writeString(in.resolve("notes.txt"), "not an image");
		Files.write(in.resolve("truncated.tif"), java.util.Arrays.copyOf(Files.readAllBytes(in.resolve("movie.tif")),
			600)); // a broken file: named in the log, the others done

		final double threshold = Simulated.TYPE.threshold(), rOut = Simulated.TYPE.rOut();
		final Module m = scripts.run(script.toFile(), true, "input", in.toFile(), "output", out.toFile(), "threshold",
			threshold, "r_out", rOut, "min_area", 20, "method", "paper", "channel", 1, "trackmate", true).get();
		assertEquals(1, m.getOutput("done"));
		assertEquals(2, m.getOutput("failed"), "the Z and T stack and the truncated file are refused");

		// the CSV is the command line's for the same image and parameters
		final ImagePlus reopened = ImageFiles.open(in.resolve("movie.tif"));
		final ImagePlusFrames frames = ImagePlusFrames.of(reopened, 0);
		final TrackerParameters params = new TrackerParameters(threshold, rOut, 20, Connectivity.EIGHT,
			TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.PAPER);
		final StringWriter expected = new StringWriter();
		SpotCsvWriter.write(expected, StackTracker.spots(new StackTracker(params).track((List) frames.frames(),
			false)), frames.calibration());
		assertEquals(expected.toString(), Files.readString(out.resolve("movie.csv")));
		assertTrue(Files.isRegularFile(out.resolve("movie.xml")), "TrackMate XML on request");
		assertFalse(Files.exists(out.resolve("volume.csv")));
		assertFalse(Files.exists(out.resolve("notes.csv")));
	}
}
