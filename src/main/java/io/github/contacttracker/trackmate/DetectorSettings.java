package io.github.contacttracker.trackmate;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;

/**
 * The TrackMate detector settings of Contact Tracker: keys, value types, defaults, validation and conversion to
 * and from {@link TrackerParameters}.
 * <p>
 * This class uses no TrackMate type, so the command line and the TrackMate XML writer can use it without
 * TrackMate on the class path; {@link ContactTrackerDetectorFactory} exposes the same keys.
 * <p>
 * Values and their Java types (TrackMate marshals them with {@code toString()} and unmarshals them by the type
 * of the default value, so the types are part of the contract):
 * <table>
 * <caption>settings</caption>
 * <tr><th>key</th><th>type</th><th>meaning</th></tr>
 * <tr><td>{@code TARGET_CHANNEL}</td><td>Integer</td><td>channel to analyse, 1-based (TrackMate's key)</td></tr>
 * <tr><td>{@code THRESHOLD}</td><td>Double</td><td>grey level: pixels {@code >=} it form the active areas</td></tr>
 * <tr><td>{@code R_OUT}</td><td>Double</td><td>radius of a particle's effective disc, in PIXELS</td></tr>
 * <tr><td>{@code MIN_AREA}</td><td>Integer</td><td>smaller components are noise, pixels</td></tr>
 * <tr><td>{@code MIN_SECOND_AREA}</td><td>Integer</td><td>below it a spot keeps its first-pass centre, pixels</td></tr>
 * <tr><td>{@code CONNECTIVITY}</td><td>Integer</td><td>4 or 8</td></tr>
 * <tr><td>{@code METHOD}</td><td>String</td><td>one of {@link Method#key()}</td></tr>
 * </table>
 */
public final class DetectorSettings {

	/** The key of the Contact Tracker detector in TrackMate (settings maps, XML files, scripts). */
	public static final String DETECTOR_KEY = "CONTACT_TRACKER_DETECTOR";

	/** TrackMate's own key for the 1-based target channel. */
	public static final String KEY_TARGET_CHANNEL = "TARGET_CHANNEL";
	/** TrackMate's own key for a detection threshold; here a grey level. */
	public static final String KEY_THRESHOLD = "THRESHOLD";
	public static final String KEY_R_OUT = "R_OUT";
	public static final String KEY_MIN_AREA = "MIN_AREA";
	public static final String KEY_MIN_SECOND_AREA = "MIN_SECOND_AREA";
	public static final String KEY_CONNECTIVITY = "CONNECTIVITY";
	public static final String KEY_METHOD = "METHOD";

	/** TrackMate's attribute naming the detector in {@code <DetectorSettings>} ({@code DetectorKeys}). */
	public static final String XML_ATTRIBUTE_DETECTOR_NAME = "DETECTOR_NAME";

	public static final int DEFAULT_TARGET_CHANNEL = 1;
	/** Default grey-level threshold; images differ, so users are expected to set it. */
	public static final double DEFAULT_THRESHOLD = 100;
	/** Default effective-disc radius (px). */
	public static final double DEFAULT_R_OUT = 20;

	private static final List<String> KEYS = List.of(KEY_TARGET_CHANNEL, KEY_THRESHOLD, KEY_R_OUT, KEY_MIN_AREA,
		KEY_MIN_SECOND_AREA, KEY_CONNECTIVITY, KEY_METHOD);

	private DetectorSettings() {}

	/** @return every key, in a fixed order (the order they are written to XML) */
	public static List<String> keys() {
		return KEYS;
	}

	/**
	 * @return the Java type of the value of {@code key}
	 * @throws IllegalArgumentException for an unknown key
	 */
	public static Class<?> type(final String key) {
		switch (key) {
			case KEY_TARGET_CHANNEL: case KEY_MIN_AREA: case KEY_MIN_SECOND_AREA: case KEY_CONNECTIVITY:
				return Integer.class;
			case KEY_THRESHOLD: case KEY_R_OUT:
				return Double.class;
			case KEY_METHOD:
				return String.class;
			default:
				throw new IllegalArgumentException("unknown Contact Tracker setting " + key);
		}
	}

	/** @return a new, modifiable map of the default settings */
	public static Map<String, Object> defaults() {
		return toMap(TrackerParameters.of(DEFAULT_THRESHOLD, DEFAULT_R_OUT), DEFAULT_TARGET_CHANNEL);
	}

