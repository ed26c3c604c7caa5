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
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;
import java.util.stream.Collectors;

import org.apache.spark.HashPartitioner;
import org.apache.spark.SparkConf;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.JavaPairRDD;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SaveMode;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructField;
import org.apache.spark.sql.types.StructType;
import org.apache.spark.storage.StorageLevel;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import scala.Tuple2;

/**
 * {@code contact-tracker-spark MOVIE... --out-dir DIR [--master URL] [track options]}: the command line's
 * {@code track --out-dir} as an Apache Spark job, for archives of movies that outgrow one machine. Each movie's CSV
 * (and TrackMate XML) is byte for byte the command line's.
 * <ol>
 * <li>Stage 1, a task per movie: the movie opened by offset through Hadoop, the settings not given measured on
 * frame 1 ({@link MeasuredSettings}, as {@code track} does), the threshold checked, and for the profile methods the
 * profile measured on the command line's sample frames ({@link StackTracker#profileStage}); the plans are
 * broadcast.</li>
 * <li>Stage 2, a task per chunk of {@code --chunk} frames of a movie: the frames tracked with the movie's profile
 * ({@link StackTracker#trackWith}), one core per task.</li>
 * <li>Stage 3, a task per movie: the chunks in frame order, written by {@link TrackingPipeline#finish} all or none,
 * so a task that fails and is retried leaves neither a partial nor a doubled file.</li>
 * <li>Every spot, with a {@code MOVIE} column, as one Parquet table partitioned by movie.</li>
 * </ol>
 * A movie that cannot be read or tracked is named in a one-line error, the others are still done, and the exit
 * status is 2.
 */
public final class SparkTrack {

	private SparkTrack() {}

	/** The exit status when a movie or an option is bad (as the command line's). */
	public static final int EXIT_BAD_INPUT = 2;

	/**
	 * A Spark setting for tests: a comma-separated list of stages ({@code track}, {@code write}) whose first task
	 * fails on its first attempt, to show that the retry gives the same files.
	 */
	static final String FAIL_FIRST_ATTEMPT = "spark.contacttracker.test.failFirstAttempt";

	/**
	 * Runs the job and exits with its status; {@code potential TABLE ...} first runs the pair potential of a spots
	 * table instead ({@link SparkPotential}).
	 */
	public static void main(final String[] args) {
		if (args.length > 0 && args[0].equals("potential")) System.exit(SparkPotential.run(Arrays.copyOfRange(args, 1,
			args.length), System.out, System.err));
		System.exit(run(args, System.out, System.err));
	}

	/**
	 * @return 0 when every movie was written, 2 when an option or a movie was bad
	 */
	public static int run(final String[] args, final PrintStream out, final PrintStream err) {
		final SparkOptions o;
		try {
			o = SparkOptions.parse(args);
		}
		catch (final InvalidInputException e) {
			err.println("contact-tracker-spark: error: " + e.getMessage());
			return EXIT_BAD_INPUT;
		}
		if (o.help) {
			out.print(SparkOptions.usage());
			return 0;
		}
		final Path outDir = Path.of(o.outDir).toAbsolutePath();
		// the folders made here are removed again, while empty, by a run that wrote nothing
		try {
			return io.github.contacttracker.io.OutputFolder.removedIfRefused(outDir, () -> prepareAndTrack(o, outDir, out,
				err));
		}
		catch (final java.io.IOException e) { // (prepareAndTrack throws none)
			throw new java.io.UncheckedIOException(e);
		}
	}

