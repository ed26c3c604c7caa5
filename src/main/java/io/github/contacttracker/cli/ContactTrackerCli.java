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
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.ProjectVersion;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;

/**
 * The command line: {@code contact-tracker track | potential | profile}, each subcommand's arguments parsed by its
 * {@link CommandOptions}; a program built on it adds its own subcommands ({@link Extension}: the lab's research
 * commands, {@code demo | simulate | bench | accuracy | demo-potential | static-error}). Every subcommand has
 * {@code --help}. Bad input (an unknown or mistyped option, a missing file, an untrackable image) ends with a
 * one-line error on stderr and exit status 2; an unexpected failure with a stack trace and exit status 1.
 */
public final class ContactTrackerCli {

	/** Exit status for bad input (missing file, bad option, untrackable image). */
	public static final int EXIT_BAD_INPUT = 2;

	/** @return what {@code --version} prints: the name and the version ({@link ProjectVersion}) */
	static String version() {
		return "Contact Tracker " + ProjectVersion.get();
	}

	/**
	 * A subcommand: its options, declared by the subclass, and its work (run once they are parsed), which writes to
	 * {@link #out} and returns the exit status.
	 */
	public abstract static class Subcommand implements Callable<Integer> {

		/** The command's options, which {@link #call()} reads once they are parsed. */
		protected final CommandOptions options;
		/** Where the command's results go. */
		protected final PrintStream out;
		/** The arguments the command was run with, its name first (for the stamp of a {@link Report}). */
		protected List<String> arguments = List.of();

		protected Subcommand(final CommandOptions options, final PrintStream out) {
			this.options = options;
			this.out = out;
		}

		/** @return the command's options */
		public final CommandOptions options() {
			return options;
		}
	}

	/**
	 * Subcommands that a program built on this command line adds to it, made by name: the lab's research commands
	 * (simulation, accuracy studies, benchmarks) join {@code track}, {@code potential} and {@code profile} this way,
	 * so that this front end needs none of the lab's code.
	 */
	public interface Extension {

		/** @return the added commands' names, in the order the help lists them after this command line's own */
		List<String> names();

		/** @return the command {@code name}, one of {@link #names()} */
		Subcommand make(String name, PrintStream out, PrintStream err);
	}

	/** No added subcommand. */
	private static final Extension NONE = new Extension() {

		@Override
		public List<String> names() {
			return List.of();
		}

		@Override
		public Subcommand make(final String name, final PrintStream out, final PrintStream err) {
			return null;
		}
	};

	private ContactTrackerCli() {}

	public static void main(final String[] args) {
		final PrintStream stdout = System.out;
		// ImageJ 1 prints its log (e.g. a damaged AVI's warnings) to System.out when headless: send that to stderr,
		// so the CSV on standard output is never broken
		System.setOut(System.err);
		System.exit(run(args, stdout, System.err));
	}

	/** The subcommands' names, in the order the help lists them. */
	private static final List<String> COMMANDS = List.of("track", "potential", "profile");

	/**
	 * @return the subcommand {@code name} (one of {@link #COMMANDS} or of {@code more}), or null. Only the one run is made: building a
	 *         command's options links lambdas and streams, a few milliseconds each on a fresh JVM
	 */
	private static Subcommand subcommand(final String name, final PrintStream out, final PrintStream err,
		final Extension more)
	{
		return switch (name) {
			case "track" -> new TrackCommand(out, err);
			case "potential" -> new PotentialCommand(out, err);
			case "profile" -> new ProfileCommand(out);
			default -> more.names().contains(name) ? more.make(name, out, err) : null;
		};
	}

	/** @return every subcommand (for the top-level help, which lists them all) */
	private static List<Subcommand> subcommands(final PrintStream out, final PrintStream err, final Extension more) {
		return names(more).stream().map(name -> subcommand(name, out, err, more)).toList();
	}

	/** @return this command line's subcommands' names, then the added ones */
	private static List<String> names(final Extension more) {
		final List<String> all = new java.util.ArrayList<>(COMMANDS);
		all.addAll(more.names());
		return all;
	}

	private static CommandOptions root(final List<Subcommand> subcommands) {
		return new CommandOptions("contact-tracker", "Sub-pixel localization of colloidal particles, also when they " +
			"touch.").withVersion().withSubcommands(subcommands.stream().map(Subcommand::options).toList()).withFooter(
				"Run 'contact-tracker COMMAND --help' for a command's options. Bad input exits with status 2 and a " +
					"one-line error; no partial output file is left behind.");
	}

	/** @return {@code --threads N} of the subcommands that simulate and track, added to {@code options} */
	public static Option<Integer> threads(final CommandOptions options) {
		return options.add(Option.integer("--threads", "N", "Worker threads (0: all processors).").withDefaultExplained(
			"0"));
	}

	/** Runs a command; returns the exit status. */
	public static int run(final String[] args, final PrintStream out, final PrintStream err) {
		return run(args, out, err, NONE);
	}

	/** Runs a command, one of this command line's or of {@code more}; returns the exit status. */
	public static int run(final String[] args, final PrintStream out, final PrintStream err, final Extension more) {
		if (args.length == 0) {
			err.print(root(subcommands(out, err, more)).usage());
			return EXIT_BAD_INPUT;
		}
		if (args[0].equals("help")) {
			out.print(root(subcommands(out, err, more)).usage());
			return 0;
		}
		final Subcommand command = subcommand(args[0], out, err, more);
		if (command == null && !args[0].startsWith("-")) {
			err.println("contact-tracker: error: unknown command '" + args[0] + "' (" + String.join(", ", names(more)) + ")");
			return EXIT_BAD_INPUT;
		}
		final CommandOptions root = command == null ? root(subcommands(out, err, more)) : null;
		final CommandOptions options = command == null ? root : command.options();
		try {
			options.parse(args, command == null ? 0 : 1);
		}
		catch (final CommandOptions.BadOptionException e) {
			err.println("contact-tracker: error: " + InvalidInputException.oneLine(e.getMessage()) + " (see " + options.commandLine() +
				" --help)");
			return EXIT_BAD_INPUT;
		}
		if (options.helpRequested()) {
			out.print(options.usage());
			return 0;
		}
		if (options.versionRequested()) {
			out.println(version());
			return 0;
		}
		if (command == null) {
			err.print(root.usage());
			return EXIT_BAD_INPUT;
		}
		command.arguments = List.of(args);
		try {
			return command.call();
		}
		catch (final InvalidInputException | IOException | UncheckedIOException e) {
			err.println("contact-tracker: error: " + InvalidInputException.oneLine(e.getMessage()));
			return EXIT_BAD_INPUT;
		}
		catch (final CancellationException e) {
			err.println("contact-tracker: cancelled");
			return 130;
		}
		catch (final OutOfMemoryError e) {
			err.println("contact-tracker: error: out of memory (" + InvalidInputException.oneLine(e.getMessage()) + "): give Java more with " +
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
	public static Path output(final String option, final Path file) {
		if (file != null) AtomicFile.checkFolder(option, file);
		return file;
	}

	/** @return {@code text} split at commas, each part trimmed */
	public static List<String> list(final String text) {
		return List.of(text.split(",")).stream().map(String::trim).toList();
	}
}
