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
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;

import org.scijava.ItemIO;
import org.scijava.command.Command;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;
import org.scijava.widget.FileWidget;

import ij.IJ;
import ij.ImagePlus;
import ij.WindowManager;
import ij.gui.Plot;
import ij.measure.ResultsTable;
import io.github.contacttracker.plot.PotentialPlots;
import io.github.contacttracker.io.SpotTableCsv;
import io.github.contacttracker.ui.WindowsBeside;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.potential.PotentialReport;
import io.github.contacttracker.potential.SpotSet;

/**
 * <i>Plugins &gt; Tracking &gt; Contact Tracker Pair Potential</i>: g(r) and U(r)/kT from a spots table, shown as
 * a plot with error bars and a table of values (the command line's {@code potential}, same numbers).
 * <p>
 * The spots come from the {@code csv} file (ours or TrackMate's spot export) when one is given, else from the
 * open table titled {@code table} (by default ImageJ's Results table, which Contact Tracker fills with the spots;
 * Contact Tracker's own spots table or a CSV file opened in Fiji work too). When the Results table no longer holds
 * spots (the Profile's suggestion or another command replaced them), the spots Contact Tracker found last are
 * used, and the Log says so. The field of view is the one given, else the real size of the image tracked last,
 * or of the open image, when the spots lie on it (not the spots' extent), else inferred from the spots. The table is named by its title, not
 * taken as a {@code ResultsTable} input: Fiji fills a command's single {@code ResultsTable} input with the Results
 * table itself, which would win over {@code csv=} and {@code table=}. Macro:
 * {@code run("Contact Tracker Pair Potential", "bin=0.05 r_max=10 zero_from=8 zero_to=10");}; {@code bin=0} and
 * {@code r_max=0} (the defaults) choose both from the field of view. The values go to ImageJ's Results table too
 * (for {@code nResults} and {@code getResult}) unless {@code results=false}. Bad input cancels the command with a
 * one-line reason and stops a calling macro ({@link MacroFailure}); the values are remembered for the next dialog,
 * but a macro's left-out keys take the defaults ({@link MacroInputs}).
 */
@Plugin(type = Command.class, menuPath = "Plugins>Tracking>Contact Tracker Pair Potential", headless = true,
	label = "Contact Tracker Pair Potential", description = "Pair distribution g(r) and pair potential U(r) from " +
		"a spots table", initializer = "macroInputs")
public class ContactTrackerPotentialCommand extends OwnCommand {

	/** A new command (SciJava makes one per run). */
	public ContactTrackerPotentialCommand() {
		super(PLOT_TITLE, "g(r) and U(r)/kT from tracked spots: a CSV file, or an open table",
			DialogHelp.POTENTIAL_PAGE);
	}


	/** Title of the table of values. */
	public static final String TABLE_TITLE = "Contact Tracker pair potential";
	/** Title of ImageJ's system results table, which macros read and Contact Tracker fills with its spots. */
	public static final String RESULTS = "Results";
	/** Bins that {@code bin=0} gives over {@code r_max}. */
	static final int AUTO_BINS = 50;
	/** Title of the plot. */
	public static final String PLOT_TITLE = "Contact Tracker Pair Potential";


	@Parameter(label = "Spots table (title)", required = false,
		description = DialogHelp.TIP + "Title of an open table of spots (columns POSITION_X, POSITION_Y, FRAME, FLAG_...): " +
			"'Results' (ImageJ's, filled by Contact Tracker), a Contact Tracker spots table, or a CSV opened in Fiji")
	private String table = RESULTS;

	@Parameter(label = "Or a spots CSV file", persist = false, required = false, style = FileWidget.OPEN_STYLE,
		description = DialogHelp.TIP + "Optional: read the spots from this CSV (ours, or TrackMate's spot export) instead of the table")
	private File csv;

	@Parameter(validater = "validateInputs", label = "Bin width (spots' units, 0 = r_max / 50)", min = "0",
		description = DialogHelp.TIP + "Width of the distance bins, in the units of the spots' positions; 0 gives 50 bins")
	private double bin = 0;

	@Parameter(validater = "validateInputs", label = "r_max (spots' units, 0 = half the field)", min = "0",
		description = DialogHelp.TIP + "Largest distance; at most the smaller side of the field of view; 0 takes half of it")
	private double r_max = 0;

	@Parameter(validater = "validateInputs", label = "Field width (0 = the image's)", min = "0",
		description = DialogHelp.TIP + "The field of view the spots were found in, in the spots' units; 0 takes the open " +
			"image's size when the spots lie on it, else infers it from the spots")
	private double width = 0;