	/** {@link #run} once the options are read: the output folder made, the movies tracked. */
	private static int prepareAndTrack(final SparkOptions o, final Path outDir, final PrintStream out,
		final PrintStream err)
	{
		try {
			io.github.contacttracker.io.OutputFolder.prepare(outDir);
		}
		catch (final InvalidInputException e) {
			err.println("contact-tracker-spark: error: " + e.getMessage());
			return EXIT_BAD_INPUT;
		}
		final Map<String, String> nameOf = new HashMap<>();
		for (final String movie : o.movies) {
			final String other = nameOf.put(name(movie), movie);
			if (other != null) {
				err.println("contact-tracker-spark: error: " + other + " and " + movie + " would both be written to " +
					outDir.resolve(name(movie) + ".csv") + ": rename one, or run them with different --out-dir");
				return EXIT_BAD_INPUT;
			}
		}
		final SparkConf conf = new SparkConf().setAppName("contact-tracker");
		if (o.master != null) conf.setMaster(o.master);
		else if (!conf.contains("spark.master")) conf.setMaster("local[*]"); // embedded, without spark-submit
		o.conf.forEach(conf::set);
		final SparkSession spark;
		try {
			spark = SparkSession.builder().config(conf).getOrCreate();
		}
		catch (final Exception e) { // Scala's SparkException, undeclared: a master URL or a --conf Spark cannot use
			err.println("contact-tracker-spark: error: Spark cannot start with master " + conf.get("spark.master") +
				(o.conf.isEmpty() ? "" : " and --conf " + String.join(" ", o.conf.keySet())) + ": " + oneLine(e
					.getMessage()));
			return EXIT_BAD_INPUT;
		}
		try {
			spark.sparkContext().setLogLevel("WARN");
			return track(spark, o, outDir, out, err);
		}
		finally {
			spark.stop();
		}
	}

	/** @return a movie's name for its outputs: its file name without extension */
	static String name(final String movie) {
		final String path = movie.replaceAll("/+$", "");
		return Outputs.baseName(path.substring(path.lastIndexOf('/') + 1));
	}

	/** @return the movie's address for Hadoop: a URI as given, a plain path as an absolute {@code file:} URI */
	static String uri(final String movie) {
		return movie.matches("^[a-zA-Z][a-zA-Z0-9+.-]*:/.*") ? movie : Path.of(movie).toAbsolutePath().normalize().toUri()
			.toString();
	}

