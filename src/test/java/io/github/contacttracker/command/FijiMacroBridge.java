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

import java.lang.reflect.Field;
import java.util.Hashtable;
import java.util.List;

import org.scijava.Context;
import org.scijava.command.Command;
import org.scijava.command.CommandService;
import org.scijava.module.Module;
import org.scijava.module.ModuleRunner;
import org.scijava.module.ModuleService;
import org.scijava.module.process.PostprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.PluginService;

import ij.ImagePlus;
import ij.Macro;
import ij.Menus;
import ij.WindowManager;
import ij.plugin.PlugIn;

/**
 * A stand-in, for tests, for what Fiji's ImageJ 1.x bridge (imagej-legacy, not on Maven Central) does when a
 * macro calls {@code run("Contact Tracker", "key=value ...")}: ImageJ 1.x finds the menu label in its command
 * table and calls this plugin on the macro's thread; it runs the SciJava command with every pre- and
 * postprocessor on another thread that sees the macro's options (as the bridge's module thread does), with the
 * macro's current image as {@code imp}, waits for it and returns, ignoring whether the module was cancelled (as
 * imagej-legacy 2.0.3 does). {@link LegacyStyleMacroPreprocessor} sets the inputs from the options.
 */
public class FijiMacroBridge implements PlugIn {

	private static Context context;
	private static volatile Module last;

	/** Makes {@code run("Contact Tracker", ...)} and {@code run("Contact Tracker Profile", ...)} macro-callable. */
	@SuppressWarnings("unchecked")
	static void install(final Context ctx) throws ReflectiveOperationException {
		context = ctx;
		// headless, ImageJ 1.x builds no menus: give it a command table of its own
		final Field f = Menus.class.getDeclaredField("pluginsTable");
		f.setAccessible(true);
		Hashtable<String, String> table = (Hashtable<String, String>) f.get(null);
		if (table == null) {
			table = new Hashtable<>();
			f.set(null, table);
		}
		table.put("Contact Tracker", entry(ContactTrackerCommand.class));
		table.put("Contact Tracker Profile", entry(ContactTrackerProfileCommand.class));
		table.put("Contact Tracker Pair Potential", entry(ContactTrackerPotentialCommand.class));
	}

	private static String entry(final Class<? extends Command> command) {
		return FijiMacroBridge.class.getName() + "(\"" + command.getName() + "\")";
	}

	/** @return the module of the last call */
	static Module last() {
		return last;
	}

	@Override
	public void run(final String commandClass) {
		final String options = Macro.getOptions();
		final ImagePlus current = WindowManager.getCurrentImage(); // the macro's, also in batch mode
		final Module module = context.service(ModuleService.class).createModule(context.service(CommandService.class)
			.getCommand(commandClass));
		if (current != null) {
			module.setInput("imp", current);
			module.resolveInput("imp");
		}
		final PluginService plugins = context.service(PluginService.class);
		final List<PreprocessorPlugin> pre = plugins.createInstancesOfType(PreprocessorPlugin.class);
		final List<PostprocessorPlugin> post = plugins.createInstancesOfType(PostprocessorPlugin.class);
		final Thread thread = new Thread(() -> new ModuleRunner(context, module, pre, post).run(), "Run$_SciJava-bridge");
		if (options != null) Macro.setOptions(thread, options);
		thread.start();
		try {
			thread.join();
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
		}
		finally {
			Macro.setOptions(thread, null);
		}
		last = module;
	}
}
