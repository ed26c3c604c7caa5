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

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.storage.StorageLevel;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.report.PotentialCsv;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.potential.SpotSet;
import scala.Tuple2;

/**
 * {@code contact-tracker-spark potential TABLE --bin W --r-max R --csv OUT.csv [--width W --height H]
 * [--start-frame F] [--flagged drop|keep] [--master URL]}: the command line's {@code potential} on an archive, as
 * a Spark aggregation over the spots table the job wrote (Parquet, a {@code MOVIE} column): each (movie, frame) is
 * selected by {@link SpotSet} and its pairs counted per bin by {@link PairCorrelation#framePairs}, the counts summed,
 * then g(r) and U(r) made by {@link PairCorrelation#fromCounts}. Frames of different movies are never paired. On
 * one movie's spots its CSV equals the command line's byte for byte.
 */
final class SparkPotential {

	private SparkPotential() {}

	/** @return 0, or 2 for bad options or data (said in one line) */
	static int run(final String[] args, final PrintStream out, final PrintStream err) {
		final Map<String, String> o = new LinkedHashMap<>();
		final List<String> positional = new ArrayList<>();
		final List<String> known = List.of("--bin", "--r-max", "--csv", "--width", "--height", "--start-frame",
			"--flagged", "--master");
		try {
			for (int i = 0; i < args.length; i++) {
				final String a = args[i];
				if (!a.startsWith("--")) {
					positional.add(a);
					continue;
				}
				final int eq = a.indexOf('=');
				final String name = eq < 0 ? a : a.substring(0, eq);
				if (!known.contains(name)) throw new InvalidInputException("unknown option " + name + " (" + String.join(
					", ", known) + ")");
				if (eq < 0 && i + 1 == args.length) throw new InvalidInputException("option " + name + " needs a value");
				o.put(name, eq < 0 ? args[++i] : a.substring(eq + 1));
			}
			if (positional.size() != 1) throw new InvalidInputException("give one spots table (the job's Parquet " +
				"folder), not " + positional.size());
			for (final String required : List.of("--bin", "--r-max", "--csv"))
				if (!o.containsKey(required)) throw new InvalidInputException("missing option " + required);
			if (o.containsKey("--width") != o.containsKey("--height")) throw new InvalidInputException("give both " +
				"--width and --height of the field of view, or neither (then it is inferred from the spots)");
			final String flagged = o.getOrDefault("--flagged", "drop").toLowerCase(Locale.ROOT);
			if (!flagged.equals("drop") && !flagged.equals("keep")) throw new InvalidInputException("--flagged must be " +
				"drop or keep, not '" + flagged + "'");
			final SpotSet.Selection selection = new SpotSet.Selection(Integer.parseInt(o.getOrDefault("--start-frame",
				"0")), flagged.equals("drop"));
			final SparkConf conf = new SparkConf().setAppName("contact-tracker potential");
			if (o.containsKey("--master")) conf.setMaster(o.get("--master"));
			else if (!conf.contains("spark.master")) conf.setMaster("local[*]");
			final SparkSession spark = SparkSession.builder().config(conf).getOrCreate();
			try {
				spark.sparkContext().setLogLevel("WARN");
				final PairCorrelation.Result r = potential(spark.read().parquet(positional.get(0)), selection, number(o,
					"--bin"), number(o, "--r-max"), o.containsKey("--width") ? FieldOfView.of(number(o, "--width"), number(
						o, "--height")) : null);
				PotentialCsv.write(Path.of(o.get("--csv")), r);
				out.println(positional.get(0) + ": " + r.spots() + " spots in " + r.frames() + " frames, " + r.pairs() +
					" pairs within r_max; g(r) and U(r) in " + o.get("--csv"));
			}
			finally {
				spark.stop();
			}
			return 0;
		}
		catch (final InvalidInputException | IOException | NumberFormatException e) {
			err.println("contact-tracker-spark potential: error: " + SparkTrack.oneLine(e.getMessage()));
			return SparkTrack.EXIT_BAD_INPUT;
		}
	}

	private static double number(final Map<String, String> o, final String name) {
		try {
			return Double.parseDouble(o.get(name));
		}
		catch (final NumberFormatException e) {
			throw new InvalidInputException("option " + name + ": '" + o.get(name) + "' is not a number");
		}
	}

