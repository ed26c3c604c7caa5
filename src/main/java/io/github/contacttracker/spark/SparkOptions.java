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
import java.util.Set;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingOptions;
import io.github.contacttracker.settings.SettingValues;

/**
 * The Spark job's command line: the movies, the job's own options, and every tracking option, parsed by the
 * command line's parser ({@link CommandOptions}) with the tracking options declared as {@code contact-tracker track}
 * declares them ({@link SettingOptions}), so the two take the same options with the same help and messages and
 * cannot drift apart.
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
	/** The tracking settings given on the command line. */
	Set<Setting<?>> given = Set.of();
	private SettingValues settings = SettingValues.defaults();

	/** The job's options: its own, then every tracking setting's, as {@code contact-tracker track} declares them. */
	private static final class Declared {

		final CommandOptions options = new CommandOptions("contact-tracker-spark", "Track movies on Apache Spark, " +
			"each movie's CSV equal to 'contact-tracker track --out-dir DIR'.", "MOVIE: a TIFF, BigTIFF or OME-TIFF, " +
				"uncompressed, as a path or a Hadoop URI (file://, hdfs://, s3a://).").withRepeatedLastParameter()
					.inDeclarationOrder();
		final Option<String> movie = options.add(Option.positionalText("MOVIE", "A movie, as a path or a Hadoop URI."));
		final Option<String> outDir = options.add(Option.text("--out-dir", "DIR", "Write each movie's spots to " +
			"DIR/NAME.csv (NAME: its file name without extension), as 'contact-tracker track --out-dir DIR' does.")
			.asRequired());
		final Option<String> master = options.add(Option.text("--master", "URL", "Spark master: spark://HOST:7077, " +
			"local[N], ... Default: the one spark-submit gives, else local[*] (all cores of this machine)."));
		final Option<String> parquet = options.add(Option.text("--parquet", "DIR", "Also write every spot, with a " +
			"MOVIE column, as one Parquet table partitioned by movie. Default: DIR/spots.parquet."));
		final Option<Integer> chunk = options.add(Option.valued("--chunk", "N", "Frames per task: a long movie " +
			"spreads over the cluster in chunks of N frames.", SparkOptions::positive).withDefault(String.valueOf(
				DEFAULT_CHUNK)));
		final Option<String> conf = options.addRepeatable(Option.text("--conf", "KEY=VALUE", "A Spark setting " +
			"(spark.executor.memory=8g, ...); may be repeated."));
		final Option<Boolean> xml = options.add(Option.flag(List.of("--trackmate-xml"), "Also write DIR/NAME.xml, a " +
			"TrackMate file, as 'track --trackmate-xml' does."));
		final SettingOptions tracking = new SettingOptions(options);
	}

	/**
	 * @throws InvalidInputException one line naming the option and what is wrong
	 */
	static SparkOptions parse(final String... args) {
		final Declared d = new Declared();
		try {
			d.options.parse(args, 0);
		}
		catch (final CommandOptions.BadOptionException e) {
			throw new InvalidInputException(e.getMessage() + " (--help lists the options)", e);
		}
		final SparkOptions o = new SparkOptions();
		o.help = d.options.helpRequested();
		if (o.help) return o;
		o.movies.addAll(d.options.values(d.movie));
		o.outDir = d.options.value(d.outDir);
		o.master = d.options.value(d.master);
		o.parquet = d.options.value(d.parquet);
		o.chunk = d.options.value(d.chunk);
		o.trackMateXml = d.options.value(d.xml);
		for (final String c : d.options.values(d.conf)) {
			final int eq = c.indexOf('=');
			if (eq <= 0) throw new InvalidInputException("option --conf takes KEY=VALUE, not '" + c + "'");
			o.conf.put(c.substring(0, eq), c.substring(eq + 1));
		}
		o.settings = d.tracking.values();
		o.given = d.tracking.given();
		return o;
	}

	private static int positive(final String value) {
		try {
			final int n = Integer.parseInt(value);
			if (n >= 1) return n;
		}
		catch (final NumberFormatException e) {
			// said below
		}
		throw new IllegalArgumentException("'" + value + "' is not a whole number >= 1");
	}

	/** @return the tracking settings given, the others at their defaults */
	SettingValues settings() {
		return settings;
	}

	/** @return whether the setting was given on the command line */
	boolean given(final Setting<?> s) {
		return given.contains(s);
	}

	/** @return the help, its tracking options from the settings descriptor */
	static String usage() {
		return new Declared().options.usage();
	}
}
