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
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.command.Command;
import org.scijava.command.CommandService;
import org.scijava.module.Module;

/**
 * Runs a Fiji command headless as a script does (SciJava inputs, every pre- and postprocessor) and states the
 * property the command fuzz tests share: no exception escapes the run, and a refusal is the command's own error, a
 * cancelled module whose reason is one line.
 */
final class CommandRuns {

	private CommandRuns() {}

	/**
	 * @return the module run; an exception that escaped the command, or no answer within {@link FuzzCase#timeout()}
	 *         seconds, is an assertion error naming the case
	 */
	static Module run(final Context context, final Class<? extends Command> command, final Map<String, Object> inputs,
		final String what) throws InterruptedException
	{
		final PrintStream out = System.out, err = System.err;
		quiet();
		try {
			return context.service(CommandService.class).run(command, true, inputs).get(FuzzCase.timeout(),
				TimeUnit.SECONDS);
		}
		catch (final TimeoutException e) {
			throw new AssertionError("no answer in " + FuzzCase.timeout() + " s (a hang?): " + what);
		}
		catch (final ExecutionException e) {
			throw new AssertionError("an exception escaped the command: " + what, e.getCause());
		}
		finally {
			System.setOut(out);
			System.setErr(err);
		}
	}

	/** @return whether the run was refused; if so, asserts the reason is one line and no internal error */
	static boolean refused(final Module m, final String what) {
		final Cancelable run = (Cancelable) m;
		if (!run.isCanceled()) return false;
		final String reason = run.getCancelReason();
		if (Boolean.getBoolean("contact.tracker.fuzz.verbose")) System.out.println(reason + "  <-  " + what);
		assertTrue(reason != null && !reason.isBlank(), "a refusal says why: " + what);
		assertEquals(1, reason.lines().count(), reason + "; " + what);
		assertFalse(reason.contains("Exception") || reason.contains("internal error"), reason + "; " + what);
		return true;
	}

	/** Headless, a command's summary and errors go to the standard streams: not into the test's output. */
	static void quiet() {
		final PrintStream sink = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
		System.setOut(sink);
		System.setErr(sink);
	}
}
