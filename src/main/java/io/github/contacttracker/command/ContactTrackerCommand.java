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
package io.github.contacttracker.command;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.ij.ShownImage;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.InvalidSettingException;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;

import net.imglib2.Interval;
import org.scijava.ItemIO;
import org.scijava.ItemVisibility;
import org.scijava.app.StatusService;
import org.scijava.command.Command;
import org.scijava.command.Previewable;
import org.scijava.module.ModuleItem;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;
import org.scijava.widget.Button;
import org.scijava.widget.FileWidget;

import ij.IJ;
import ij.ImagePlus;
import ij.Prefs;
import ij.WindowManager;
import ij.gui.Overlay;
import ij.io.FileInfo;
import ij.measure.ResultsTable;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.ui.WindowsBeside;

/**
 * <i>Plugins &gt; Tracking &gt; Contact Tracker</i>: localizes the particles of every frame of the image with the
 * close-contact radial-symmetry method; shows the spots as a results table and as ROIs on the image. With an area
 * selection on the image, only the selection's bounding rectangle is tracked (as TrackMate detects within it), its
 * edges cutting particles as the frame's do; the spots keep the image's coordinates.
 * <p>
 * The {@code @Parameter} field names are the keys of an ImageJ macro call, e.g.
 * {@code run("Contact Tracker", "threshold=110 r_out=55 min_area=20");}. After a run, ImageJ's system Results
 * table holds the spots (or the pairs, or is left alone: {@code results}), which is what a macro reads. Invalid
 * values (an RGB image, Z and T both above 1, {@code r_out <= 0}, an unknown method, ...) cancel the command with
 * a one-line reason ({@link #getCancelReason()}), which is also logged as an error and stops a calling macro
 * ({@link MacroFailure}). It is a plain {@code ContextCommand} ({@link OwnCommand}), so
 * {@code commandService.run(ContactTrackerCommand.class, true, ...)} returns its module and outputs. It checks
 * its inputs itself, with no global preprocessor: each value as SciJava resolves it ({@code validater=}), and a
 * macro's values and left-out keys from its initializer on ({@link OwnInputs}). In Fiji's
 * dialog it previews the frame on display when its Preview box is ticked ({@link #preview()}), and its "Measure from the image" button fills in
 * {@code threshold}, {@code r_out} and {@code diameter} from the profile helper.
 * <p>
 * Outputs {@code spots} (and {@code pairs} when {@code pair_cutoff > 0}) are ImageJ results tables, returned to
 * scripts also when they are not shown. The command shows them itself ({@code table=true}, not headless), so
 * the command marks them resolved so that SciJava does not display them a second time.
 */
@Plugin(type = Command.class, menuPath = "Plugins>Tracking>Contact Tracker", headless = true,
	label = "Contact Tracker", description = "Sub-pixel centres of colloidal particles close to contact " +
		"(Yucel & Okumusoglu 2017)", initializer = "macroInputs")
public class ContactTrackerCommand extends OwnCommand implements Previewable {

	/** A new command (SciJava makes one per run). */
	public ContactTrackerCommand() {
		super(TITLE, "Finds the centres of particles, also where they touch, in every frame", DialogHelp.TRACKER_PAGE);
	}


	/** Values of {@code results}: what ImageJ's system Results table gets. */
	public static final String RESULTS_SPOTS = "spots", RESULTS_PAIRS = "pairs", RESULTS_NONE = "none";

	private static final String TITLE = "Contact Tracker";

	/** The names (macro keys) of the command's own checked inputs, which are not tracking settings. */
	static final String PAIR_CUTOFF = "pair_cutoff", THREADS = "threads", RESULTS = "results";

	/** The messages' first texts, replaced once the dialog is open. */
	static final String ORIGIN_UNKNOWN = "<html>Values: ...</html>", PREVIEW_OFF = "<html>Preview: off</html>";

	/** The dialog's format of lengths in pixels: to 0.01 px, as the helper suggests them (SciJava's "format:"). */
	static final String LENGTH_FORMAT = "format:0.0#";


	@Parameter(required = false)
	private StatusService status;

	@Parameter(label = "Image", persist = false)
	private ImagePlus imp;

