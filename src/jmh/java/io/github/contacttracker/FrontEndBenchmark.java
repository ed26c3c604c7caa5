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
package io.github.contacttracker;

import java.io.File;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.scijava.Context;
import org.scijava.command.CommandModule;
import org.scijava.command.CommandService;

import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import ij.IJ;
import ij.ImagePlus;
import ij.ImageStack;
import io.github.contacttracker.cli.ContactTrackerCli;
import io.github.contacttracker.command.ContactTrackerCommand;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.settings.SettingsOf;
import io.github.contacttracker.trackmate.ContactTrackerDetectorFactory;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.FinalInterval;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.type.numeric.real.FloatType;

/**
 * One whole movie through each front end, with the same values: the command line ({@code track}, in process), the
 * Fiji command (headless, through SciJava's command service, as a macro runs it), the TrackMate detector (its
 * factory's detector over the whole movie, as TrackMate's global detection calls it) and, for reference, the core
 * ({@code StackTracker}) alone. Every front end should cost what the core costs: this measures what each adds
 * (reading, converting, tables, overlays). The movie is given, as a grey 8-bit or RGB file ImageJ opens (an RGB
 * movie is made 8-bit grey first, as a user does for TrackMate):
 *
 * <pre>
 * scripts/jmh-bench FrontEndBenchmark -p movie=/path/to/1.avi -p values=186,43,34.06
 * </pre>
 *
 * {@code values} are the threshold, r_out and diameter every front end is given (none measured: the helper's cost
 * is the same for all and is not what this compares).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2)
@Measurement(iterations = 5)
@Fork(1)
public class FrontEndBenchmark {

	@Param({ "" })
	public String movie;

	@Param({ "186,43,34.06" })
	public String values;

	@Param({ "core", "cli", "command", "trackmate" })
	public String frontEnd;

	@Param({ "2" })
	public int threads;

	private ImagePlus grey;
	private Path tif, csv;
	private double threshold, rOut, diameter;
	private Context context;
	private ImgPlus<FloatType> img;
	private final PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
	/** what the latest run found (spots, or the CSV's bytes), said at the end: each front end's own check */
	private long found;

	@Setup(Level.Trial)
	public void setUp() throws Exception {
		if (movie.isEmpty()) throw new IllegalArgumentException("give the movie: -p movie=PATH");
		final String[] v = values.split(",");
		threshold = Double.parseDouble(v[0]);
		rOut = Double.parseDouble(v[1]);
		diameter = Double.parseDouble(v[2]);
		final ImagePlus opened = IJ.openImage(movie);
		if (opened == null) throw new IllegalArgumentException("ImageJ cannot open " + movie);
		grey = eightBitGrey(opened);
		final Path dir = Files.createTempDirectory("front-ends");
		tif = dir.resolve("movie.tif");
		csv = dir.resolve("spots.csv");
		IJ.saveAsTiff(grey, tif.toString());
		if (frontEnd.equals("command")) context = new Context();
		if (frontEnd.equals("trackmate")) img = floats(grey);
	}

	@TearDown(Level.Trial)
	public void tearDown() throws Exception {
		System.err.println(frontEnd + " found " + found + (frontEnd.equals("cli") || frontEnd.equals("command")
			? " bytes of CSV" : " spots"));
		if (context != null) context.dispose();
		Files.deleteIfExists(csv);
		Files.deleteIfExists(csv.resolveSibling("spots.settings.txt"));
		Files.deleteIfExists(tif);
		Files.deleteIfExists(tif.getParent());
	}

	/** @return the number of spots found, so that nothing is optimised away */
	@Benchmark
	public long track() throws Exception {
		switch (frontEnd) {
			case "core":
				return found = core();
			case "cli":
				return found = cli();
			case "command":
				return found = command();
			case "trackmate":
				return found = trackMate();
			default:
				throw new IllegalArgumentException("front end one of core, cli, command, trackmate, not " + frontEnd);
		}
	}

	private long core() {
		@SuppressWarnings({ "rawtypes", "unchecked" })
		final java.util.List frames = io.github.contacttracker.ij.ImagePlusFrames.of(grey, 1).frames();
		@SuppressWarnings("unchecked")
		final java.util.List<io.github.contacttracker.core.track.FrameResult> results = io.github.contacttracker.core.track.StackTracker
			.withThreads(threads, () -> new io.github.contacttracker.core.track.StackTracker(parameters()).track(frames,
				false));
		long n = 0;
		for (final io.github.contacttracker.core.track.FrameResult r : results)
			n += r.spots().size();
		return n;
	}

	private long cli() throws Exception {
		final int code = ContactTrackerCli.run(new String[] { "track", tif.toString(), "--threshold", "" + threshold,
			"--r-out", "" + rOut, "--diameter", "" + diameter, "--threads", "" + threads, "--csv", csv.toString(),
			"--no-progress" }, quiet, quiet);
		if (code != 0) throw new IllegalStateException("track ended with " + code);
		return Files.size(csv);
	}

	private long command() throws Exception {
		final CommandModule m = context.service(CommandService.class).run(ContactTrackerCommand.class, true, "imp",
			grey, "threshold", threshold, "r_out", rOut, "diameter", diameter, "threads", threads, "overlay", false,
			"table", false, "csv", csv.toFile()).get();
		if (m.isCanceled()) throw new IllegalStateException("the command was cancelled: " + m.getCancelReason());
		return Files.size(csv);
	}

	private long trackMate() {
		final ContactTrackerDetectorFactory<FloatType> factory = new ContactTrackerDetectorFactory<>();
		final Map<String, Object> settings = new java.util.HashMap<>(SettingsOf.map(parameters(), 1));
		final String error = factory.checkSettings(settings);
		if (error != null) throw new IllegalStateException(error);
		final SpotGlobalDetector<FloatType> detector = factory.getDetector(img, settings, new FinalInterval(new long[] {
			0, 0, 0 }, new long[] { img.max(0), img.max(1), img.max(2) }));
		((net.imglib2.algorithm.MultiThreaded) detector).setNumThreads(threads);
		if (!(detector.checkInput() && detector.process())) throw new IllegalStateException(detector.getErrorMessage());
		return detector.getResult().getNSpots(false);
	}

	private TrackerParameters parameters() {
		return TrackerParameters.of(threshold, rOut).withDiameter(diameter);
	}

	/** @return the movie as 8-bit grey (an RGB movie as ImageJ's Image > Type > 8-bit makes it) */
	private static ImagePlus eightBitGrey(final ImagePlus imp) {
		if (imp.getBitDepth() == 8) return imp;
		final ImagePlus copy = imp.duplicate();
		new ij.process.StackConverter(copy).convertToGray8();
		return copy;
	}

	/** @return the movie as TrackMate hands it to a detector: float pixels, axes X, Y, T */
	private static ImgPlus<FloatType> floats(final ImagePlus imp) {
		final int w = imp.getWidth(), h = imp.getHeight(), n = imp.getStackSize();
		final ArrayImg<FloatType, FloatArray> img = ArrayImgs.floats(w, h, n);
		final float[] data = img.update(null).getCurrentStorageArray();
		final ImageStack stack = imp.getStack();
		for (int t = 0; t < n; t++) {
			final byte[] plane = (byte[]) stack.getPixels(t + 1);
			for (int i = 0; i < plane.length; i++)
				data[t * w * h + i] = plane[i] & 0xff;
		}
		return new ImgPlus<>(img, "movie", new AxisType[] { Axes.X, Axes.Y, Axes.TIME }, new double[] { 1, 1, 1 });
	}
}
