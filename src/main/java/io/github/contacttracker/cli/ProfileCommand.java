package io.github.contacttracker.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.ProfileAnalysis;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImagePlusFrames;
import io.github.contacttracker.io.ProfilePlots;
import net.imglib2.RandomAccessibleInterval;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code profile MOVIE [--at X,Y] [--frame N] [--diameter D] [--max-radius R] [--png OUT.png] [--csv OUT.csv]}:
 * the radial profile of the movie's isolated particles (or of the one at a point), printed as a table, plotted,
 * and read off into the tracking settings to copy. The same analysis as Fiji's Contact Tracker Profile
 * ({@link ProfileAnalysis}).
 */
@Command(name = "profile", sortOptions = false, mixinStandardHelpOptions = true,
	description = { "Radial profile of isolated particles and suggested --threshold, --r-out and --diameter.",
		"Finds the frame's most isolated particles itself (or takes --at X,Y), pools their profiles (ring medians " +
			"above a local background plane), estimates the noise robustly, and prints a line to copy." })
public final class ProfileCommand implements Callable<Integer> {

	/** The line the command ends with, followed by the suggested options. */
	public static final String SUGGESTION = "suggested:";

	@Parameters(index = "0", paramLabel = "MOVIE", description = "the image or movie (as 'track' reads it)")
	Path movie;

	@Option(names = "--at", paramLabel = "X,Y", split = ",", arity = "1",
		description = "a point on the particle to profile (px, pixel (0,0)'s centre at 0,0); default: find isolated " +
			"particles")
	double[] at;

	@Option(names = "--frame", paramLabel = "N", description = "frame to profile, counted from 1 (default: 1)")
	int frame = 1;

	@Option(names = "--diameter", paramLabel = "D",
		description = "particle diameter in px (the centre distance at contact); default: estimated from the " +
			"particles' nearest-neighbour distances")
	double diameter = 0;

	@Option(names = "--max-radius", paramLabel = "R",
		description = "how far out the profile is measured (px); default: 2.5 diameters")
	double maxRadius = 0;

	@Option(names = "--channel", paramLabel = "C", description = "channel of a multi-channel image (from 1)")
	int channel = 0;

	@Option(names = "--png", paramLabel = "OUT.png", description = "write the profile plot")
	Path png;

	@Option(names = "--csv", paramLabel = "OUT.csv", description = "write the profile table")
	Path csv;

	private final PrintStream out;

	ProfileCommand(final PrintStream out) {
		this.out = out;
	}

	@Override
	public Integer call() throws IOException {
		if (at != null && at.length != 2) throw new InvalidInputException("--at needs X,Y, not " + at.length +
			" numbers");
		if (png != null) AtomicFile.checkFolder("png", png);
		if (csv != null) AtomicFile.checkFolder("csv", csv);
		final ImagePlus imp = ImageFiles.open(movie);
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, channel);
		if (frame < 1 || frame > frames.frameCount())
			throw new InvalidInputException("--frame " + frame + " does not exist: " + movie + " has " + frames
				.frameCount() + " frame" + (frames.frameCount() == 1 ? "" : "s"));
		final ProfileAnalysis.Result r = analyse(frames.frames().get(frame - 1));
		final boolean integerData = imp.getBitDepth() != 32;
		final double threshold = r.suggestedThreshold(integerData), rOut = r.suggestedROut();

		out.printf(Locale.ROOT, "%s, frame %d: profile of %d particle%s around %s%n", movie.getFileName(), frame, r
			.particles(), r.particles() == 1 ? "" : "s", centres(r));
		out.println("   r_px    level  above_bg  pixels");
		for (int k = 0; k < r.radius().length; k++)
			if (r.count()[k] > 0) out.printf(Locale.ROOT, "%7.2f %8.2f %9.2f %7d%n", r.radius()[k], r.level()[k], r
				.level()[k] - r.background(), r.count()[k]);
		for (final String line : r.report(integerData))
			out.println(line);
		for (final String w : r.warnings())
			out.println("  warning: " + w);
		final List<Path> targets = new ArrayList<>();
		if (png != null) {
			ProfilePlots.writePng(ProfilePlots.plot(r, "Contact Tracker Profile: " + movie.getFileName(), threshold,
				rOut), png);
			targets.add(png);
		}
		if (csv != null) {
			try {
				ProfilePlots.writeCsv(r, csv);
			}
			catch (final IOException e) {
				if (png != null) java.nio.file.Files.deleteIfExists(png); // both or neither
				throw e;
			}
			targets.add(csv);
		}
		for (final Path t : targets)
			out.println("  wrote " + t);
		out.println(SUGGESTION + " --threshold " + fmt(threshold) + " --r-out " + fmt(rOut) + " --diameter " + new java.math
			.BigDecimal(String.format(Locale.ROOT, "%.2f", r.diameter())).stripTrailingZeros().toPlainString());
		return 0;
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private ProfileAnalysis.Result analyse(final RandomAccessibleInterval frame) {
		return at != null ? ProfileAnalysis.analyse(frame, at[0], at[1], diameter, maxRadius) : ProfileAnalysis.analyse(
			frame, diameter, maxRadius);
	}

	private static String centres(final ProfileAnalysis.Result r) {
		final StringBuilder b = new StringBuilder();
		for (final double[] c : r.centres())
			b.append(b.length() == 0 ? "" : " ").append(String.format(Locale.ROOT, "(%.1f, %.1f)", c[0], c[1]));
		return b.toString();
	}

	private static String fmt(final double v) {
		return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : String.format(Locale.ROOT, "%.4g", v);
	}
}
