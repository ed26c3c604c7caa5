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
package io.github.contacttracker.lab.cli;

import java.io.PrintStream;
import java.util.List;

import io.github.contacttracker.cli.ContactTrackerCli.Subcommand;
import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * The lab's command line: {@code contact-tracker} with the research subcommands added to {@code track},
 * {@code potential} and {@code profile}: {@code demo} (the paper's figure on simulated pairs), {@code simulate}
 * (movies with known centres), {@code bench} (speed), {@code accuracy} (the methods against the truth and the
 * Cramer-Rao bound), {@code demo-potential} and {@code static-error} (the pair potential's checks). It ships in its
 * own jar beside the command line's, not in the Fiji plugin, since users tracking their movies need none of it;
 * {@code scripts/contact-tracker} runs it.
 */
public final class ContactTrackerLab {

	/** The research subcommands, in the order the help lists them. */
	private static final ContactTrackerCli.Extension COMMANDS = new ContactTrackerCli.Extension() {

		@Override
		public List<String> names() {
			return List.of("demo", "simulate", "bench", "accuracy", "demo-potential", "static-error");
		}

		@Override
		public Subcommand make(final String name, final PrintStream out, final PrintStream err) {
			return switch (name) {
				case "demo" -> new DemoCommand(out);
				case "simulate" -> new SimulateCommand(out);
				case "bench" -> new BenchCommand(out);
				case "accuracy" -> new AccuracyCommand(out);
				case "demo-potential" -> new DemoPotentialCommand(out);
				case "static-error" -> new StaticErrorCommand(out);
				default -> throw new IllegalArgumentException("no lab command " + name);
			};
		}
	};

	private ContactTrackerLab() {}

	public static void main(final String[] args) {
		final PrintStream stdout = System.out;
		// as ContactTrackerCli.main: ImageJ 1's headless log goes to stderr, so a CSV on standard output stays whole
		System.setOut(System.err);
		System.exit(run(args, stdout, System.err));
	}

	/** Runs a command of the command line or of the lab; returns the exit status. */
	public static int run(final String[] args, final PrintStream out, final PrintStream err) {
		return ContactTrackerCli.run(args, out, err, COMMANDS);
	}
}
