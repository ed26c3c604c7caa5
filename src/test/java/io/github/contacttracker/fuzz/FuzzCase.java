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
package io.github.contacttracker.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import io.github.contacttracker.cli.ContactTrackerCli;

/**
 * One fuzz case of the command line: runs it with the given arguments and asserts the property every front end
 * keeps, whatever the input: no exception escapes, no internal error, an answer within {@link #timeout()} seconds,
 * the exit status 0 or 2, and a refusal is one line. The fuzz tests share it so that the property is stated once.
 */
final class FuzzCase {

	/** The exit status. */
	final int status;
	/** What the command line wrote to its error stream. */
	final String said;
	/** The case for a failure's message: its seed, its arguments and what was said. */
	final String what;

	/** @return the cases to run: the property {@code contact.tracker.fuzz.cases}, else the suite's short run */
	static int cases(final int shortRun) {
		return Integer.getInteger("contact.tracker.fuzz.cases", shortRun);
	}

	/** @return the random numbers of a run: from the property {@code contact.tracker.fuzz.seed}, else a fixed seed */
	static SplittableRandom seeds() {
		return new SplittableRandom(Long.getLong("contact.tracker.fuzz.seed", 20261205L));
	}

	/** @return the seconds a case may take: the property {@code contact.tracker.fuzz.timeout}, else 120 */
	static int timeout() {
		return Integer.getInteger("contact.tracker.fuzz.timeout", 120);
	}

	/**
	 * Reports a fuzz run's reach and asserts it: the share of cases that passed the checks and ran the computation
	 * must be at least {@code floor}, so that a generator (or a stricter check) that stops reaching the computation
	 * fails the suite instead of testing only the refusals; and some cases must be refused, so that the refusals are
	 * tested too. Not asserted in runs shorter than 10 cases, whose shares say little.
	 *
	 * @param fuzzer the fuzzer's name for the report
	 * @param reached the cases that ran the computation (tracked, measured, computed)
	 * @param refused the cases refused in one line
	 * @param floor the least share of cases that must reach the computation, 0 to 1
	 */
	static void reach(final String fuzzer, final int cases, final int reached, final int refused, final double floor) {
		System.out.println(String.format(java.util.Locale.ROOT,
			"%s: %d cases, %d reached the computation (%.0f%%, floor %.0f%%), %d refused in one line", fuzzer, cases,
			reached, 100.0 * reached / Math.max(1, cases), 100 * floor, refused));
		if (cases < 10) return;
		assertTrue(reached >= floor * cases, fuzzer + ": only " + reached + " of " + cases + " cases reached the " +
			"computation, fewer than " + Math.round(100 * floor) + "%: the generator no longer reaches it");
		assertTrue(refused > 0, fuzzer + ": no case of " + cases + " was refused: the refusals are not tested");
	}

	/**
	 * @return which of {@code n} choices get an odd value (any of its values, maybe the sensible one): none in half
	 *         the cases, one or two in the others; the rest keep the sensible value or are left out
	 */
	static List<Integer> oddOnes(final SplittableRandom r, final int n) {
		final int odd = Math.max(0, r.nextInt(4) - 1);
		final List<Integer> oddOnes = new java.util.ArrayList<>();
		for (int k = 0; k < odd; k++)
			oddOnes.add(r.nextInt(n));
		return oddOnes;
	}

	/**
	 * Adds random options to {@code args}: of {@code choices} (each an option, its sensible value, then its odd
	 * ones), none, one or two get any of their values ({@link #oddOnes}); the others their sensible value, given one
	 * time in three (the command then measures or defaults it) or always for the first {@code always} choices
	 * counted from the end.
	 *
	 * @return whether an odd value may have been given
	 */
	static boolean options(final SplittableRandom r, final String[][] choices, final int always,
		final List<String> args)
	{
		final List<Integer> odd = oddOnes(r, choices.length);
		for (int i = 0; i < choices.length; i++) {
			final String[] c = choices[i];
			if (odd.contains(i)) {
				args.add(c[0]);
				args.add(c[1 + r.nextInt(c.length - 1)]);
			}
			else if (i >= choices.length - always || r.nextInt(3) == 0) {
				args.add(c[0]);
				args.add(c[1]);
			}
		}
		return !odd.isEmpty();
	}

	FuzzCase(final long caseSeed, final List<String> args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		// on a thread of its own, so that a case that never ends is a failure naming it, not a run that never ends
		final FutureTask<Integer> run = new FutureTask<>(() -> ContactTrackerCli.run(args.toArray(String[]::new),
			new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)));
		final Thread thread = new Thread(run, "fuzz case " + caseSeed);
		thread.setDaemon(true);
		thread.start();
		try {
			status = run.get(timeout(), TimeUnit.SECONDS);
		}
		catch (final ExecutionException e) {
			throw new AssertionError("case seed " + caseSeed + " " + args + ": an exception escaped", e.getCause());
		}
		catch (final TimeoutException e) {
			run.cancel(true);
			throw new AssertionError("case seed " + caseSeed + " " + args + ": no answer in " + timeout() + " s (a hang?)");
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new AssertionError("interrupted", e);
		}
		said = err.toString(StandardCharsets.UTF_8);
		what = "case seed " + caseSeed + " " + args + ":\n" + said;
		assertFalse(said.contains("internal error"), what);
		assertTrue(status == 0 || status == ContactTrackerCli.EXIT_BAD_INPUT, "exit " + status + ": " + what);
		if (refused()) assertEquals(1, said.lines().filter(l -> l.contains("error")).count(), what);
		if (refused() && Boolean.getBoolean("contact.tracker.fuzz.verbose")) System.out.print("refused: " + said);
	}

	/** @return whether the command line refused the input (exit 2) */
	boolean refused() {
		return status == ContactTrackerCli.EXIT_BAD_INPUT;
	}
}
