package io.github.contacttracker.command;

import org.scijava.Priority;
import org.scijava.log.LogService;
import org.scijava.module.Module;
import org.scijava.module.process.AbstractPreprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;

/**
 * Refuses invalid parameter values after the dialog (or macro, or script) has given them and before SciJava
 * remembers them: the dialogs remember their last values, and a refused value must not come back as the next
 * run's default. Applies to the commands that implement {@link Checked}.
 */
@Plugin(type = PreprocessorPlugin.class, priority = InputCheck.PRIORITY)
public class InputCheck extends AbstractPreprocessorPlugin {

	/**
	 * After the input harvester (the dialog, {@link Priority#VERY_LOW}) and before SciJava's
	 * {@code SaveInputsPreprocessor} ({@code VERY_LOW - 1}), which writes the values to the preferences.
	 */
	static final double PRIORITY = Priority.VERY_LOW - 0.5;

	/** A command whose inputs can be checked before it runs. */
	interface Checked {
		/** @throws IllegalArgumentException with a one-line reason when an input is invalid */
		void checkInputs();
	}

	@Parameter(required = false)
	private LogService log;

	@Override
	public void process(final Module module) {
		if (!MacroOptionsCheck.ours(module.getInfo()) || !(module.getDelegateObject() instanceof Checked)) return;
		try {
			((Checked) module.getDelegateObject()).checkInputs();
		}
		catch (final IllegalArgumentException e) {
			refuse(this, log, module, e.getMessage());
		}
	}

	/**
	 * Cancels a module from a preprocessor: the reason is logged as an error and stops a calling macro
	 * ({@link MacroFailure}).
	 */
	static void refuse(final AbstractPreprocessorPlugin preprocessor, final LogService log, final Module module,
		final String reason)
	{
		final String title = module.getInfo().getTitle();
		if (log != null) log.error(title + ": " + reason);
		preprocessor.cancel(reason);
		MacroFailure.report(title, null, reason);
	}
}
