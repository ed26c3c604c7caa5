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

import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.io.AtomicFile;
import java.nio.charset.StandardCharsets;
import java.io.OutputStreamWriter;
import java.io.BufferedWriter;
import io.github.contacttracker.core.InvalidInputException;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.lab.sim.DetectionScenes;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;
import net.imglib2.img.array.ArrayImg;

/**
 * {@code simulate --scenario pair|triple --separation R --out stack.tif --truth truth.csv}, or {@code simulate
 * --detection-scene KEY --out movie.tif --truth truth.csv}: one of the detection study's scenes as a movie to open in
 * Fiji or track, with its truth.
 */
final class SimulateCommand extends ContactTrackerCli.Subcommand {

	private final Option<String> scenarioOption = options.add(Option.text("--scenario", "pair|triple", "Two " +
		"particles, or three starting as a touching triangle (required unless --detection-scene)."));
	private final Option<Double> separationOption = options.add(Option.decimal("--separation", "R_OVER_D", "Centre " +
		"distance over the diameter (1 = contact; required with --scenario)."));
	private final Option<String> detectionSceneOption = options.add(Option.text("--detection-scene", "KEY",
		"Instead of --scenario, one movie of a scene of 'accuracy --detection-scenes' (" + String.join(", ",
			DetectionScenes.KEYS) + "), as the study renders it; its truth CSV holds each particle's frame, index, " +
		"x, y (px), diameter (px) and band."));
	private final Option<Integer> framesOption = options.add(Option.integer("--frames", "N", "Frames (with " +
		"--detection-scene: default the study's).").withDefault("100"));
	private final Option<Long> seedOption = options.add(Option.longInteger("--seed", "S", "Random seed.").withDefault(
		"1"));
	private final Option<Path> outOption = options.add(Option.path("--out", "stack.tif", "The TIFF to write.")
		.asRequired());
	private final Option<Path> truthOption = options.add(Option.path("--truth", "truth.csv", "The true centres (CSV).")
		.asRequired());
	private final Option<String> particleOption = options.add(Option.text("--particle", "5.53|2.06", "Particle type " +
		"(um).").withDefault("5.53"));
	private final Option<Integer> bitsOption = options.add(Option.integer("--bit-depth", "8|16", "Bits per pixel.")
		.withDefault("8"));

	SimulateCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker simulate", "Write a simulated TIFF time series of a pair or triple " +
			"and its truth CSV; print the suggested --threshold and --r-out."), out);
	}

	@Override
	public Integer call() throws IOException {
		if (options.given(detectionSceneOption)) return detectionScene();
		if (!options.given(scenarioOption) || !options.given(separationOption))
			throw new InvalidInputException("simulate needs --scenario and --separation, or --detection-scene");
		final Scenario scenario = scenario(options.value(scenarioOption));
		final double separation = options.value(separationOption);
		final int frames = options.value(framesOption), bits = options.value(bitsOption);
		if (!(separation > 0) || Double.isInfinite(separation))
			throw new InvalidInputException("--separation must be positive (1 = contact)");
		if (frames < 1) throw new InvalidInputException("--frames must be at least 1");
		if (bits != 8 && bits != 16) throw new InvalidInputException("--bit-depth must be 8 or 16");
		final ParticleType type = particle(options.value(particleOption));
		final Path stackFile = ContactTrackerCli.output("--out", options.value(outOption)), truthFile = ContactTrackerCli
			.output("--truth", options.value(truthOption));
		final SimulatedStack<?> stack = SimulatedStack.simulate(type, scenario, separation, frames, options.value(
			seedOption), bits);
		final Calibration cal = Calibration.ofPixelSize(type.pixelSizeMicrons(), "micron");
		write(stackFile, stack.frames(), cal, truthFile, stack::writeTruthCsv);
		out.printf(Locale.ROOT,
			"%s: %d frames %dx%d, %s of %s at r/D = %.3f; suggested --threshold %s --r-out %s; truth in %s%n",
			stackFile, frames, stack.width(), stack.height(), scenario.name().toLowerCase(Locale.ROOT), type.name(),
			separation, Numbers.fmt(type.threshold()), Numbers.fmt(type.rOut()), truthFile);
		return 0;
	}

	/** Writes one movie of a detection-study scene and its truth. */
	private int detectionScene() throws IOException {
		final String key = options.value(detectionSceneOption).trim();
		if (!DetectionScenes.KEYS.contains(key)) throw new InvalidInputException("--detection-scene must be one of " +
			String.join(", ", DetectionScenes.KEYS) + ", not '" + key + "'");
		if (options.given(scenarioOption) || options.given(separationOption) || options.given(particleOption) || options
			.given(bitsOption)) throw new InvalidInputException("--detection-scene takes no --scenario, --separation, " +
				"--particle or --bit-depth (the scene sets them)");
		final int frames = options.given(framesOption) ? options.value(framesOption) : DetectionScenes.defaultFrames(
			key);
		if (frames < 1) throw new InvalidInputException("--frames must be at least 1");
		final Path stackFile = ContactTrackerCli.output("--out", options.value(outOption)), truthFile = ContactTrackerCli
			.output("--truth", options.value(truthOption));
		final DetectionScene scene = DetectionScenes.of(key, frames, options.value(seedOption));
		final Calibration cal = Calibration.ofPixelSize(scene.pixelSizeNm() / 1000, "micron");
		write(stackFile, scene.frames(), cal, truthFile, w -> {
			w.write("frame,particle,x_px,y_px,diameter_px,band\n");
			for (int t = 0; t < scene.frames().size(); t++)
				for (int k = 0; k < scene.truth().get(t).size(); k++) {
					final double[] c = scene.truth().get(t).get(k);
					w.write(String.format(Locale.ROOT, "%d,%d,%.6f,%.6f,%.4f,%s%n", t, k, c[0], c[1], scene.diameter(k),
						scene.band(t, k)));
				}
			w.flush();
		});
		out.printf(Locale.ROOT, "%s: %d frames %dx%d of the detection scene %s (%d particles; %s); truth in %s%n",
			stackFile, frames, scene.width(), scene.height(), key, scene.scene().particles().size(), scene.description(),
			truthFile);
		return 0;
	}

	/** Writes the truth CSV to {@code w} (UTF-8), flushing it. */
	private interface Truth {
		void write(BufferedWriter w) throws IOException;
	}

	/** Writes the stack, then its truth: both or neither (the stack is deleted where the truth cannot be written). */
	private static void write(final Path stackFile, final List<? extends ArrayImg<?, ?>> frames,
		final Calibration cal, final Path truthFile, final Truth truth) throws IOException
	{
		ImageFiles.saveTiff(TimeSeries.of(stackFile.getFileName().toString(), frames, cal), stackFile);
		try {
			AtomicFile.write(truthFile, stream -> truth.write(new BufferedWriter(new OutputStreamWriter(stream,
				StandardCharsets.UTF_8))));
		}
		catch (final IOException e) {
			Files.deleteIfExists(stackFile); // both or neither
			throw e;
		}
	}

	static Scenario scenario(final String text) {
		for (final Scenario s : Scenario.values())
			if (s.name().equalsIgnoreCase(text.trim())) return s;
		throw new InvalidInputException("--scenario must be pair or triple, not '" + text + "'");
	}

	static ParticleType particle(final String text) {
		switch (text.trim()) {
			case "5.53": return PaperParticles.silica553();
			case "2.06": return PaperParticles.silica206();
			default: throw new InvalidInputException("--particle must be 5.53 or 2.06 (um), not '" + text + "'");
		}
	}
}