	// Where the values below come from (ValuesOrigin), set when the dialog opens and as they change. A message: not
	// remembered, no macro key.
	@Parameter(visibility = ItemVisibility.MESSAGE, persist = false, required = false)
	private String origin = ORIGIN_UNKNOWN;

	// The tracking settings: names, help and defaults from the settings descriptor (TrackingSettings); a test pins
	// every one of these inputs to it.
	@Parameter(validater = "validateInputs", label = "Threshold (grey level)", description = DialogHelp.TIP + TrackingSettings.HELP_THRESHOLD)
	private double threshold = TrackingSettings.THRESHOLD.defaultValue();

	// format: the helper fills in 0.01 px (a diameter of 34.06 showed as 34.1: the dialog's format follows the
	// default's decimals)
	@Parameter(validater = "validateInputs", label = "r_out (px)", min = "" + TrackerParameters.R_OUT_ABOVE, stepSize = "0.5", style = LENGTH_FORMAT, description = DialogHelp.TIP + TrackingSettings.HELP_R_OUT)
	private double r_out = TrackingSettings.R_OUT.defaultValue();

	@Parameter(validater = "validateInputs", label = "Min area (px)", min = "" + TrackerParameters.MIN_AREA_AT_LEAST, description = DialogHelp.TIP + TrackingSettings.HELP_MIN_AREA)
	private int min_area = TrackingSettings.MIN_AREA.defaultValue();

	@Parameter(validater = "validateInputs", label = "Min second area (px)", min = "" + TrackerParameters.MIN_SECOND_AREA_AT_LEAST, description = DialogHelp.TIP + TrackingSettings.HELP_MIN_SECOND_AREA)
	private int min_second_area = TrackingSettings.MIN_SECOND_AREA.defaultValue();

	@Parameter(validater = "validateInputs", label = "Connectivity", choices = { "8", "4" }, description = DialogHelp.TIP + TrackingSettings.HELP_CONNECTIVITY)
	private String connectivity = String.valueOf(TrackingSettings.CONNECTIVITY.defaultValue());

	// a macro may still pass any text, which is refused with the valid ones when unknown
	@Parameter(validater = "validateInputs", label = "Method", choices = { "first", "paper", "iterative", "deblend", "fit" },
		description = DialogHelp.TIP + TrackingSettings.HELP_METHOD)
	private String method = TrackingSettings.METHOD.defaultValue();

	@Parameter(validater = "validateInputs", label = "Particle diameter (px, 0 = not given)", min = "" + TrackerParameters.DIAMETER_AT_LEAST, stepSize = "0.5",
		style = LENGTH_FORMAT,
		description = DialogHelp.TIP + TrackingSettings.HELP_DIAMETER)
	private double diameter = TrackingSettings.DIAMETER.defaultValue();

	@Parameter(validater = "validateInputs", label = "Kinds of particle (0 = automatic, 1 = all alike)", min = "" +
		TrackingSettings.KINDS_AT_LEAST,
		max = "" + TrackerParameters.KINDS_AT_MOST, description = DialogHelp.TIP + TrackingSettings.HELP_KINDS)
	private int kinds = TrackingSettings.KINDS.defaultValue();

	@Parameter(validater = "validateInputs", label = "Particles", choices = { "bright", TrackingSettings.DARK },
		description = DialogHelp.TIP + TrackingSettings.HELP_PARTICLES)
	private String particles = TrackingSettings.PARTICLES.defaultValue();

	@Parameter(validater = "validateInputs", label = "Detection", choices = { TrackingSettings.AUTO, TrackingSettings.BY_THRESHOLD,
		TrackingSettings.IMAGE },
		description = DialogHelp.TIP + TrackingSettings.HELP_DETECTION)
	private String detection = TrackingSettings.DETECTION.defaultValue();

	@Parameter(validater = "validateInputs", label = "Channel", min = "" + TrackingSettings.CHANNEL_AT_LEAST, description = DialogHelp.TIP + TrackingSettings.HELP_CHANNEL)
	private int channel = TrackingSettings.CHANNEL.defaultValue();

	// A button, not a setting: optional (a Button), never remembered, not recorded (it holds no value), and Fiji's
	// macro preprocessor resolves it: it is no macro option, and headless nobody presses it.
	@Parameter(label = "Measure from the image", callback = "measureFromImage", persist = false,
		description = DialogHelp.TIP + "Runs the profile helper on the frame on display (in the channel above) and fills in " +
			"threshold, r_out and the diameter; a diameter above 0 is kept and used (estimated instead if it does not fit " +
			"this image)")
	private Button measure;

