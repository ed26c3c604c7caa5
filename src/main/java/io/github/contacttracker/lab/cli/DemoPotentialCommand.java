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

import io.github.contacttracker.core.InvalidInputException;
import java.awt.Color;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.lab.eval.PotentialStudy;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.plot.PotentialPlots;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.lab.sim.FluidMovie;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * {@code demo-potential}: a simulated 2D fluid with a known pair potential (hard core + short-range attraction),
 * rendered as a movie, tracked with the default method and with the first pass, and U(r) measured from both
 * against the truth; writes the comparison plot and the default method's spots (to rerun {@code potential} on).
 */
final class DemoPotentialCommand extends ContactTrackerCli.Subcommand {

	private final Option<Integer> framesOption = options.add(Option.integer("--frames", "N", "Frames to simulate (at " +
		"least 10).").withDefault("300"));
	private final Option<String> particleOption = options.add(Option.text("--particle", "2.06|5.53", "Particle type " +
		"(um).").withDefault("2.06"));
	private final Option<Path> dirOption = options.add(Option.path("--out-dir", "DIR", "Where the plot and spots go.")
		.withDefault("demo-output"));
	private final Option<Integer> threadsOption = ContactTrackerCli.threads(options);

	DemoPotentialCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker demo-potential", "A simulated fluid with a known U(r): U(r) by the " +
			"default method and the first pass against the truth."), out);
	}

	@Override
	public Integer call() throws IOException {
		final int frames = options.value(framesOption), threads = options.value(threadsOption);
		final Path dir = options.value(dirOption);
		if (frames < 10) throw new InvalidInputException("--frames must be at least 10");
		final ParticleType type = SimulateCommand.particle(options.value(particleOption));
		Files.createDirectories(dir);
		final long start = System.nanoTime();

		final PotentialStudy study = PotentialStudy.demo(type, frames);
		final double d = type.diameterPx(), um = type.pixelSizeMicrons();
		out.printf(Locale.ROOT, "%s particles (D = %.1f px at %.1f nm/px), %d in a %d x %d px frame, %d frames, %d Monte " +
			"Carlo sweeps apart%n  true potential: %s%n", type.name(), d, type.pixelSizeNm(), study.particles(), study
				.size(), study.size(), frames, study.sweepsBetween(), study.interaction().describe());
		final FluidMovie movie = study.simulate();
		final List<Localization> fit = study.track(movie, Method.DEFAULT, threads);
		final List<Localization> first = study.track(movie, Method.FIRST, threads);
		final PairCorrelation.Result truth = study.measureTruth(movie), best = study.measure(fit), biased = study
			.measure(first);

		out.printf(Locale.ROOT, "  U(r)/kT set to 0 over [%.0f D, %.0f D]; bins of %.3f D; flagged spots left out, " +
			"field of view inferred from the spots%n%n", study.zeroFrom(), study.rMax(), study.bin());
		out.printf(Locale.ROOT, "  r/D    | true U | U from true centres | %-6s U +- err   (pairs) | first pass U +- " +
			"err (pairs)%n", Method.DEFAULT.key());
		for (int i = 0; i < best.bins().size(); i++) {
			final double r = best.bins().get(i).r();
			if (r < 0.9 || r > 1.6) continue;
			out.printf(Locale.ROOT, "  %6.4f | %6s | %19s | %22s | %22s%n", r, u(study.trueU(r)), cell(truth, i, false),
				cell(best, i, true), cell(biased, i, true));
		}
		final PotentialStudy.Comparison cTruth = study.compare(truth, 1, 2), cBest = study.compare(best, 1, 2), cFirst =
			study.compare(biased, 1, 2);
		out.printf(Locale.ROOT, "%nAgainst the true U(r), bins from contact to 2 D (chi2/bin ~ 1 means within the " +
			"error bars):%n");
		out.printf(Locale.ROOT, "  true centres:  chi2/bin %.2f, max |z| %.1f over %d bins, %d pairs inside the hard core%n",
			cTruth.chi2PerBin(), cTruth.maxAbsZ(), cTruth.bins(), cTruth.pairsInsideCore());
		out.printf(Locale.ROOT, "  %-13s chi2/bin %.2f, max |z| %.1f over %d bins, %d pairs inside the hard core%n",
			Method.DEFAULT.key() + ":", cBest.chi2PerBin(), cBest.maxAbsZ(), cBest.bins(), cBest.pairsInsideCore());
		out.printf(Locale.ROOT, "  first pass:    chi2/bin %.2f, max |z| %.1f over %d bins, %d pairs inside the hard core%n",
			cFirst.chi2PerBin(), cFirst.maxAbsZ(), cFirst.bins(), cFirst.pairsInsideCore());

		final Path png = dir.resolve("contact-tracker-potential.png");
		PotentialPlots.writePng(PotentialPlots.comparison(List.of( //
			new PotentialPlots.Series("from the true centres", truth, new Color(140, 140, 140), "x"), //
			new PotentialPlots.Series("method " + Method.DEFAULT.key() + " (default)", best, new Color(0, 90, 200),
				"circle"), //
			new PotentialPlots.Series("first pass (method first)", biased, new Color(220, 60, 0), "triangle")), //
			study::trueU, "true U(r)", "Pair potential of a simulated " + type.name() + " fluid, " + frames + " frames",
			"diameters", 0.85, 2.0), png);
		final Path spots = dir.resolve("potential-spots.csv");
		SpotCsvWriter.write(spots, fit, Calibration.ofPixelSize(um, "micron"));
		out.printf(Locale.ROOT, "%nPlot: %s%nSpots (method %s, micron): %s%n  analyse them with:%n  scripts/contact-tracker " +
			"potential %s --bin %s --r-max %s --zero %s,%s --csv %s --png %s%n", png, Method.DEFAULT.key(), spots, spots,
			num(study.bin() * d * um), num(study.rMax() * d * um), num(study.zeroFrom() * d * um), num(study.rMax() * d *
				um), dir.resolve("potential.csv"), dir.resolve("potential.png"));
		if (movie.clippedPixels() > 0) out.printf(Locale.ROOT, "  (%d pixels clipped to 0..255)%n", movie.clippedPixels());
		out.printf(Locale.ROOT, "Demo took %.1f s.%n", (System.nanoTime() - start) * 1e-9);
		return 0;
	}

	private static String cell(final PairCorrelation.Result r, final int i, final boolean withError) {
		final PairCorrelation.Bin b = r.bins().get(i);
		if (b.pairs() == 0) return "-    (0)";
		return withError ? String.format(Locale.ROOT, "%+6.2f +- %4.2f (%4d)", r.u(i), b.uError(), b.pairs()) : String
			.format(Locale.ROOT, "%+6.2f (%4d)", r.u(i), b.pairs());
	}

	private static String u(final double v) {
		return Double.isInfinite(v) ? "inf" : String.format(Locale.ROOT, "%+6.2f", v);
	}

	private static String num(final double v) {
		return String.format(Locale.ROOT, "%.4f", v);
	}
}