	@Parameter(validater = "validateInputs", label = "Field height (0 = the image's)", min = "0",
		description = DialogHelp.TIP + "See the width")
	private double height = 0;

	@Parameter(validater = "validateInputs", label = "Start frame", min = "0",
		description = DialogHelp.TIP + "Spots of earlier frames are left out (0-based, as the FRAME column)")
	private int start_frame = 0;

	@Parameter(label = "Leave out flagged spots",
		description = DialogHelp.TIP + "Spots with a warning flag (every FLAG_ column but FLAG_SECOND_PASS) are left out")
	private boolean skip_flagged = true;

	@Parameter(validater = "validateInputs", label = "U = 0 from r", min = "0",
		description = DialogHelp.TIP + "With 'to r', sets U to 0 on average over this range (both 0: U = -ln g)")
	private double zero_from = 0;

	@Parameter(validater = "validateInputs", label = "U = 0 to r", min = "0")
	private double zero_to = 0;

	@Parameter(label = "Show plot and table")
	private boolean show = true;

	@Parameter(label = "Results table gets the values",
		description = DialogHelp.TIP + "Puts R, PAIRS, G, U_KT, U_KT_ERR into ImageJ's Results table, which macros read with " +
			"nResults and getResult (it replaces the spots there)")
	private boolean results = true;

	@Parameter(label = "Pair potential", type = ItemIO.OUTPUT)
	private ResultsTable potential;

	@Parameter(label = "Plot", type = ItemIO.OUTPUT)
	private Plot plot;


	@Override
	public void run() {
		besideImage.disarm(); // in case there was no dialog (a macro, a script)
		try {
			if (own.problem() != null) throw new InvalidInputException(own.problem());
			analyse();
			MacroFailure.succeeded();
		}
		catch (final InvalidInputException | IOException e) {
			errorOnce(PLOT_TITLE + ": " + e.getMessage());
			cancel(e.getMessage());
			MacroFailure.report(PLOT_TITLE, null, e.getMessage());
		}
		finally {
			own.finish();
		}
	}


	/**
	 * The validater of the numeric inputs, as SciJava resolves them: a negative or non-finite value is noted for
	 * {@link #run()} and not remembered.
	 */
	private void validateInputs() {
		final Object[][] numbers = { { "bin", bin }, { "r_max", r_max }, { "width", width }, { "height", height }, {
			"start_frame", (double) start_frame }, { "zero_from", zero_from }, { "zero_to", zero_to } };
		for (final Object[] n : numbers) {
			final double v = (Double) n[1];
			if (!(v >= 0) || !Double.isFinite(v)) own.refuse((String) n[0], n[0] +
				" must be a number >= 0, not " + v, 0);
		}
	}

