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
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

import io.github.contacttracker.core.Localization;

/**
 * Writes spots as CSV with ONE header row of {@link SpotColumn} keys: TrackMate's keys first (its CSV importer
 * reads exactly one header row and maps columns by name), then ours. Positions are in the calibration's units;
 * IDs run from 0 in the order given.
 */
public final class SpotCsvWriter {

	private SpotCsvWriter() {}

	/** Writes the table to {@code file}, atomically. */
	public static void write(final Path file, final List<Localization> spots, final Calibration cal)
		throws IOException
	{
		AtomicFile.write(file, body(spots, cal));
	}

	/** @return the table as the body of an {@link AtomicFile} write (UTF-8) */
	public static AtomicFile.Body body(final List<Localization> spots, final Calibration cal) {
		// bytes straight from the text (all ASCII), not through a character encoder: a third of the writing time
		return out -> write(spots, cal, block -> out.write(block.toString().getBytes(StandardCharsets.UTF_8)));
	}

	/** Writes the table to {@code out} (not closed). */
	public static void write(final Writer out, final List<Localization> spots, final Calibration cal)
		throws IOException
	{
		write(spots, cal, out::append);
	}

	/** A piece of the table's text, handed on before the builder is reused. */
	private interface Block {
		void take(StringBuilder text) throws IOException;
	}

	private static void write(final List<Localization> spots, final Calibration cal, final Block to)
		throws IOException
	{
		final SpotColumn[] cols = SpotColumn.values();
		final StringBuilder b = new StringBuilder(1 << 16);
		for (int c = 0; c < cols.length; c++)
			b.append(c == 0 ? "" : ",").append(cols[c].key());
		b.append('\n');
		for (int id = 0; id < spots.size(); id++) {
			final Localization s = spots.get(id);
			for (int c = 0; c < cols.length; c++) {
				if (c > 0) b.append(',');
				cols[c].appendTo(b, s, id, cal);
			}
			b.append('\n');
			if (b.length() >= 1 << 15) { // in blocks: a movie's table is not held twice
				to.take(b);
				b.setLength(0);
			}
		}
		to.take(b);
	}
}
