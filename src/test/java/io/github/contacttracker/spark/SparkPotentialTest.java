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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.report.PotentialCsv;
import io.github.contacttracker.potential.SpotSet;

/**
 * {@code potential} on an archive as a Spark aggregation (pair counts per bin per frame, summed) equals the command
 * line's {@code potential}: on one movie's spots byte for byte, and on two movies whose frame numbers collide as the
 * command line on one table with the second movie's frames renumbered (frames of different movies never pair).
 * Flagged spots are left out, and spots before the start frame, the same way.
 */
class SparkPotentialTest {

	@TempDir
	Path dir;

	/** Random spots: {movie, frame, x, y, flagged}. */
	private static List<Object[]> spots(final String movie, final long seed) {
		final Random r = new Random(seed);
		final List<Object[]> spots = new ArrayList<>();
		for (int t = 0; t < 20; t++)
			for (int i = 0; i < 25; i++)
				spots.add(new Object[] { movie, (long) t, 100 * r.nextDouble(), 80 * r.nextDouble(), r.nextInt(10) == 0 ?
					1L : 0L });
		return spots;
	}

	private static Path csv(final Path file, final List<Object[]> spots, final long frameShift) throws IOException {
		final List<String> lines = new ArrayList<>(List.of("FRAME,POSITION_X,POSITION_Y,FLAG_MERGED"));
		for (final Object[] s : spots)
			lines.add(((long) s[1] + frameShift) + "," + s[2] + "," + s[3] + "," + s[4]);
		Files.write(file, lines);
		return file;
	}

	@Test
	void equalsTheCommandLinesPotentialOnOneMovieAndOnAnArchive() throws IOException {
		final List<Object[]> one = spots("one", 1), two = spots("two", 2);
		final Path oneCsv = csv(dir.resolve("one.csv"), one, 0);
		final List<Object[]> both = new ArrayList<>(one);
		both.addAll(two);
		final List<Object[]> renumbered = new ArrayList<>(one);
		for (final Object[] s : two) // --start-frame applies to each movie: the command line's table leaves them out
			if ((long) s[1] >= 2) renumbered.add(new Object[] { s[0], (long) s[1] + 1000, s[2], s[3], s[4] });
		final Path bothCsv = csv(dir.resolve("both.csv"), renumbered, 0);
		final String[] options = { "--bin", "2", "--r-max", "30", "--start-frame", "2" };

		final SparkSession spark = SparkSession.builder().master("local[2]").appName("potential").getOrCreate();
		try {
			final StructType schema = DataTypes.createStructType(List.of(DataTypes.createStructField("MOVIE",
				DataTypes.StringType, false), DataTypes.createStructField("FRAME", DataTypes.LongType, false), DataTypes
					.createStructField("POSITION_X", DataTypes.DoubleType, false), DataTypes.createStructField("POSITION_Y",
						DataTypes.DoubleType, false), DataTypes.createStructField("FLAG_MERGED", DataTypes.LongType, false)));
			for (final Object[] run : new Object[][] { { oneCsv, one }, { bothCsv, both } }) {
				final Path cliCsv = dir.resolve("cli-" + run[0].toString().hashCode() + ".csv");
				final List<String> args = new ArrayList<>(List.of("potential", run[0].toString(), "--csv", cliCsv
					.toString()));
				args.addAll(List.of(options));
				final Object[] c = SparkTestMovies.cli(args.toArray(String[]::new));
				assertEquals(0, c[0], (String) c[2]);
				@SuppressWarnings("unchecked")
				final List<Row> rows = ((List<Object[]>) run[1]).stream().map(RowFactory::create).toList();
				final Dataset<Row> table = spark.createDataFrame(rows, schema).repartition(3);
				final Path sparkCsv = dir.resolve("spark.csv");
				PotentialCsv.write(sparkCsv, SparkPotential.potential(table, new SpotSet.Selection(2, true), 2, 30, null));
				assertArrayEquals(Files.readAllBytes(cliCsv), Files.readAllBytes(sparkCsv), run[0].toString());
			}
		}
		finally {
			spark.stop();
		}
	}
}
