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
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;

import javax.imageio.ImageIO;

import ij.gui.Plot;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.potential.PairCorrelation;

/**
 * Plots of g(r) and U(r) with ImageJ's {@link Plot}: the same picture in a Fiji window and, rendered headless,
 * in the command line's PNG files. Empty bins (no pair: U unbounded) are left out of the plot.
 */
public final class PotentialPlots {

	/** Plot size (px) of the frame inside the axes. */
	public static final int WIDTH = 720, HEIGHT = 440;

	private static final Color G_COLOUR = new Color(0, 90, 200), U_COLOUR = new Color(200, 30, 30);

	/**
	 * One measured U(r) curve for {@link #comparison}.
	 *
	 * @param label legend text
	 * @param result the measurement (its U includes its zero shift)
	 * @param colour colour of points and error bars
	 * @param shape an ImageJ plot shape ("circle", "box", "triangle", "x", ...)
	 */
	public record Series(String label, PairCorrelation.Result result, Color colour, String shape) {}

	private PotentialPlots() {}

	/**
	 * g(r) and U(r)/kT on one plot, both dimensionless, with their error bars and the reference lines g = 1 and
	 * U = 0.
	 *
	 * @param r the result
	 * @param title plot title
	 * @param unit the distances' unit (for the axis label)
	 * @return the plot (not shown)
	 */
	public static Plot potential(final PairCorrelation.Result r, final String title, final String unit) {
		final Plot p = new Plot(title, "r (" + unit + ")", "g(r)  and  U(r) / kT");
		p.setSize(WIDTH, HEIGHT);
		final double[][] g = points(r, true), u = points(r, false);
		final double right = r.bins().get(r.bins().size() - 1).rHigh();
		final double[] range = range(new double[][] { g[1], u[1] }, new double[][] { g[2], u[2] });
		p.setLimits(0, right, Math.min(range[0], -0.5), Math.max(range[1], 1.5));
		p.setColor(Color.GRAY);
		p.add("line", new double[] { 0, right }, new double[] { 1, 1 });
		p.add("line", new double[] { 0, right }, new double[] { 0, 0 });
		p.setColor(G_COLOUR);
		p.addPoints(g[0], g[1], g[2], Plot.CIRCLE);
		p.setColor(U_COLOUR);
		p.addPoints(u[0], u[1], u[2], Plot.BOX);
		p.setColor(Color.BLACK);
		p.addLegend("g = 1\tU = 0\tg(r)\tU(r) / kT", "top-right");
		return p;
	}

	/**
	 * Several measured U(r) on one plot, with the true U(r) as a line (infinite values drawn at the top edge).
	 *
	 * @param series the measurements
	 * @param truth the true U(r)/kT as a function of r, or null
	 * @param truthLabel legend text of the truth
	 * @param title plot title
	 * @param unit the distances' unit
	 * @param from left end of the r axis
	 * @param to right end of the r axis
	 * @return the plot
	 */
	public static Plot comparison(final List<Series> series, final DoubleUnaryOperator truth, final String truthLabel,
		final String title, final String unit, final double from, final double to)
	{
		final Plot p = new Plot(title, "r (" + unit + ")", "U(r) / kT");
		p.setSize(WIDTH, HEIGHT);
		final List<double[]> ys = new ArrayList<>(), es = new ArrayList<>();
		final List<double[][]> pts = new ArrayList<>();
		for (final Series s : series) {
			final double[][] u = points(s.result(), false, from, to);
			pts.add(u);
			ys.add(u[1]);
			es.add(u[2]);
		}
		final double[] range = range(ys.toArray(new double[0][]), es.toArray(new double[0][]));
		final double lo = Math.min(range[0], -0.5) - 0.2, hi = Math.max(range[1], 0.5) + 0.5;
		p.setLimits(from, to, lo, hi);
		final StringBuilder legend = new StringBuilder();
		p.setColor(Color.GRAY);
		p.add("line", new double[] { from, to }, new double[] { 0, 0 });
		legend.append("U = 0");
		if (truth != null) {
			final int n = 800;
			final double[] x = new double[n + 1], y = new double[n + 1];
			for (int i = 0; i <= n; i++) {
				x[i] = from + (to - from) * i / n;
				y[i] = Math.min(truth.applyAsDouble(x[i]), hi); // the hard core drawn as a wall at the top
			}
			p.setColor(Color.BLACK);
			p.setLineWidth(2);
			p.add("line", x, y);
			p.setLineWidth(1);
			legend.append('\t').append(truthLabel);
		}
		for (int k = 0; k < series.size(); k++) {
			p.setColor(series.get(k).colour());
			final double[][] u = pts.get(k);
			p.add(series.get(k).shape(), u[0], u[1]);
			p.addErrorBars(u[2]);
			legend.append('\t').append(series.get(k).label());
		}
		p.setColor(Color.BLACK);
		p.addLegend(legend.toString(), "bottom-right");
		return p;
	}

	/**
	 * Renders a plot headless and writes it as PNG, atomically.
	 *
	 * @param plot the plot
	 * @param file the PNG file
	 * @throws IOException when writing fails (nothing is left behind)
	 */
	public static void writePng(final Plot plot, final Path file) throws IOException {
		final BufferedImage image = plot.getImagePlus().getBufferedImage();
		AtomicFile.write(file, out -> {
			if (!ImageIO.write(image, "png", out)) throw new IOException("no PNG writer");
		});
	}

	private static double[][] points(final PairCorrelation.Result r, final boolean g) {
		return points(r, g, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
	}

	/** @return {x, y, error} of the non-empty bins with centres in [from, to] */
	private static double[][] points(final PairCorrelation.Result r, final boolean g, final double from,
		final double to)
	{
		final List<double[]> rows = new ArrayList<>();
		for (int i = 0; i < r.bins().size(); i++) {
			final PairCorrelation.Bin b = r.bins().get(i);
			if (b.pairs() == 0 || b.r() < from || b.r() > to) continue;
			rows.add(g ? new double[] { b.r(), b.g(), b.gError() } : new double[] { b.r(), r.u(i), b.uError() });
		}
		final double[][] out = new double[3][rows.size()];
		for (int k = 0; k < rows.size(); k++)
			for (int c = 0; c < 3; c++)
				out[c][k] = rows.get(k)[c];
		return out;
	}

	/** @return {min, max} of {@code y - e} and {@code y + e} over all arrays, clipped to [-8, 12] */
	private static double[] range(final double[][] ys, final double[][] es) {
		double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
		for (int k = 0; k < ys.length; k++)
			for (int i = 0; i < ys[k].length; i++) {
				lo = Math.min(lo, ys[k][i] - es[k][i]);
				hi = Math.max(hi, ys[k][i] + es[k][i]);
			}
		if (lo > hi) return new double[] { 0, 1 };
		return new double[] { Math.max(lo, -8), Math.min(hi, 12) };
	}
}
