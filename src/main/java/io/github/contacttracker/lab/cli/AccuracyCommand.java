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
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.lab.eval.CramerRao;
import io.github.contacttracker.lab.eval.DistanceError;
import io.github.contacttracker.lab.eval.DistanceStudy;
import io.github.contacttracker.lab.eval.SceneStudy;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * {@code accuracy}: the paper's protocol for every method: two and three particles of the 5.53 um-like and
 * 2.06 um-like profiles, from 2 D down to contact, many noisy images per separation; prints per separation
 * and method the bias and spread of the measured distance against the Cramer-Rao bound.
 */
final class AccuracyCommand extends ContactTrackerCli.Subcommand {

	private final Option<Integer> repsOption = options.add(Option.integer("--reps", "N", "Noisy images per " +
		"separation (at least 2).").withDefault("200"));
	private final Option<Integer> threadsOption = ContactTrackerCli.threads(options);
	private final Option<Path> csvOption = options.add(Option.path("--csv", "OUT.csv", "Also write the table as CSV."));
	private final Option<Path> reportOption = options.add(Option.path("--report", "FILE.md", "Also write the tables " +
		"as a markdown page, stamped with this command, the version and the date (the documentation's reports)."));
	private final Option<String> particlesOption = options.add(Option.text("--particle", "5.53,2.06", "Particle " +
		"types (um); with --scene also flat, and movie:PATH, particles like a movie's: one per kind of particle " +
		"found on its first frames, each with its kind's profile as the fit measures it, and the movie's noise " +
		"and settings (profile helper on its first frame); the mixed scenes put the kinds together.").withDefault(
			"5.53,2.06"));
	private final Option<String> scenariosOption = options.add(Option.text("--scenario", "pair,triple", "Scenarios.")
		.withDefault("pair,triple"));
	private final Option<String> methodsOption = options.add(Option.text("--methods", "M,...", "Methods. Default: " +
		"every method for the paper's protocol, fit for --scene."));
	private final Option<String> sceneOption = options.add(Option.text("--scene", "S,...", "Instead of the paper's " +
		"protocol, the harder scenes at contact (eval.SceneStudy): pair, chain4, triple, hex7, hex19, hex37, unlike, unlike13, " +
		"ramp, saturated, photon, or all; and, for a movie of several kinds, mixed (its first and last kind at " +
		"contact) and mixed7 (hex7 of its kinds in turn), each particle with its own kind's profile."));
	private final Option<String> detectionScenesOption = options.add(Option.text("--detection-scenes", "S,...",
		"Instead of the paper's protocol, the study of detection as a new user meets it: each scene tracked as " +
			"'track MOVIE' tracks it with no value given, judged against its truth: pair-sweep (a blurred pair from 2 D " +
			"apart to 0.5 D), dim (16-bit spots at SNR 3-5), dark (dark spheres on a bright background), clipped (a " +
			"background clipped at 0), dense (a packed monolayer of one size), dense-bidisperse (of two sizes), ring-pair " +
			"(a tweezer pair of ring-cored particles on a ramp of light), dense-polydisperse (a confocal slice of a " +
			"packing of many sizes, background clipped at 0), or all; " +
			"--reps is then the movies per scene (default 3)."));
	private final Option<Integer> framesOption = options.add(Option.integer("--frames", "N", "With " +
		"--detection-scenes: frames per movie (a pair sweep's separations). Default: 40 for pair-sweep and ring-pair, " +
		"2 for the dense scenes, 5 for the " +
		"others."));
	private final Option<Boolean> trueDiameterOption = options.add(Option.flag(List.of("--true-diameter"), "With " +
		"--detection-scenes: give each scene's true diameter, as a control that tells the profile helper's diameter " +
		"from the detection's own failures."));
	private final Option<String> separationsOption = options.add(Option.text("--separations", "R,...", "Separations " +
		"over the diameter (1 = contact). Default: 2 down to 1."));

	AccuracyCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker accuracy", "The paper's protocol for every method, against the " +
			"Cramer-Rao bound."), out);
	}

	@Override
	public Integer call() throws IOException {
		final int reps = options.value(repsOption), threads = options.value(threadsOption);
		final String particles = options.value(particlesOption), scene = options.value(sceneOption), methodList =
			options.value(methodsOption);
		final Path csv = ContactTrackerCli.output("--csv", options.value(csvOption));
		final Path report = ContactTrackerCli.output("--report", options.value(reportOption));
		final String detectionScenes = options.value(detectionScenesOption);
		if (detectionScenes != null) {
			if (reps < 1) throw new InvalidInputException("--reps must be at least 1 with --detection-scenes");
			return detectionScenes(detectionScenes, options.given(repsOption) ? reps : 3, threads, csv, report);
		}
		if (reps < 2) throw new InvalidInputException("--reps must be at least 2");
		if (scene != null) { // the scenes of eval.SceneStudy (clusters, unlike particles, ramp, saturation)
			final long t0 = System.nanoTime();
			final SceneStudy study = new SceneStudy(Method.parse(methodList == null ? "fit" : methodList), threads);
			final List<SceneStudy.Kinds> sets = new ArrayList<>();
			for (final String p : ContactTrackerCli.list(particles)) {
				if (p.startsWith(MeasuredParticle.PREFIX)) sets.add(MeasuredParticle.kinds(Path.of(p.substring(
					MeasuredParticle.PREFIX.length()))));
				else {
					final ParticleType t = SceneStudy.particle(p);
					sets.add(new SceneStudy.Kinds(t.name(), List.of(t)));
				}
			}
			final List<SceneStudy.Result> results = study.reportKinds(out, sets, scene, reps);
			final double seconds = (System.nanoTime() - t0) * 1e-9;
			out.printf(Locale.ROOT, "%nAccuracy run took %.0f s.%n", seconds);
			if (csv != null) {
				final StringBuilder sceneCsv = new StringBuilder(SceneStudy.CSV_HEADER);
				for (final SceneStudy.Result r : results)
					sceneCsv.append(study.csv(r));
				AtomicFile.write(csv, os -> os.write(sceneCsv.toString().getBytes(StandardCharsets.UTF_8)));
			}
			if (report != null) AccuracyReport.scenes(results, study, reps).write(report, arguments, seconds);
			return 0;
		}
		final List<ParticleType> types = new ArrayList<>();
		for (final String p : ContactTrackerCli.list(particles))
			types.add(SimulateCommand.particle(p));
		final List<Scenario> scenarios = new ArrayList<>();
		for (final String s : ContactTrackerCli.list(options.value(scenariosOption)))
			scenarios.add(SimulateCommand.scenario(s));
		final List<Method> methods = new ArrayList<>();
		for (final String m : ContactTrackerCli.list(methodList == null ? "first,paper,iterative,deblend,fit" : methodList))
			methods.add(Method.parse(m));
		final double[] separations = parseList(options.value(separationsOption));

		final StringBuilder table = new StringBuilder(
			"particle,scenario,separation_over_d,method,images,measured,failures,fallbacks,mean_error_nm,std_nm," +
				"mean_reported_sigma_nm,crb_nm\n");
		final long start = System.nanoTime();
		final AccuracyReport rows = new AccuracyReport(reps);
		for (final ParticleType type : types)
			for (final Scenario scenario : scenarios) {
				final DistanceStudy study = new DistanceStudy(type, scenario, threads);
				final String heading = String.format(Locale.ROOT, "%s, %s (D = %.1f px at %.1f nm/px), threshold " +
					"%.0f, r_out %.0f px, %d images per separation, %s", type.name(), scenario == Scenario.PAIR ?
						"two particles" : "three particles", type.diameterPx(), type.pixelSizeNm(), type.threshold(), type
							.rOut(), reps, type.noise());
				out.printf(Locale.ROOT, "%n%s%n", heading);
				out.println("  r/D  method     | mean err   std (nm) | std/CRB | reported sigma | lost  fell back | " +
					"CRB (nm)");
				for (int i = 0; i < separations.length; i++) {
					final SimulatedStack<?> stack = study.simulate(separations[i], reps, 100L * i + 7);
					final double crb = crbNm(type, scenario, stack);
					for (final Method m : methods) {
						final DistanceError e = study.measure(stack, study.track(stack, m), m);
						out.printf(Locale.ROOT, "  %4.2f %-10s | %8.2f %7.2f | %7.2f | %14.2f | %4d %10d | %6.2f%n",
							separations[i], m.key(), e.meanErrorNm(), e.stdNm(), e.stdNm() / crb, e.meanSigmaNm(), e
								.failures(), e.fallbacks(), crb);
						table.append(String.format(Locale.ROOT, "%s,%s,%.3f,%s,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f%n", type
							.name(), scenario.name().toLowerCase(Locale.ROOT), separations[i], m.key(), e.images(), e
								.measured(), e.failures(), e.fallbacks(), e.meanErrorNm(), e.stdNm(), e.meanSigmaNm(), crb));
						rows.add(type.name() + (scenario == Scenario.PAIR ? " pair" : " triple"), heading, e, crb);
					}
				}
			}
		final double seconds = (System.nanoTime() - start) * 1e-9;
		out.printf(Locale.ROOT, "%nAccuracy run took %.0f s.%n", seconds);
		if (report != null) rows.paper().write(report, arguments, seconds);
		if (csv != null) {
			AtomicFile.write(csv, os -> {
				final Writer w = new OutputStreamWriter(os, StandardCharsets.UTF_8);
				w.write(table.toString());
				w.flush();
			});
			out.println("Table written to " + csv);
		}
		return 0;
	}

	/** The study of detection ({@link DetectionScenesRun}): the table, and the report where asked for. */
	private int detectionScenes(final String scenes, final int movies, final int threads, final Path csv,
		final Path report) throws IOException
	{
		if (csv != null) throw new InvalidInputException("--csv is not written with --detection-scenes: give --report");
		final Integer frames = options.value(framesOption);
		if (frames != null && frames < 2) throw new InvalidInputException("--frames must be at least 2");
		final long t0 = System.nanoTime();
		final boolean trueDiameter = options.value(trueDiameterOption);
		final List<DetectionScenesRun.SceneResult> results = DetectionScenesRun.run(out, DetectionScenesRun.keys(
			scenes), movies, frames == null ? 0 : frames, threads, trueDiameter);
		final double seconds = (System.nanoTime() - t0) * 1e-9;
		out.printf(Locale.ROOT, "%nDetection study took %.0f s.%n", seconds);
		if (report != null) DetectionScenesRun.report(results, trueDiameter).write(report, arguments, seconds);
		return 0;
	}

	/** The bound for the configuration of the stack's first frame (the bound barely depends on the offset). */
	private static double crbNm(final ParticleType type, final Scenario scenario, final SimulatedStack<?> stack) {
		return CramerRao.distanceBound(type, stack.truth().get(0), scenario.measuredPair(), stack.width(), stack
			.height()) * type.pixelSizeNm();
	}

	private static double[] parseList(final String text) {
		if (text == null) return DistanceStudy.SEPARATIONS;
		final String[] parts = text.split(",");
		final double[] v = new double[parts.length];
		for (int i = 0; i < parts.length; i++) {
			try {
				v[i] = Double.parseDouble(parts[i].trim());
			}
			catch (final NumberFormatException e) {
				throw new InvalidInputException("--separations must be numbers separated by commas, not '" + text +
					"'");
			}
			if (!(v[i] > 0)) throw new InvalidInputException("--separations must be positive (1 = contact)");
		}
		return v;
	}
}
