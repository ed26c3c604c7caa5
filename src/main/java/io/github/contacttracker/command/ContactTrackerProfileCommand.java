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
import java.awt.Point;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.scijava.ItemIO;
import org.scijava.command.Command;
import org.scijava.plugin.Parameter;
import org.scijava.plugin.Plugin;

import ij.IJ;
import ij.ImagePlus;
import ij.gui.Plot;
import ij.gui.PointRoi;
import ij.gui.Roi;
import ij.measure.ResultsTable;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.plot.ProfilePlots;
import io.github.contacttracker.report.ProfileReport;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.ui.WindowsBeside;

/**
 * <i>Plugins &gt; Tracking &gt; Contact Tracker Profile</i>: the parameter helper. The user marks an isolated
 * particle with the point tool; the command plots the particle's radial intensity profile with the background,
 * the noise band and the suggested {@code threshold} and {@code r_out} marked (as in the paper's Fig. 2), and
 * prints the numbers to the Log window. The rule is {@link ProfileAnalysis}'s.
 * <p>
 * The profile is taken in the channel and frame on display. Suggestions are rounded up: {@code r_out} to whole
 * pixels, the threshold to a whole grey level for 8- and 16-bit images. They are also outputs, for scripts (the
 * command prints and plots them itself, and keeps SciJava from displaying them again). A macro reads them from
 * ImageJ's Results table, one row ({@link #RESULT_COLUMNS}), with {@code getResult("THRESHOLD", 0)} and so on;
 * {@code results=false} leaves the Results table alone.
 */
@Plugin(type = Command.class, menuPath = "Plugins>Tracking>Contact Tracker Profile", headless = true,
	label = "Contact Tracker Profile", description = "Radial profile of one particle and suggested threshold and " +
		"r_out for Contact Tracker", initializer = "macroInputs")
public class ContactTrackerProfileCommand extends OwnCommand {

	/** A new command (SciJava makes one per run). */
	public ContactTrackerProfileCommand() {
		super(PLOT_TITLE, "First click on an isolated particle with the point tool: its profile " +
			"suggests threshold and r_out", DialogHelp.PROFILE_PAGE);
	}


	/** The columns of the row the command puts into ImageJ's Results table, for macros. */
	public static final List<String> RESULT_COLUMNS = List.of("THRESHOLD", "R_OUT", "DIAMETER", "BACKGROUND",
		"NOISE", "X", "Y", "FRAME");

	/** Title of the plot window (followed by the image title). */
	public static final String PLOT_TITLE = "Contact Tracker Profile";

	@Parameter(label = "Image", persist = false)
	private ImagePlus imp;

	@Parameter(validater = "validateInputs", label = "Particle diameter (px, 0 = estimate)", min = "0",
		description = DialogHelp.TIP + "The centre distance of two particles at contact, in pixels; 0 estimates it from the " +
			"particles' nearest-neighbour distances")
	private double diameter = 0;

	@Parameter(validater = "validateInputs", label = "Max radius (px, 0 = 2.5 diameters)", min = "0",
		description = DialogHelp.TIP + "How far out the profile is measured; its outer 20% give the background")
	private double max_radius = 0;

	@Parameter(label = "Show plot")
	private boolean plot = true;

	@Parameter(label = "Results table gets the suggestion",
		description = DialogHelp.TIP + "Puts one row (THRESHOLD, R_OUT, DIAMETER, BACKGROUND, NOISE, X, Y, FRAME) into ImageJ's " +
			"Results table, which macros read with getResult (it replaces what the table held)")
	private boolean results = true;


	@Parameter(label = "Suggested threshold", type = ItemIO.OUTPUT)
	private double suggested_threshold;

	@Parameter(label = "Suggested r_out (px)", type = ItemIO.OUTPUT)
	private double suggested_r_out;

	@Parameter(label = "Background", type = ItemIO.OUTPUT)
	private double background;

	@Parameter(label = "Noise (sigma)", type = ItemIO.OUTPUT)
	private double noise;

	@Parameter(label = "Centre x (px)", type = ItemIO.OUTPUT)
	private double centre_x;

	@Parameter(label = "Centre y (px)", type = ItemIO.OUTPUT)
	private double centre_y;

	@Parameter(label = "Profile", type = ItemIO.OUTPUT)
	private Plot profile;

	/** The dialog goes beside the image with the marked particle, not over it. */
	@Override
	protected ImagePlus image() {
		return imp;
	}

