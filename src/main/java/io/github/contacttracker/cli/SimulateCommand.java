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
import java.util.concurrent.Callable;

import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.sim.PaperParticles;
import io.github.contacttracker.sim.ParticleType;
import io.github.contacttracker.sim.Scenario;
import io.github.contacttracker.sim.SimulatedStack;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code simulate --scenario pair|triple --separation R --out stack.tif --truth truth.csv}. */
@Command(name = "simulate", description = { "Write a simulated TIFF time series of a pair or triple and its " +
	"truth CSV; print the suggested --threshold and --r-out." })
final class SimulateCommand implements Callable<Integer> {

	@Option(names = "--scenario", required = true, paramLabel = "pair|triple", description = "Two particles, or " +
		"three starting as a touching triangle.")
	String scenarioName;

	@Option(names = "--separation", required = true, paramLabel = "R_OVER_D", description = "Centre distance over " +
		"the diameter (1 = contact).")
	double separation;

	@Option(names = "--frames", paramLabel = "N", defaultValue = "100", description = "Frames. Default: " +
		"${DEFAULT-VALUE}.")
	int frames;

	@Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "Random seed. Default: " +
		"${DEFAULT-VALUE}.")
	long seed;

	@Option(names = "--out", required = true, paramLabel = "stack.tif", description = "The TIFF to write.")
	Path outFile;

	@Option(names = "--truth", required = true, paramLabel = "truth.csv", description = "The true centres (CSV).")
	Path truthOption;

	@Option(names = "--particle", paramLabel = "5.53|2.06", defaultValue = "5.53", description = "Particle type " +
		"(um). Default: ${DEFAULT-VALUE}.")
	String particleName;

	@Option(names = "--bit-depth", paramLabel = "8|16", defaultValue = "8", description = "Bits per pixel. " +
		"Default: ${DEFAULT-VALUE}.")
	int bits;

	private final PrintStream out;

	SimulateCommand(final PrintStream out) {
		this.out = out;
	}

	@Override
	public Integer call() throws IOException {
		final Scenario scenario = scenario(scenarioName);
		if (!(separation > 0) || Double.isInfinite(separation))
			throw new InvalidInputException("--separation must be positive (1 = contact)");
		if (frames < 1) throw new InvalidInputException("--frames must be at least 1");
		if (bits != 8 && bits != 16) throw new InvalidInputException("--bit-depth must be 8 or 16");
		final ParticleType type = particle(particleName);
		final Path stackFile = ContactTrackerCli.output("--out", outFile), truthFile = ContactTrackerCli.output(
			"--truth", truthOption);
		final SimulatedStack<?> stack = SimulatedStack.simulate(type, scenario, separation, frames, seed, bits);
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
