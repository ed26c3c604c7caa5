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

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.TrackerParameters;

/**
 * The TrackMate form of the tracking settings: a map from {@link Setting#trackMateKey()} ({@code THRESHOLD},
 * {@code R_OUT}, ..., TrackMate's own {@code TARGET_CHANNEL}) to values of the setting's Java type, derived from
 * {@link TrackingSettings#ALL}. TrackMate marshals the values with {@code toString()} and its default unmarshalling
 * goes by the type of the default value, so the types are part of the contract.
 * <p>
 * Uses no TrackMate type: the TrackMate XML writer (package {@code io}) and the TrackMate adapter (package
 * {@code trackmate}) both use it.
 */
public final class TrackMateSettings {

	/** The key of the Contact Tracker detector in TrackMate (settings maps, XML files, scripts). */
	public static final String DETECTOR_KEY = "CONTACT_TRACKER_DETECTOR";

	/** TrackMate's attribute naming the detector in {@code <DetectorSettings>} ({@code DetectorKeys}). */
	public static final String XML_ATTRIBUTE_DETECTOR_NAME = "DETECTOR_NAME";

	public static final String KEY_TARGET_CHANNEL = TrackingSettings.CHANNEL.trackMateKey();
	public static final String KEY_THRESHOLD = TrackingSettings.THRESHOLD.trackMateKey();
	/**
	 * The key of the threshold in files saved before it was renamed {@code GREY_THRESHOLD} (TrackMate's LoG and
	 * DoG detectors use {@code THRESHOLD} for a quality cut-off); still read.
	 */
	public static final String OLD_KEY_THRESHOLD = "THRESHOLD";
	public static final String KEY_R_OUT = TrackingSettings.R_OUT.trackMateKey();
	public static final String KEY_MIN_AREA = TrackingSettings.MIN_AREA.trackMateKey();
	public static final String KEY_MIN_SECOND_AREA = TrackingSettings.MIN_SECOND_AREA.trackMateKey();
	public static final String KEY_CONNECTIVITY = TrackingSettings.CONNECTIVITY.trackMateKey();
	public static final String KEY_METHOD = TrackingSettings.METHOD.trackMateKey();
	public static final String KEY_DIAMETER = TrackingSettings.DIAMETER.trackMateKey();
	/** Kinds of particle; maps written before it existed lack it, which means 0 (found automatically). */
	public static final String KEY_KINDS = TrackingSettings.KINDS.trackMateKey();

	public static final int DEFAULT_TARGET_CHANNEL = TrackingSettings.CHANNEL.defaultValue();

	private static final List<String> KEYS = TrackingSettings.ALL.stream().map(Setting::trackMateKey).toList();

	private TrackMateSettings() {}

	/** @return every key, in {@link TrackingSettings#ALL} order (the order they are written to XML) */
	public static List<String> keys() {
		return KEYS;
	}

	/** @return the setting of a TrackMate key, or {@code null} */
	public static Setting<?> setting(final String key) {
		for (final Setting<?> s : TrackingSettings.ALL)
			if (s.trackMateKey().equals(key)) return s;
		return null;
	}

	/**
	 * @return the Java type of the value of {@code key}
	 * @throws InvalidInputException for an unknown key
	 */
	public static Class<?> type(final String key) {
		final Setting<?> s = setting(key);
		if (s == null) throw new InvalidInputException("unknown Contact Tracker setting " + key);
		return s.type();
	}

	/** @return a new, modifiable map of the default settings */
	public static Map<String, Object> defaults() {
		return toMap(SettingValues.defaults());
	}

	/** @return a new, modifiable settings map of {@code values}, in {@link #keys()} order */
	public static Map<String, Object> toMap(final SettingValues values) {
		final Map<String, Object> map = new LinkedHashMap<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			map.put(s.trackMateKey(), values.get(s));
		return map;
	}