	// Off by default, as in ImageJ's own dialogs: the dialog opens at once and nothing is tracked before the user
	// asks. Not remembered, so that a slow method chosen last time does not run when the dialog opens.
	@Parameter(label = "Preview (frame on display)", persist = false, required = false,
		description = DialogHelp.TIP + "Tracks the frame on display in the background and shows its spots while you edit; " +
			"typing is never held up, and a newer value replaces a preview still running")
	private boolean preview = false;

	// What the preview is doing, and its spot count: in the dialog, where the person looks (a message)
	@Parameter(visibility = ItemVisibility.MESSAGE, persist = false, required = false)
	private String preview_note = PREVIEW_OFF;

	@Parameter(validater = "validateInputs", label = "Pair cutoff (calibrated units, 0 = none)", min = "0",
		description = DialogHelp.TIP + "List the distances of spot pairs of the same frame closer than this in a second table")
	private double pair_cutoff = 0;

	@Parameter(label = "Show overlay", description = DialogHelp.TIP + "Marks each spot on the image: its final centre " +
		"as a cross, its first-pass centre as a dot, a circle of its radius coloured by its flags; the legend is drawn " +
		"on the image")
	private boolean overlay = true;

	@Parameter(label = "Show r_out circles and second areas",
		description = DialogHelp.TIP + "Diagnostics on the overlay: each spot's r_out disc around its first-pass centre and the " +
			"outline of its second active area (the pixels the final centre comes from)")
	private boolean r_out_circles = false;

	@Parameter(label = "Show table", description = DialogHelp.TIP + "Opens the spots table (one row per spot: FRAME, " +
		"SLICE, position, radius, errors, flags), beside the image; the Results table gets what 'Results table gets' says")
	private boolean table = true;

	@Parameter(validater = "validateInputs", label = "Results table gets", choices = { RESULTS_SPOTS, RESULTS_PAIRS, RESULTS_NONE },
		description = DialogHelp.TIP + "What goes into ImageJ's Results table, which macros read with nResults and getResult: the " +
			"spots, the pairs (with pair_cutoff > 0) or nothing (the Results table is left alone)")
	private String results = RESULTS_SPOTS;

	@Parameter(label = "Save spots as CSV", persist = false, required = false, style = FileWidget.SAVE_STYLE,
		description = DialogHelp.TIP + "Optional: the spots table as CSV, the same file the command line writes")
	private File csv;

	@Parameter(label = "Save TrackMate XML", persist = false, required = false, style = FileWidget.SAVE_STYLE,
		description = DialogHelp.TIP + "Optional: a TrackMate file with the spots (File > Load a TrackMate file)")
	private File trackmate_xml;

	@Parameter(validater = "validateInputs", label = "Threads (0 = ImageJ's setting)", min = "0",
		description = DialogHelp.TIP + "Frames are localized in parallel on this many threads")
	private int threads = 0;

	@Parameter(label = "Spots", type = ItemIO.OUTPUT)
	private ResultsTable spots;

	@Parameter(label = "Pairs", type = ItemIO.OUTPUT, required = false)
	private ResultsTable pairs;


	/** The image's overlay before the first preview, put back when the dialog is cancelled. */
	private Overlay beforePreview;
	private boolean previewShown;
	/** The latest preview asked for; an older one still computing is abandoned and never shown. */
	private final AtomicInteger previewGeneration = new AtomicInteger();
	/** One thread computes previews, off the dialog's event thread: typing is never held up. */
	private ExecutorService previewer;
	private Future<?> pendingPreview;

	/** The dialog goes beside the image, not over it: its preview and its Measure button work on the image. */
	@Override
	protected ImagePlus image() {
		return imp;
	}

	/** The dialog is open, its values loaded: it says where they come from. */
	@Override
	protected void dialogOpened() {
		showOrigin();
	}

	/** @return the values the helper fills in, on this image */
	private ValuesOrigin.Values helperValues() {
		return new ValuesOrigin.Values(imp == null ? "" : imp.getTitle(), threshold, r_out, diameter);
	}

