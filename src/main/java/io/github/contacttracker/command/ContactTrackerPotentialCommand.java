package io.github.contacttracker.command;

import io.github.contacttracker.core.InvalidInputException;
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;

import org.scijava.ItemIO;
import org.scijava.command.Command;
import org.scijava.command.ContextCommand;
import org.scijava.log.LogService;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;
import org.scijava.widget.FileWidget;

import ij.IJ;
import ij.gui.Plot;
import ij.measure.ResultsTable;
import io.github.contacttracker.io.PotentialPlots;
import io.github.contacttracker.io.SpotTableCsv;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.potential.PotentialReport;
import io.github.contacttracker.potential.SpotSet;

/**
 * <i>Plugins &gt; Tracking &gt; Contact Tracker Pair Potential</i>: g(r) and U(r)/kT from a spots table, shown as
 * a plot with error bars and a table of values (the command line's {@code potential}, same numbers).
 * <p>
 * The spots come from, in this order: the {@code spots} input (a results table, for scripts), the {@code csv}
 * file (ours or TrackMate's spot export), or the open table titled {@code table} (by default Contact Tracker's
 * spots table; a CSV file opened in Fiji works too). Macro: {@code run("Contact Tracker Pair Potential",
 * "bin=0.05 r_max=10 zero_from=8 zero_to=10");}. Bad input cancels the command with a one-line reason.
 */
@Plugin(type = Command.class, menuPath = "Plugins>Tracking>Contact Tracker Pair Potential", headless = true,
	label = "Contact Tracker Pair Potential", description = "Pair distribution g(r) and pair potential U(r) from " +
		"a spots table")
public class ContactTrackerPotentialCommand extends ContextCommand {

	/** Title of the table of values. */
	public static final String TABLE_TITLE = "Contact Tracker pair potential";
	/** Title of the plot. */
	public static final String PLOT_TITLE = "Contact Tracker Pair Potential";

	@Parameter
	private LogService log;

	@Parameter(label = "Spots table (title)", persist = false, required = false,
		description = "Title of an open table of spots (columns POSITION_X, POSITION_Y, FRAME, FLAG_...)")
	private String table = SpotTables.SPOTS_TITLE;

	@Parameter(label = "Or a spots CSV file", persist = false, required = false, style = FileWidget.OPEN_STYLE,
		description = "Optional: read the spots from this CSV (ours, or TrackMate's spot export) instead")
	private File csv;

	@Parameter(label = "Bin width (spots' units)", persist = false, min = "0",
		description = "Width of the distance bins, in the units of the spots' positions")
	private double bin = 0;

	@Parameter(label = "r_max (spots' units)", persist = false, min = "0",
		description = "Largest distance; at most the smaller side of the field of view")
	private double r_max = 0;

	@Parameter(label = "Field width (0 = infer from spots)", persist = false, min = "0")
	private double width = 0;

	@Parameter(label = "Field height (0 = infer from spots)", persist = false, min = "0")
	private double height = 0;

	@Parameter(label = "Start frame", persist = false, min = "0",
		description = "Spots of earlier frames are left out (0-based, as the FRAME column)")
	private int start_frame = 0;

	@Parameter(label = "Leave out flagged spots", persist = false,
		description = "Spots with a warning flag (every FLAG_ column but FLAG_SECOND_PASS) are left out")
	private boolean skip_flagged = true;

	@Parameter(label = "U = 0 from r", persist = false, min = "0",
		description = "With 'to r', sets U to 0 on average over this range (both 0: U = -ln g)")
	private double zero_from = 0;

	@Parameter(label = "U = 0 to r", persist = false, min = "0")
	private double zero_to = 0;

	@Parameter(label = "Show plot and table", persist = false)
	private boolean show = true;

	@Parameter(label = "Spots (for scripts)", persist = false, required = false)
	private ResultsTable spots;

	@Parameter(label = "Pair potential", type = ItemIO.OUTPUT)
	private ResultsTable potential;

	@Parameter(label = "Plot", type = ItemIO.OUTPUT)
	private Plot plot;

	@Override
	public void run() {
		try {
			analyse();
		}
		catch (final InvalidInputException | IOException e) {
			log.error(PLOT_TITLE + ": " + e.getMessage());
			cancel(e.getMessage());
		}
	}

	private void analyse() throws IOException {
		if (!(bin > 0)) throw new InvalidInputException("bin must be a positive width");
		if ((width > 0) != (height > 0))
			throw new InvalidInputException("give both the field's width and height, or neither (0: inferred)");
		String unit = "";
		final Map<String, double[]> columns;
		final String source;
		if (spots != null) {
			columns = columns(spots);
			source = "spots table";
		}
		else if (csv != null) {
			final SpotTableCsv.Table t = SpotTableCsv.read(csv.toPath(), SpotSet::reads);
			columns = t.columns();
			unit = t.unit();
			source = csv.getName();
		}
		else {
			final String title = table == null || table.isBlank() ? SpotTables.SPOTS_TITLE : table;
			final ResultsTable rt = ResultsTable.getResultsTable(title);
			if (rt == null) throw new InvalidInputException("no open table titled '" + title + "': track first, open " +
				"a spots CSV, or give the csv file");
			columns = columns(rt);
			source = title;
		}
		final SpotSet set;
		try {
			set = SpotSet.fromColumns(columns, new SpotSet.Selection(start_frame, skip_flagged));
		}
		catch (final IllegalArgumentException e) {
			throw new InvalidInputException(source + ": " + e.getMessage());
		}
		if (set.size() == 0) throw new InvalidInputException(source + ": no spot left");
		final FieldOfView field = width > 0 ? FieldOfView.of(width, height) : FieldOfView.inferred(set.allX(), set
			.allY());
		PairCorrelation.Result r = PairCorrelation.compute(set, field, bin, r_max);
		if (zero_from > 0 || zero_to > 0) r = r.withZero(zero_from, zero_to);
		potential = PotentialColumns.table(r, TABLE_TITLE);
		plot = PotentialPlots.potential(r, PLOT_TITLE + ": " + source, unit.isEmpty() ? "spots' units" : unit);
		final StringBuilder b = new StringBuilder(PLOT_TITLE + ": " + source);
		for (final String line : PotentialReport.lines(set, r, unit.isEmpty() ? "" : unit))
			b.append("\n  ").append(line);
		final String warning = PotentialReport.fieldWarning(set, field);
		if (warning != null) b.append("\n  warning: ").append(warning);
		IJ.log(b.toString());
		if (show && !GraphicsEnvironment.isHeadless()) {
			((TitledResultsTable) potential).show();
			plot.show();
		}
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
