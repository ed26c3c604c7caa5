package io.github.contacttracker.command;

import java.awt.GraphicsEnvironment;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.function.BooleanSupplier;

import org.scijava.ItemIO;
import org.scijava.app.StatusService;
import org.scijava.command.Command;
import org.scijava.command.ContextCommand;
import org.scijava.log.LogService;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;
import org.scijava.widget.FileWidget;

import ij.IJ;
import ij.ImagePlus;
import ij.Prefs;
import ij.io.FileInfo;
import ij.measure.ResultsTable;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.FrameResult;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.StackTracker;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.ImagePlusFrames;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.io.TrackMateXmlWriter;
import io.github.contacttracker.trackmate.DetectorSettings;
import net.imglib2.RandomAccessibleInterval;

/**
 * <i>Plugins &gt; Tracking &gt; Contact Tracker</i>: localizes the particles of every frame of the image with the
 * close-contact radial-symmetry method; shows the spots as a results table and as ROIs on the image.
 * <p>
 * The {@code @Parameter} field names are the keys of an ImageJ macro call, e.g.
 * {@code run("Contact Tracker", "threshold=110 r_out=55 min_area=20");}. Invalid values (an RGB image, Z and T
 * both above 1, {@code r_out <= 0}, an unknown method, ...) cancel the command with a one-line reason
 * ({@link #getCancelReason()}), which is also logged as an error. It is a plain {@link ContextCommand}, so
 * {@code commandService.run(ContactTrackerCommand.class, true, ...)} returns its module and outputs.
 * <p>
 * Outputs {@code spots} (and {@code pairs} when {@code pair_cutoff > 0}) are ImageJ results tables, returned to
 * scripts also when they are not shown. The command shows them itself ({@code table=true}, not headless), so
 * {@link ShownOutputs} keeps SciJava from displaying them a second time.
 */
@Plugin(type = Command.class, menuPath = "Plugins>Tracking>Contact Tracker", headless = true,
	label = "Contact Tracker", description = "Sub-pixel centres of colloidal particles close to contact " +
		"(Yucel & Okumusoglu 2017)")
public class ContactTrackerCommand extends ContextCommand {

	@Parameter
	private LogService log;

	@Parameter(required = false)
	private StatusService status;

	@Parameter(label = "Image", persist = false)
	private ImagePlus imp;

	@Parameter(label = "Threshold (grey level)", persist = false,
		description = "Pixels at or above it form the active areas, one per particle; above the brightest point " +
			"between two particles at contact (see Contact Tracker Profile)")
	private double threshold = DetectorSettings.DEFAULT_THRESHOLD;

	@Parameter(label = "r_out (px)", persist = false, min = "0", stepSize = "0.5",
		description = "Radius of a particle's effective disc: where its image has returned to background, plus 2 px")
	private double r_out = DetectorSettings.DEFAULT_R_OUT;

	@Parameter(label = "Min area (px)", persist = false, min = "1",
		description = "Smaller active areas are noise and dropped")
	private int min_area = TrackerParameters.DEFAULT_MIN_AREA;

	@Parameter(label = "Min second area (px)", persist = false, min = "3",
		description = "Below this many pixels outside the neighbours' discs a spot keeps its first-pass centre " +
			"(flagged)")
	private int min_second_area = TrackerParameters.DEFAULT_MIN_SECOND_AREA;

	@Parameter(label = "Connectivity", persist = false, choices = { "8", "4" },
		description = "Pixel neighbourhood of the active areas")
	private String connectivity = "8";

	@Parameter(label = "Method", persist = false,
		description = "How centres are computed, e.g. paper (the paper's two passes) or first (one pass, biased " +
			"near contact); the README lists every method, and an unknown name is refused with the valid ones")
	private String method = Method.DEFAULT.key();

	@Parameter(label = "Channel", persist = false, min = "1",
		description = "The channel to track (1-based); single-channel images have only channel 1")
	private int channel = 1;

	@Parameter(label = "Pair cutoff (calibrated units, 0 = none)", persist = false, min = "0",
		description = "List the distances of spot pairs of the same frame closer than this in a second table")
	private double pair_cutoff = 0;

	@Parameter(label = "Show overlay", persist = false)
	private boolean overlay = true;

	@Parameter(label = "Show table", persist = false)
	private boolean table = true;

	@Parameter(label = "Save spots as CSV", persist = false, required = false, style = FileWidget.SAVE_STYLE,
		description = "Optional: the spots table as CSV, the same file the command line writes")
	private File csv;

	@Parameter(label = "Save TrackMate XML", persist = false, required = false, style = FileWidget.SAVE_STYLE,
		description = "Optional: a TrackMate file with the spots (File > Load a TrackMate file)")
	private File trackmate_xml;

	@Parameter(label = "Threads (0 = ImageJ's setting)", persist = false, min = "0",
		description = "Frames are localized in parallel on this many threads")
	private int threads = 0;

	@Parameter(label = "Spots", type = ItemIO.OUTPUT)
	private ResultsTable spots;

	@Parameter(label = "Pairs", type = ItemIO.OUTPUT, required = false)
	private ResultsTable pairs;