	/** Says in the dialog where its values come from ({@link ValuesOrigin}). */
	private void showOrigin() {
		if (imp == null) return;
		note(true, ValuesOrigin.describe(helperValues(), new ValuesOrigin.Values(imp.getTitle(),
			TrackingSettings.THRESHOLD.defaultValue(), TrackingSettings.R_OUT.defaultValue(), TrackingSettings.DIAMETER
				.defaultValue())));
	}

	/**
	 * Sets one of the dialog's two message rows, in the field (what SciJava shows when it redraws the dialog) and
	 * in the open dialog at once.
	 *
	 * @param ofOrigin the values' origin row, else the preview's
	 */
	private synchronized void note(final boolean ofOrigin, final String text) {
		final String was = ofOrigin ? origin : preview_note;
		if (ofOrigin) origin = text;
		else preview_note = text;
		besideImage.relabel(was, text);
	}

	/** @return the preview row's text: HTML, escaped */
	private static String previewText(final String text) {
		return "<html>Preview: " + text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") + "</html>";
	}

	/** @return the dialog's message rows: the values' origin and the preview's state (for tests) */
	String[] notes() {
		return new String[] { origin, preview_note };
	}

	@Override
	public void run() {
		besideImage.disarm(); // in case there was no dialog (a macro, a script)
		IJ.resetEscape();
		stopPreviews();
		clearPreview(false); // a real run replaces the preview's ROIs (or leaves the image alone)
		try {
			if (own.problem() != null) throw new InvalidInputException(own.problem());
			analyse();
		}
		catch (final InvalidInputException | IOException e) {
			fail(e.getMessage());
		}
		catch (final OutOfMemoryError e) {
			// frames too large for the heap, or a virtual stack's reader that believed its file: a reason, no trace
			fail("out of memory (" + InvalidInputException.oneLine(e.getMessage()) + "): give Fiji more with Edit > " +
				"Options > Memory & Threads, or use fewer threads");
		}
		catch (final CancellationException e) {
			final String m = e.getMessage();
			final String reason = m != null && m.startsWith("cancelled") ? m : "cancelled" + (m == null ? "" : " (" + m +
				")");
			log.warn(TITLE + ": " + reason);
			stop(reason);
		}
		finally {
			own.finish();
		}
	}

	/** @return the tracking settings of this run, each read and checked by its descriptor ({@link TrackingSettings}) */
	private SettingValues settings() {
		SettingValues v = SettingValues.defaults();
		for (final Setting<?> s : TrackingSettings.ALL)
			v = v.withText(s, String.valueOf(input(s)));
		return v;
	}

	/** @return the parameters as the core takes them, validated */
	private TrackerParameters parameters() {
		return settings().parameters();
	}


	/**
	 * The validater of every checked input, called by SciJava as each is resolved (after the dialog, or as a macro
	 * or script gives it) and before the values are remembered: a refused value is noted for {@link #run()} to
	 * report, and the input is set back to its remembered value (else its default) before SciJava remembers the
	 * values, so that the next dialog does not open with it.
	 */
	private void validateInputs() {
		for (final Setting<?> s : TrackingSettings.ALL) {
			try {
				SettingValues.defaults().withText(s, String.valueOf(input(s)));
			}
			catch (final InvalidSettingException e) {
				own.refuse(e.key(), e.getMessage(), s.defaultValue());
			}
		}
		try {
			checkOwnInputs(false);
		}
		catch (final InvalidSettingException e) {
			own.refuse(e.key(), e.getMessage(), e.key().equals(RESULTS) ? RESULTS_SPOTS : 0);
		}
	}

	/**
	 * @return the value of the input of a tracking setting: the field named as the setting (its macro key), which
	 *         SciJava fills in ({@code CommandMatchesSettingsTest} pins one field to each setting)
	 */
	private Object input(final Setting<?> s) {
		try {
			return ContactTrackerCommand.class.getDeclaredField(s.name()).get(this);
		}
		catch (final ReflectiveOperationException e) {
			throw new IllegalStateException("no input for the setting " + s.name(), e);
		}
	}

