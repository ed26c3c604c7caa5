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
import java.io.UncheckedIOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.SettingOptions;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * {@code contact-tracker track MOVIE... --threshold T --r-out R [options]}: localizes every frame with
 * {@link TrackingPipeline}, frames read from disk as the threads need them, and writes the spots as CSV (stdout
 * without {@code --csv}) and optionally as a TrackMate file. The tracking options and their help are
 * {@link TrackingSettings#ALL}, each as {@link Setting#cliOption()}, generated from the descriptor so they cannot
 * drift from it; their values are read by the settings themselves (the same checks and messages as in Fiji and
 * TrackMate).
 */
final class TrackCommand extends ContactTrackerCli.Subcommand {

	/** The system property the launcher sets to {@code true} when standard error is a terminal. */
	static final String STDERR_TTY = "contact.tracker.stderr.tty";

	private final PrintStream err;
	private final Option<Path> movieOption;
	/** Each tracking setting's option, its text read by the setting itself. */
	private final SettingOptions settingOptions;
	private final Option<Integer> threadsOption;
	private final Option<Path> csvOption;
	private final Option<Path> trackMateXmlOption;
	private final Option<Path> outDirOption;
	private final Option<Boolean> progressOption;

	/** The {@code track} command: its tracking options generated from the settings descriptor. */
	TrackCommand(final PrintStream out, final PrintStream err) {
		super(new CommandOptions("contact-tracker track", "Localize the particles of every frame of a movie; the " +
			"spots go to stdout as CSV without --csv.", "MOVIE: a TIFF (multi-page, BigTIFF, OME-TIFF, 8/16/32-bit " +
				"integer or 32/64-bit float), an AVI (uncompressed, MJPEG, PNG; grey or colour), a folder of " +
				"TIFF/PNG/JPEG frames, or another image ImageJ opens. Several movies, with --out-dir, run one after the " +
				"other in one process: the JVM starts and warms up once.").withRepeatedLastParameter(), out);
		this.err = err;
		movieOption = options.add(Option.positionalPath("MOVIE", "The movie, image or folder of frames."));
		settingOptions = new SettingOptions(options);
		threadsOption = ContactTrackerCli.threads(options);
		csvOption = options.add(Option.path("--csv", "OUT.csv", "Write the spots here."));
		trackMateXmlOption = options.add(Option.path("--trackmate-xml", "OUT.xml", "Also write a TrackMate file (with " +
			"--csv: both or neither)."));
		outDirOption = options.add(Option.path("--out-dir", "DIR", "Write each movie's spots to DIR/NAME.csv (NAME: " +
			"its file or folder name without extension); needed for several movies, instead of --csv."));
		progressOption = options.add(Option.negatableFlag("--progress", "Show progress (frames/s, time left) on " +
			"stderr; by default only when stderr is a terminal."));
	}

	@Override
	public Integer call() throws IOException {
		final List<Path> movies = options.values(movieOption);
		final SettingValues settings = settingOptions.values();
		final Path outDir = options.value(outDirOption);
		final Path csv = options.value(csvOption), xml = options.value(trackMateXmlOption);
		if (outDir != null && (csv != null || xml != null)) throw new InvalidInputException("--out-dir writes each " +
			"movie's CSV itself: give it without --csv and --trackmate-xml");
		if (movies.size() > 1 && outDir == null) throw new InvalidInputException(movies.size() + " movies need " +
			"--out-dir DIR (each movie's spots go to DIR/NAME.csv)");
		return io.github.contacttracker.io.OutputFolder.removedIfRefused(outDir, () -> run(movies, settings, outDir, csv,
			xml));
	}

	/** Tracks the movies into their outputs; @return the exit status (some of several movies failed: 2) */
	private int run(final List<Path> movies, final SettingValues settings, final Path outDir, final Path csv,
		final Path xml) throws IOException
	{
		final List<Outputs> outputs = new ArrayList<>();
		if (outDir == null) outputs.add(new Outputs(csv, xml, null));
		else {
			io.github.contacttracker.io.OutputFolder.prepare(outDir);
			final Map<Path, Path> movieOf = new HashMap<>();
			for (final Path movie : movies) {
				final Path file = outDir.resolve(name(movie) + ".csv");
				final Path other = movieOf.put(file.toAbsolutePath().normalize(), movie);
				if (other != null) throw new InvalidInputException(other + " and " + movie + " would both be written to " +
					file + ": rename one, or run them with different --out-dir");
				outputs.add(new Outputs(file, null, null));
			}
		}
		for (final Outputs o : outputs)
			o.check();
		final int threads = options.value(threadsOption);
		final boolean showProgress = options.given(progressOption) ? options.value(progressOption) : Boolean.getBoolean(
			STDERR_TTY);
		if (movies.size() == 1) {
			final Path movie = movies.get(0);
			try {
				track(movie, outputs.get(0), settings, threads, showProgress);
			}
			catch (final InvalidInputException e) { // named after the movie, as each of several movies is
				final String name = movie.getFileName().toString();
				if (e.getMessage() != null && e.getMessage().contains(name)) throw e;
				throw new InvalidInputException(name + ": " + e.getMessage(), e);
			}
			return 0;
		}
		// several movies: a movie that cannot be tracked is reported, and the others are still done
		int failed = 0;
		for (int m = 0; m < movies.size(); m++) {
			try {
				track(movies.get(m), outputs.get(m), settings, threads, showProgress);
			}
			catch (final InvalidInputException | IOException | UncheckedIOException e) {
				err.println("contact-tracker: error: " + movies.get(m) + ": " + InvalidInputException.oneLine(e.getMessage()));
				failed++;
			}
		}
		if (failed == 0) return 0;
		err.println("contact-tracker: " + failed + " of " + movies.size() + " movies failed (see above); the others " +
			"were written");
		return ContactTrackerCli.EXIT_BAD_INPUT;
	}

	/** Tracks one movie into {@code outputs} (the spots to stdout without a CSV file), its summary on stdout. */
	private void track(final Path input, final Outputs outputs, final SettingValues settings, final int threads,
		final boolean showProgress) throws IOException
	{
		final ImagePlus imp = ImageFiles.open(input);
		// without --channel, a multi-channel image is refused rather than silently reduced to its first channel
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, settingOptions.given(TrackingSettings.CHANNEL)
			? settings.channel() : 0);
		final StringBuilder notice = new StringBuilder();
		if (!frames.colourChoice().isEmpty()) notice.append("contact-tracker: ").append(frames.colourChoice());
		final String calibrated = calibrated(input, frames.calibration());
		if (!calibrated.isEmpty()) notice.append(notice.length() > 0 ? "\n" : "").append(calibrated);
		final SettingValues used = measured(input, imp, frames, settings, notice);
		final Outputs files = new Outputs(outputs.csv(), outputs.trackMateXml(), outputs.trackMateXml() == null ? null
			: ImageSource.of(input, frames.width(), frames.height(), frames.frameCount()));
		final ProgressLine progress = showProgress ? new ProgressLine(err) : null;
		final TrackingResult result;
		try {
			result = new TrackingPipeline(used).run(FrameSource.of(frames, input.toString()), files, threads, false,
				progress == null ? null : progress::progress, () -> false);
		}
		finally {
			if (progress != null) progress.end();
		}
		if (files.csv() == null) {
			final Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
			SpotCsvWriter.write(w, result.spots(), frames.calibration());
			w.flush();
		}
		// said after the tracking, so that a run refused for a given value still ends with one line
		if (notice.length() > 0) err.println(notice);
		(files.csv() != null ? out : err).println(input + ": " + result.summary(input.getFileName().toString()));
	}

	/**
	 * The settings with what was not given measured from the movie's first frame ({@link MeasuredSettings}); what was
	 * measured goes into {@code notice}.
	 */
	private SettingValues measured(final Path input, final ImagePlus imp, final ImagePlusFrames frames,
		final SettingValues settings, final StringBuilder notice)
	{
		final MeasuredSettings.Result r = MeasuredSettings.of(input.getFileName().toString(), frames::frame, frames
			.frameCount(), imp.getBitDepth() != 32, settings, settingOptions.given(), FrontEnd.COMMAND_LINE);
		if (notice.length() > 0 && !r.notice().isEmpty()) notice.append('\n');
		notice.append(r.notice());
		return r.settings();
	}

	/**
	 * @return where the file's calibration is a printer's resolution, in inches or centimetres, a line that says the
	 *         spots' positions and sizes are in that unit: a TIFF saved by a camera program or a screenshot tool at 96
	 *         pixels per inch gives positions of a few inches across a whole frame, which read as a tracker gone wrong
	 *         (two public tweezer snapshots: every spot within 13 units of the corner). A microscope's calibration (µm,
	 *         nm) is what TrackMate's tables use, and is not said. Empty otherwise.
	 */
	static String calibrated(final Path input, final Calibration c) {
		if (!PRINTER_UNITS.contains(c.unit().toLowerCase(Locale.ROOT))) return "";
		return String.format(Locale.ROOT, "contact-tracker: %s is calibrated: the spots' positions and sizes are in %s, " +
			"a pixel %s x %s %s (the file's own calibration, as ImageJ reads it)", input.getFileName(), c.unit(), Numbers
				.fmt(c.pixelWidth(), 6), Numbers.fmt(c.pixelHeight(), 6), c.unit());
	}

	/** Units of a printer's resolution, as ImageJ names them from a TIFF's resolution tags. */
	private static final List<String> PRINTER_UNITS = List.of("inch", "in", "cm", "centimeter", "centimetre");

	/** @return a movie's name for its CSV: the file name without its extension (a folder's name as it is) */
	static String name(final Path movie) {
		final Path fileName = movie.toAbsolutePath().normalize().getFileName();
		final String name = fileName == null ? "movie" : fileName.toString();
		return Files.isDirectory(movie) ? name : Outputs.baseName(name);
	}
}
