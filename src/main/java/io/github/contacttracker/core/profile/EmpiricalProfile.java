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
package io.github.contacttracker.core.profile;

import java.io.Serializable;

/**
 * A single particle's radial intensity profile measured from the data: a smooth even function of the
 * distance to the centre (a uniform cubic B-spline, mirrored at r = 0 so that P'(0) = 0), going to zero with
 * zero slope at {@code radius}, above a constant background.
 * <p>
 * It is the pixel-integrated profile (values are fitted to pixel values at pixel-centre distances), so models
 * built from it need no further pixel integration.
 */
public final class EmpiricalProfile implements Serializable {

	// serializable: a distributed front end measures it once per movie and ships it to the workers
	private static final long serialVersionUID = 1L;

	private final double spacing;
	private final double[] coefficients;
	private final double background;
	private final double radius;
	private final int samples;
	/** Tables of P and P' at {@link #TABLE_STEP} for fast lookups. */
	private final double[] tableValue;
	private final double[] tableDerivative;
	/** The least and greatest values in {@link #tableValue} (linear interpolation stays between them). */
	private final double least, greatest;

	/** Step of the lookup tables (px): linear interpolation errs by well under 1e-3 grey levels there. */
	public static final double TABLE_STEP = 1.0 / 32;

	/**
	 * @param spacing knot spacing (px)
	 * @param coefficients B-spline coefficients c_0..c_m (c_-j = c_j; c_j = 0 beyond m)
	 * @param background the background grey level
	 * @param samples pixels that went into the estimate
	 */
	EmpiricalProfile(final double spacing, final double[] coefficients, final double background, final int samples) {
		this.spacing = spacing;
		this.coefficients = coefficients.clone();
		this.background = background;
		this.radius = (coefficients.length + 1) * spacing;
		this.samples = samples;
		final int n = (int) Math.ceil(radius / TABLE_STEP) + 2;
		tableValue = new double[n];
		tableDerivative = new double[n];
		double lo = 0, hi = 0;
		for (int i = 0; i < n; i++) {
			tableValue[i] = value(i * TABLE_STEP);
			tableDerivative[i] = derivative(i * TABLE_STEP);
			lo = Math.min(lo, tableValue[i]);
			hi = Math.max(hi, tableValue[i]);
		}
		least = lo;
		greatest = hi;
	}

	/** P(r) from the table (linear interpolation); 0 beyond the radius. */
	public double lookup(final double r) {
		final double u = r / TABLE_STEP;
		final int i = (int) u;
		if (i >= tableValue.length - 1) return 0;
		final double f = u - i;
		return tableValue[i] + f * (tableValue[i + 1] - tableValue[i]);
	}

	/**
	 * @return the least of {@code amplitude P(r)} over all r, as the lookup gives it (at most 0: P is 0 beyond its
	 *         radius): a bound on the light of a particle of that amplitude, for any scale and distance
	 */
	public double leastLight(final double amplitude) {
		return Math.min(0, Math.min(amplitude * least, amplitude * greatest));
	}

	/** @return the greatest of {@code amplitude P(r)} over all r, as the lookup gives it (at least 0) */
	public double greatestLight(final double amplitude) {
		return Math.max(0, Math.max(amplitude * least, amplitude * greatest));
	}

	/** @return the table of P at multiples of {@link #TABLE_STEP} (not a copy: for inner loops, read only) */
	public double[] valueTable() {
		return tableValue;
	}

	/** @return the table of P' at multiples of {@link #TABLE_STEP} (not a copy: for inner loops, read only) */
	public double[] derivativeTable() {
		return tableDerivative;
	}

	/** @return the grey level above background at distance {@code r} (px) */
	public double value(final double r) {
		final double u = Math.abs(r) / spacing;
		final int i = (int) u;
		double s = 0;
		for (int j = i - 1; j <= i + 2; j++)
			s += coefficient(j) * bspline(u - j);
		return s;
	}

	/** @return dP/dr at distance {@code r} (px) */
	public double derivative(final double r) {
		final double u = Math.abs(r) / spacing;
		final int i = (int) u;
		double s = 0;
		for (int j = i - 1; j <= i + 2; j++)
			s += coefficient(j) * bsplineDerivative(u - j);
		return s / spacing;
	}