	private static int track(final SparkSession spark, final SparkOptions o, final Path outDir, final PrintStream out,
		final PrintStream err)
	{
		final JavaSparkContext sc = JavaSparkContext.fromSparkContext(spark.sparkContext());
		final String failFirst = sc.getConf().get(FAIL_FIRST_ATTEMPT, "");
		final Map<String, Object> given = MoviePlan.ship(o.settings());
		final boolean channelGiven = o.given(TrackingSettings.CHANNEL);
		// by name: a setting is not serializable, the tasks get the names
		final ArrayList<String> givenNames = new ArrayList<>();
		for (final Setting<?> s : o.given)
			givenNames.add(s.name());
		final long jobStart = System.currentTimeMillis();
		final List<Tuple2<Integer, String>> movies = new ArrayList<>();
		for (int m = 0; m < o.movies.size(); m++)
			movies.add(new Tuple2<>(m, o.movies.get(m)));

		// stage 1: a task per movie
		final List<MoviePlan> plans = new ArrayList<>(sc.parallelize(movies, movies.size()).map(m -> plan(m._1, m._2,
			given, givenNames, channelGiven)).collect());
		plans.sort((a, b) -> Integer.compare(a.index(), b.index()));
		final Broadcast<List<MoviePlan>> shared = sc.broadcast(plans);

		// stage 2: a task per chunk of frames
		final List<Tuple2<Integer, int[]>> chunks = new ArrayList<>();
		final List<Tuple2<Integer, List<FrameResult[]>>> none = new ArrayList<>();
		for (final MoviePlan p : plans) {
			if (p.error() != null) continue;
			final int[] todo = p.stage() == null ? range(p.frames()) : p.stage().others(p.frames());
			for (int from = 0; from < todo.length; from += o.chunk)
				chunks.add(new Tuple2<>(p.index(), Arrays.copyOfRange(todo, from, Math.min(todo.length, from + o.chunk))));
			none.add(new Tuple2<>(p.index(), null)); // every movie reaches stage 3, even one without chunks
		}
		final boolean failTrack = failFirst.contains("track"), failWrite = failFirst.contains("write");
		final JavaPairRDD<Integer, TrackedChunk> tracked = sc.parallelize(chunks, Math.max(1, chunks.size()))
			.mapToPair(c -> {
				if (failTrack && c._2[0] == firstChunkFrame(shared.value().get(c._1))) failOnFirstAttempt("track");
				return new Tuple2<>(c._1, trackChunk(shared.value().get(c._1), c._2));
			});
		final JavaPairRDD<Integer, TrackedChunk> everyMovie = tracked.union(sc.parallelize(movies, 1).filter(m -> plans
			.get(m._1).error() == null).mapToPair(m -> new Tuple2<>(m._1, TrackedChunk.NONE)));

		// stage 3: a task per movie writes its files, all or none
		final String dir = outDir.toString();
		final boolean xml = o.trackMateXml;
		final JavaRDD<MovieOutcome> outcomes = everyMovie.groupByKey(new HashPartitioner(Math.max(1, movies.size())))
			.map(g -> {
				final MovieOutcome written = write(shared.value().get(g._1), g._2, dir, xml, jobStart);
				// after the files are written: the retry writes them again, and must leave them as they were
				if (failWrite && g._1 == firstGood(shared.value())) failOnFirstAttempt("write");
				return written;
			}).persist(StorageLevel.MEMORY_AND_DISK());
		final List<MovieOutcome> done = new ArrayList<>(outcomes.map(MovieOutcome::withoutSpots).collect());
		done.sort((a, b) -> Integer.compare(a.index(), b.index()));

		// the table of all spots, partitioned by movie
		final String parquet = o.parquet != null ? o.parquet : outDir.resolve("spots.parquet").toUri().toString();
		if (done.stream().anyMatch(m -> m.error() == null)) spark.createDataFrame(outcomes.flatMap(m -> rows(m).iterator()), schema()).write().mode(
			SaveMode.Overwrite).partitionBy("MOVIE").parquet(parquet);
		outcomes.unpersist();

		final Map<Integer, MovieOutcome> outcomeOf = new HashMap<>();
		done.forEach(m -> outcomeOf.put(m.index(), m));
		int failed = 0;
		for (final MoviePlan p : plans) {
			final String error = p.error() != null ? p.error() : outcomeOf.get(p.index()).error();
			if (error != null) {
				err.println("contact-tracker-spark: error: " + p.movie() + ": " + error);
				failed++;
				continue;
			}
			if (!p.notice().isEmpty()) err.println(p.notice());
		}
		for (final MovieOutcome m : done)
			if (m.error() == null) out.println(m.summary());
		if (failed == 0) return 0;
		err.println("contact-tracker-spark: " + failed + " of " + plans.size() + " movies failed (see above); the " +
			"others were written");
		return EXIT_BAD_INPUT;
	}

	/**
	 * The frames of a chunk, tracked, or why they could not be (a NaN pixel: one line, naming the frame); {@link #NONE}
	 * stands for a movie's place in stage 3.
	 */
	record TrackedChunk(int[] frames, List<FrameResult> results, String error) implements java.io.Serializable {
		static final TrackedChunk NONE = new TrackedChunk(new int[0], List.of(), null);
	}

	/**
	 * What stage 3 wrote of a movie.
	 *
	 * @param summary the command line's summary line
	 * @param spots the spots written (empty once collected to the driver)
	 */
	record MovieOutcome(int index, String name, String summary, List<Localization> spots,
		io.github.contacttracker.io.Calibration calibration, String error) implements java.io.Serializable
	{
		MovieOutcome withoutSpots() {
			return new MovieOutcome(index, name, summary, List.of(), calibration, error);
		}
	}

