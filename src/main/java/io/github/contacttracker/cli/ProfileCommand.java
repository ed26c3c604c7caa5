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

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import ij.ImagePlus;
import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.plot.ProfilePlots;
import io.github.contacttracker.report.ProfileReport;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;

/**
 * {@code profile MOVIE [--at X,Y] [--frame N] [--diameter D] [--max-radius R] [--png OUT.png] [--csv OUT.csv]}:
 * the radial profile of the movie's isolated particles (or of the one at a point), printed as a table, plotted,
 * and read off into the tracking settings to copy; the kinds of particle at those settings, a line each. The same
 * analysis as Fiji's Contact Tracker Profile ({@link ProfileAnalysis}).
 */
public final class ProfileCommand extends ContactTrackerCli.Subcommand {

	/** The line the command ends with, followed by the suggested options. */
	public static final String SUGGESTION = "suggested:";

	private final Option<Path> movieOption = options.add(Option.positionalPath("MOVIE", "the image or movie (as " +
		"'track' reads it)"));
	private final Option<double[]> atOption = options.add(Option.valued("--at", "X,Y", "a point on the particle to " +
		"profile (px, pixel (0,0)'s centre at 0,0); default: find isolated particles", ProfileCommand::numbers));
	private final Option<Integer> frameOption = options.add(Option.integer("--frame", "N", "frame to profile, " +
		"counted from 1 (default: 1)").withDefaultExplained("1"));
	private final Option<Double> diameterOption = options.add(Option.decimal("--diameter", "D", "particle diameter " +
		"in px (the centre distance at contact); default: estimated from the particles' nearest-neighbour distances")
		.withDefaultExplained("0"));
	private final Option<Double> maxRadiusOption = options.add(Option.decimal("--max-radius", "R", "how far out the " +
		"profile is measured (px); default: 2.5 diameters").withDefaultExplained("0"));
	private final Option<Integer> channelOption = options.add(Option.integer("--channel", "C", "channel of a " +
		"multi-channel image (from 1), or of a colour one (1 red, 2 green, 3 blue)").withDefaultExplained("0"));
	private final Option<String> particlesOption = options.add(Option.text("--particles", "bright|dark", "particles " +
		"brighter or darker than the background (dark: the image inverted first, as 'track --particles dark'); " +
		"default: as 'track' judges it: dark where the frame's dark blobs stand out more than its bright ones (and " +
		"its brightest pixel lies at most 1.2 times as far above the background as its darkest below), else bright")
			.withDefaultExplained("bright"));
	private final Option<Path> pngOption = options.add(Option.path("--png", "OUT.png", "write the profile plot"));
	private final Option<Path> csvOption = options.add(Option.path("--csv", "OUT.csv", "write the profile table"));

	ProfileCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker profile", "Radial profile of isolated particles and suggested " +
			"--threshold, --r-out and --diameter.", "Finds the frame's most isolated particles itself (or takes --at " +
				"X,Y), pools their profiles (ring medians above a local background plane), estimates the noise " +
				"robustly, reports the kinds of particle at the suggested settings (on the frame and the next " +
				"four), and prints a line to copy.").inDeclarationOrder(), out);
	}

	@Override
	public Integer call() throws IOException {
		final Path movie = options.value(movieOption), png = options.value(pngOption), csv = options.value(csvOption);
		final double[] at = options.value(atOption);
		final int frame = options.value(frameOption);
		if (at != null && at.length != 2) throw new InvalidInputException("--at needs X,Y, not " + at.length +
			" numbers");
		if (png != null) AtomicFile.checkFolder("png", png);
		if (csv != null) AtomicFile.checkFolder("csv", csv);
		final ImagePlus imp = ImageFiles.open(movie);
		final boolean given = options.given(particlesOption);
		final boolean said = SettingValues.defaults().withText(TrackingSettings.PARTICLES, options.value(
			particlesOption)).dark();
		final ImagePlusFrames plain = ImagePlusFrames.of(imp, options.value(channelOption));
		// as 'track' measures: dark where the frame looks so, unless bright or dark was said
		final boolean dark = said || !given && frame >= 1 && frame <= plain.frameCount() && Contrast.looksDark(plain
			.frame(frame - 1), options.value(diameterOption));
		final ImagePlusFrames frames = dark ? ImagePlusFrames.of(imp, options.value(channelOption), true) : plain;
		if (frame < 1 || frame > frames.frameCount())
			throw new InvalidInputException("--frame " + frame + " does not exist: " + movie + " has " + frames
				.frameCount() + " frame" + (frames.frameCount() == 1 ? "" : "s"));
		final ProfileAnalysis.Result r;
		try {
			r = analyse(frames.frames().get(frame - 1), at, ShownFrameProfile.kindFrames(frames, frame - 1));
		}
		catch (final InvalidInputException e) { // the helper's finding, said of this movie's frame
			throw new InvalidInputException(movie.getFileName() + ", frame " + frame + ": " + e.getMessage(), e);
		}
		final boolean integerData = imp.getBitDepth() != 32;
		final double threshold = r.suggestedThreshold(integerData), rOut = r.suggestedROut();

		if (!frames.colourChoice().isEmpty()) out.println(frames.colourChoice());
		out.printf(Locale.ROOT, "%s, frame %d: profile of %d particle%s around %s%n", movie.getFileName(), frame, r
			.particles(), r.particles() == 1 ? "" : "s", centres(r));
		out.println("   r_px    level  above_bg  pixels");
		for (int k = 0; k < r.radius().length; k++)
			if (r.count()[k] > 0) out.printf(Locale.ROOT, "%7.2f %8.2f %9.2f %7d%n", r.radius()[k], r.level()[k], r
				.level()[k] - r.background(), r.count()[k]);
		for (final String line : ProfileReport.lines(r, integerData))
			out.println(line);
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
		final double[] range = ImagePlusFrames.range(frames.frame(frame - 1), frame - 1);
		if (threshold > range[1] || threshold < range[0]) {
			out.println(SUGGESTION + byImage(movie, plain.frame(frame - 1), threshold, range, integerData, given, said));
			return 0;
		}
		out.println(SUGGESTION + " --threshold " + MeasuredSettings.optionValue(threshold) + " --r-out " + MeasuredSettings
			.optionValue(rOut) + " --diameter " + MeasuredSettings.optionValue(r.suggestedDiameter()) + (r.smallParticles(
				threshold) ? " --min-area " + r.suggestedMinArea(threshold) : "") + (dark ? " --particles dark" : ""));
		return 0;
	}

	/**
	 * Where the helper's threshold lies outside the frame's range, no threshold keeps two such particles apart (or
	 * the helper's background lies under every pixel, in a field packed edge to edge): the values {@code track}
	 * measures then, by the particles' image ({@link MeasuredSettings}), said in a warning first.
	 *
	 * @return the options to suggest, or where {@code track} would refuse the frame, why
	 */
	private String byImage(final Path movie, final RandomAccessibleInterval<?> frame, final double threshold,
		final double[] range, final boolean integerData, final boolean particlesGiven, final boolean dark)
	{
		final boolean above = threshold > range[1];
		out.println("  warning: the threshold " + MeasuredSettings.optionValue(threshold) + " lies " + (above ? "above"
			: "below") + " every pixel of the frame (" + MeasuredSettings.optionValue(above ? range[1] : range[0]) +
			"): no threshold cuts these particles apart, and 'track' finds them by their image with the values below");
		try {
			final SettingValues v = MeasuredSettings.of(movie.getFileName().toString(), frame, integerData, SettingValues
				.defaults(), options.value(diameterOption), !particlesGiven ? null : dark ? TrackingSettings.DARK
					: TrackingSettings.PARTICLES.defaultValue(), FrontEnd.COMMAND_LINE).settings();
			return " --detection " + v.get(TrackingSettings.DETECTION) + " --threshold " + MeasuredSettings.optionValue(v
				.get(TrackingSettings.THRESHOLD)) + " --r-out " + MeasuredSettings.optionValue(v.get(TrackingSettings.R_OUT)) +
				" --diameter " + MeasuredSettings.optionValue(v.diameter()) + (v.dark() ? " --particles dark" : "");
		}
		catch (final InvalidInputException e) {
			return " none: " + InvalidInputException.oneLine(e.getMessage());
		}
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private ProfileAnalysis.Result analyse(final RandomAccessibleInterval frame, final double[] at,
		final List kindFrames)
	{
		final double diameter = options.value(diameterOption), maxRadius = options.value(maxRadiusOption);
		return at != null ? ProfileAnalysis.analyse(frame, at[0], at[1], diameter, maxRadius, kindFrames)
			: ProfileAnalysis.analyse(frame, diameter, maxRadius, kindFrames);
	}

	/** @return the numbers of {@code --at}, separated by commas (their count is checked when the command runs) */
	private static double[] numbers(final String text) {
		final String[] parts = text.split(",");
		final double[] numbers = new double[parts.length];
		for (int i = 0; i < parts.length; i++)
			numbers[i] = Option.DOUBLE.apply(parts[i]);
		return numbers;
	}

	private static String centres(final ProfileAnalysis.Result r) {
		final StringBuilder b = new StringBuilder();
		for (final double[] c : r.centres())
			b.append(b.length() == 0 ? "" : " ").append(String.format(Locale.ROOT, "(%.1f, %.1f)", c[0], c[1]));
		return b.toString();
	}

}