	/** @return the background grey level */
	public double background() {
		return background;
	}

	/** @return the distance beyond which the profile is zero (px) */
	public double radius() {
		return radius;
	}

	/**
	 * @return the radius of the central area at or above {@code threshold} (the active area of an isolated
	 *         particle), 0 if the centre itself is below it
	 */
	public double activeRadius(final double threshold) {
		final double step = 0.05;
		double r = 0;
		while (r < radius && background + value(r) >= threshold)
			r += step;
		return r;
	}

	/**
	 * @return the radius within which a particle's image holds the fraction {@code fraction} of the information on
	 *         its centre: the Fisher information on x from a ring at r is proportional to {@code P'(r)^2 r} (for
	 *         uniform noise), so this is where the cumulative {@code integral P'^2 r dr} reaches that fraction
	 */
	public double informationRadius(final double fraction) {
		final double[] d = tableDerivative;
		double total = 0;
		for (int i = 0; i < d.length; i++)
			total += d[i] * d[i] * i;
		if (!(total > 0)) return radius;
		double sum = 0;
		for (int i = 0; i < d.length; i++) {
			sum += d[i] * d[i] * i;
			if (sum >= fraction * total) return Math.min(radius, (i + 1) * TABLE_STEP);
		}
		return radius;
	}

	/**
	 * The share of the information on a particle's centre that a frame's edge cuts off: with the particle drawn at
	 * {@code (x, y)} (px, pixel centres at integers) with radial scale {@code scale}, the Fisher information on its
	 * x from the pixels outside the frame's {@code width x height} pixels over that from all pixels within reach (for
	 * uniform noise: the squares of the model's derivative), and the same for y.
	 *
	 * @return the larger of the two shares, in [0, 1]; 0 when the particle's reach lies inside the frame
	 */
	public double informationOutside(final double x, final double y, final double scale, final int width,
		final int height)
	{
		final double reach = radius * scale;
		if (x - reach >= -0.5 && y - reach >= -0.5 && x + reach <= width - 0.5 && y + reach <= height - 0.5) return 0;
		final double perStep = 1 / (TABLE_STEP * scale);
		final double[] d = tableDerivative;
		double allX = 0, allY = 0, outX = 0, outY = 0;
		for (int py = (int) Math.ceil(y - reach); py <= y + reach; py++)
			for (int px = (int) Math.ceil(x - reach); px <= x + reach; px++) {
				final double dx = px - x, dy = py - y, r = Math.sqrt(dx * dx + dy * dy), t = r * perStep;
				final int k = (int) t;
				if (!(r < reach) || k + 1 >= d.length || r == 0) continue;
				final double slope = d[k] + (t - k) * (d[k + 1] - d[k]), g = slope * slope / (r * r);
				final double wx = g * dx * dx, wy = g * dy * dy;
				allX += wx;
				allY += wy;
				if (px < 0 || py < 0 || px >= width || py >= height) {
					outX += wx;
					outY += wy;
				}
			}
		return Math.max(allX > 0 ? outX / allX : 0, allY > 0 ? outY / allY : 0);
	}

	private double coefficient(final int j) {
		final int a = Math.abs(j);
		return a < coefficients.length ? coefficients[a] : 0;
	}

	/** Index of the coefficient for knot j (mirrored), or -1 beyond the last. */
	static int coefficientIndex(final int j, final int count) {
		final int a = Math.abs(j);
		return a < count ? a : -1;
	}

	/** The centred cubic B-spline. */
	static double bspline(final double t) {
		final double a = Math.abs(t);
		if (a < 1) return 2.0 / 3 - a * a + 0.5 * a * a * a;
		if (a < 2) {
			final double b = 2 - a;
			return b * b * b / 6;
		}
		return 0;
	}

	static double bsplineDerivative(final double t) {
		final double a = Math.abs(t);
		final double sign = t < 0 ? -1 : 1;
		if (a < 1) return sign * (-2 * a + 1.5 * a * a);
		if (a < 2) {
			final double b = 2 - a;
			return -sign * 0.5 * b * b;
		}
		return 0;
	}
}
