package io.github.contacttracker.command;

import org.scijava.Priority;
import org.scijava.module.Module;
import org.scijava.module.ModuleItem;
import org.scijava.module.process.AbstractPostprocessorPlugin;
import org.scijava.module.process.PostprocessorPlugin;
import org.scijava.plugin.Plugin;

/**
 * Marks the outputs of Contact Tracker's commands as resolved before SciJava's display postprocessor runs, so it
 * does not display them: the commands show their tables, plot and numbers themselves (or not, in batch runs),
 * and scripts still get every output from the module.
 */
@Plugin(type = PostprocessorPlugin.class, priority = Priority.VERY_HIGH)
public class ShownOutputs extends AbstractPostprocessorPlugin {

	@Override
	public void process(final Module module) {
		if (!MacroOptionsCheck.ours(module.getInfo())) return;
		for (final ModuleItem<?> output : module.getInfo().outputs())
			module.resolveOutput(output.getName());
	}
}