	/** Stage 1 of one movie (on an executor): open, measure, check, profile; a bad movie gives a failed plan. */
	private static MoviePlan plan(final int index, final String movie, final Map<String, Object> given,
		final List<String> givenNames, final boolean channelGiven)
	{
		final String uri = uri(movie);
		try {
			final SettingValues settings = new MoviePlan(index, movie, uri, given, channelGiven, "", 0, 0, 0, null, null,
				null).values();
			final Movies.Open open = Movies.open(uri, movie, channelGiven ? settings.channel() : 0);
			final ImagePlusFrames frames = open.frames();
			final String path = movie.replaceAll("/+$", "");
			final MeasuredSettings.Result measured = MeasuredSettings.of(path.substring(path.lastIndexOf('/') + 1),
				frames::frame, frames.frameCount(), !open.floats(), settings, givenNames.stream().map(
					TrackingSettings::named).collect(Collectors.toSet()), FrontEnd.COMMAND_LINE);
			final TrackingPipeline pipeline = new TrackingPipeline(measured.settings());
			final FrameSource source = pipeline.frames(FrameSource.of(frames, movie));
			pipeline.checkThreshold(source);
			final StackTracker.ProfileStage stage = StackTracker.withThreads(1, () -> new StackTracker(measured.settings()
				.parameters()).profileStage(frames.frameCount(), frameFunction(source), () -> false));
			final String notice = (frames.colourChoice().isEmpty() ? "" : "contact-tracker: " + frames.colourChoice() +
				(measured.notice().isEmpty() ? "" : "\n")) + measured.notice();
			return new MoviePlan(index, movie, uri, MoviePlan.ship(measured.settings()), channelGiven, notice,
				frames.frameCount(), frames.width(), frames.height(), frames.calibration(), stage, null);
		}
		catch (final InvalidInputException | IOException | UncheckedIOException e) {
			return MoviePlan.failed(index, movie, uri, oneLine(e.getMessage()));
		}
	}

	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static IntFunction frameFunction(final FrameSource frames) {
		return (IntFunction) frames::frame; // raw: the pixel type varies by movie
	}

	/** Stage 2 of one chunk (on an executor), one thread: the executor's cores are Spark's tasks. */
	@SuppressWarnings("unchecked")
	private static TrackedChunk trackChunk(final MoviePlan plan, final int[] chunk) {
		try {
			final FrameSource frames = new TrackingPipeline(plan.values()).frames(FrameSource.of(Movies.open(plan.uri(), plan
				.movie(), plan.channel()).frames(), plan.movie()));
			final List<FrameResult> results = StackTracker.withThreads(1, () -> new StackTracker(plan.values()
				.parameters()).trackWith(plan.stage(), chunk, frameFunction(frames), () -> false));
			return new TrackedChunk(chunk, results, null);
		}
		catch (final InvalidInputException | IOException | UncheckedIOException e) {
			// the movie's fault, not the task's: retrying cannot help, and the other movies must still be done
			return new TrackedChunk(chunk, List.of(), oneLine(e.getMessage()));
		}
	}

