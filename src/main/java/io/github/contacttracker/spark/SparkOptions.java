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
package io.github.contacttracker.spark;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * The Spark job's command line: the movies, the job's own options, and every tracking option generated from
 * {@link TrackingSettings#ALL} (each {@link Setting#cliOption()} with its help), as {@code contact-tracker track}
 * has them, so the two cannot drift apart. Values are read by the settings themselves (the same checks and
 * messages). Syntax: {@code --name VALUE} or {@code --name=VALUE}, each option at most once.
 */
final class SparkOptions {

	/** Frames per task when {@code --chunk} is not given: about 10 s of work for a 512 x 512 frame per core. */
	static final int DEFAULT_CHUNK = 500;

	final List<String> movies = new ArrayList<>();
	String outDir;
	String master;
	String parquet;
	boolean trackMateXml;
	boolean help;
	int chunk = DEFAULT_CHUNK;
	/** Spark settings given with {@code --conf KEY=VALUE}, in order. */
	final Map<String, String> conf = new LinkedHashMap<>();
	/** The tracking settings given, as text, by setting. */
	final Map<Setting<?>, String> given = new LinkedHashMap<>();

	/** The job's own options (those with a value), each with its label and help. */
	private static final String[][] OWN = { //
		{ "--out-dir", "DIR", "Write each movie's spots to DIR/NAME.csv (NAME: its file name without extension), as " +
			"'contact-tracker track --out-dir DIR' does. Required." }, //
		{ "--master", "URL", "Spark master: spark://HOST:7077, local[N], ... Default: the one spark-submit gives, else " +
			"local[*] (all cores of this machine)." }, //
		{ "--parquet", "DIR", "Also write every spot, with a MOVIE column, as one Parquet table partitioned by movie. " +
			"Default: DIR/spots.parquet." }, //
		{ "--chunk", "N", "Frames per task: a long movie spreads over the cluster in chunks of N frames. Default: " +
			DEFAULT_CHUNK + "." }, //
		{ "--conf", "KEY=VALUE", "A Spark setting (spark.executor.memory=8g, ...); may be repeated." } };

	/**
	 * @throws InvalidInputException one line naming the option and what is wrong
	 */
	static SparkOptions parse(final String... args) {
		final SparkOptions o = new SparkOptions();
		final Map<String, Setting<?>> settings = new LinkedHashMap<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			settings.put(s.cliOption(), s);
		final List<String> seen = new ArrayList<>();
		boolean optionsEnded = false;
		for (int i = 0; i < args.length; i++) {
			final String arg = args[i];
			if (optionsEnded || !arg.startsWith("--") || arg.length() == 2) {
				if (!optionsEnded && arg.equals("--")) optionsEnded = true;
				else o.movies.add(arg);
				continue;
			}
			final int equals = arg.indexOf('=');
			final String name = equals < 0 ? arg : arg.substring(0, equals);
			if (name.equals("--help")) {
				o.help = true;
				continue;
			}
			if (name.equals("--trackmate-xml")) {
				o.trackMateXml = true;
				continue;
			}
			if (!settings.containsKey(name) && !ownOption(name)) throw new InvalidInputException("unknown option " + name +
				" (--help lists them)");
			if (!name.equals("--conf") && seen.contains(name)) throw new InvalidInputException("option " + name +
				" should be given only once");
			seen.add(name);
			if (equals < 0 && i + 1 == args.length) throw new InvalidInputException("option " + name + " needs a value");
			final String value = equals < 0 ? args[++i] : arg.substring(equals + 1);
			final Setting<?> setting = settings.get(name);
			if (setting != null) {
				try {
					SettingValues.defaults().withText(setting, value); // checked now, by the setting itself
				}
				catch (final InvalidInputException e) {
					throw new InvalidInputException("option " + name + ": " + e.getMessage(), e);
				}
				o.given.put(setting, value);
			}
			else switch (name) {
				case "--out-dir" -> o.outDir = value;
				case "--master" -> o.master = value;
				case "--parquet" -> o.parquet = value;
				case "--chunk" -> o.chunk = positive(name, value);
				default -> {
					final int eq = value.indexOf('=');
					if (eq <= 0) throw new InvalidInputException("option --conf takes KEY=VALUE, not '" + value + "'");
					o.conf.put(value.substring(0, eq), value.substring(eq + 1));
				}
			}
		}
		if (o.help) return o;
		if (o.movies.isEmpty()) throw new InvalidInputException("no movie given (MOVIE... --out-dir DIR)");
		if (o.outDir == null) throw new InvalidInputException("--out-dir DIR is required (each movie's spots go to " +
			"DIR/NAME.csv)");
		return o;
	}

	private static boolean ownOption(final String name) {
		for (final String[] own : OWN)
			if (own[0].equals(name)) return true;
		return false;
	}

	private static int positive(final String name, final String value) {
		try {
			final int n = Integer.parseInt(value);
			if (n >= 1) return n;
		}
		catch (final NumberFormatException e) {
			// said below
		}
		throw new InvalidInputException("option " + name + ": '" + value + "' is not a whole number >= 1");
	}

	/** @return the tracking settings given, the others at their defaults */
	SettingValues settings() {
		SettingValues v = SettingValues.defaults();
		for (final Map.Entry<Setting<?>, String> e : given.entrySet())
			v = v.withText(e.getKey(), e.getValue());
		return v;
	}

	/** @return whether the setting was given on the command line */
	boolean given(final Setting<?> s) {
		return given.containsKey(s);
	}

	/** @return the help, its tracking options from the settings descriptor */
	static String usage() {
		final StringBuilder b = new StringBuilder();
		b.append("Usage: contact-tracker-spark MOVIE... --out-dir DIR [--master URL] [--parquet DIR] [--chunk N] ")
			.append("[--trackmate-xml] [--conf KEY=VALUE]... [tracking options]\n");
		b.append("Track movies on Apache Spark, each movie's CSV equal to 'contact-tracker track --out-dir DIR'. MOVIE: ")
			.append("a TIFF, BigTIFF or OME-TIFF, uncompressed, as a path or a Hadoop URI (file://, hdfs://, s3a://).\n");
		for (final String[] own : OWN)
			b.append(String.format("  %s %s%n      %s%n", own[0], own[1], own[2]));
		b.append("  --trackmate-xml\n      Also write DIR/NAME.xml, a TrackMate file, as 'track --trackmate-xml' does.\n");
		for (final Setting<?> s : TrackingSettings.ALL)
			b.append(String.format("  %s %s%n      %s%s%n", s.cliOption(), s.type() == String.class ? String.join("|", s
				.choices().stream().map(String::valueOf).toList()) : s.type() == Integer.class ? "N" : "X", s.help(), s
					.isImageSpecific() ? " Default: measured on frame 1 by the profile helper." : " Default: " + s
						.defaultValue() + "."));
		b.append("  --help\n      Show this help.\n");
		return b.toString();
	}
}
