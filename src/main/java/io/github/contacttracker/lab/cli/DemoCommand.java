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
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.lab.eval.DistanceError;
import io.github.contacttracker.lab.eval.DistanceStudy;
import io.github.contacttracker.io.OverlayPng;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * {@code demo}: the paper's two scenarios for 5.53 um particles, from well apart to contact, tracked with the
 * first pass, the paper's method and the default method; prints the distance errors and writes an overlay PNG
 * at contact.
 */
final class DemoCommand extends ContactTrackerCli.Subcommand {

	private final Option<Integer> repsOption = options.add(Option.integer("--reps", "N", "Noisy images per " +
		"separation (at least 2).").withDefault("50"));
	private final Option<Path> dirOption = options.add(Option.path("--out-dir", "DIR", "Where the overlay PNG goes.")
		.withDefault("demo-output"));
	private final Option<Integer> threadsOption = ContactTrackerCli.threads(options);

	DemoCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker demo", "Simulate pairs and triples of 5.53 um particles from apart " +
			"to contact, track them, print the distance errors, write an overlay PNG."), out);
	}

	@Override
	public Integer call() throws IOException {
		final int reps = options.value(repsOption), threads = options.value(threadsOption);
		final Path dir = options.value(dirOption);
		if (reps < 2) throw new InvalidInputException("--reps must be at least 2");
		Files.createDirectories(dir);
		final ParticleType type = PaperParticles.silica553();
		final List<OverlayPng.Panel> panels = new ArrayList<>();
		final long start = System.nanoTime();
		for (final Scenario scenario : Scenario.values()) {
			final DistanceStudy study = new DistanceStudy(type, scenario, threads);
			out.printf(Locale.ROOT, "%n%s of %s particles (%.1f nm/px, D = %.1f px): threshold %.0f, r_out %.0f px, " +
				"%d images per separation, noise %s%n", scenario == Scenario.PAIR ? "Two" : "Three", type.name(), type
					.pixelSizeNm(), type.diameterPx(), type.threshold(), type.rOut(), reps, type.noise());
			out.println("Error of the measured distance of the pair (measured - true), mean and standard deviation in nm:");
			out.printf(Locale.ROOT, "  r/D  |  first pass: mean    std |  paper:  mean    std | %6s:  mean    std | lost " +
				"| paper fell back%n", Method.DEFAULT.key());
			for (int i = 0; i < DistanceStudy.SEPARATIONS.length; i++) {
				final SimulatedStack<?> stack = study.simulate(DistanceStudy.SEPARATIONS[i], reps, 1000L * scenario.ordinal() + i);
				final List<DistanceError> e = study.measure(stack, List.of(Method.FIRST, Method.PAPER, Method.DEFAULT));
				final DistanceError first = e.get(0), paper = e.get(1), best = e.get(2);
				out.printf(Locale.ROOT, "  %4.2f | %19.2f %6.2f | %13.2f %6.2f | %14.2f %6.2f | %4d | %4d%n",
					DistanceStudy.SEPARATIONS[i], first.meanErrorNm(), first.stdNm(), paper.meanErrorNm(), paper.stdNm(), best
						.meanErrorNm(), best.stdNm(), first.failures() + paper.failures() + best.failures(), paper
							.fallbacks());
				if (DistanceStudy.SEPARATIONS[i] == 1.0) panels.add(panel(study, stack, scenario));
			}
		}
		final Path png = dir.resolve("contact-tracker-demo.png");
		OverlayPng.write(png, panels, 3);
		out.printf(Locale.ROOT, "%nOverlay of a frame at contact: %s%n  cyan: r_out disc, green: second active " +
			"area, yellow: first-pass centre, red: final centre (magenta disc: flagged)%n", png);
		out.printf(Locale.ROOT, "Demo took %.1f s.%n", (System.nanoTime() - start) * 1e-9);
		return 0;
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static OverlayPng.Panel panel(final DistanceStudy study, final SimulatedStack<?> stack,
		final Scenario scenario)
	{
		final FrameResult r = new ContactTracker(study.parameters()).analyse((net.imglib2.RandomAccessibleInterval) stack
			.frames().get(0), 0);
		return new OverlayPng.Panel(stack.frames().get(0), r, study.parameters().exclusionRadius(), scenario.name()
			.toLowerCase(Locale.ROOT) + " at contact, method " + study.parameters().method().key());
	}
}
