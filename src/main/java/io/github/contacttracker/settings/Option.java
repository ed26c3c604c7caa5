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
package io.github.contacttracker.settings;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;

/**
 * One option or positional parameter of a command: its names, its value's label and type, its help and its
 * default. Immutable; declared with the factories ({@link #integer}, {@link #path}, {@link #flag}, ...) and added to
 * a command's {@link CommandOptions}, which parses it and hands back its value.
 *
 * @param <T> the type of the value
 * @param names the names, short before long ({@code -h}, {@code --help}); empty for a positional parameter
 * @param label the value's placeholder in the help ({@code N}, {@code OUT.csv}); null for a flag
 * @param description the help text, one paragraph
 * @param converter text to value; throws an {@link IllegalArgumentException} whose message says what is wrong
 *        ({@code 'two' is not an int})
 * @param required whether the command cannot run without it
 * @param defaultValue the text that stands for the value when the option is not given; null for none
 * @param defaultInHelp whether the help appends {@code Default: <defaultValue>.} (false when the description says
 *        it in its own words)
 * @param negatable whether a flag also has a {@code --no-} form that sets it to false
 */
public record Option<T>(List<String> names, String label, String description, Function<String, T> converter,
	boolean required, String defaultValue, boolean defaultInHelp, boolean negatable)
{

	/** The prefix of a negatable flag's negative form. */
	public static final String NEGATION = "--no-";

	/** The converters of the typed options: Java's syntax ({@code +5}, {@code 2e-3}, {@code NaN}), nothing else. */
	public static final Function<String, Integer> INT = checked(Integer::valueOf, "an int");
	public static final Function<String, Long> LONG = checked(Long::valueOf, "a long");
	public static final Function<String, Double> DOUBLE = checked(Double::valueOf, "a double");
	public static final Function<String, Path> PATH = checked(Path::of, "a path");
	public static final Function<String, Boolean> BOOLEAN = checked(Option::bool, "a boolean");

	/** Checks what the parser relies on: a positional parameter has a label, only a long-named flag is negatable. */
	public Option {
		names = List.copyOf(names);
		if (names.isEmpty() && label == null) throw new IllegalArgumentException("a positional parameter needs a label");
		if (negatable && (label != null || !names.get(names.size() - 1).startsWith("--")))
			throw new IllegalArgumentException("only a flag with a long name is negatable: " + names);
	}

	/** @return an option with an int value ({@code --name N}) */
	public static Option<Integer> integer(final String name, final String label, final String description) {
		return valued(name, label, description, INT);
	}

	/** @return an option with a long value */
	public static Option<Long> longInteger(final String name, final String label, final String description) {
		return valued(name, label, description, LONG);
	}

	/** @return an option with a double value */
	public static Option<Double> decimal(final String name, final String label, final String description) {
		return valued(name, label, description, DOUBLE);
	}

	/** @return an option naming a file or folder */
	public static Option<Path> path(final String name, final String label, final String description) {
		return valued(name, label, description, PATH);
	}

	/** @return an option with a text value, checked by the command itself */
	public static Option<String> text(final String name, final String label, final String description) {
		return valued(name, label, description, Function.identity());
	}

	/**
	 * @param converter text to value; throws an {@link IllegalArgumentException} whose message says what is wrong
	 * @return an option with a value of the command's own type (e.g. a list of numbers)
	 */
	public static <T> Option<T> valued(final String name, final String label, final String description,
		final Function<String, T> converter)
	{
		return new Option<>(List.of(name), label, description, converter, false, null, false, false);
	}

	/** @return a flag (no value; true when given, else false) with these names, e.g. {@code -h}, {@code --help} */
	public static Option<Boolean> flag(final List<String> names, final String description) {
		return new Option<>(names, null, description, BOOLEAN, false, "false", false, false);
	}

	/** @return a flag with a negative form: {@code --progress} sets it, {@code --no-progress} clears it */
	public static Option<Boolean> negatableFlag(final String name, final String description) {
		return new Option<>(List.of(name), null, description, BOOLEAN, false, "false", false, true);
	}

	/** @return a required positional parameter naming a file or folder */
	public static Option<Path> positionalPath(final String label, final String description) {
		return new Option<>(List.of(), label, description, PATH, true, null, false, false);
	}

	/** @return a required positional parameter taken as it is written (a path or a URI: {@code hdfs://host/a.tif}) */
	public static Option<String> positionalText(final String label, final String description) {
		return new Option<>(List.of(), label, description, Function.identity(), true, null, false, false);
	}

	/** @return this option, which the command cannot run without */
	public Option<T> asRequired() {
		return new Option<>(names, label, description, converter, true, defaultValue, defaultInHelp, negatable);
	}

	/** @return this option with a default value, which the help states ({@code Default: 50.}) */
	public Option<T> withDefault(final String value) {
		return new Option<>(names, label, description, converter, required, value, true, negatable);
	}

	/** @return this option with a default value that the description already explains in its own words */
	public Option<T> withDefaultExplained(final String value) {
		return new Option<>(names, label, description, converter, required, value, false, negatable);
	}

	/** @return a converter that turns {@code parse}'s failure into {@code 'x' is not <what>} */
	private static <T> Function<String, T> checked(final Function<String, T> parse, final String what) {
		return text -> {
			try {
				return parse.apply(text);
			}
			catch (final IllegalArgumentException e) {
				throw new IllegalArgumentException("'" + text + "' is not " + what, e);
			}
		};
	}

	private static Boolean bool(final String text) {
		switch (text.toLowerCase(Locale.ROOT)) {
			case "true": return true;
			case "false": return false;
			default: throw new IllegalArgumentException(text);
		}
	}

	/** @return whether this is a positional parameter, not an option */
	public boolean positional() {
		return names.isEmpty();
	}

	/** @return whether this option takes no value */
	public boolean isFlag() {
		return label == null;
	}

	/** @return the name that messages use: the long one ({@code --help}), or the label of a positional parameter */
	public String mainName() {
		return positional() ? label : names.get(names.size() - 1);
	}

	/** @return the one-letter name ({@code -h}), or null */
	public String shortName() {
		return !positional() && !names.get(0).startsWith("--") ? names.get(0) : null;
	}

	/** @return how the help and the messages write it: {@code --reps=N}, {@code --[no-]progress}, {@code MOVIE} */
	public String synopsis() {
		if (positional()) return label;
		if (negatable) return "--[no-]" + mainName().substring(2);
		return mainName() + (isFlag() ? "" : "=" + label);
	}

	/** @return the help text, the default appended where the description does not explain it */
	public String help() {
		return defaultInHelp ? description + " Default:" + CommandOptions.NO_BREAK + defaultValue + "." : description;
	}
}