	@Override
	public void run() {
		besideImage.disarm(); // in case there was no dialog (a macro, a script)
		try {
			if (own.problem() != null) throw new InvalidInputException(own.problem());
			analyse();
			MacroFailure.succeeded();
		}
		catch (final InvalidInputException e) {
			errorOnce(PLOT_TITLE + ": " + e.getMessage());
			cancel(e.getMessage());
			MacroFailure.report(PLOT_TITLE, imp == null ? null : imp.getTitle(), e.getMessage());
		}
		finally {
			own.finish();
		}
	}


	/** The validater of the lengths: a negative or non-finite one is noted for {@link #run()}, not remembered. */
	private void validateInputs() {
		if (!(diameter >= 0) || !Double.isFinite(diameter)) own.refuse("diameter", "diameter must be a number of pixels >= 0 (0 = estimate), not " + diameter, 0);
		if (!(max_radius >= 0) || !Double.isFinite(max_radius)) own.refuse("max_radius", "max_radius must be a number of pixels >= 0 (0 = 2.5 diameters), not " + max_radius, 0);
	}

	private void analyse() {
		if (imp == null) throw new InvalidInputException("no image");
		final double[] point = point(imp.getRoi());
		final ShownFrameProfile p = ShownFrameProfile.at(imp, point, diameter, max_radius);
		final ProfileAnalysis.Result r = p.result();

		suggested_threshold = p.threshold();
		suggested_r_out = p.rOut();
		background = r.background();
		noise = r.noise();
		centre_x = r.x();
		centre_y = r.y();
		profile = ProfilePlots.plot(r, PLOT_TITLE + ": " + imp.getTitle(), suggested_threshold, suggested_r_out);
		report(p, point);
		if (results) toResultsTable(p);
		if (plot && !GraphicsEnvironment.isHeadless()) WindowsBeside.move(profile.show(), imp);
	}

	/** @return the marked point in pixel units, TrackMate's convention (pixel (0,0)'s centre at 0,0) */
	static double[] point(final Roi roi) {
		if (roi == null)
			throw new InvalidInputException("no point on the image: click on an isolated particle with the point " +
				"tool first (in a macro: makePoint(x, y))");
		if (roi instanceof PointRoi) {
			final Point[] p = roi.getContainedPoints();
			if (p.length == 0) throw new InvalidInputException("the point selection is empty");
			return new double[] { p[0].x, p[0].y };
		}
		if (!roi.isArea())
			throw new InvalidInputException("the selection is a line: click on an isolated particle with the " +
				"point tool");
		final double[] c = roi.getContourCentroid();
		return new double[] { c[0] - 0.5, c[1] - 0.5 };
	}

	private void report(final ShownFrameProfile p, final double[] point) {
		final ProfileAnalysis.Result r = p.result();
		final StringBuilder b = new StringBuilder();
		b.append(String.format(Locale.ROOT, "%s: '%s'%s, particle at (%.2f, %.2f) px%s%n", PLOT_TITLE, imp.getTitle(),
			p.frameCount() > 1 ? ", frame " + (p.frame() + 1) : "", r.x(), r.y(), r.refined() ? String.format(
				Locale.ROOT, " (point given: %.0f, %.0f)", point[0], point[1]) : " (not refined)"));
		for (final String line : ProfileReport.lines(r, p.integerData()))
			b.append(ShownFrameProfile.wrap(line, ShownFrameProfile.LOG_WIDTH, "    ")).append('\n');
		b.append(String.format(Locale.ROOT, "  macro: run(\"Contact Tracker\", \"threshold=%s r_out=%.0f diameter=%s\");",
			Numbers.fmt(suggested_threshold, 3), suggested_r_out, Numbers.fmt(p.diameter(), 3)));
		WindowsBeside.log(b.toString(), imp);
	}

	/** One row in ImageJ's Results table: what a macro reads with {@code getResult("THRESHOLD", 0)}. */
	private void toResultsTable(final ShownFrameProfile p) {
		final ResultsTable rt = ResultsTable.getResultsTable();
		rt.reset();
		rt.incrementCounter();
		final double[] values = { suggested_threshold, suggested_r_out, p.diameter(), background, noise, centre_x,
			centre_y, p.frame() };
		for (int i = 0; i < values.length; i++)
			rt.addValue(RESULT_COLUMNS.get(i), values[i]);
		rt.setDecimalPlaces(rt.getColumnIndex("FRAME"), 0);
		if (!GraphicsEnvironment.isHeadless() && ij.WindowManager.getWindow("Results") != null) rt.show("Results");
	}

}
