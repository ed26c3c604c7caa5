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

import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;

/**
 * One tracking setting, described once: its name (the key of a macro call, {@code r_out}), label, help text,
 * value type, default, allowed values and unit. Every front end derives its form of the setting from this: the
 * command line option ({@link #cliOption()}), the TrackMate key ({@link #trackMateKey()}), the Fiji dialog's
 * labels and the TrackMate panel's fields. Parsing and checking give the same one-line messages everywhere.
 *
 * @param <V> the value type: {@code Double}, {@code Integer} or {@code String}
 */
public final class Setting<V> {

	/** What a number means, which decides how a front end shows it. */
	public enum Unit {
		/** A grey level of the image. */
		GREY_LEVEL("grey level"),
		/** A length in pixels: shown in the image's physical units where the front end knows them. */
		PIXELS("px"),
		/** A number of pixels (an area). */
		PIXEL_COUNT("pixels"),
		/** No unit. */
		NONE("");

		private final String symbol;

		Unit(final String symbol) {
			this.symbol = symbol;
		}

		/** @return how the unit is written after a value ("" for none) */
		public String symbol() {
			return symbol;
		}
	}

	private final String name;
	private final String label;
	private final String help;
	private final Class<V> type;
	private final V defaultValue;
	private final List<V> choices;
	private final Predicate<V> allowed;
	private final String allowedText;
	private final Number min;
	private final Number max;
	private final Unit unit;
	private String trackMateKey;
	private boolean imageSpecific;
	private boolean optionalInMaps;
	private V absentInMaps;

	private Setting(final String name, final String label, final String help, final Class<V> type,
		final V defaultValue, final List<V> choices, final Predicate<V> allowed, final String allowedText,
		final Number min, final Number max, final Unit unit, final String trackMateKey)
	{
		this.name = name;
		this.label = label;
		this.help = help;
		this.type = type;
		this.defaultValue = defaultValue;
		this.choices = choices;
		this.allowed = allowed;
		this.allowedText = allowedText;
		this.min = min;
		this.max = max;
		this.unit = unit;
		this.trackMateKey = trackMateKey;
	}

	/**
	 * A decimal setting.
	 *
	 * @param min the smallest allowed value ({@code Double.NEGATIVE_INFINITY} for none)
	 * @param minAllowed whether {@code min} itself is allowed
	 * @param allowedText what a valid value is, for messages ("a positive number of pixels")
	 */
	static Setting<Double> decimal(final String name, final String label, final String help, final double defaultValue,
		final double min, final boolean minAllowed, final String allowedText, final Unit unit)
	{
		return new Setting<>(name, label, help, Double.class, defaultValue, List.of(), v -> Double.isFinite(v) &&
			(minAllowed ? v >= min : v > min), allowedText, Double.isInfinite(min) ? null : min, null, unit, upper(name));
	}

	/** An integer setting with a smallest allowed value. */
	static Setting<Integer> integer(final String name, final String label, final String help, final int defaultValue,
		final int min, final String allowedText, final Unit unit, final String trackMateKey)
	{
		return new Setting<>(name, label, help, Integer.class, defaultValue, List.of(), v -> v >= min, allowedText, min,
			null, unit, trackMateKey == null ? upper(name) : trackMateKey);
	}

	/** An integer setting with a smallest and a largest allowed value. */
	static Setting<Integer> integer(final String name, final String label, final String help, final int defaultValue,
		final int min, final int max, final String allowedText, final Unit unit)
	{
		return new Setting<>(name, label, help, Integer.class, defaultValue, List.of(), v -> v >= min && v <= max,
			allowedText, min, max, unit, upper(name));
	}

	/** A setting that takes one of a list of values (the first is the default unless given). */
	static <V> Setting<V> choice(final String name, final String label, final String help, final Class<V> type,
		final V defaultValue, final List<V> choices)
	{
		return new Setting<>(name, label, help, type, defaultValue, List.copyOf(choices), choices::contains,
			"one of " + String.join(", ", choices.stream().map(String::valueOf).toList()), null, null, Unit.NONE, upper(
				name));
	}

	private static String upper(final String name) {
		return name.toUpperCase(Locale.ROOT);
	}

	/** Marks a setting whose default fits no real image, so the command line requires it. */
	Setting<V> imageSpecific() {
		imageSpecific = true;
		return this;
	}