	/**
	 * Checks what the core does not: the command's own inputs.
	 *
	 * @param together whether to check also how inputs go together (not only each one alone)
	 */
	private void checkOwnInputs(final boolean together) {
		if (pair_cutoff < 0 || !Double.isFinite(pair_cutoff))
			throw new InvalidSettingException(PAIR_CUTOFF, PAIR_CUTOFF + " must be a distance >= 0 (0 = no pair " +
				"table), not " + pair_cutoff);
		if (threads < 0) throw new InvalidSettingException(THREADS, THREADS + " must be >= 0 (0 = ImageJ's " +
			"setting), not " + threads);
		final String r = results == null ? "" : results.trim();
		if (!r.equals(RESULTS_SPOTS) && !r.equals(RESULTS_PAIRS) && !r.equals(RESULTS_NONE))
			throw new InvalidSettingException(RESULTS, RESULTS + " must be one of " + RESULTS_SPOTS + ", " +
				RESULTS_PAIRS + ", " + RESULTS_NONE + ", not '" + results + "'");
		if (together && r.equals(RESULTS_PAIRS) && pair_cutoff == 0)
			throw new InvalidSettingException(RESULTS, RESULTS + "=pairs needs " + PAIR_CUTOFF + " > 0 (the distance " +
				"up to which pairs are listed)");
	}

	private void analyse() throws IOException {
		checkOwnInputs(true);
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, channel);
		final String measured = measureWhatTheMacroLeftOut(frames);
		ValuesOrigin.run(helperValues());
		final SettingValues settings = settings();
		final TrackerParameters params = settings.parameters();
		final Interval region = ShownImage.selection(imp);
		final File csvFile = given(csv), xmlFile = given(trackmate_xml);
		final Outputs outputs = new Outputs(csvFile == null ? null : csvFile.toPath(), xmlFile == null ? null : xmlFile
			.toPath(), xmlFile == null ? null : source(imp, frames));

		final int count = frames.frameCount();
		final Thread caller = Thread.currentThread();
		final BooleanSupplier cancelled = () -> isCanceled() || caller.isInterrupted() || IJ.escapePressed();
		progress(0, count);
		// checks, tracking and both files, all or nothing; nothing is shown before everything is computed
		final TrackingResult result = new TrackingPipeline(settings, FrontEnd.FIJI).run(FrameSource.of(frames, imp
			.getTitle()).within(region), outputs, threads > 0 ? threads : Prefs.getThreads(), overlay, this::progress, cancelled);
		final List<FrameResult> found = result.frames();
		final List<Localization> all = result.spots();
		final TitledResultsTable spotTable = SpotTables.spots(all, frames.calibration(), imp.getTitle(),
			frames.width(), frames.height(), settings);
		final List<PairDistances.Pair> pairList = pair_cutoff > 0 ? PairDistances.within(all, frames.calibration(),
			pair_cutoff) : null;
		final TitledResultsTable pairTable = pairList == null ? null : SpotTables.pairs(pairList, imp.getTitle());
		if (overlay) SpotOverlay.show(imp, SpotOverlay.rois(found, params.exclusionRadius(), settings.diameter(),
			r_out_circles, SpotOverlay.placer(imp)));

