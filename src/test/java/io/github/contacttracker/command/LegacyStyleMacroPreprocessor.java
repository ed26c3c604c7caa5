package io.github.contacttracker.command;

import org.scijava.Priority;
import org.scijava.convert.ConvertService;
import org.scijava.module.Module;
import org.scijava.module.ModuleItem;
import org.scijava.module.process.AbstractPreprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;
import org.scijava.widget.Button;

import ij.Macro;

/**
 * For tests: sets a module's inputs from the ImageJ macro options of its thread, at the priority and with the
 * conversion rules of Fiji's own macro preprocessor (a value that does not convert is skipped; buttons are
 * resolved, not set). Acts only on threads that carry macro options ({@link FijiMacroBridge}).
 */
@Plugin(type = PreprocessorPlugin.class, priority = 2 * Priority.VERY_HIGH)
public class LegacyStyleMacroPreprocessor extends AbstractPreprocessorPlugin {

	@Parameter
	private ConvertService convert;

	@Override
	public void process(final Module module) {
		final String options = Macro.getOptions();
		if (options == null) return;
		for (final ModuleItem<?> input : module.getInfo().inputs()) {
			if (input.getType() == Button.class) {
				// as Fiji's: a button is no macro option, resolved so that nobody asks for it
				module.resolveInput(input.getName());
				continue;
			}
			final String value = Macro.getValue(options, input.getName(), null);
			if (value == null || !convert.supports(value, input.getType())) continue;
			module.setInput(input.getName(), convert.convert(value, input.getType()));
			module.resolveInput(input.getName());
		}
	}
}
