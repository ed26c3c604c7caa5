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

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.ProjectVersion;

/**
 * A command's results as a markdown page ({@code --report FILE} of {@code accuracy} and {@code bench}), stamped with
 * the command that made it, the project's version, the date and the machine, so that a report in the documentation
 * is never typed by hand and says what it measured: run the command again to update it.
 */
public final class Report {

	private final StringBuilder text = new StringBuilder();
	private final String title;

	/** @param title the page's title (its first line, a level-1 heading) */
	public Report(final String title) {
		this.title = title;
	}

	/** Adds a level-2 heading. */
	public Report heading(final String heading) {
		text.append("## ").append(heading).append("\n\n");
		return this;
	}

	/** Adds a paragraph. */
	public Report paragraph(final String paragraph) {
		text.append(paragraph).append("\n\n");
		return this;
	}

	/** Adds a bullet list. */
	public Report bullets(final List<String> items) {
		for (final String item : items)
			text.append("* ").append(item).append('\n');
		text.append('\n');
		return this;
	}

	/** Adds a table: the header's cells, then each row's ({@code |} in a cell is escaped). */
	public Report table(final List<String> header, final List<List<String>> rows) {
		row(header);
		text.append('|');
		for (int i = 0; i < header.size(); i++)
			text.append("---|");
		text.append('\n');
		for (final List<String> r : rows)
			row(r);
		text.append('\n');
		return this;
	}

	private void row(final List<String> cells) {
		text.append('|');
		for (final String c : cells)
			text.append(' ').append(c.replace("|", "\\|")).append(" |");
		text.append('\n');
	}

	/** Adds a fenced code block (e.g. the command's own output). */
	public Report code(final String block) {
		text.append("```\n").append(block.endsWith("\n") ? block : block + "\n").append("```\n\n");
		return this;
	}

	/**
	 * @param arguments the command's arguments, as given ({@code accuracy --report FILE ...})
	 * @param seconds how long the run took
	 * @return the stamp: the command, the version, the date (UTC), the machine and the run's time
	 */
	public static String stamp(final List<String> arguments, final double seconds) {
		final StringBuilder command = new StringBuilder("scripts/contact-tracker");
		for (final String a : arguments)
			command.append(' ').append(a.isEmpty() || a.matches(".*[\\s'\"$`\\\\|&;<>()*?].*") ? "'" + a.replace("'",
				"'\\''") + "'" : a);
		return String.format(Locale.ROOT, "Written by `%s` (Contact Tracker %s) on %s (UTC), %d cores, Java %s, %s; " +
			"the run took %.0f s. Not typed by hand: run the command again to update this page.", command, ProjectVersion
				.get(), LocalDate.now(ZoneOffset.UTC), Runtime.getRuntime().availableProcessors(), System.getProperty(
					"java.version"), System.getProperty("os.name"), seconds);
	}

	/** Writes the page (title, stamp, then what was added) to {@code file}, all or nothing. */
	public void write(final Path file, final List<String> arguments, final double seconds) throws IOException {
		final String page = "# " + title + "\n\n" + stamp(arguments, seconds) + "\n\n" + text.toString().stripTrailing() +
			"\n";
		AtomicFile.write(file, os -> os.write(page.getBytes(StandardCharsets.UTF_8)));
	}

	/** @return {@code v} with two decimals and its sign ({@code +1.56}, {@code -0.06}) */
	public static String signed(final double v) {
		return String.format(Locale.ROOT, "%+.2f", v);
	}

	/** @return {@code v} with two decimals */
	public static String two(final double v) {
		return String.format(Locale.ROOT, "%.2f", v);
	}
}