	/**
	 * @param params the localizer parameters
	 * @param targetChannel the 1-based channel
	 * @return a new, modifiable settings map, in {@link #keys()} order
	 */
	public static Map<String, Object> toMap(final TrackerParameters params, final int targetChannel) {
		final Map<String, Object> map = new LinkedHashMap<>();
		map.put(KEY_TARGET_CHANNEL, targetChannel);
		map.put(KEY_THRESHOLD, params.threshold());
		map.put(KEY_R_OUT, params.rOut());
		map.put(KEY_MIN_AREA, params.minArea());
		map.put(KEY_MIN_SECOND_AREA, params.minSecondArea());
		map.put(KEY_CONNECTIVITY, params.connectivity().neighbours());
		map.put(KEY_METHOD, params.method().key());
		return map;
	}

	/**
	 * Checks a settings map: every key present, no unknown key, every value non-null, of the right type and
	 * valid.
	 *
	 * @return {@code null} when the map is fine, else a message naming each problem (one per line)
	 */
	public static String check(final Map<String, Object> settings) {
		if (settings == null) return "Contact Tracker: no settings map given.";
		final StringBuilder errors = new StringBuilder();
		for (final String key : KEYS) {
			final Object value = settings.get(key);
			final Class<?> type = type(key);
			if (value == null) {
				line(errors, (settings.containsKey(key) ? "The value of " + key + " is null" : "Missing setting " + key) +
					": expected " + describe(type) + ".");
			}
			else if (!type.isInstance(value)) {
				line(errors, "Setting " + key + " must be " + describe(type) + ", not the " +
					value.getClass().getSimpleName() + " '" + value + "'.");
			}
		}
		for (final String key : settings.keySet())
			if (!KEYS.contains(key)) line(errors, "Unknown setting " + key + " (expected " + String.join(", ", KEYS) + ").");
		if (errors.length() > 0) return errors.toString();

		final int channel = (Integer) settings.get(KEY_TARGET_CHANNEL);
		if (channel < 1) line(errors, KEY_TARGET_CHANNEL + " is 1-based and must be at least 1, not " + channel + ".");
		try {
			parameters(settings);
		}
		catch (final IllegalArgumentException e) {
			line(errors, "Invalid setting: " + e.getMessage() + ".");
		}
		return errors.length() > 0 ? errors.toString() : null;
	}

	/**
	 * @return the localizer parameters of a settings map
	 * @throws IllegalArgumentException with a one-line message when the map is incomplete, mistyped or invalid
	 */
	public static TrackerParameters parameters(final Map<String, Object> settings) {
		final double threshold = get(settings, KEY_THRESHOLD, Double.class);
		final double rOut = get(settings, KEY_R_OUT, Double.class);
		final int minArea = get(settings, KEY_MIN_AREA, Integer.class);
		final int minSecondArea = get(settings, KEY_MIN_SECOND_AREA, Integer.class);
		final int connectivity = get(settings, KEY_CONNECTIVITY, Integer.class);
		final String method = get(settings, KEY_METHOD, String.class);
		return new TrackerParameters(threshold, rOut, minArea, Connectivity.parse(Integer.toString(connectivity)),
			minSecondArea, Method.parse(method));
	}

	/**
	 * @return the 1-based target channel of a settings map
	 * @throws IllegalArgumentException when it is missing or not an Integer
	 */
	public static int targetChannel(final Map<String, Object> settings) {
		return get(settings, KEY_TARGET_CHANNEL, Integer.class);
	}

	/**
	 * Parses the text form of one setting (as TrackMate writes it into XML attributes).
	 *
	 * @throws IllegalArgumentException naming the key and the text when it does not parse
	 */
	public static Object parse(final String key, final String text) {
		final Class<?> type = type(key);
		final String t = text == null ? "" : text.trim();
		try {
			if (type == Integer.class) return Integer.valueOf(t);
			if (type == Double.class) return Double.valueOf(t);
			return text;
		}
		catch (final NumberFormatException e) {
			throw new IllegalArgumentException("cannot read " + key + " = '" + text + "' as " + describe(type));
		}
	}

	/** @return a one-line human-readable form of a settings map, keys in {@link #keys()} order */
	public static String echo(final Map<String, Object> settings) {
		final StringBuilder sb = new StringBuilder();
		for (final String key : KEYS)
			sb.append(sb.length() == 0 ? "" : ", ").append(key).append(" = ").append(settings.get(key));
		return sb.toString();
	}

	private static <V> V get(final Map<String, Object> settings, final String key, final Class<V> type) {
		final Object value = settings == null ? null : settings.get(key);
		if (value == null) throw new IllegalArgumentException("missing setting " + key);
		if (!type.isInstance(value))
			throw new IllegalArgumentException(key + " must be " + describe(type) + ", not the " +
				value.getClass().getSimpleName() + " '" + value + "'");
		return type.cast(value);
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
