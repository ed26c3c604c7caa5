package io.github.contacttracker.cli;

import io.github.contacttracker.io.AtomicFile;
import java.nio.charset.StandardCharsets;
import java.io.OutputStreamWriter;
import java.io.BufferedWriter;
import io.github.contacttracker.core.InvalidInputException;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Set;

import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.sim.PaperParticles;
import io.github.contacttracker.sim.ParticleType;
import io.github.contacttracker.sim.Scenario;
import io.github.contacttracker.sim.SimulatedStack;

/** {@code simulate --scenario pair|triple --separation R --out stack.tif --truth truth.csv}. */
final class SimulateCommand {

	private static final Set<String> OPTIONS = Set.of("scenario", "separation", "frames", "seed", "out", "truth",
		"particle", "bit-depth");

	private final PrintStream out;

	SimulateCommand(final PrintStream out) {
		this.out = out;
	}

	int run(final String[] args) throws IOException {
		final Options o = new Options(args, OPTIONS);
		if (!o.positional().isEmpty())
			throw new InvalidInputException("simulate takes no positional argument: '" + o.positional().get(0) + "'");
		final Scenario scenario = scenario(o.required("scenario"));
		final double separation = o.number("separation");
		if (!(separation > 0)) throw new InvalidInputException("--separation must be positive (1 = contact)");
		final int frames = o.integer("frames", 100);
		if (frames < 1) throw new InvalidInputException("--frames must be at least 1");
		final int bits = o.integer("bit-depth", 8);
		if (bits != 8 && bits != 16) throw new InvalidInputException("--bit-depth must be 8 or 16");
		final ParticleType type = particle(o.string("particle", "5.53"));
		o.required("out");
		o.required("truth");
		final Path stackFile = o.outputPath("out"), truthFile = o.outputPath("truth");
		final SimulatedStack<?> stack = SimulatedStack.simulate(type, scenario, separation, frames, o.longInteger(
			"seed", 1), bits);
		final Calibration cal = Calibration.ofPixelSize(type.pixelSizeMicrons(), "micron");
		ImageFiles.saveTiff(ImageFiles.timeSeries(stackFile.getFileName().toString(), stack.frames(), cal), stackFile);
		try {
			AtomicFile.write(truthFile, stream -> stack.writeTruthCsv(new BufferedWriter(new OutputStreamWriter(stream,
				StandardCharsets.UTF_8))));
		}
		catch (final IOException e) {
			Files.deleteIfExists(stackFile); // both or neither
			throw e;
		}
		out.printf(Locale.ROOT,
			"%s: %d frames %dx%d, %s of %s at r/D = %.3f; suggested --threshold %s --r-out %s; truth in %s%n",
			stackFile, frames, stack.width(), stack.height(), scenario.name().toLowerCase(Locale.ROOT), type.name(),
			separation, fmt(type.threshold()), fmt(type.rOut()), truthFile);
		return 0;
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

	private static String fmt(final double v) {
		return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.1f", v);
	}
}