	/**
	 * @param table spots with MOVIE (optional), FRAME, POSITION_X, POSITION_Y and the FLAG_ columns
	 * @param field the field of view, or null to infer it from the selected spots (as the command line does)
	 * @return g(r) and U(r) of all movies' frames together
	 */
	static PairCorrelation.Result potential(final Dataset<Row> table, final SpotSet.Selection selection,
		final double binWidth, final double rMax, final FieldOfView field)
	{
		final List<String> columns = new ArrayList<>();
		for (final String c : table.columns())
			if (SpotSet.reads(c)) columns.add(c);
		final boolean byMovie = Arrays.asList(table.columns()).contains("MOVIE");
		final String[] names = columns.toArray(String[]::new);
		final Dataset<Row> selected = byMovie ? table.selectExpr(concat("MOVIE", names)) : table.selectExpr(concat(
			"''", names));
		// one (movie, frame) per group: its spots selected exactly as the command line selects a table's
		final int startFrame = selection.startFrame();
		final boolean dropFlagged = selection.dropFlagged();
		final JavaRDD<double[][]> frames = selected.javaRDD().groupBy(r -> r.get(0) + "\u0000" + ((Number) r.get(
			1 + columns.indexOf(SpotSet.FRAME))).longValue()).map(g -> frame(g._2, names, new SpotSet.Selection(startFrame, dropFlagged))).filter(f -> f != null)
			.persist(StorageLevel.MEMORY_AND_DISK());
		try {
			final FieldOfView found = field != null ? field : inferred(frames);
			// spots left out at the border: the field shrinks with them, as the command line's (SpotSet.awayFromBorder)
			final double deepest = frames.map(xy -> {
				double d = Double.NEGATIVE_INFINITY;
				for (int i = 0; i < xy[2].length; i++)
					if (xy[4][i] != 0) d = Math.max(d, found.depth(xy[2][i], xy[3][i]));
				return d;
			}).reduce(Math::max);
			final double reach = SpotSet.borderReach(found, deepest);
			final FieldOfView f = reach > 0 ? found.inset(reach) : found;
			final int bins = PairCorrelation.bins(f, binWidth, rMax);
			final Tuple2<long[], double[]> sums = frames.map(all -> {
				final double[][] xy = reach > 0 ? within(all, f) : all;
				final int n = xy[0].length;
				return new Tuple2<>(PairCorrelation.framePairs(xy[0], xy[1], binWidth, bins), new double[] { 0.5 * n * (n -
					1.0), n > 0 ? 1 : 0, n, all[0].length - n });
			}).reduce((a, b) -> {
				final long[] p = a._1.clone();
				for (int k = 0; k < p.length; k++)
					p[k] += b._1[k];
				return new Tuple2<>(p, new double[] { a._2[0] + b._2[0], a._2[1] + b._2[1], a._2[2] + b._2[2], a._2[3] +
					b._2[3] });
			});
			if (sums._2[2] == 0) throw new InvalidInputException("no spot left in the table");
			return PairCorrelation.fromCounts(sums._1, sums._2[0], (int) sums._2[1], (int) sums._2[2], f, binWidth, reach,
				(int) sums._2[3]);
		}
		catch (final UnsupportedOperationException e) { // reduce of no frame
			throw new InvalidInputException("no spot left in the table");
		}
		finally {
			frames.unpersist();
		}
	}

	private static String[] concat(final String first, final String[] rest) {
		final String[] all = new String[rest.length + 1];
		all[0] = first;
		for (int i = 0; i < rest.length; i++)
			all[i + 1] = "CAST(`" + rest[i] + "` AS DOUBLE)";
		return all;
	}

	/** @return the frame's spots {x, y} inside the field */
	private static double[][] within(final double[][] xy, final FieldOfView f) {
		int n = 0;
		for (int i = 0; i < xy[0].length; i++)
			if (f.depth(xy[0][i], xy[1][i]) >= 0) n++;
		final double[][] out = new double[2][n];
		for (int i = 0, k = 0; i < xy[0].length; i++)
			if (f.depth(xy[0][i], xy[1][i]) >= 0) {
				out[0][k] = xy[0][i];
				out[1][k++] = xy[1][i];
			}
		return out;
	}

	/**
	 * @return one frame's selected spots {x, y} and its spots left out for a flag {x, y, 1 at the border else 0}, as
	 *         five arrays; null when the frame has neither
	 */
	private static double[][] frame(final Iterable<Row> rows, final String[] names,
		final SpotSet.Selection selection)
	{
		final List<Row> list = new ArrayList<>();
		rows.forEach(list::add);
		final Map<String, double[]> columns = new LinkedHashMap<>();
		for (int c = 0; c < names.length; c++) {
			final double[] v = new double[list.size()];
			for (int i = 0; i < v.length; i++)
				v[i] = list.get(i).isNullAt(c + 1) ? Double.NaN : list.get(i).getDouble(c + 1);
			columns.put(names[c], v);
		}
		final SpotSet set = SpotSet.fromColumns(columns, selection);
		final List<double[]> flagged = set.flaggedPositions();
		if (set.frames().isEmpty() && flagged.isEmpty()) return null;
		final double[][] out = new double[5][];
		out[0] = set.frames().isEmpty() ? new double[0] : set.frames().get(0)[0];
		out[1] = set.frames().isEmpty() ? new double[0] : set.frames().get(0)[1];
		for (int a = 0; a < 3; a++) {
			out[2 + a] = new double[flagged.size()];
			for (int i = 0; i < flagged.size(); i++)
				out[2 + a][i] = flagged.get(i)[a];
		}
		return out;
	}

	private static FieldOfView inferred(final JavaRDD<double[][]> frames) {
		final double[] e = frames.map(xy -> {
			// every spot with a position, used or left out for a flag, as SpotSet.inferredField
			final double[] r = { Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
				Double.NEGATIVE_INFINITY, xy[0].length + xy[2].length };
			for (int part = 0; part < 4; part += 2)
				for (int i = 0; i < xy[part].length; i++) {
					r[0] = Math.min(r[0], xy[part][i]);
					r[1] = Math.max(r[1], xy[part][i]);
					r[2] = Math.min(r[2], xy[part + 1][i]);
					r[3] = Math.max(r[3], xy[part + 1][i]);
				}
			return r;
		}).reduce((a, b) -> new double[] { Math.min(a[0], b[0]), Math.max(a[1], b[1]), Math.min(a[2], b[2]), Math.max(
			a[3], b[3]), a[4] + b[4] });
		return FieldOfView.inferred(e[0], e[1], e[2], e[3], (long) e[4]);
	}
}
