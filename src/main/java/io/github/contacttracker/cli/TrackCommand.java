package io.github.contacttracker.cli;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImagePlusFrames;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * {@code contact-tracker track MOVIE --threshold T --r-out R [options]}: localizes every frame with
 * {@link TrackingPipeline}, frames read from disk as the threads need them, and writes the spots as CSV (stdout
 * without {@code --csv}) and optionally as a TrackMate file. The tracking options and their help are
 * {@link TrackingSettings#ALL}, each as {@link Setting#cliOption()}, built with picocli's programmatic API so they
 * cannot drift from the descriptor; their values are read by the settings themselves (the same checks and
 * messages as in Fiji and TrackMate).
 */
final class TrackCommand implements Callable<Integer> {

	/** The system property the launcher sets to {@code true} when standard error is a terminal. */
	static final String STDERR_TTY = "contact.tracker.stderr.tty";

	private final PrintStream out;
	private final PrintStream err;
	private CommandSpec spec;

	private TrackCommand(final PrintStream out, final PrintStream err) {
		this.out = out;
		this.err = err;
	}

	/** @return the {@code track} command: its options generated from the settings descriptor */
	static CommandSpec spec(final PrintStream out, final PrintStream err) {
		final TrackCommand command = new TrackCommand(out, err);
		final CommandSpec spec = CommandSpec.wrapWithoutInspection(command);
		command.spec = spec;
		spec.name("track");
		spec.usageMessage().description("Localize the particles of every frame of a movie; the spots go to stdout as " +
			"CSV without --csv.", "MOVIE: a TIFF (multi-page, BigTIFF, OME-TIFF, 8/16/32-bit integer or 32/64-bit " +
				"float), an AVI (uncompressed, MJPEG, PNG), a folder of TIFF/PNG/JPEG frames, or another image ImageJ " +
				"opens.");
		spec.addPositional(PositionalParamSpec.builder().paramLabel("MOVIE").type(Path.class).description(
			"The movie, image or folder of frames.").build());
		for (final Setting<?> s : TrackingSettings.ALL)
			spec.addOption(OptionSpec.builder(s.cliOption()).type(String.class).paramLabel(metavar(s)).required(s
				.isImageSpecific()).description(s.help() + (s.isImageSpecific() ? "" : " Default: " + s.defaultValue() +
					".")).build());
		spec.addOption(OptionSpec.builder("--threads").type(int.class).paramLabel("N").defaultValue("0").description(
			"Worker threads (0: all processors).").build());
		spec.addOption(OptionSpec.builder("--csv").type(Path.class).paramLabel("OUT.csv").description(
			"Write the spots here.").build());
		spec.addOption(OptionSpec.builder("--trackmate-xml").type(Path.class).paramLabel("OUT.xml").description(
			"Also write a TrackMate file (with --csv: both or neither).").build());
		spec.addOption(OptionSpec.builder("--progress").type(boolean.class).negatable(true).description(
			"Show progress (frames/s, time left) on stderr; by default only when stderr is a terminal.").build());
		spec.addOption(OptionSpec.builder("-h", "--help").usageHelp(true).description("Show this help and exit.")
			.build());
		return spec;
	}

	private static String metavar(final Setting<?> s) {
		if (!s.choices().isEmpty()) return String.join("|", s.choices().stream().map(String::valueOf).toList());
		return s.type() == Integer.class ? "N" : s.name().equals("threshold") ? "T" : s.name().equals("r_out") ? "R" :
			"X";
	}

	private <V> V option(final String name) {
		return spec.findOption(name).getValue();
	}

	private boolean given(final Setting<?> s) {
		return spec.commandLine().getParseResult().hasMatchedOption(s.cliOption());
	}

	@Override
	public Integer call() throws IOException {
		final Path input = spec.positionalParameters().get(0).getValue();
		final SettingValues settings = settings();
		final Outputs outputs = new Outputs(option("--csv"), option("--trackmate-xml"), null);
		outputs.check();
		final int threads = option("--threads");
		final Boolean progressOption = spec.commandLine().getParseResult().hasMatchedOption("--progress") ? option(
			"--progress") : null;
		final boolean showProgress = progressOption != null ? progressOption : Boolean.getBoolean(STDERR_TTY);

		final ImagePlus imp = ImageFiles.open(input);
		// without --channel, a multi-channel image is refused rather than silently reduced to its first channel
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, given(TrackingSettings.CHANNEL) ? settings.channel() : 0);
		final Outputs files = new Outputs(outputs.csv(), outputs.trackMateXml(), outputs.trackMateXml() == null ? null
			: ImageSource.of(input, frames.width(), frames.height(), frames.frameCount()));
		final ProgressLine progress = showProgress ? new ProgressLine(err) : null;
		final TrackingResult result;
		try {
			result = new TrackingPipeline(settings).run(FrameSource.of(frames, input.toString()), files, threads, false,
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
		(files.csv() != null ? out : err).println(input + ": " + result.summary(input.getFileName().toString()));
		return 0;
	}

	/** @return the tracking settings given on the command line, the others at their defaults */
	private SettingValues settings() {
		SettingValues v = SettingValues.defaults();
		for (final Setting<?> s : TrackingSettings.ALL) {
			if (!given(s)) continue;
			try {
				v = v.withText(s, option(s.cliOption()));
			}
			catch (final InvalidInputException e) {
				throw new InvalidInputException("option " + s.cliOption() + ": " + e.getMessage(), e);
			}
		}
		return v;
	}
}
