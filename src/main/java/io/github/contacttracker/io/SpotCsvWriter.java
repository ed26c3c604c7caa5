package io.github.contacttracker.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
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
		return out -> {
			final Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
			write(w, spots, cal);
			w.flush();
		};
	}

	/** Writes the table to {@code out} (not closed). */
	public static void write(final Writer out, final List<Localization> spots, final Calibration cal)
		throws IOException
	{
		final SpotColumn[] cols = SpotColumn.values();
		for (int c = 0; c < cols.length; c++)
			out.write((c == 0 ? "" : ",") + cols[c].key());
		out.write('\n');
		for (int id = 0; id < spots.size(); id++) {
			final Localization s = spots.get(id);
			for (int c = 0; c < cols.length; c++)
				out.write((c == 0 ? "" : ",") + cols[c].format(s, id, cal));
			out.write('\n');
		}
	}
}