	/** Stage 3 of one movie (on an executor): its frames in order, its files written all or none. */
	private static MovieOutcome write(final MoviePlan plan, final Iterable<TrackedChunk> chunks, final String dir,
		final boolean xml, final long jobStartMillis) throws IOException
	{
		// the summary's time is the job's so far (wall clock: the driver's nanoTime means nothing here)
		final long start = System.nanoTime() - (System.currentTimeMillis() - jobStartMillis) * 1_000_000L;
		TrackedChunk failed = null; // the first in frame order, as the command line reports the first bad frame
		for (final TrackedChunk c : chunks)
			if (c.error() != null && (failed == null || c.frames()[0] < failed.frames()[0])) failed = c;
		if (failed != null) return new MovieOutcome(plan.index(), name(plan.movie()), null, List.of(), plan
			.calibration(), failed.error());
		final FrameResult[] byFrame = new FrameResult[plan.frames()];
		if (plan.stage() != null) {
			final int[] sample = plan.stage().sample();
			for (int i = 0; i < sample.length; i++)
				byFrame[sample[i]] = plan.stage().sampleResult(i);
		}
		for (final TrackedChunk c : chunks)
			for (int i = 0; i < c.frames().length; i++)
				byFrame[c.frames()[i]] = c.results().get(i);
		for (int t = 0; t < byFrame.length; t++)
			if (byFrame[t] == null) throw new IllegalStateException("frame " + (t + 1) + " of " + plan.movie() +
				" was not tracked");
		final String name = name(plan.movie());
		final Path folder = Path.of(dir);
		final Outputs outputs = new Outputs(folder.resolve(name + ".csv"), xml ? folder.resolve(name + ".xml") : null,
			xml ? imageSource(plan) : null);
		final TrackingPipeline pipeline = new TrackingPipeline(plan.values());
		// the first frame read once more, for the blobs of the other contrast (as the command line counts them)
		final FrameSource first = pipeline.frames(FrameSource.of(Movies.open(plan.uri(), plan.movie(), plan.channel())
			.frames(), plan.movie()));
		final TrackingResult r = pipeline.finish(Arrays.asList(byFrame), plan.calibration(), outputs, start, pipeline
			.otherContrast(first, byFrame[0]));
		final String fileName = plan.uri().substring(plan.uri().lastIndexOf('/') + 1);
		return new MovieOutcome(plan.index(), name, plan.movie() + ": " + r.summary(fileName), r.spots(), plan
			.calibration(), null);
	}

	/** @return the image TrackMate's XML names: a local movie as the command line names it, else its URI */
	private static ImageSource imageSource(final MoviePlan plan) {
		if (plan.uri().startsWith("file:")) return ImageSource.of(Path.of(java.net.URI.create(plan.uri())), plan.width(),
			plan.height(), plan.frames());
		final int slash = plan.uri().lastIndexOf('/');
		return new ImageSource(plan.uri().substring(slash + 1), plan.uri().substring(0, slash), plan.width(), plan
			.height(), 1, plan.frames());
	}

	/** @return the table's columns: MOVIE, then every column of the CSV (integers as long) */
	static StructType schema() {
		final List<StructField> fields = new ArrayList<>();
		fields.add(DataTypes.createStructField("MOVIE", DataTypes.StringType, false));
		for (final SpotColumn c : SpotColumn.values())
			fields.add(DataTypes.createStructField(c.key(), c.isInteger() ? DataTypes.LongType : DataTypes.DoubleType,
				true));
		return DataTypes.createStructType(fields);
	}

	private static List<Row> rows(final MovieOutcome m) {
		final SpotColumn[] cols = SpotColumn.values();
		final List<Row> rows = new ArrayList<>(m.spots().size());
		for (int id = 0; id < m.spots().size(); id++) {
			final Object[] v = new Object[cols.length + 1];
			v[0] = m.name();
			for (int c = 0; c < cols.length; c++) {
				final double x = cols[c].value(m.spots().get(id), id, m.calibration());
				v[c + 1] = cols[c].isInteger() ? (Object) (long) x : (Object) x;
			}
			rows.add(RowFactory.create(v));
		}
		return rows;
	}

	private static int firstChunkFrame(final MoviePlan plan) {
		return plan.stage() == null ? 0 : plan.stage().others(plan.frames())[0];
	}

	private static int firstGood(final List<MoviePlan> plans) {
		for (final MoviePlan p : plans)
			if (p.error() == null) return p.index();
		return -1;
	}

	/** The test hook: the task's first attempt fails (after its work, before handing it on). */
	private static void failOnFirstAttempt(final String stage) {
		final TaskContext task = TaskContext.get();
		if (task != null && task.attemptNumber() == 0) throw new IllegalStateException("injected failure of the first " +
			"attempt of a " + stage + " task (" + FAIL_FIRST_ATTEMPT + ")");
	}

	private static int[] range(final int n) {
		final int[] r = new int[n];
		for (int i = 0; i < n; i++)
			r[i] = i;
		return r;
	}

	static String oneLine(final String message) {
		return message == null ? "(no message)" : message.replace('\n', ' ').replace('\r', ' ').strip();
	}
}
