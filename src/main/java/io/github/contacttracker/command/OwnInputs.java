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

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.scijava.event.EventHandler;
import org.scijava.event.EventService;
import org.scijava.event.EventSubscriber;
import org.scijava.module.Module;
import org.scijava.module.ModuleItem;
import org.scijava.module.ModuleService;
import org.scijava.module.event.ModuleCanceledEvent;
import org.scijava.module.event.ModuleErroredEvent;
import org.scijava.module.event.ModuleEvent;
import org.scijava.module.event.ModuleFinishedEvent;
import org.scijava.module.event.ModulePreprocessEvent;

import ij.Macro;

/**
 * Checks one run of one of our commands, from inside the command: no pre- or postprocessor of ours runs for every
 * command Fiji executes.
 * <p>
 * The command's {@code validater=} methods report refused values here ({@link #refuse}); its initializer calls
 * {@link #start}, which listens to the events of the command's own module from then on. SciJava publishes an event
 * after each preprocessor and waits for its handlers (run on the event dispatch thread) before the next one runs; so right after the initializer this
 * sees the module and, in an ImageJ macro, checks the macro's values and resolves the keys it leaves out at their
 * defaults ({@link MacroInputs}) before the remembered values are loaded and a dialog could ask for them. After
 * each later preprocessor it sets refused inputs back to their remembered values, before SciJava remembers the
 * values (its {@code SaveInputsPreprocessor} follows the dialog). {@link #finish} marks the outputs shown, so that
 * SciJava does not display again the tables the command shows itself, and stops listening.
 */
final class OwnInputs {

	private final Object command;
	private final Map<String, String> refused = new LinkedHashMap<>();
	private final Map<String, Object> fallbacks = new LinkedHashMap<>();
	private EventService events;
	private ModuleService modules;
	private List<EventSubscriber<?>> subscribers;
	private Module module;
	private String macroProblem;
	/** The macro options of the thread running the command, read by {@link #start} (null: no macro). */
	private String macroOptions;

	/** @param command the command whose module is followed */
	OwnInputs(final Object command) {
		this.command = command;
	}

	/**
	 * From the command's initializer: follows its module's events from now on.
	 *
	 * @param eventService the context's events (null: nothing is followed, as in a run without preprocessing)
	 * @param moduleService where remembered values are read (may be null)
	 */
	void start(final EventService eventService, final ModuleService moduleService) {
		if (eventService == null || subscribers != null) return;
		events = eventService;
		modules = moduleService;
		// read here, on the module's thread: SciJava delivers events on the event dispatch thread
		macroOptions = Macro.getOptions();
		subscribers = events.subscribe(this);
	}

	/**
	 * From a {@code validater=}: notes a refused input, to be reported by the run and not remembered.
	 *
	 * @param name the input
	 * @param reason the one-line reason
	 * @param fallback its value when none is remembered (a number or text)
	 */
	void refuse(final String name, final String reason, final Object fallback) {
		refused.putIfAbsent(name, reason);
		fallbacks.putIfAbsent(name, fallback);
	}

	/** @return the ImageJ macro options of this run, or null when no macro runs the command */
	String macroOptions() {
		return macroOptions;
	}

	/** @return the first problem of this run (a macro value that does not convert, else a refused input), or null */
	String problem() {
		if (macroProblem != null) return macroProblem;
		return refused.isEmpty() ? null : refused.values().iterator().next();
	}

	/** At the end of the run: marks the outputs shown (the command shows them itself) and stops listening. */
	void finish() {
		if (module != null) MacroInputs.outputsShown(module);
		stop();
	}

	@EventHandler
	private void onEvent(final ModuleEvent e) {
		if (e.getModule() == null || e.getModule().getDelegateObject() != command) return;
		if (e instanceof ModulePreprocessEvent) {
			if (module == null) {
				module = e.getModule();
				macroProblem = MacroInputs.prepare(module, macroOptions);
			}
			restoreRefused();
		}
		else if (e instanceof ModuleCanceledEvent || e instanceof ModuleFinishedEvent || e instanceof ModuleErroredEvent)
			stop();
	}

	/** Sets each refused input back to its remembered value, else its fallback. */
	private void restoreRefused() {
		for (final Map.Entry<String, Object> f : fallbacks.entrySet()) {
			final ModuleItem<?> item = module.getInfo().getInput(f.getKey());
			if (item == null) continue;
			final Object remembered = modules == null ? null : modules.load(item);
			final Class<?> type = item.getType();
			final Object fallback = f.getValue();
			module.setInput(f.getKey(), remembered != null ? remembered : type == String.class ? String.valueOf(
				fallback) : type == int.class ? (Object) ((Number) fallback).intValue() : (Object) ((Number) fallback)
					.doubleValue());
		}
	}

	private void stop() {
		if (subscribers != null) events.unsubscribe(subscribers);
		subscribers = null;
	}
}