	private void analyse() throws IOException {
		if ((width > 0) != (height > 0))
			throw new InvalidInputException("give both the field's width and height, or neither (0: inferred)");
		String unit = "";
		final SpotTables.LastRun last = SpotTables.lastRun();
		final Map<String, double[]> columns;
		final String source;
		if (csv != null && !csv.getPath().isBlank()) {
			final SpotTableCsv.Table t = SpotTableCsv.read(csv.toPath(), SpotSet::reads);
			columns = t.columns();
			unit = t.unit();
			source = csv.getName();
		}
		else {
			final String title = table == null || table.isBlank() ? RESULTS : table.trim();
			// the Results table has no window headless (nor before it is shown): ImageJ keeps it in a static
			ResultsTable rt = title.equals(RESULTS) ? ResultsTable.getResultsTable() : ResultsTable.getResultsTable(
				title);
			String from = title;
			if (title.equals(RESULTS) && (rt == null || rt.getColumnIndex(SpotSet.X) == ResultsTable.COLUMN_NOT_FOUND)) {
				// another command (the Profile's suggestion, Analyze Particles) replaced the spots there
				if (last == null) throw new InvalidInputException("the Results table holds no spots (no column " + SpotSet.X +
					"): run Contact Tracker first, or name its spots table ('" + SpotTables.SPOTS_TITLE + ": ...') or a " +
					"spots CSV");
				rt = last.spots();
				from = rt.getTitle() + " (Results holds no spots)";
			}
			if (rt == null) throw new InvalidInputException("no open table titled '" + title + "': track first, open " +
				"a spots CSV, or give the csv file");
			columns = columns(rt);
			source = from;
		}
		final SpotSet set;
		try {
			set = SpotSet.fromColumns(columns, new SpotSet.Selection(start_frame, skip_flagged));
		}
		catch (final IllegalArgumentException e) {
			throw new InvalidInputException(source + ": " + e.getMessage());
		}
		if (set.size() == 0) throw new InvalidInputException(source + ": no spot left");
		// the image tracked last, else the open one, when the spots lie on it
		final ImagePlus open = WindowManager.getCurrentImage();
		final String image;
		final FieldOfView field;
		if (width > 0) {
			image = null;
			field = FieldOfView.of(width, height);
		}
		else if (last != null && onImage(set, last.field())) {
			image = last.image();
			field = last.field();
		}
		else if (open != null && onImage(set, imageField(open))) {
			image = open.getTitle();
			field = imageField(open);
		}
		else {
			image = null;
			field = set.inferredField();
		}
		// 0 = chosen from the field: half its smaller side (the edge correction holds up to all of it), 50 bins
		final double rMax = r_max > 0 ? r_max : field.maxDistance() / 2;
		final double width = bin > 0 ? bin : rMax / AUTO_BINS;
		PairCorrelation.Result r = PairCorrelation.compute(set, field, width, rMax);
		if (zero_from > 0 || zero_to > 0) r = r.withZero(zero_from, zero_to);
		potential = PotentialColumns.table(r, TABLE_TITLE);
		plot = PotentialPlots.potential(r, PLOT_TITLE + ": " + source, unit.isEmpty() ? "spots' units" : unit);
		final StringBuilder b = new StringBuilder(PLOT_TITLE + ": " + source);
		for (final String line : PotentialReport.lines(set, r, unit.isEmpty() ? "" : unit))
			b.append("\n  ").append(line);
		if (image != null) b.append("\n  field of view: the image '").append(image).append("', its real size");
		final String warning = PotentialReport.fieldWarning(set, field);
		if (warning != null) b.append("\n  warning: ").append(warning);
		if (bin == 0 || r_max == 0) b.append(String.format(java.util.Locale.ROOT, "%n  bin %s, r_max %s (chosen from " +
			"the field of view)", num(width), num(rMax)));
		WindowsBeside.log(b.toString(), null);
		if (results) PotentialColumns.fill(ResultsTable.getResultsTable(), r);
		if (show && !GraphicsEnvironment.isHeadless()) {
			// the table and the plot beside each other, not one over the other
			((TitledResultsTable) potential).show();
			final java.awt.Window tableWindow = WindowManager.getWindow(potential.getTitle());
			WindowsBeside.move(tableWindow, WindowManager.getCurrentImage());
			WindowsBeside.move(plot.show(), WindowManager.getCurrentImage(), tableWindow);
		}
	}

	/** @return the image's field of view, in its calibrated units (the spots' units) */
	private static FieldOfView imageField(final ImagePlus image) {
		final ij.measure.Calibration c = image.getCalibration();
		return FieldOfView.ofImage(image.getWidth(), image.getHeight(), c.pixelWidth, c.pixelHeight);
	}

	/**
	 * @return whether every spot used lies on the image's field (a particle cut by the border is located from the
	 *         part of its image inside the frame, and its centre may fall just outside it)
	 */
	private static boolean onImage(final SpotSet set, final FieldOfView f) {
		if (set.size() == 0) return false;
		final double[] x = set.allX(), y = set.allY();
		for (int i = 0; i < x.length; i++)
			if (f.depth(x[i], y[i]) < 0) return false;
		return true;
	}

	private static String num(final double v) {
		return new java.math.BigDecimal(String.format(java.util.Locale.ROOT, "%.6g", v)).stripTrailingZeros()
			.toPlainString();
	}

	/**
	 * The columns of a results table; leading rows without a position (the extra header rows of TrackMate's
	 * export, opened as a table) are skipped.
	 */
	static Map<String, double[]> columns(final ResultsTable rt) {
		final Map<String, double[]> out = new LinkedHashMap<>();
		final int x = rt.getColumnIndex(SpotSet.X);
		int skip = 0;
		if (x != ResultsTable.COLUMN_NOT_FOUND) {
			final double[] xs = rt.getColumnAsDoubles(x);
			while (skip < Math.min(3, xs.length) && Double.isNaN(xs[skip]))
				skip++;
		}
		for (final String h : rt.getHeadings()) {
			if (!SpotSet.reads(h)) continue;
			final double[] c = rt.getColumnAsDoubles(rt.getColumnIndex(h));
			if (c != null) out.put(h, java.util.Arrays.copyOfRange(c, skip, c.length));
		}
		return out;
	}

}
