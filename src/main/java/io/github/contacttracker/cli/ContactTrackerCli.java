package io.github.contacttracker.cli;

import java.io.UncheckedIOException;

import io.github.contacttracker.core.InvalidInputException;
import java.io.IOException;
import java.io.PrintStream;
import java.util.Arrays;
import java.util.concurrent.CancellationException;

/**
 * The command line: {@code contact-tracker demo | track | simulate | bench | accuracy | potential |
 * demo-potential}. Bad input ends with a
 * one-line error on stderr and exit status 2; an unexpected failure with exit status 1.
 */
public final class ContactTrackerCli {

	/** Exit status for bad input (missing file, bad option, untrackable image). */
	public static final int EXIT_BAD_INPUT = 2;

	static final String USAGE = String.join("\n", //
		"usage: contact-tracker COMMAND [options]", //
		"", //
		"  demo                       simulate pairs and triples of 5.53 um particles from apart to contact,", //
		"                             track them, print the distance errors, write an overlay PNG", //
		"      [--reps N] [--out-dir DIR] [--threads N]", //
		TrackCommand.usage(), //
		"  profile MOVIE [--at X,Y] [--frame N] [--diameter D] [--png OUT.png] [--csv OUT.csv]", //
		"                             radial profile of isolated particles; prints --threshold, --r-out and", //
		"                             --diameter to copy (profile --help for more)", //
		"  simulate --scenario pair|triple --separation R_OVER_D --out stack.tif --truth truth.csv", //
		"      [--frames N] [--seed S] [--particle 5.53|2.06] [--bit-depth 8|16]", //
		"  bench [--frames N]          speed on a 512x512 8-bit stack with 12 particles", //
		"  accuracy [--reps N] [--particle 5.53,2.06] [--scenario pair,triple] [--methods M,...]", //
		"      [--separations 2,1.5,1] [--csv OUT.csv]", //
		"                             the paper's protocol for every method, against the Cramer-Rao bound", //
		"  potential SPOTS.csv --bin W --r-max R [--csv OUT.csv] [--png OUT.png]", //
		"      [--width W --height H] [--start-frame F] [--flagged drop|keep] [--zero FROM,TO]", //
		"                             pair distribution g(r) and pair potential U(r)/kT from a spots table", //
		"  demo-potential [--frames N] [--particle 2.06|5.53] [--out-dir DIR] [--threads N]", //
		"                             a simulated fluid with a known U(r): U(r) by the default method and the", //
		"                             first pass against the truth", //
		"", //
		"Bad input exits with status 2 and a one-line error; no partial output file is left behind.");

	private ContactTrackerCli() {}

	public static void main(final String[] args) {
		System.exit(run(args, System.out, System.err));
	}

	/** Runs a command; returns the exit status. */
	public static int run(final String[] args, final PrintStream out, final PrintStream err) {
		if (args.length == 0 || args[0].equals("-h") || args[0].equals("--help") || args[0].equals("help")) {
			(args.length == 0 ? err : out).println(USAGE);
			return args.length == 0 ? EXIT_BAD_INPUT : 0;
		}
		final String[] rest = Arrays.copyOfRange(args, 1, args.length);
		try {
			switch (args[0]) {
				case "demo": return new DemoCommand(out).run(rest);
				case "track": return new TrackCommand(out, err).run(rest);
				case "simulate": return new SimulateCommand(out).run(rest);
				case "bench": return new BenchCommand(out).run(rest);
				case "accuracy": return new AccuracyCommand(out).run(rest);
				case "potential": return new PotentialCommand(out, err).run(rest);
				case "demo-potential": return new DemoPotentialCommand(out).run(rest);
				case "profile": return ProfileCommand.run(rest, out, err);
				default:
					err.println("contact-tracker: error: unknown command '" + args[0] + "' (demo, track, simulate, bench, accuracy, potential, demo-potential)");
					return EXIT_BAD_INPUT;
			}
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
		catch (final RuntimeException | Error e) {
			// not the user's input: a bug. Say so, with everything a bug report needs.
			err.println("contact-tracker: internal error (please report it with the trace below): " + e);
			e.printStackTrace(err);
			return 1;
		}
	}

	private static String oneLine(final String message) {
		return message == null ? "(no message)" : message.replace('\n', ' ');
	}
}
