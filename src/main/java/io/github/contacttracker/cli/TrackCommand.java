package io.github.contacttracker.cli;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Set;

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

/**
 * {@code contact-tracker track INPUT.tif --threshold T --r-out R [options]}: localizes every frame with
 * {@link TrackingPipeline} and writes the spots as CSV (stdout without {@code --csv}) and optionally as a TrackMate
 * file. The tracking options are {@link TrackingSettings#ALL}, each as {@link Setting#cliOption()}.
 */
final class TrackCommand {

	/** Options of the run itself, beside the tracking settings. */
	private static final String THREADS = "threads", CSV = "csv", XML = "trackmate-xml";

	private final PrintStream out;
	private final PrintStream err;

	TrackCommand(final PrintStream out, final PrintStream err) {
		this.out = out;
		this.err = err;
	}

	/** @return every option name (without "--") */
	static Set<String> options() {
		final Set<String> names = new LinkedHashSet<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			names.add(s.cliOption().substring(2));
		names.add(THREADS);
		names.add(CSV);
		names.add(XML);
		return names;
	}

	/** @return the usage text of {@code track}, generated from the settings so it cannot drift from them */
	static String usage() {
		final StringBuilder sb = new StringBuilder("  track INPUT.tif");
		for (final Setting<?> s : TrackingSettings.ALL)
			if (s.isImageSpecific()) sb.append(' ').append(s.cliOption()).append(' ').append(metavar(s));
		sb.append(" [options]\n");
		sb.append("                             localize the particles of every frame; CSV to stdout without --csv\n");
		for (final Setting<?> s : TrackingSettings.ALL)
			option(sb, s.cliOption() + " " + metavar(s), s.help() + (s.isImageSpecific() ? " Required." : " Default " +
				s.defaultValue() + "."));
		option(sb, "--threads N", "Worker threads. Default: all processors.");
		option(sb, "--csv OUT.csv", "Write the spots here.");
		option(sb, "--trackmate-xml OUT.xml", "Also write a TrackMate file (with --csv: both or neither).");
		return sb.toString().stripTrailing();
	}

	/** One option of the usage: its name, then its help wrapped to 100 columns under the help column. */
	private static void option(final StringBuilder sb, final String name, final String help) {
		final String indent = " ".repeat(33);
		String line = String.format(Locale.ROOT, "      %-26s ", name);
		if (line.length() > indent.length()) {
			sb.append(line.stripTrailing()).append('\n');
			line = indent;
		}
		for (final String word : help.split(" ")) {
			if (line.length() + word.length() > 100 && !line.isBlank()) {
				sb.append(line.stripTrailing()).append('\n');
				line = indent;
			}
			line += word + " ";
		}
		sb.append(line.stripTrailing()).append('\n');
	}

	private static String metavar(final Setting<?> s) {
		if (!s.choices().isEmpty()) return String.join("|", s.choices().stream().map(String::valueOf).toList());
		return s.type() == Integer.class ? "N" : s.name().equals("threshold") ? "T" : s.name().equals("r_out") ? "R" :
			"X";
	}

	int run(final String[] args) throws IOException {
		final Options o = new Options(args, options());
		if (o.positional().size() != 1)
			throw new InvalidInputException("track needs exactly one input file, got " + o.positional().size());
		final Path input = Path.of(o.positional().get(0));
		final SettingValues settings = settings(o);
		final Outputs outputs = new Outputs(o.path(CSV), o.path(XML), null);
		outputs.check();
		final int threads = o.integer(THREADS, 0);

		final ImagePlus imp = ImageFiles.open(input);
		// without --channel, a multi-channel image is refused rather than silently reduced to its first channel
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, o.has(option(TrackingSettings.CHANNEL)) ? settings
			.channel() : 0);
		final Outputs files = new Outputs(outputs.csv(), outputs.trackMateXml(), outputs.trackMateXml() == null ? null
			: ImageSource.of(input, frames.width(), frames.height(), frames.frameCount()));
		final TrackingResult result = new TrackingPipeline(settings).run(FrameSource.of(frames, input.toString()),
			files, threads, false, null, () -> false);
		if (files.csv() == null) {
			final Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
			SpotCsvWriter.write(w, result.spots(), frames.calibration());
			w.flush();
		}
		(files.csv() != null ? out : err).println(input + ": " + result.summary(input.getFileName().toString()));
		return 0;
	}

	private static String option(final Setting<?> s) {
		return s.cliOption().substring(2);
	}

	/** @return the tracking settings given on the command line, the others at their defaults */
	static SettingValues settings(final Options o) {
		SettingValues v = SettingValues.defaults();
		for (final Setting<?> s : TrackingSettings.ALL) {
			final String name = option(s);
			if (o.has(name)) {
				try {
					v = v.withText(s, o.string(name, null));
				}
				catch (final InvalidInputException e) {
					throw new InvalidInputException("option " + s.cliOption() + ": " + e.getMessage(), e);
				}
			}
			else if (s.isImageSpecific()) throw new InvalidInputException("missing option " + s.cliOption() + " (" + s
				.help() + ")");
		}
		return v;
	}
}