		// We show the tables ourselves (or not); the run marks them resolved so that SciJava does not display them again.
		spots = spotTable;
		pairs = pairTable;
		final ResultsTable system = switch (results.trim()) {
			case RESULTS_SPOTS -> SpotTables.spotsToSystemTable(all, frames.calibration());
			case RESULTS_PAIRS -> SpotTables.pairsToSystemTable(pairList);
			default -> null;
		};
		if (table && !GraphicsEnvironment.isHeadless()) {
			// beside the image and the dialog, not over them
			spotTable.show();
			final java.awt.Window spotWindow = WindowManager.getWindow(spotTable.getTitle());
			WindowsBeside.move(spotWindow, imp);
			if (pairTable != null) {
				pairTable.show();
				WindowsBeside.move(WindowManager.getWindow(pairTable.getTitle()), imp, spotWindow);
			}
		}
		if (overlay && !GraphicsEnvironment.isHeadless()) OverlayLegend.show(imp, r_out_circles, table ? WindowManager
			.getWindow(spotTable.getTitle()) : null);
		if (table && !GraphicsEnvironment.isHeadless()) {
			// refresh an open Results window; none is opened, the named tables show the same
			if (system != null && WindowManager.getWindow("Results") != null) system.show("Results");
		}
		// short lines: ImageJ's Log window cuts long ones
		final List<String> lines = new java.util.ArrayList<>(result.summaryLines(imp.getTitle()));
		lines.set(0, TITLE + ": " + lines.get(0));
		if (region != null) lines.add(1, "  within the selection: " + ShownImage.describe(region));
		if (measured != null) lines.add(1, measured);
		final String unit = frames.calibration().unit();
		lines.add("  positions, RADIUS, SIGMA in " + (unit == null || unit.isEmpty() ? "pixels" : unit) + "; r_out " +
			"and areas in pixels");
		if (overlay) lines.addAll(SpotOverlay.legend(r_out_circles));
		final String summary = String.join("\n", lines);
		log.info(summary);
		// the Log window (standard output headless): where ImageJ users and batch macros see results
		WindowsBeside.log(summary, imp);
		if (status != null) {
			status.showProgress(count, count);
			status.showStatus(lines.get(0));
		}
		MacroFailure.succeeded();
	}

	/**
	 * A macro that gives no threshold or no r_out gets what it leaves out of them, the diameter and (for small
	 * particles) min_area measured on the first frame by the profile helper, as the command line's {@code track}
	 * does ({@link MeasuredSettings}): the fixed defaults fit no particular movie. What the macro gives wins. The
	 * inputs are set to the values used.
	 *
	 * @return the line saying what was measured, or null when nothing was (no macro, or every value given)
	 */
	private String measureWhatTheMacroLeftOut(final ImagePlusFrames frames) {
		final String options = own.macroOptions();
		if (options == null) return null;
		final Set<Setting<?>> given = new HashSet<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			if (ij.Macro.getValue(options, s.name(), null) != null) given.add(s);
		if (given.contains(TrackingSettings.THRESHOLD) && given.contains(TrackingSettings.R_OUT)) return null;
		final SettingValues before = settings();
		final MeasuredSettings.Result r;
		try {
			r = MeasuredSettings.of(imp.getTitle(), frames::frame, frames.frameCount(), imp.getBitDepth() != 32, before,
				given, FrontEnd.FIJI);
		}
		catch (final InvalidInputException e) {
			throw new InvalidInputException("the macro gives no threshold and r_out, and they cannot be measured: " + e
				.getMessage());
		}
		final SettingValues after = r.settings();
		if (r.notice().isEmpty()) return null;
		final StringBuilder b = new StringBuilder();
		for (final Setting<?> s : TrackingSettings.ALL)
			if (!String.valueOf(before.get(s)).equals(String.valueOf(after.get(s)))) {
				b.append(' ').append(s.name()).append('=').append(after.get(s) instanceof Double d ? MeasuredSettings
					.optionValue(d) : String.valueOf(after.get(s)));
			}
		threshold = after.get(TrackingSettings.THRESHOLD);
		r_out = after.get(TrackingSettings.R_OUT);
		diameter = after.diameter();
		min_area = after.get(TrackingSettings.MIN_AREA);
		particles = after.dark() ? TrackingSettings.DARK : particles;
		return "  not given by the macro, measured on frame 1 by the profile helper:" + b + " (give them to use " +
			"your own)";
	}

	/**
	 * Shows the spots and {@code r_out} discs of the frame on display as the dialog's values change (called by
	 * Fiji's dialog, also once when it opens), when the Preview box is ticked; unticking it takes the preview
	 * off. The frame is tracked on a background thread and this returns at once: the dialog never waits for it. A
	 * newer call abandons a preview still computing (its spots are never shown). Invalid values show nothing new;
	 * {@link #cancel()} puts the overlay back as it was.
	 */
	@Override
	public void preview() {
		final int generation = previewGeneration.incrementAndGet();
		if (imp == null) return;
		showOrigin(); // the dialog calls this on every change
		if (!preview) {
			synchronized (this) {
				clearPreview(true);
			}
			note(false, PREVIEW_OFF);
			return;
		}
		final SettingValues settings;
		final ImagePlusFrames frames;
		final Interval region;
		try {
			// the values are read here, on the dialog's thread, as they are now
			settings = settings();
			frames = ImagePlusFrames.of(imp, channel);
			region = ShownImage.selection(imp);
		}
		catch (final RuntimeException e) {
			// while values are being typed they are often invalid: say why, keep the last preview
			if (status != null) status.showStatus(TITLE + " preview: " + e.getMessage());
			note(false, previewText("not run, " + e.getMessage()));
			return;
		}
		final int t = ShownImage.frame(imp);
		if (status != null) status.showStatus(TITLE + " preview: tracking frame " + (t + 1) + "...");
		note(false, previewText("working on frame " + (t + 1) + "..."));
		synchronized (this) {
			if (previewer == null) previewer = Executors.newSingleThreadExecutor(r -> {
				final Thread thread = new Thread(r, TITLE + " preview");
				thread.setDaemon(true);
				return thread;
			});
			pendingPreview = previewer.submit(() -> previewFrame(generation, settings, frames, region, t));
		}
	}

	/**
	 * Tracks frame {@code t} (within {@code region}, or all of it when null) and shows it, unless a newer preview (or
	 * the run, or Cancel) came meanwhile.
	 */
	private void previewFrame(final int generation, final SettingValues settings, final ImagePlusFrames frames,
		final Interval region, final int t)
	{
		if (generation != previewGeneration.get()) return; // superseded before it started
		final long start = System.nanoTime();
		final FrameResult r;
		try {
			// the frame alone, through the same pipeline as a run (no file, no data-range pass over the stack)
			r = new TrackingPipeline(settings, FrontEnd.FIJI).run(FrameSource.of(frames, imp.getTitle()).within(region).only(t),
				Outputs.NONE, 1, true, null, () -> generation != previewGeneration.get()).frames().get(0);
		}
		catch (final RuntimeException | IOException e) {
			if (generation == previewGeneration.get()) {
				if (status != null) status.showStatus(TITLE + " preview: " + e.getMessage());
				note(false, previewText("not run, " + e.getMessage()));
			}
			return;
		}
		synchronized (this) {
			if (generation != previewGeneration.get()) return;
			if (!previewShown) {
				beforePreview = imp.getOverlay() == null ? null : imp.getOverlay().duplicate();
				previewShown = true;
			}
			final SpotOverlay.FramePlacer placer = SpotOverlay.placer(imp);
			SpotOverlay.show(imp, SpotOverlay.rois(List.of(r), settings.parameters().exclusionRadius(), settings
				.diameter(), r_out_circles, (roi, frame) -> placer.place(roi, t)));
		}
		final String count = r.spots().size() + " spots on frame " + (t + 1) + (region == null ? ""
			: " within the selection");
		if (status != null) status.showStatus(TITLE + " preview: " + count);
		note(false, previewText(String.format(java.util.Locale.ROOT, "%s (%.1f s)", count, (System.nanoTime() - start) *
			1e-9)));
	}

	/** Waits for the preview asked for last (for tests and scripts); returns at once when none is pending. */
	void awaitPreview() throws InterruptedException, ExecutionException {
		final Future<?> f;
		synchronized (this) {
			f = pendingPreview;
		}
		if (f != null) f.get();
	}

	/** Abandons any preview still computing and ends the preview thread. */
	private void stopPreviews() {
		previewGeneration.incrementAndGet();
		synchronized (this) {
			if (previewer != null) previewer.shutdown();
			previewer = null;
		}
	}

	/**
	 * The dialog's "Measure from the image" button: runs the profile helper on the most isolated particles of the
	 * frame on display, in the channel to be tracked, and fills {@code threshold}, {@code r_out} and {@code diameter}
	 * with its suggestions, and lowers {@code min_area} for particles so small that the default would drop some; a
	 * diameter already given (above 0) is kept and used, or estimated instead if the helper cannot measure with it
	 * ({@link ShownFrameProfile#measure}). What was measured, with the helper's
	 * warnings, goes to the Log window and the status bar. When the helper finds nothing to measure, the fields stay
	 * as they were and the status bar and the Log say why in one line.
	 */
	private void measureFromImage() {
		final ShownFrameProfile p;
		try {
			p = ShownFrameProfile.measure(imp, channel, TrackingSettings.DARK.equals(particles), diameter);
		}
		catch (final InvalidInputException e) {
			final String message = TITLE + ": cannot measure from the image: " + e.getMessage();
			WindowsBeside.log(message, imp);
			if (status != null) status.showStatus(message);
			return;
		}
		if (!p.thresholdInFrame()) {
			// no threshold keeps two such particles apart: what 'track' measures on this frame, by their image
			final MeasuredSettings.Result m;
			try {
				m = MeasuredSettings.of(imp.getTitle(), p.frameAsGiven(imp), p.integerData(), SettingValues.defaults()
					.withText(TrackingSettings.METHOD, method).withText(TrackingSettings.DETECTION, detection), diameter,
					TrackingSettings.DARK.equals(particles) ? TrackingSettings.DARK : null, FrontEnd.FIJI);
			}
			catch (final InvalidInputException e) {
				final String message = TITLE + ": cannot measure from the image: " + e.getMessage();
				WindowsBeside.log(message, imp);
				if (status != null) status.showStatus(message);
				return;
			}
			particles = m.settings().get(TrackingSettings.PARTICLES);
			detection = m.settings().get(TrackingSettings.DETECTION);
			threshold = m.settings().get(TrackingSettings.THRESHOLD);
			r_out = m.settings().get(TrackingSettings.R_OUT);
			diameter = m.settings().diameter();
			ValuesOrigin.measured(helperValues());
			showOrigin();
			WindowsBeside.log(p.logText(TITLE + ": measured") + "\n" + m.notice(), imp);
			if (status != null) status.showStatus(TITLE + ": tracked by the particles' image: no threshold keeps them " +
				"apart");
			preview();
			return;
		}
		if (p.darkFound()) particles = TrackingSettings.DARK;
		threshold = p.threshold();
		r_out = p.rOut();
		diameter = p.diameter();
		if (p.smallParticles()) min_area = Math.min(min_area, p.minArea());
		ValuesOrigin.measured(helperValues());
		showOrigin();
		WindowsBeside.log(p.logText(TITLE + ": measured"), imp);
		if (status != null) status.showStatus(TITLE + ": measured " + p.status());
		preview(); // the dialog previews its values as they change; these changed without an edit
	}

	/** Takes the preview off the image: the dialog was cancelled. */
	@Override
	public void cancel() {
		besideImage.disarm();
		stopPreviews();
		synchronized (this) {
			clearPreview(true);
		}
	}

	/** @param restore whether to put back the overlay as it was before the preview (else it is left to the run) */
	private synchronized void clearPreview(final boolean restore) {
		if (!previewShown) return;
		previewShown = false;
		if (restore) imp.setOverlay(beforePreview);
		else if (beforePreview == null) SpotOverlay.clear(imp);
		else imp.setOverlay(beforePreview);
		beforePreview = null;
	}

	private void progress(final int done, final int count) {
		// methods that measure the profile pass over the stack several times: count is all passes' frames
		if (status != null) status.showStatus(done, count, "Contact Tracker: " + (100 * done / Math.max(1, count)) +
			"%");
	}

	/**
	 * Cancels with a one-line reason, shown once ({@link #errorOnce}: stderr headless), and stops the
	 * calling ImageJ macro, if any, as ImageJ's own commands do ({@link MacroFailure}).
	 */
	private void fail(final String reason) {
		errorOnce(TITLE + ": " + reason);
		stop(reason);
		final boolean redirected = MacroFailure.macroRunning() && IJ.redirectingErrorMessages();
		if (MacroFailure.report(TITLE, imp == null ? null : imp.getTitle(), reason) && redirected && !RESULTS_NONE
			.equals(results))
			// the macro goes on: its nResults must not show the previous image's spots as this one's
			ResultsTable.getResultsTable().reset();
	}

	private void stop(final String reason) {
		if (status != null) status.clearStatus();
		cancel(reason);
	}

	/** @return the file, or null when none was given (an empty file field gives an empty path) */
	private static File given(final File file) {
		return file == null || file.getPath().isBlank() ? null : file;
	}

	/** The image as TrackMate's XML names it: its file when it was opened from one. */
	private static ImageSource source(final ImagePlus imp, final ImagePlusFrames frames) {
		final FileInfo fi = imp.getOriginalFileInfo();
		if (fi != null && fi.fileName != null && !fi.fileName.isEmpty() && fi.directory != null && !fi.directory
			.isEmpty()) return ImageSource.of(Path.of(fi.directory, fi.fileName), frames.width(), frames.height(), frames
				.frameCount());
		return new ImageSource("", "", frames.width(), frames.height(), 1, frames.frameCount());
	}

}
