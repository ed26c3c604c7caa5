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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.command.CommandInfo;
import org.scijava.command.CommandService;
import org.scijava.module.Module;
import org.scijava.module.ModuleRunner;
import org.scijava.module.ModuleService;
import org.scijava.module.process.PostprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.PluginService;
import org.scijava.command.Command;

import ij.Macro;

/** Macro values that do not fit their parameter refuse the command instead of silently becoming 0 or false. */
class MacroInputsTest {

	private static Context context;
	private static CommandInfo tracker;

	@BeforeAll
	static void start() {
		context = new Context();
		tracker = context.service(CommandService.class).getCommand(ContactTrackerCommand.class);
	}

	@AfterAll
	static void stop() {
		context.dispose();
	}

	@Test
	void wellFormedOptionsPass() {
		assertNull(MacroInputs.problem(tracker, "threshold=110 r_out=55 min_area=20"));
		assertNull(MacroInputs.problem(tracker, "threshold=1.5e2 r_out=55.5 method=first connectivity=4 " +
			"overlay=false table=TRUE csv=[/data/my images/a.csv] channel=2"));
		assertNull(MacroInputs.problem(tracker, ""));
		// the dialog's button is no macro option (Fiji resolves buttons itself); a recorded key for it is ignored
		assertNull(MacroInputs.problem(tracker, "threshold=110 measure=[Measure from the image]"));
	}

	@Test
	void malformedValuesAreNamed() {
		assertEquals("threshold must be a number, not 'abc'", MacroInputs.problem(tracker,
			"threshold=abc r_out=55"));
		assertEquals("r_out must be a number, not '5,5'", MacroInputs.problem(tracker, "threshold=1 r_out=5,5"));
		assertEquals("min_area must be a whole number, not '2.5'", MacroInputs.problem(tracker, "min_area=2.5"));
		assertEquals("overlay must be true or false, not 'yes'", MacroInputs.problem(tracker, "overlay=yes"));
		assertEquals("threshold must be a number, not 'NaN'", MacroInputs.problem(tracker, "threshold=NaN"));
		final CommandInfo profile = context.service(CommandService.class).getCommand(
			ContactTrackerProfileCommand.class);
		assertEquals("diameter must be a number, not 'big'", MacroInputs.problem(profile, "diameter=big"));
	}

	/** Our checks are the commands' own: no pre- or postprocessor of ours runs for every command Fiji executes. */
	@Test
	void noGlobalProcessorOfOurs() {
		final PluginService plugins = context.service(PluginService.class);
		for (final Class<?> type : List.of(PreprocessorPlugin.class, PostprocessorPlugin.class))
			for (final var p : plugins.getPluginsOfType((Class) type)) {
				final String cls = ((org.scijava.plugin.PluginInfo<?>) p).getClassName();
				// the test stand-in for Fiji's own macro preprocessor is Fiji's, not ours
				if (cls.equals(LegacyStyleMacroPreprocessor.class.getName())) continue;
				assertFalse(cls.startsWith("io.github.contacttracker."), cls + " runs for every command");
			}
	}

	/** Another command, for {@link #anotherCommandsMacroRunIsUntouched}. */
	public static class OtherCommand implements Command {
		@Parameter
		private double x = 1;
		@Parameter(required = false)
		private String s = "";
		@Parameter(type = org.scijava.ItemIO.OUTPUT)
		private String ran;

		@Override
		public void run() {
			ran = s + " " + x;
		}
	}

	/**
	 * A macro run of another command, with every pre- and postprocessor: a value that does not convert and a
	 * left-out key are left to SciJava as without our plugin (the remembered x is loaded, nothing refused).
	 */
	@Test
	void anotherCommandsMacroRunIsUntouched() throws Exception {
		final CommandInfo other = new CommandInfo(OtherCommand.class);
		final ModuleService modules = context.service(ModuleService.class);
		assertEquals("a 7.0", modules.run(other, true, "x", 7.0, "s", "a").get().getOutput("ran"));
		final Module leftOut = modules.createModule(other);
		runAsMacro(leftOut, "s=again");
		assertEquals("again 7.0", leftOut.getOutput("ran"), "a left-out key of another command: its remembered value");
		final Module module = modules.createModule(other);
		runAsMacro(module, "s=hello x=abc");
		// Fiji's own conversion turns 'abc' into 0 for a command that is not ours (SciJava's converters); ours refuse it
		assertEquals("hello 0.0", module.getOutput("ran"), "the macro's s, x as SciJava converts it");
		// the same call of ours refuses the value
		final Module ours = modules.createModule(tracker);
		ours.setInput("imp", Simulated.image());
		ours.resolveInput("imp");
		runAsMacro(ours, "threshold=abc r_out=55");
		assertTrue(((Cancelable) ours).isCanceled());
		assertEquals("threshold must be a number, not 'abc'", ((Cancelable) ours).getCancelReason());
		assertNull(ours.getOutput("spots"), "refused before anything is tracked");
	}

	/** Runs a module as Fiji does for a macro's run(...): on a {@code Run$_} thread that carries the options. */
	private static void runAsMacro(final Module module, final String options) throws InterruptedException {
		final List<PreprocessorPlugin> pre = context.service(PluginService.class).createInstancesOfType(
			PreprocessorPlugin.class);
		final List<PostprocessorPlugin> post = context.service(PluginService.class).createInstancesOfType(
			PostprocessorPlugin.class);
		final Thread macro = new Thread(() -> {
			Macro.setOptions(Thread.currentThread(), options);
			try {
				new ModuleRunner(context, module, pre, post).run();
			}
			finally {
				Macro.setOptions(Thread.currentThread(), null);
			}
		}, "Run$_contact_tracker_test");
		macro.start();
		macro.join();
	}
}
