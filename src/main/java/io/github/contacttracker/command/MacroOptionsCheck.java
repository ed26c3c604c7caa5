package io.github.contacttracker.command;

import java.io.File;
import java.util.Locale;

import org.scijava.Priority;
import org.scijava.log.LogService;
import org.scijava.module.Module;
import org.scijava.module.ModuleInfo;
import org.scijava.module.ModuleItem;
import org.scijava.module.process.AbstractPreprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;

import ij.Macro;

/**
 * Refuses Contact Tracker commands whose ImageJ macro options hold a value that is not a number (or a whole
 * number, or true/false) where the parameter needs one.
 * <p>
 * Fiji converts macro values with SciJava's converters; a value that does not convert ({@code threshold=abc},
 * {@code min_area=2.5}, {@code overlay=yes}) is silently replaced by 0 or false, and the command would run with
 * it. This check runs first and cancels the command with a one-line message instead (which also stops the
 * macro: see {@link MacroFailure}). It only looks at the modules of this package and only while a macro passes
 * options.
 * <p>
 * It also keeps macros reproducible although the dialog remembers its last values: an input the macro leaves
 * out is marked resolved at its documented default, so SciJava does not load the remembered value into it nor
 * ask for it (values the macro gives are set afterwards by Fiji's macro preprocessor, which runs after this
 * one).
 */
@Plugin(type = PreprocessorPlugin.class, priority = 2 * Priority.VERY_HIGH + 1)
public class MacroOptionsCheck extends AbstractPreprocessorPlugin {

	@Parameter(required = false)
	private LogService log;

	@Override
	public void process(final Module module) {
		if (!ours(module.getInfo())) return;
		final String options = Macro.getOptions();
		if (options == null) return;
		final String problem = problem(module.getInfo(), options);
		if (problem == null) {
			useDefaultsForLeftOut(module, options);
			return;
		}
		InputCheck.refuse(this, log, module, problem);
	}

	/**
	 * Resolves the inputs a macro leaves out, so that they keep their defaults: not the dialog's remembered
	 * values, and no file chooser for an optional output file (SciJava's file preprocessor asks for a lone
	 * unresolved file input, e.g. {@code trackmate_xml} when the macro gives only {@code csv}).
	 */
	static void useDefaultsForLeftOut(final Module module, final String options) {
		for (final ModuleItem<?> input : module.getInfo().inputs()) {
			if (module.isInputResolved(input.getName()) || !textual(input.getType())) continue;
			if (Macro.getValue(options, input.getName(), null) == null) module.resolveInput(input.getName());
		}
	}

	/** @return whether a macro gives a value of this type as text (not an image, a service, ...) */
	private static boolean textual(final Class<?> type) {
		return type.isPrimitive() || Number.class.isAssignableFrom(type) || type == Boolean.class ||
			type == String.class || type == File.class;
	}

	/** @return whether the module is one of Contact Tracker's commands */
	static boolean ours(final ModuleInfo info) {
		final String cls = info.getDelegateClassName();
		return cls != null && cls.startsWith(MacroOptionsCheck.class.getPackageName() + ".");
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
