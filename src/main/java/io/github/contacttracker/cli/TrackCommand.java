package io.github.contacttracker.cli;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import ij.ImagePlus;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.FrameResult;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.StackTracker;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImagePlusFrames;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.io.TrackMateXmlWriter;

/** {@code track INPUT.tif --threshold T --r-out R ...}: localizes every frame of a TIFF stack. */
final class TrackCommand {

	private static final Set<String> OPTIONS = Set.of("threshold", "r-out", "min-area", "min-second-area",
		"connectivity", "method", "channel", "threads", "csv", "trackmate-xml");

	private final PrintStream out;
	private final PrintStream err;

	TrackCommand(final PrintStream out, final PrintStream err) {
		this.out = out;
		this.err = err;
	}

	int run(final String[] args) throws IOException {
		final Options o = new Options(args, OPTIONS);
		if (o.positional().size() != 1)
			throw new IllegalArgumentException("track needs exactly one input file, got " + o.positional().size());
		final Path input = Path.of(o.positional().get(0));
		final TrackerParameters params = parameters(o);
		final Path csv = o.outputPath("csv"), xml = o.outputPath("trackmate-xml");
		final int threads = o.integer("threads", 0);

		final long start = System.nanoTime();
		final ImagePlus imp = ImageFiles.open(input);
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, o.integer("channel", 0));
		final double[] range = frames.dataRange();
		if (params.threshold() < range[0] || params.threshold() > range[1])
			throw new IllegalArgumentException(String.format(Locale.ROOT,
				"threshold %s is outside the data range [%s, %s] of %s", fmt(params.threshold()), fmt(range[0]),
				fmt(range[1]), input));
		final List<FrameResult> results = track(frames, params, threads);
		final List<Localization> spots = StackTracker.spots(results);
		final double seconds = (System.nanoTime() - start) * 1e-9;

		if (xml != null) TrackMateXmlWriter.write(xml, spots, frames.calibration(), ImageSource.of(input, frames
			.width(), frames.height(), frames.frameCount()), params, frames.channel());
		if (csv != null) {
			try {
				SpotCsvWriter.write(csv, spots, frames.calibration());
			}
			catch (final IOException e) {
				if (xml != null) Files.deleteIfExists(xml); // both or neither
				throw e;
			}
		}
		else {
			final Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
			SpotCsvWriter.write(w, spots, frames.calibration());
			w.flush();
		}
		int flagged = 0, discarded = 0;
		for (final Localization s : spots)
			if (s.isFlagged()) flagged++;
		for (final FrameResult r : results)
			discarded += r.discarded();
		(csv != null ? out : err).printf(Locale.ROOT,
			"%s: %d frames, %d spots, %d flagged, %d components discarded, %.2f s (%.1f frames/s)%n", input,
			frames.frameCount(), spots.size(), flagged, discarded, seconds, frames.frameCount() / seconds);
		return 0;
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static List<FrameResult> track(final ImagePlusFrames frames, final TrackerParameters params,
		final int threads)
	{
		final List list = frames.frames();
		return StackTracker.withThreads(threads, () -> new StackTracker(params).track(list, false));
	}

	static TrackerParameters parameters(final Options o) {
		final TrackerParameters p = new TrackerParameters(o.number("threshold"), o.number("r-out"), o.integer(
			"min-area", TrackerParameters.DEFAULT_MIN_AREA), Connectivity.parse(o.string("connectivity", "8")), o
				.integer("min-second-area", TrackerParameters.DEFAULT_MIN_SECOND_AREA), Method.parse(o.string("method",
					Method.DEFAULT.key())));
		return p;
	}

	private static String fmt(final double v) {
		return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
	}
}
