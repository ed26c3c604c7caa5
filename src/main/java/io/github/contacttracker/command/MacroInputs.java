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

import java.io.File;
import java.util.Locale;

import org.scijava.module.Module;
import org.scijava.module.ModuleInfo;
import org.scijava.module.ModuleItem;

import ij.Macro;

/**
 * What Fiji's macro bridge leaves to our commands, done by each command itself ({@link OwnInputs}), not by a
 * global preprocessor that would run for every command Fiji executes.
 * <p>
 * Fiji converts macro values with SciJava's converters; a value that does not convert ({@code threshold=abc},
 * {@code min_area=2.5}, {@code overlay=yes}) is silently skipped and the command would run with its default:
 * {@link #prepare} names it instead, and the command refuses to run (which also stops the macro: see
 * {@link MacroFailure}).
 * <p>
 * It also keeps macros reproducible although the dialog remembers its last values, and keeps a dialog from
 * popping up in a macro: an input the macro leaves out is marked resolved at its default, so SciJava neither
 * loads the remembered value into it nor asks for it. Fiji's macro preprocessor (priority {@code 2 * VERY_HIGH})
 * has set the values the macro gives before the commands' initializers run (SciJava's {@code InitPreprocessor},
 * {@code HIGH}), and remembered values are loaded after them ({@code LoadInputsPreprocessor}, just before the
 * dialog): {@link OwnInputs} calls this in between.
 */
final class MacroInputs {

	private MacroInputs() {}

	/**
	 * With ImageJ macro options, resolves the inputs the macro leaves out at their defaults and checks the values
	 * it gives.
	 *
	 * @param module the command's module
	 * @param options the macro options of the thread running the command (null: not called by a macro)
	 * @return a one-line message naming the first macro value that does not fit its input, or null (also without
	 *         a macro)
	 */
	static String prepare(final Module module, final String options) {
		if (options == null) return null;
		final String problem = problem(module.getInfo(), options);
		useDefaultsForLeftOut(module, options);
		return problem;
	}

	/**
	 * Resolves the inputs a macro leaves out (or gives a value that does not convert), so that they keep their
	 * defaults: not the dialog's remembered values, no dialog, and no file chooser for an optional output file
	 * (SciJava's file preprocessor asks for a lone unresolved file input, e.g. {@code trackmate_xml} when the macro
	 * gives only {@code csv}).
	 */
	static void useDefaultsForLeftOut(final Module module, final String options) {
		for (final ModuleItem<?> input : module.getInfo().inputs())
			if (!module.isInputResolved(input.getName()) && textual(input.getType())) module.resolveInput(input
				.getName());
	}

	/**
	 * Marks a command's outputs resolved, so that SciJava's display does not show them again: our commands show
	 * their tables and plots themselves (or not, in batch runs), and scripts still get every output from the
	 * module. Done by each command at the end of its run ({@link OwnInputs#finish}) instead of by a global
	 * postprocessor.
	 */
	static void outputsShown(final Module module) {
		for (final ModuleItem<?> output : module.getInfo().outputs())
			module.resolveOutput(output.getName());
	}

	/** @return whether a macro gives a value of this type as text (not an image, a service, ...) */
	private static boolean textual(final Class<?> type) {
		return type.isPrimitive() || Number.class.isAssignableFrom(type) || type == Boolean.class ||
			type == String.class || type == File.class;
	}

	/**
	 * @param info the module
	 * @param options ImageJ macro options ({@code key=value key=[value with spaces] ...})
	 * @return a one-line message naming the first input whose value does not fit its type, or null
	 */
	static String problem(final ModuleInfo info, final String options) {
		for (final ModuleItem<?> input : info.inputs()) {
			final String value = Macro.getValue(options, input.getName(), null);
			if (value == null) continue;
			final String problem = problem(input.getName(), input.getType(), value.trim());
			if (problem != null) return problem;
		}
		return null;
	}

	/** @return a message when {@code value} does not fit {@code type}, else null */
	static String problem(final String name, final Class<?> type, final String value) {
		if (type == double.class || type == Double.class || type == float.class || type == Float.class) {
			try {
				final double v = Double.parseDouble(value);
				if (!Double.isNaN(v)) return null;
			}
			catch (final NumberFormatException e) {
				// reported below
			}
			return name + " must be a number, not '" + value + "'";
		}
		if (type == int.class || type == Integer.class || type == long.class || type == Long.class ||
			type == short.class || type == Short.class)
		{
			try {
				Long.parseLong(value);
				return null;
			}
			catch (final NumberFormatException e) {
				return name + " must be a whole number, not '" + value + "'";
			}
		}
		if (type == boolean.class || type == Boolean.class) {
			final String v = value.toLowerCase(Locale.ROOT);
			if (v.equals("true") || v.equals("false")) return null;
			return name + " must be true or false, not '" + value + "'";
		}
		return null;
	}
}
