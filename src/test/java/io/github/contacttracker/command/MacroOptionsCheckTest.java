package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

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
import org.scijava.plugin.PluginService;

import ij.Macro;

/** Macro values that do not fit their parameter refuse the command instead of silently becoming 0 or false. */
class MacroOptionsCheckTest {

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
		assertNull(MacroOptionsCheck.problem(tracker, "threshold=110 r_out=55 min_area=20"));
		assertNull(MacroOptionsCheck.problem(tracker, "threshold=1.5e2 r_out=55.5 method=first connectivity=4 " +
			"overlay=false table=TRUE csv=[/data/my images/a.csv] channel=2"));
		assertNull(MacroOptionsCheck.problem(tracker, ""));
		// the dialog's button is no macro option (Fiji resolves buttons itself); a recorded key for it is ignored
		assertNull(MacroOptionsCheck.problem(tracker, "threshold=110 measure=[Measure from the image]"));
	}

	@Test
	void malformedValuesAreNamed() {
		assertEquals("threshold must be a number, not 'abc'", MacroOptionsCheck.problem(tracker,
			"threshold=abc r_out=55"));
		assertEquals("r_out must be a number, not '5,5'", MacroOptionsCheck.problem(tracker, "threshold=1 r_out=5,5"));
		assertEquals("min_area must be a whole number, not '2.5'", MacroOptionsCheck.problem(tracker, "min_area=2.5"));
		assertEquals("overlay must be true or false, not 'yes'", MacroOptionsCheck.problem(tracker, "overlay=yes"));
		assertEquals("threshold must be a number, not 'NaN'", MacroOptionsCheck.problem(tracker, "threshold=NaN"));
		final CommandInfo profile = context.service(CommandService.class).getCommand(
			ContactTrackerProfileCommand.class);
		assertEquals("diameter must be a number, not 'big'", MacroOptionsCheck.problem(profile, "diameter=big"));
	}

	@Test
	void onlyOurCommandsAreChecked() {
		assertTrue(MacroOptionsCheck.ours(tracker));
		assertTrue(MacroOptionsCheck.ours(context.service(CommandService.class).getCommand(
			ContactTrackerProfileCommand.class)));
		assertFalse(MacroOptionsCheck.ours(new CommandInfo("org.example.OtherCommand")));
		assertFalse(MacroOptionsCheck.ours(new CommandInfo("io.github.contacttracker.commandline.Other")));
	}

	/**
	 * The whole path: ImageJ hands macro options to the thread running the command ({@code Run$_...}); the
	 * preprocessors see them there and the command is cancelled before it runs.
	 */
	@Test
	void aMacroCallWithABadValueIsCancelled() throws Exception {
		final Module module = context.service(ModuleService.class).createModule(tracker);
		final List<PreprocessorPlugin> pre = context.service(PluginService.class).createInstancesOfType(
			PreprocessorPlugin.class);
		final List<PostprocessorPlugin> post = context.service(PluginService.class).createInstancesOfType(
			PostprocessorPlugin.class);
		final AtomicReference<Throwable> failure = new AtomicReference<>();
		final Thread macro = new Thread(() -> {
			try {
				Macro.setOptions(Thread.currentThread(), "threshold=abc r_out=55");
				new ModuleRunner(context, module, pre, post).run();
			}
			catch (final Throwable t) {
				failure.set(t);
			}
			finally {
				Macro.setOptions(Thread.currentThread(), null);
			}
		}, "Run$_contact_tracker_test");
		macro.start();
		macro.join();
		assertNull(failure.get());
		assertTrue(((Cancelable) module).isCanceled());
		assertEquals("threshold must be a number, not 'abc'", ((Cancelable) module).getCancelReason());
		assertNull(module.getOutput("spots"));
	}
}
