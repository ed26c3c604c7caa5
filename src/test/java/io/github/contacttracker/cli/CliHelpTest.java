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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.TrackingSettings;

/** Every subcommand's help, typed options with one-line errors, and the progress line. */
class CliHelpTest {

	@TempDir
	Path dir;

	private static final List<String> COMMANDS = List.of("demo", "track", "simulate", "bench", "accuracy",
		"potential", "demo-potential");

	@Test
	void everySubcommandHasHelpOnStdoutAndExitsZero() {
		for (final String command : COMMANDS)
			for (final String flag : new String[] { "--help", "-h" }) {
				final Object[] r = ContactTrackerCliTest.run(command, flag);
				assertEquals(0, r[0], command + " " + flag + ": " + r[2]);
				final String help = (String) r[1];
				assertTrue(help.startsWith("Usage: contact-tracker " + command), help);
				assertTrue(help.contains("-h, --help"), help);
				assertEquals("", r[2]);
			}
		final Object[] top = ContactTrackerCliTest.run("--help");
		assertEquals(0, top[0]);
		for (final String command : COMMANDS)
			assertTrue(((String) top[1]).contains("  " + command + " "), (String) top[1]);
	}

	/** The command line alone has no research subcommand: those are the lab's ({@link ContactTrackerLab}). */
	@Test
	void theCommandLineAloneKnowsNoLabCommand() {
		final java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream(), err =
			new java.io.ByteArrayOutputStream();
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, ContactTrackerCli.run(new String[] { "simulate", "--help" },
			new java.io.PrintStream(out), new java.io.PrintStream(err)));
		assertEquals("contact-tracker: error: unknown command 'simulate' (track, potential, profile)", err.toString()
			.strip());
		out.reset();
		assertEquals(0, ContactTrackerCli.run(new String[] { "--help" }, new java.io.PrintStream(out),
			new java.io.PrintStream(err)));
		assertTrue(out.toString().contains("  track ") && !out.toString().contains("  demo "), out.toString());
	}

	@Test
	void trackHelpIsGeneratedFromTheSettingsDescriptor() {
		final String help = (String) ContactTrackerCliTest.run("track", "--help")[1];
		for (final Setting<?> s : TrackingSettings.ALL) {
			assertTrue(help.contains(s.cliOption() + "="), s.cliOption() + " in\n" + help);
			// the help text's first words (the help wraps the rest)
			final String start = String.join(" ", List.of(s.help().split(" ")).subList(0, 3));
			assertTrue(help.contains(start), start + " in\n" + help);
		}
		assertTrue(help.contains("--[no-]progress"), help);
	}

	@Test
	void mistypedOptionsAreOneLineErrorsNamingTheOption() {
		final String[][] cases = { { "demo", "--reps", "many" }, { "bench", "--frames", "1.5" }, { "simulate",
			"--scenario", "pair", "--separation", "x", "--out", "a.tif", "--truth", "t.csv" }, { "accuracy",
				"--threads", "" }, { "potential", "s.csv", "--bin", "wide", "--r-max", "3" }, { "demo-potential",
					"--frames" }, { "demo", "extra" } };
		for (final String[] c : cases) {
			final Object[] r = ContactTrackerCliTest.run(c);
			final String err = ((String) r[2]).strip();
			assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0], String.join(" ", c) + ": " + err);
			assertEquals(1, err.lines().count(), err);
			assertTrue(err.startsWith("contact-tracker: error: ") && err.endsWith("(see contact-tracker " + c[0] +
				" --help)"), err);
			assertEquals("", r[1]);
		}
	}

	@Test
	void progressGoesToStderrOnlyWhenAskedAndTheCsvStaysClean() {
		final Path tif = dir.resolve("pair.tif");
		assertEquals(0, ContactTrackerCliTest.run("simulate", "--scenario", "pair", "--separation", "1.2", "--frames",
			"3", "--out", tif.toString(), "--truth", dir.resolve("t.csv").toString())[0]);
		final Object[] quiet = ContactTrackerCliTest.run("track", tif.toString(), "--threshold", "85", "--r-out", "61",
			"--method", "paper");
		final Object[] shown = ContactTrackerCliTest.run("track", tif.toString(), "--threshold", "85", "--r-out", "61",
			"--method", "paper", "--progress");
		assertEquals(0, shown[0], (String) shown[2]);
		assertEquals(quiet[1], shown[1], "the CSV on stdout is the same");
		assertTrue(((String) shown[2]).contains("3/3 frames, "), (String) shown[2]);
		assertTrue(!((String) quiet[2]).contains("frames/s, "), (String) quiet[2]);
	}

	@Test
	void theProgressLineSaysRateAndTimeLeftAtMostTwiceASecond() {
		final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		final AtomicLong now = new AtomicLong();
		final ProgressLine line = new ProgressLine(new PrintStream(bytes, true, StandardCharsets.UTF_8), now::get);
		now.set(1_000_000_000L); // 1 s: 10 of 100 frames
		line.progress(10, 100);
		now.set(1_100_000_000L); // too soon: not drawn
		line.progress(11, 100);
		now.set(2_000_000_000L);
		line.progress(20, 100);
		line.end();
		assertEquals("\r10/100 frames, 10.0 frames/s, 9 s left\r20/100 frames, 10.0 frames/s, 8 s left\n", bytes
			.toString(StandardCharsets.UTF_8));
		assertEquals("3 min 05 s", ProgressLine.duration(185));
		assertEquals("2 h 07 min", ProgressLine.duration(2 * 3600 + 7 * 60 + 20));
	}
}
