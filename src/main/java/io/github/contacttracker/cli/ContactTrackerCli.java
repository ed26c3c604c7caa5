package io.github.contacttracker.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.AtomicFile;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;

/**
 * The command line: {@code contact-tracker demo | track | simulate | bench | accuracy | potential |
 * demo-potential}, parsed with picocli; every subcommand has {@code --help}. Bad input (an unknown or mistyped
 * option, a missing file, an untrackable image) ends with a one-line error on stderr and exit status 2; an
 * unexpected failure with a stack trace and exit status 1.
 */
public final class ContactTrackerCli {

	/** Exit status for bad input (missing file, bad option, untrackable image). */
	public static final int EXIT_BAD_INPUT = 2;

	/** The top-level command: only a list of subcommands and the help. */
	@Command(name = "contact-tracker", mixinStandardHelpOptions = true, version = "Contact Tracker",
		description = "Sub-pixel localization of colloidal particles, also when they touch.", footer = { "",
			"Run 'contact-tracker COMMAND --help' for a command's options. Bad input exits with status 2 and a " +
				"one-line error; no partial output file is left behind." })
	static final class Root {}

	/** {@code -h}/{@code --help} of every subcommand. */
	@Command(mixinStandardHelpOptions = false)
	static final class Help {
		@CommandLine.Option(names = { "-h", "--help" }, usageHelp = true, description = "Show this help and exit.")
		boolean help;
	}

	/** {@code --threads N} of the subcommands that simulate and track. */
	static final class Threads {
		@CommandLine.Option(names = "--threads", paramLabel = "N", defaultValue = "0", description = "Worker threads " +
			"(0: all processors).")
		int threads;
	}

	private ContactTrackerCli() {}

	public static void main(final String[] args) {
		final PrintStream stdout = System.out;
		// ImageJ 1 prints its log (e.g. a damaged AVI's warnings) to System.out when headless: send that to stderr,
		// so the CSV on standard output is never broken
		System.setOut(System.err);
		System.exit(run(args, stdout, System.err));
	}

	/** @return the command line with every subcommand, writing to {@code out} and {@code err} */
	static CommandLine commandLine(final PrintStream out, final PrintStream err) {
		final CommandLine cl = new CommandLine(new Root());
		cl.addSubcommand("demo", withHelp(new DemoCommand(out)));
		cl.addSubcommand("track", new CommandLine(TrackCommand.spec(out, err)));
		cl.addSubcommand("simulate", withHelp(new SimulateCommand(out)));
		cl.addSubcommand("bench", withHelp(new BenchCommand(out)));
		cl.addSubcommand("accuracy", withHelp(new AccuracyCommand(out)));
		cl.addSubcommand("potential", withHelp(new PotentialCommand(out, err)));
		cl.addSubcommand("demo-potential", withHelp(new DemoPotentialCommand(out)));
		cl.addSubcommand("profile", new CommandLine(new ProfileCommand(out))); // has its own -h/--help
		cl.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
		cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
		cl.setUsageHelpWidth(100);
		return cl;
	}

	private static CommandLine withHelp(final Object command) {
		final CommandSpec spec = CommandSpec.forAnnotatedObject(command);
		spec.addMixin("help", CommandSpec.forAnnotatedObject(new Help()));
		return new CommandLine(spec);
	}

	/** Runs a command; returns the exit status. */
	public static int run(final String[] args, final PrintStream out, final PrintStream err) {
		final CommandLine cl = commandLine(out, err);
		if (args.length == 0) {
			cl.usage(err);
			return EXIT_BAD_INPUT;
		}
		if (args[0].equals("help")) {
			cl.usage(out);
			return 0;
		}
		if (!args[0].startsWith("-") && !cl.getSubcommands().containsKey(args[0])) {
			err.println("contact-tracker: error: unknown command '" + args[0] + "' (" + String.join(", ", cl
				.getSubcommands().keySet()) + ")");
			return EXIT_BAD_INPUT;
		}
		final ParseResult parsed;
		try {
			parsed = cl.parseArgs(args);
		}
		catch (final ParameterException e) {
			final String sub = e.getCommandLine() == cl ? "" : " " + e.getCommandLine().getCommandName();
			err.println("contact-tracker: error: " + oneLine(e.getMessage()) + " (see contact-tracker" + sub +
				" --help)");
			return EXIT_BAD_INPUT;
		}
		if (CommandLine.printHelpIfRequested(parsed)) return 0;
		if (!parsed.hasSubcommand()) {
			cl.usage(err);
			return EXIT_BAD_INPUT;
		}
		try {
			return ((Callable<?>) parsed.subcommand().commandSpec().userObject()).call() instanceof Integer status ? status
				: 0;
		}
		catch (final InvalidInputException | IOException | UncheckedIOException e) {
			err.println("contact-tracker: error: " + oneLine(e.getMessage()));
			return EXIT_BAD_INPUT;
		}
		catch (final CancellationException e) {
			err.println("contact-tracker: cancelled");
			return 130;
		}
		catch (final OutOfMemoryError e) {
			err.println("contact-tracker: error: out of memory (" + oneLine(e.getMessage()) + "): give Java more with " +
				"CONTACT_TRACKER_JAVA_OPTS=-Xmx8g, or use fewer --threads");
			return 1;
		}
		catch (final Exception | Error e) {
			// not the user's input: a bug. Say so, with everything a bug report needs.
			err.println("contact-tracker: internal error (please report it with the trace below): " + e);
			e.printStackTrace(err);
			return 1;
		}
	}

	/**
	 * An output file's path, checked before any work is done: its folder must exist.
	 *
	 * @param option the option that names it ({@code --csv}), for the message
	 * @return {@code file} (null when the option was not given)
	 */
	static Path output(final String option, final Path file) {
		if (file != null) AtomicFile.checkFolder(option, file);
		return file;
	}

	/** @return {@code text} split at commas, each part trimmed */
	static List<String> list(final String text) {
		return List.of(text.split(",")).stream().map(String::trim).toList();
	}

	static String oneLine(final String message) {
		return message == null ? "(no message)" : message.replace('\n', ' ').replace('\r', ' ').strip();
	}
}