	/**
	 * Checks a settings map: every key present (but those of settings added after maps without them were written,
	 * {@link Setting#isOptionalInMaps()}: absent, they mean {@link Setting#absentInMaps()}), no unknown key, every value non-null, of
	 * the right type and allowed.
	 *
	 * @return {@code null} when the map is fine, else a message naming each problem (one per line)
	 */
	public static String check(final Map<String, Object> settings) {
		if (settings == null) return "Contact Tracker: no settings map given.";
		final StringBuilder errors = new StringBuilder();
		for (final Setting<?> s : TrackingSettings.ALL) {
			final String key = s.trackMateKey();
			final Object value = settings.get(key);
			if (value == null && s.isOptionalInMaps() && !settings.containsKey(key)) continue;
			if (value == null) line(errors, (settings.containsKey(key) ? "The value of " + key + " is null" :
				"Missing setting " + key) + ": expected " + describe(s.type()) + ".");
			else if (!s.type().isInstance(value)) line(errors, "Setting " + key + " must be " + describe(s.type()) +
				", not the " + value.getClass().getSimpleName() + " '" + value + "'.");
			else try {
				check(s, value);
			}
			catch (final InvalidInputException e) {
				line(errors, "Invalid setting " + key + ": " + e.getMessage() + ".");
			}
		}
		for (final String key : settings.keySet())
			if (!KEYS.contains(key)) line(errors, "Unknown setting " + key + " (expected " + String.join(", ", KEYS) + ").");
		return errors.length() > 0 ? errors.toString() : null;
	}

	@SuppressWarnings("unchecked")
	private static <V> void check(final Setting<V> s, final Object value) {
		s.check((V) value);
	}

	/**
	 * @return the checked values of a settings map; a setting that may be absent ({@link Setting#isOptionalInMaps()})
	 *         and is absent has the value it meant ({@link Setting#absentInMaps()})
	 * @throws InvalidInputException with every problem when the map is incomplete, mistyped or invalid
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public static SettingValues values(final Map<String, Object> settings) {
		final String error = check(settings);
		if (error != null) throw new InvalidInputException(error.replace('\n', ' '));
		SettingValues v = SettingValues.defaults();
		for (final Setting s : TrackingSettings.ALL)
			if (settings.containsKey(s.trackMateKey())) v = v.with(s, settings.get(s.trackMateKey()));
			else if (s.isOptionalInMaps()) v = v.with(s, s.absentInMaps());
		return v;
	}

	/**
	 * @return a new, modifiable settings map with every key, in {@link #keys()} order: {@code settings} with the
	 *         values the settings it may lack mean when absent ({@link Setting#absentInMaps()})
	 * @throws InvalidInputException when the map is incomplete, mistyped or invalid
	 */
	public static Map<String, Object> complete(final Map<String, Object> settings) {
		return toMap(values(settings));
	}

	/**
	 * @return the localizer parameters of a settings map
	 * @throws InvalidInputException when the map is incomplete, mistyped or invalid
	 */
	public static TrackerParameters parameters(final Map<String, Object> settings) {
		return values(settings).parameters();
	}

	/**
	 * @return the 1-based target channel of a settings map
	 * @throws InvalidInputException when the map is incomplete, mistyped or invalid
	 */
	public static int targetChannel(final Map<String, Object> settings) {
		return values(settings).channel();
	}

	/**
	 * Parses the text form of one setting (as TrackMate writes it into XML attributes).
	 *
	 * @throws InvalidInputException naming the key and the text when it does not parse or is not allowed
	 */
	public static Object parse(final String key, final String text) {
		final Setting<?> s = setting(key);
		if (s == null) throw new InvalidInputException("unknown Contact Tracker setting " + key);
		try {
			return s.parse(text);
		}
		catch (final InvalidInputException e) {
			throw new InvalidInputException("cannot read " + key + " = '" + text + "': " + e.getMessage(), e);
		}
	}

	/** @return a one-line human-readable form of a settings map, keys in {@link #keys()} order */
	public static String echo(final Map<String, Object> settings) {
		final StringBuilder sb = new StringBuilder();
		for (final String key : KEYS)
			sb.append(sb.length() == 0 ? "" : ", ").append(key).append(" = ").append(settings.get(key));
		return sb.toString();
	}

	private static String describe(final Class<?> type) {
		if (type == Integer.class) return "an Integer";
		if (type == Double.class) return "a Double";
		return "a String";
	}

	private static void line(final StringBuilder sb, final String message) {
		if (sb.length() > 0) sb.append('\n');
		sb.append(message);
	}
}
