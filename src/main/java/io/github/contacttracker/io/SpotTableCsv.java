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

import io.github.contacttracker.core.InvalidInputException;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Reads a spots table from CSV: ours (one header row of {@link SpotColumn} keys, as every front end writes) or
 * TrackMate's spot-table export, whose first row holds the feature keys and up to three more header rows follow
 * (feature names, short names, units such as {@code (micron)}). Rows after the first whose {@code POSITION_X}
 * cell is not a number are taken as those extra header rows; the units row gives {@link Table#unit()}. Fields may
 * be quoted ({@code "..."}, with {@code ""} for a quote inside).
 */
public final class SpotTableCsv {

	/** The key whose cells tell header rows from data rows. */
	private static final String PROBE = "POSITION_X";
	/** TrackMate's export has at most this many header rows. */
	private static final int MAX_HEADER_ROWS = 4;

	/**
	 * The columns read.
	 *
	 * @param columns the wanted columns present in the file, by key, one value per data row (NaN for an empty
	 *          cell)
	 * @param rows the number of data rows
	 * @param headerRows header rows found (1 for ours, up to 4 for TrackMate's export)
	 * @param unit the spatial unit from TrackMate's units row, or "" when the file has none
	 */
	public record Table(Map<String, double[]> columns, int rows, int headerRows, String unit) {}

	private SpotTableCsv() {}

	/**
	 * @param file the CSV file
	 * @param wanted which column keys to read (others, e.g. text labels, are skipped)
	 * @return the wanted columns
	 * @throws IOException when the file cannot be read
	 * @throws IllegalArgumentException naming the file, line and column of the first problem: an empty file, no
	 *           data row, a cell that is not a number, a row with too few cells
	 */
	public static Table read(final Path file, final Predicate<String> wanted) throws IOException {
		final List<String> lines;
		try (BufferedReader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
			lines = r.lines().toList();
		}
		catch (final NoSuchFileException e) {
			throw new InvalidInputException(file + ": no such file");
		}
		catch (final java.io.UncheckedIOException e) {
			throw new InvalidInputException(file + ": not a text file (" + e.getCause().getMessage() + ")");
		}
		return parse(lines, wanted, file.toString());
	}

	/**
	 * {@link #read} on lines already in memory.
	 *
	 * @param lines the file's lines
	 * @param wanted which column keys to read
	 * @param name the file's name, for messages
	 * @return the wanted columns
	 */
	public static Table parse(final List<String> lines, final Predicate<String> wanted, final String name) {
		int first = 0;
		while (first < lines.size() && lines.get(first).isBlank())
			first++;
		if (first == lines.size()) throw new InvalidInputException(name + " is empty");
		final List<String> keys = split(stripBom(lines.get(first)));
		final int probe = keys.indexOf(PROBE);
		final List<Integer> indices = new ArrayList<>();
		final List<String> names = new ArrayList<>();
		for (int c = 0; c < keys.size(); c++)
			if (wanted.test(keys.get(c)) && !names.contains(keys.get(c))) {
				indices.add(c);
				names.add(keys.get(c));
			}
		int headerRows = 1;
		String unit = "";
		int line = first + 1;
		// TrackMate's extra header rows: their POSITION_X cell is a name, a short name or a unit, not a number
		while (probe >= 0 && line < lines.size() && headerRows < MAX_HEADER_ROWS) {
			if (lines.get(line).isBlank()) {
				line++;
				continue;
			}
			final List<String> cells = split(lines.get(line));
			final String cell = probe < cells.size() ? cells.get(probe).trim() : "";
			if (isNumber(cell)) break;
			if (cell.startsWith("(") && cell.endsWith(")")) unit = cell.substring(1, cell.length() - 1).trim();
			headerRows++;
			line++;
		}
		final List<double[]> rows = new ArrayList<>();
		final int width = indices.isEmpty() ? 0 : indices.get(indices.size() - 1) + 1;
		for (; line < lines.size(); line++) {
			if (lines.get(line).isBlank()) continue;
			final List<String> cells = split(lines.get(line));
			if (cells.size() < width)
				throw new InvalidInputException(String.format(Locale.ROOT, "%s line %d: %d cells, but column %s is " +
					"number %d", name, line + 1, cells.size(), keys.get(width - 1), width));
			final double[] row = new double[indices.size()];
			for (int k = 0; k < row.length; k++) {
				final String cell = cells.get(indices.get(k)).trim();
				if (cell.isEmpty()) row[k] = Double.NaN;
				else if (isNumber(cell)) row[k] = Double.parseDouble(cell);
				else throw new InvalidInputException(String.format(Locale.ROOT, "%s line %d: %s is not a number: '%s'",
					name, line + 1, names.get(k), cell));
			}
			rows.add(row);
		}
		if (rows.isEmpty()) throw new InvalidInputException(name + " has a header but no data row");
		final Map<String, double[]> columns = new LinkedHashMap<>();
		for (int k = 0; k < names.size(); k++) {
			final double[] c = new double[rows.size()];
			for (int i = 0; i < c.length; i++)
				c[i] = rows.get(i)[k];
			columns.put(names.get(k), c);
		}
		return new Table(columns, rows.size(), headerRows, unit);
	}

	private static boolean isNumber(final String s) {
		if (s.isEmpty()) return false;
		try {
			Double.parseDouble(s);
			return !s.endsWith("d") && !s.endsWith("D") && !s.endsWith("f") && !s.endsWith("F"); // Java suffixes
		}
		catch (final NumberFormatException e) {
			return false;
		}
	}

	private static String stripBom(final String s) {
		return s.startsWith("\uFEFF") ? s.substring(1) : s;
	}

	/** Splits one CSV line at commas outside double quotes; quotes are removed, {@code ""} inside is a quote. */
	static List<String> split(final String line) {
		final List<String> cells = new ArrayList<>();
		final StringBuilder b = new StringBuilder();
		boolean quoted = false;
		for (int i = 0; i < line.length(); i++) {
			final char ch = line.charAt(i);
			if (quoted) {
				if (ch == '"') {
					if (i + 1 < line.length() && line.charAt(i + 1) == '"') {
						b.append('"');
						i++;
					}
					else quoted = false;
				}
				else b.append(ch);
			}
			else if (ch == '"') quoted = true;
			else if (ch == ',') {
				cells.add(b.toString());
				b.setLength(0);
			}
			else b.append(ch);
		}
		cells.add(b.toString());
		return cells;
	}
}
