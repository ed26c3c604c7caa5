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

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * The settings a spots table was found with, in a small text file beside it ({@code spots.csv} ->
 * {@code spots.settings.txt}): one {@code name = value} line per setting, named as macros and settings maps name
 * them ({@code r_out = 20.0}), after a comment line. The table itself stays plain CSV, which spreadsheets, ImageJ
 * and pandas read without being told to skip comments; the file is what makes a table's run repeatable and is
 * read back by {@link #read(Path)}.
 */
public final class SettingsFile {

	/** What the settings file's name ends with, in place of the table's {@code .csv}. */
	public static final String SUFFIX = ".settings.txt";

	private SettingsFile() {}

	/** @return the settings file of the spots table {@code csv}: its name with {@code .csv} replaced by {@value #SUFFIX} */
	public static Path beside(final Path csv) {
		final String name = csv.getFileName().toString();
		final String base = name.toLowerCase(Locale.ROOT).endsWith(".csv") ? name.substring(0, name.length() - 4) : name;
		return csv.resolveSibling(base + SUFFIX);
	}

	/** @return the text of the file: a comment line, then every setting in {@link TrackingSettings#ALL} order */
	public static String text(final SettingValues settings) {
		final StringBuilder b = new StringBuilder("# Contact Tracker ").append(ProjectVersion.get()).append(
			": the settings the spots were found with\n");
		for (final Setting<?> s : TrackingSettings.ALL)
			b.append(s.name()).append(" = ").append(settings.get(s)).append('\n');
		return b.toString();
	}

	/** @return the file as the body of an {@link AtomicFile} write (UTF-8) */
	public static AtomicFile.Body body(final SettingValues settings) {
		final byte[] bytes = text(settings).getBytes(StandardCharsets.UTF_8);
		return out -> out.write(bytes);
	}

	/**
	 * @return the settings of a file written by {@link #text}
	 * @throws InvalidInputException naming the file and the line when a line is not {@code name = value} of a known
	 *         setting, a setting is given twice or missing, or a value is not allowed
	 * @throws IOException when the file cannot be read
	 */
	public static SettingValues read(final Path file) throws IOException {
		return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.toString());
	}

	/** @see #read(Path) */
	static SettingValues parse(final List<String> lines, final String source) {
		SettingValues v = SettingValues.defaults();
		final Set<Setting<?>> seen = new HashSet<>();
		for (int i = 0; i < lines.size(); i++) {
			final String line = lines.get(i).strip();
			if (line.isEmpty() || line.startsWith("#")) continue;
			final int eq = line.indexOf('=');
			final Setting<?> s = eq < 0 ? null : TrackingSettings.named(line.substring(0, eq).strip());
			final String where = source + " line " + (i + 1) + ": ";
			if (s == null) throw new InvalidInputException(where + "expected 'name = value' of a setting (" + String.join(
				", ", TrackingSettings.ALL.stream().map(Setting::name).toList()) + "), not '" + line + "'");
			if (!seen.add(s)) throw new InvalidInputException(where + s.name() + " is given twice");
			try {
				v = v.withText(s, line.substring(eq + 1));
			}
			catch (final InvalidInputException e) {
				throw new InvalidInputException(where + e.getMessage(), e);
			}
		}
		for (final Setting<?> s : TrackingSettings.ALL)
			if (!seen.contains(s)) throw new InvalidInputException(source + ": the setting " + s.name() + " is missing");
		return v;
	}
}