	/**
	 * Marks a setting added after TrackMate settings maps without it were written (scripts, sessions): a map that
	 * lacks its key means its default.
	 */
	Setting<V> optionalInMaps() {
		return optionalInMaps(defaultValue);
	}

	/**
	 * Lets a TrackMate settings map lack the setting, which then means {@code absent}: the value maps written before
	 * the setting existed were tracked with, where the default has changed since (used while the descriptor is built).
	 */
	Setting<V> optionalInMaps(final V absent) {
		optionalInMaps = true;
		absentInMaps = absent;
		return this;
	}

	/** Gives the setting a TrackMate key other than its upper-case name (used while the descriptor is built). */
	Setting<V> trackMateKey(final String key) {
		trackMateKey = key;
		return this;
	}

	/**
	 * @return whether the value depends on the images so much that the command line insists on it (the
	 *         interactive front ends start from the default and preview)
	 */
	public boolean isImageSpecific() {
		return imageSpecific;
	}

	/**
	 * @return whether a TrackMate settings map may lack the setting's key, which then means {@link #absentInMaps()} (a
	 *         setting added after maps without it were written)
	 */
	public boolean isOptionalInMaps() {
		return optionalInMaps;
	}

	/**
	 * @return what a TrackMate settings map that lacks the setting means: the value maps were tracked with before it
	 *         existed (its default, unless that changed since); null for a setting every map holds
	 */
	public V absentInMaps() {
		return absentInMaps;
	}

	/** @return the name: the key in macros ({@code r_out=20}) and settings maps */
	public String name() {
		return name;
	}

	/** @return a short label for dialogs and panels */
	public String label() {
		return label;
	}

	/** @return one or two sentences of help */
	public String help() {
		return help;
	}

	/** @return the value type */
	public Class<V> type() {
		return type;
	}

	/** @return the default value */
	public V defaultValue() {
		return defaultValue;
	}

	/** @return the allowed values of a choice setting, in display order; empty for numbers */
	public List<V> choices() {
		return choices;
	}

	/** @return the smallest allowed value of a number setting, or {@code null} */
	public Number min() {
		return min;
	}

	/** @return the largest allowed value of a number setting, or {@code null} */
	public Number max() {
		return max;
	}

	/** @return the unit of a number setting */
	public Unit unit() {
		return unit;
	}

	/** @return the command-line option: {@code --r-out} */
	public String cliOption() {
		return "--" + name.replace('_', '-');
	}

	/** @return the key in TrackMate settings maps and XML files: {@code R_OUT} */
	public String trackMateKey() {
		return trackMateKey;
	}

	/** @return what a valid value is, for help texts ("a positive number of pixels") */
	public String allowedText() {
		return allowedText;
	}

	/**
	 * Reads a value from text (a macro option, a command-line argument, a TrackMate XML attribute) and checks it.
	 *
	 * @throws InvalidSettingException naming the setting ({@link InvalidSettingException#key()}) and the text
	 */
	public V parse(final String text) {
		final String t = text == null ? "" : text.trim();
		final Object value;
		try {
			if (type == Double.class) value = Double.valueOf(t);
			else if (type == Integer.class) value = Integer.valueOf(t);
			else value = canonicalChoice(t);
		}
		catch (final NumberFormatException e) {
			throw new InvalidSettingException(name, name + " must be " + (type == Integer.class ? "a whole number"
				: "a number") + ", not '" + text + "'");
		}
		return check(type.cast(value));
	}

	/** A text choice given in any case ({@code FIT}) is the listed one ({@code fit}). */
	private String canonicalChoice(final String t) {
		for (final V c : choices)
			if (c instanceof String && ((String) c).equalsIgnoreCase(t)) return (String) c;
		return t;
	}

	/**
	 * @return {@code value}, when it is allowed
	 * @throws InvalidSettingException naming the setting ({@link InvalidSettingException#key()}), what is allowed
	 *         and the value
	 */
	public V check(final V value) {
		if (value == null) throw new InvalidSettingException(name, name + " must be given (" + allowedText + ")");
		if (!allowed.test(value)) throw new InvalidSettingException(name, name + " must be " + allowedText + ", not " +
			(type == String.class ? "'" + value + "'" : String.valueOf(value)));
		return value;
	}

	@Override
	public String toString() {
		return name;
	}
}
