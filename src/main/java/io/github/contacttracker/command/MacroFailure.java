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
package io.github.contacttracker.command;

import ij.IJ;
import ij.Macro;
import ij.macro.Interpreter;

/**
 * Stops the ImageJ macro that called a failing Contact Tracker command, the way ImageJ's own commands do.
 * <p>
 * Fiji runs a SciJava command called by {@code run("Contact Tracker", ...)} on a thread of its own and ignores
 * the command's {@code cancel(reason)} (imagej-legacy 2.0.3 returns from the call as if it had worked), so the
 * macro would go on with its next line. ImageJ 1.x's {@link IJ#error(String, String)} aborts the macro whose
 * {@code run(...)} is in progress (the interpreter is remembered in a static field, not per thread): it shows
 * "Macro Error: <i>reason</i> in line <i>n</i>", marks the macro done and throws {@link Macro#MACRO_CANCELED}
 * on the calling thread, which we swallow because the command itself ends normally (cancelled).
 * <p>
 * A macro that calls {@code IJ.redirectErrorMessages()} before {@code run("Contact Tracker", ...)} is not stopped:
 * the reason goes to the Log window (standard output headless), as ImageJ does for images that fail to open,
 * so that a batch loop can report the file and go on.
 */
final class MacroFailure {

	private MacroFailure() {}

	/** @return whether an ImageJ macro is running (and so may be waiting on this command) */
	static boolean macroRunning() {
		return Interpreter.getInstance() != null;
	}

	/**
	 * Reports a failure to the running macro, if any: stops it, or logs the reason when the macro redirected error
	 * messages. Does nothing without a running macro.
	 *
	 * @param title the command's title
	 * @param subject what failed, e.g. the image's title (may be null)
	 * @param reason the one-line reason
	 * @return whether a running macro was told
	 */
	static boolean report(final String title, final String subject, final String reason) {
		if (!macroRunning()) return false;
		if (IJ.redirectingErrorMessages()) {
			// ImageJ's convention for batch loops: one error goes to the Log and the macro carries on
			IJ.redirectErrorMessages(false);
			IJ.log(title + (subject == null || subject.isEmpty() ? "" : " ('" + subject + "')") + ": " + reason);
			return true;
		}
		try {
			IJ.error(title, reason);
		}
		catch (final RuntimeException e) {
			// MACRO_CANCELED: the interpreter is already marked done; plain ImageJ 1.x headless also throws
			// HeadlessException from its error dialog after marking it done. Either way the macro stops.
		}
		return true;
	}

	/**
	 * Ends a successful run: like ImageJ's own plugin calls, a {@code IJ.redirectErrorMessages()} applies to the
	 * next command only.
	 */
	static void succeeded() {
		if (macroRunning() && IJ.redirectingErrorMessages()) IJ.redirectErrorMessages(false);
	}
}
