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
package io.github.contacttracker.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;

/**
 * What every reader promises for any file, however broken or hostile: {@link ImageFiles#open} and the reading of
 * every frame either succeed, or end in {@link IOException} / {@link InvalidInputException} with one line that
 * names the file; nothing else is thrown (no out-of-memory, no stray runtime exception) and ImageJ prints nothing
 * of its own. Shared by the mutation suite and the fuzz test.
 */
final class ReaderContract {

	private ReaderContract() {}

	/** What {@link #check} saw. */
	enum Outcome {
		/** every frame was read */
		READ,
		/** refused with one line naming the file */
		REFUSED
	}

	/**
	 * Opens {@code file} and reads all its frames (at most {@code maxFrames}), asserting the contract.
	 *
	 * @return whether it was read or refused
	 */
	static Outcome check(final Path file, final int maxFrames) {
		final PrintStream out = System.out, err = System.err;
		final ByteArrayOutputStream printed = new ByteArrayOutputStream();
		final PrintStream capture = new PrintStream(printed, true, StandardCharsets.UTF_8);
		System.setOut(capture);
		System.setErr(capture);
		Outcome outcome;
		String message = null;
		try {
			final ImagePlus imp = ImageFiles.open(file);
			final ImagePlusFrames frames = ImagePlusFrames.of(imp, 1);
			for (int t = 0; t < Math.min(maxFrames, frames.frameCount()); t++)
				frames.frameRange(t);
			outcome = Outcome.READ;
		}
		catch (final IOException | InvalidInputException | UncheckedIOException e) {
			outcome = Outcome.REFUSED;
			message = e.getMessage();
		}
		catch (final OutOfMemoryError e) {
			throw new AssertionError(file + ": out of memory instead of a refusal", e);
		}
		catch (final RuntimeException e) {
			throw new AssertionError(file + ": " + e + " instead of a one-line refusal", e);
		}
		finally {
			System.setOut(out);
			System.setErr(err);
		}
		// (fuzzing, Jazzer reports on the classes it instruments as they load, "INFO: ..." and "WARN: ..." with
		// indented continuation lines: not the readers' output)
		final String stray = printed.toString(StandardCharsets.UTF_8).lines().filter(l -> !l.startsWith("INFO: ") && !l
			.startsWith("WARN: ") && !l.startsWith("        ")).collect(java.util.stream.Collectors.joining("\n"));
		assertEquals("", stray, file + ": printed while reading");
		if (outcome == Outcome.REFUSED) {
			if (message == null) fail(file + ": refused without a message");
			assertFalse(message.contains("\n") || message.contains("\r"), "one line: " + message);
			// the file is named (by its path, or as the image's title); a bad pixel by its frame, which the front
			// ends put after the movie's name
			assertTrue(message.contains(file.getFileName().toString()) || message.startsWith("frame "),
				"names the file: " + message);
		}
		return outcome;
	}
}
