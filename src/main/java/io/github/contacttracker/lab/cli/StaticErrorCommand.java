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
package io.github.contacttracker.lab.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Map;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.io.SpotTableCsv;
import io.github.contacttracker.potential.SpotSet;
import io.github.contacttracker.potential.StaticError;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * {@code contact-tracker static-error SPOTS.csv}: how accurate the positions of a movie are, from the particles'
 * own motion ({@link StaticError}), beside the standard errors the tracker reported.
 */
final class StaticErrorCommand extends ContactTrackerCli.Subcommand {

	private final Option<Path> inputOption = options.add(Option.positionalPath("SPOTS.csv", "The spots table " +
		"(ours, or any with FRAME, POSITION_X, POSITION_Y)."));
	private final Option<Double> stepOption = options.add(Option.decimal("--max-step", "S", "Largest displacement " +
		"between consecutive frames that links two spots, in the spots' units.").asRequired());
	private final Option<Integer> lagsOption = options.add(Option.integer("--lags", "L", "Lags (frames) the line " +
		"through the mean squared displacement is fitted to.").withDefault("4"));
	private final Option<Integer> startFrameOption = options.add(Option.integer("--start-frame", "F", "Leave out " +
		"earlier frames.").withDefault("0"));

	StaticErrorCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker static-error", "The static localization error from the intercept " +
			"of the mean squared displacement of diffusing particles (Savin & Doyle 2005), against the reported " +
			"SIGMA_X/SIGMA_Y. Flagged spots are left out."), out);
	}

	@Override
	public Integer call() throws IOException {
		final Path input = options.value(inputOption);
		final double step = options.value(stepOption);
		final int lags = options.value(lagsOption);
		final SpotTableCsv.Table table = SpotTableCsv.read(input, key -> SpotSet.reads(key) || key.equals("SIGMA_X") ||
			key.equals("SIGMA_Y"));
		final SpotSet spots;
		final StaticError.Result r;
		try {
			spots = SpotSet.fromColumns(table.columns(), new SpotSet.Selection(options.value(startFrameOption), true));
			r = StaticError.estimate(spots, step, lags);
		}
		catch (final IllegalArgumentException e) {
			throw new InvalidInputException(input + ": " + e.getMessage());
		}
		final String unit = table.unit().isEmpty() ? "px" : table.unit();
		out.println(input + ": " + r.tracks() + " tracks, " + r.steps() + " steps linked within " + Numbers.fmt(step,
			4) + " " + unit + " (" + spots.flaggedLeftOut() + " flagged spots left out)");
		for (int k = 0; k < r.msdX().length; k++)
			out.println(String.format(Locale.ROOT, "  lag %d: MSD x %.6g, y %.6g %s^2 (%d displacements)", k + 1, r
				.msdX()[k], r.msdY()[k], unit, r.pairs()[k]));
		out.println(String.format(Locale.ROOT, "  D: x %.4g, y %.4g %s^2/frame", r.diffusionX(), r.diffusionY(), unit));
		out.println(String.format(Locale.ROOT, "  static error variance from the intercept: x %.3g, y %.3g %s^2, " +
			"standard error %.2g%s", r.varianceX(), r.varianceY(), unit, r.varianceError(), resolved(r) ? "" :
				" (not resolved: the intercept is within two standard errors of 0)"));
		if (resolved(r)) out.println("  static error: sigma_x " + Numbers.fmt(r.sigmaX(), 4) + ", sigma_y " + Numbers
			.fmt(r.sigmaY(), 4) + " " + unit);
		final Map<String, double[]> c = table.columns();
		if (c.containsKey("SIGMA_X") && c.containsKey("SIGMA_Y")) out.println("  reported, median over the spots: " +
			"SIGMA_X " + Numbers.fmt(median(c.get("SIGMA_X")), 4) + ", SIGMA_Y " + Numbers.fmt(median(c.get("SIGMA_Y")), 4) +
			" " + unit + " (all spots)");
		out.println("  (motion during the exposure lowers the intercept: then the static error is at least this)");
		return 0;
	}

	/** @return whether both variances lie more than two standard errors above 0 */
	private static boolean resolved(final StaticError.Result r) {
		return Double.isFinite(r.varianceError()) && Math.min(r.varianceX(), r.varianceY()) > 2 * r.varianceError();
	}

	private static double median(final double[] v) {
		return Statistics.median(Arrays.stream(v).filter(Double::isFinite).toArray());
	}
}