	@Override
	public void run() {
		IJ.resetEscape();
		try {
			analyse();
		}
		catch (final IllegalArgumentException | IOException e) {
			fail(e.getMessage());
		}
		catch (final CancellationException e) {
			final String m = e.getMessage();
			final String reason = m != null && m.startsWith("cancelled") ? m : "cancelled" + (m == null ? "" : " (" + m +
				")");
			log.warn("Contact Tracker: " + reason);
			stop(reason);
		}
	}

	/** @return the parameters as the core takes them, validated */
	private TrackerParameters parameters() {
		return new TrackerParameters(threshold, r_out, min_area, Connectivity.parse(connectivity), min_second_area,
			Method.parse(method));
	}

	private void analyse() throws IOException {
		final TrackerParameters params = parameters();
		if (pair_cutoff < 0 || !Double.isFinite(pair_cutoff))
			throw new IllegalArgumentException("pair_cutoff must be a distance >= 0 (0 = no pair table), not " +
				pair_cutoff);
		if (threads < 0) throw new IllegalArgumentException("threads must be >= 0 (0 = ImageJ's setting), not " +
			threads);
		final File csvFile = given(csv), xmlFile = given(trackmate_xml);
		checkFolder("csv", csvFile);
		checkFolder("trackmate_xml", xmlFile);
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, channel);
		final double[] range = frames.dataRange();
		if (params.threshold() < range[0] || params.threshold() > range[1])
			throw new IllegalArgumentException(String.format(Locale.ROOT,
				"threshold %s is outside the data range [%s, %s] of '%s'", fmt(params.threshold()), fmt(range[0]), fmt(
					range[1]), imp.getTitle()));

		final int count = frames.frameCount();
		final Thread caller = Thread.currentThread();
		final BooleanSupplier cancelled = () -> isCanceled() || caller.isInterrupted() || IJ.escapePressed();
		final StackTracker tracker = new StackTracker(params);
		progress(0, count);
		final List<FrameResult> results = track(tracker, frames, overlay, cancelled);
		final List<Localization> all = StackTracker.spots(results);

		final TitledResultsTable spotTable = SpotTables.spots(all, frames.calibration());
		final TitledResultsTable pairTable = pair_cutoff > 0 ? SpotTables.pairs(PairDistances.within(all, frames
			.calibration(), pair_cutoff)) : null;
		if (csvFile != null) SpotCsvWriter.write(csvFile.toPath(), all, frames.calibration());
		if (xmlFile != null) TrackMateXmlWriter.write(xmlFile.toPath(), all, frames.calibration(), source(
			imp, frames), params, frames.channel());
		if (overlay) SpotOverlay.show(imp, SpotOverlay.rois(results, params.rOut(), SpotOverlay.placer(imp)));

		// We show the tables ourselves (or not); ShownOutputs keeps SciJava from displaying them again.
		spots = spotTable;
		pairs = pairTable;
		if (table && !GraphicsEnvironment.isHeadless()) {
			spotTable.show();
			if (pairTable != null) pairTable.show();
		}
		int flagged = 0;
		for (final Localization s : all)
			if (s.isFlagged()) flagged++;
		final String summary = String.format(Locale.ROOT, "Contact Tracker: %d spots in %d frame%s of '%s', %d flagged",
			all.size(), count, count == 1 ? "" : "s", imp.getTitle(), flagged);
		log.info(summary);
		if (status != null) {
			status.showProgress(count, count);
			status.showStatus(summary);
		}
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private List<FrameResult> track(final StackTracker tracker, final ImagePlusFrames frames,
		final boolean keepRegions, final BooleanSupplier cancelled)
	{
		final List<RandomAccessibleInterval> list = (List) frames.frames();
		return StackTracker.withThreads(threads > 0 ? threads : Prefs.getThreads(), () -> tracker.track(list
			.size(), t -> list.get(t), keepRegions, this::progress, cancelled));
	}

	private void progress(final int done, final int count) {
		// methods that measure the profile pass over the stack several times: count is all passes' frames
		if (status != null) status.showStatus(done, count, "Contact Tracker: " + (100 * done / Math.max(1, count)) +
			"%");
	}

	/** Cancels with a one-line reason, logged as an error (the Console in Fiji, stderr headless). */
	private void fail(final String reason) {
		log.error("Contact Tracker: " + reason);
		stop(reason);
	}

	private void stop(final String reason) {
		if (status != null) status.clearStatus();
		cancel(reason);
	}

	/** @return the file, or null when none was given (an empty file field gives an empty path) */
	private static File given(final File file) {
		return file == null || file.getPath().isBlank() ? null : file;
	}

	private static void checkFolder(final String name, final File file) {
		if (file == null) return;
		final Path dir = file.toPath().toAbsolutePath().getParent();
		if (dir == null || !Files.isDirectory(dir))
			throw new IllegalArgumentException("cannot write " + name + " " + file + ": folder " + dir +
				" does not exist");
	}

	/** The image as TrackMate's XML names it: its file when it was opened from one. */
	private static ImageSource source(final ImagePlus imp, final ImagePlusFrames frames) {
		final FileInfo fi = imp.getOriginalFileInfo();
		if (fi != null && fi.fileName != null && !fi.fileName.isEmpty() && fi.directory != null && !fi.directory
			.isEmpty()) return ImageSource.of(Path.of(fi.directory, fi.fileName), frames.width(), frames.height(), frames
				.frameCount());
		return new ImageSource("", "", frames.width(), frames.height(), 1, frames.frameCount());
	}

	private static String fmt(final double v) {
		return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
	}
}
