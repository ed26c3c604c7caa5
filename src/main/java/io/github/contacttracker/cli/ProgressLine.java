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

import java.io.PrintStream;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * Progress of a long run on one line of standard error, rewritten in place ({@code \r}): frames done, frames per
 * second and the time left, at most twice a second. Standard output is never touched, so a CSV there stays intact.
 * Called from the worker threads.
 */
final class ProgressLine {

	private static final long EVERY_NS = 500_000_000L;

	private final PrintStream err;
	private final LongSupplier clock;
	private final long start;
	private long last;
	private int width;

	ProgressLine(final PrintStream err) {
		this(err, System::nanoTime);
	}

	/** @param clock nanoseconds (a test's own clock) */
	ProgressLine(final PrintStream err, final LongSupplier clock) {
		this.err = err;
		this.clock = clock;
		this.start = clock.getAsLong();
		this.last = start;
	}

	/** @param done frames finished, of {@code total} (all passes of the profile methods counted) */
	synchronized void progress(final int done, final int total) {
		final long now = clock.getAsLong();
		if (now - last < EVERY_NS && done < total) return;
		last = now;
		final double seconds = (now - start) * 1e-9, rate = done / Math.max(seconds, 1e-9);
		final String line = String.format(Locale.ROOT, "%d/%d frames, %.1f frames/s, %s left", done, total, rate,
			duration((total - done) / Math.max(rate, 1e-9)));
		// pad over a longer previous line
		err.print("\r" + line + " ".repeat(Math.max(0, width - line.length())));
		err.flush();
		width = line.length();
	}

	/** Ends the line (if one was drawn), so that what follows starts on a fresh one. */
	synchronized void end() {
		if (width > 0) err.println();
		width = 0;
	}

	/** @return "42 s", "3 min 05 s", "2 h 07 min" */
	static String duration(final double seconds) {
		final long s = Math.round(seconds);
		if (s < 60) return s + " s";
		if (s < 3600) return String.format(Locale.ROOT, "%d min %02d s", s / 60, s % 60);
		return String.format(Locale.ROOT, "%d h %02d min", s / 3600, s % 3600 / 60);
	}
}
