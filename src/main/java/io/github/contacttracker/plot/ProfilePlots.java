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
package io.github.contacttracker.plot;

import java.awt.Color;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;

import ij.gui.Plot;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.io.AtomicFile;

/**
 * The radial profile of {@link ProfileAnalysis} as a plot (the paper's Fig. 2: the profile, the background, the
 * noise band, {@code D/2} and the suggested threshold and {@code r_out}) and as a CSV table; shared by the Fiji
 * helper and the command line's {@code profile}.
 */
public final class ProfilePlots {

	/**
	 * Colours of the noise band's upper and lower lines: readable on the white plot and in its legend, and told
	 * apart (one grey for both could not be).
	 */
	public static final Color NOISE_BAND = new Color(220, 120, 0), NOISE_BAND_LOW = new Color(140, 60, 190);

	private ProfilePlots() {}

	/**
	 * @param r the analysis
	 * @param title the plot's title
	 * @param threshold the threshold to mark (rounded as suggested)
	 * @param rOut the {@code r_out} to mark (rounded as suggested)
	 * @return the plot (renders headless)
	 */
	public static Plot plot(final ProfileAnalysis.Result r, final String title, final double threshold,
		final double rOut)
	{
		double lo = r.background() - r.noise(), hi = Math.max(threshold, r.background() + r.noise());
		for (final double m : r.level())
			if (Double.isFinite(m)) {
				lo = Math.min(lo, m);
				hi = Math.max(hi, m);
			}
		final double pad = 0.05 * (hi - lo);
		lo -= pad;
		// headroom above every curve and level for the legend (top right): it covered the profile
		hi += pad + LEGEND_ROOM * (hi - lo);
		final double right = r.maxRadius();
		final Plot p = new Plot(title, "distance from centre (px)", "grey level");
		p.setLimits(0, right, lo, hi);
		p.setLineWidth(2);
		p.setColor(Color.BLACK);
		p.add("line", r.radius(), r.level());
		p.setLineWidth(1);
		p.add("line", new double[] { 0, right }, new double[] { r.background(), r.background() });
		p.setColor(NOISE_BAND);
		p.setLineWidth(2);
		p.add("line", new double[] { 0, right }, new double[] { r.background() + r.noise(), r.background() + r
			.noise() });
		p.setColor(NOISE_BAND_LOW);
		p.add("line", new double[] { 0, right }, new double[] { r.background() - r.noise(), r.background() - r
			.noise() });
		p.setLineWidth(1);
		p.setColor(Color.RED);
		p.add("line", new double[] { 0, right }, new double[] { threshold, threshold });
		p.setColor(Color.BLUE);
		p.add("line", new double[] { rOut, rOut }, new double[] { lo, hi });
		p.setColor(new Color(0, 150, 0));
		p.add("line", new double[] { r.diameter() / 2, r.diameter() / 2 }, new double[] { lo, hi });
		p.setColor(Color.BLACK);
		p.addLegend("radial profile\tbackground\tnoise band (+1 sigma)\tnoise band (-1 sigma)\t" +
			"suggested threshold\tsuggested r_out\tD/2", "top-right");
		return p;
	}

	/** The plot's height above the data kept free for the legend, as a fraction of the data's range. */
	static final double LEGEND_ROOM = 0.75;

	/** Writes the plot as a PNG, atomically. */
	public static void writePng(final Plot plot, final Path file) throws IOException {
		PotentialPlots.writePng(plot, file);
	}

	/** Writes the profile as CSV ({@code r_px,level,above_background,pixels}), atomically. */
	public static void writeCsv(final ProfileAnalysis.Result r, final Path file) throws IOException {
		AtomicFile.write(file, out -> {
			final Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
			w.write("r_px,level,above_background,pixels\n");
			for (int k = 0; k < r.radius().length; k++)
				if (r.count()[k] > 0) w.write(String.format(Locale.ROOT, "%.4f,%.4f,%.4f,%d%n", r.radius()[k], r.level()[k],
					r.level()[k] - r.background(), r.count()[k]));
			w.flush();
		});
	}
}
