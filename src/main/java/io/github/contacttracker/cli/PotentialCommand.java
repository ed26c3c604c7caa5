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

import io.github.contacttracker.core.InvalidInputException;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import io.github.contacttracker.report.PotentialCsv;
import io.github.contacttracker.plot.PotentialPlots;
import io.github.contacttracker.io.SpotTableCsv;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.potential.PotentialReport;
import io.github.contacttracker.potential.SpotSet;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;

/**
 * {@code potential SPOTS.csv --bin W --r-max R [--csv OUT.csv] [--png OUT.png]}: g(r) and U(r)/kT from a spots
 * table (ours or TrackMate's export). CSV to stdout without {@code --csv}; the summary then goes to stderr.
 */
final class PotentialCommand extends ContactTrackerCli.Subcommand {

	private final Option<Path> inputOption = options.add(Option.positionalPath("SPOTS.csv", "The spots table."));
	private final Option<Double> binOption = options.add(Option.decimal("--bin", "W", "Bin width of r, in the " +
		"spots' units.").asRequired());
	private final Option<Double> rMaxOption = options.add(Option.decimal("--r-max", "R", "Largest r, in the spots' " +
		"units.").asRequired());
	private final Option<Path> csvOption = options.add(Option.path("--csv", "OUT.csv", "Write the table here (else " +
		"to stdout)."));
	private final Option<Path> pngOption = options.add(Option.path("--png", "OUT.png", "Also plot U(r)."));
	private final Option<Double> widthOption = options.add(Option.decimal("--width", "W", "Field of view width " +
		"(with --height); else inferred from the spots."));
	private final Option<Double> heightOption = options.add(Option.decimal("--height", "H", "Field of view height " +
		"(with --width)."));
	private final Option<Integer> startFrameOption = options.add(Option.integer("--start-frame", "F", "Leave out " +
		"earlier frames.").withDefault("0"));
	private final Option<String> flaggedOption = options.add(Option.text("--flagged", "drop|keep", "Flagged spots: " +
		"left out or kept.").withDefault("drop"));
	private final Option<String> zeroOption = options.add(Option.text("--zero", "FROM,TO", "Set U(r) to 0 on " +
		"average over this range of r."));

	private final PrintStream err;

	PotentialCommand(final PrintStream out, final PrintStream err) {
		super(new CommandOptions("contact-tracker potential", "Pair distribution g(r) and pair potential U(r)/kT from " +
			"a spots table (ours or TrackMate's export); CSV to stdout without --csv."), out);
		this.err = err;
	}

	@Override
	public Integer call() throws IOException {
		final Path input = options.value(inputOption);
		final double bin = options.value(binOption), rMax = options.value(rMaxOption);
		final Double width = options.value(widthOption), height = options.value(heightOption);
		if (!Double.isFinite(bin) || !Double.isFinite(rMax))
			throw new InvalidInputException("--bin and --r-max must be finite numbers");
		final Path csv = ContactTrackerCli.output("--csv", options.value(csvOption)), png = ContactTrackerCli.output(
			"--png", options.value(pngOption));
		if ((width == null) != (height == null))
			throw new InvalidInputException("give both --width and --height of the field of view, or neither (then " +
				"it is inferred from the spots)");
		final SpotSet.Selection selection = new SpotSet.Selection(options.value(startFrameOption), dropFlagged(options
			.value(flaggedOption)));
		final String zeroText = options.value(zeroOption);
		final double[] zero = zeroText != null ? zeroRange(zeroText) : null;

		final SpotTableCsv.Table table = SpotTableCsv.read(input, SpotSet::reads);
		final SpotSet spots;
		try {
			spots = SpotSet.fromColumns(table.columns(), selection);
		}
		catch (final IllegalArgumentException e) {
			throw new InvalidInputException(input + ": " + e.getMessage());
		}
		if (spots.size() == 0)
			throw new InvalidInputException(input + ": no spot left (" + spots.flaggedLeftOut() + " flagged, " + spots
				.earlyLeftOut() + " before the start frame)");
		final FieldOfView field = width != null ? FieldOfView.of(width, height) : spots.inferredField();
		PairCorrelation.Result result = PairCorrelation.compute(spots, field, bin, rMax);
		if (zero != null) result = result.withZero(zero[0], zero[1]);

		final String unit = table.unit();
		if (png != null) PotentialPlots.writePng(PotentialPlots.potential(result, "Pair potential: " + input
			.getFileName(), table.unit().isEmpty() ? "spots' units" : table.unit()), png);
		if (csv != null) {
			try {
				PotentialCsv.write(csv, result);
			}
			catch (final IOException e) {
				if (png != null) Files.deleteIfExists(png); // both or neither
				throw e;
			}
		}
		else {
			final Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
			PotentialCsv.write(w, result);
			w.flush();
		}
		final PrintStream report = csv != null ? out : err;
		report.println(input + ":");
		for (final String line : PotentialReport.lines(spots, result, unit))
			report.println("  " + line);
		final String warning = PotentialReport.fieldWarning(spots, field);
		if (warning != null) err.println("contact-tracker: warning: " + warning);
		if (field.inferred()) err.println("contact-tracker: note: field of view inferred from the spots (" + String
			.format(Locale.ROOT, "%.6g x %.6g", field.width(), field.height()) + "); give --width and --height to set it");
		return 0;
	}

	private static boolean dropFlagged(final String text) {
		switch (text.trim().toLowerCase(Locale.ROOT)) {
			case "drop": return true;
			case "keep": return false;
			default: throw new InvalidInputException("--flagged must be drop or keep, not '" + text + "'");
		}
	}

	/** @return {from, to} from "A,B" */
	static double[] zeroRange(final String text) {
		final String[] parts = text.split(",");
		if (parts.length == 2) try {
			final double a = Double.parseDouble(parts[0].trim()), b = Double.parseDouble(parts[1].trim());
			if (Double.isFinite(a) && Double.isFinite(b) && a <= b) return new double[] { a, b };
		}
		catch (final NumberFormatException e) {
			// reported below
		}
		throw new InvalidInputException("--zero must be a range FROM,TO of r (FROM <= TO), not '" + text + "'");
	}
}
