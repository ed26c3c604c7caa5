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
	/** The noise of a background clipped at the floor, measured as a censored normal with it; NaN where none. */
	private final double floorNoise;
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
		this(spacing, coefficients, background, samples, Double.NaN);
	}

	/**
	 * As {@link #EmpiricalProfile(double, double[], double, int)}, measured on frames whose background is clipped at
	 * the floor: {@code floorNoise} that background's noise standard deviation (grey levels), measured with it as a
	 * censored normal, NaN where not.
	 */
	EmpiricalProfile(final double spacing, final double[] coefficients, final double background, final int samples,
		final double floorNoise)
	{
		this.spacing = spacing;
		this.coefficients = coefficients.clone();
		this.background = background;
		this.floorNoise = floorNoise;
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
		return interpolated(tableValue, r);
	}

	/** P'(r) from the table (linear interpolation); 0 beyond the radius. */
	public double slope(final double r) {
		return interpolated(tableDerivative, r);
	}

	/** A table at {@link #TABLE_STEP} read at {@code r} (linear interpolation); 0 beyond its end. */
	private static double interpolated(final double[] table, final double r) {
		final double u = r / TABLE_STEP;
		final int i = (int) u;
		if (i >= table.length - 1) return 0;
		final double f = u - i;
		return table[i] + f * (table[i + 1] - table[i]);
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

	/**
	 * @return the noise standard deviation of the frames' background where it is clipped at the floor, measured with
	 *         the profile as a censored normal (which the fit links the floor with: {@code Censoring#withFloorNoise});
	 *         NaN where the background is not clipped, or its spread is no noise
	 */
	public double floorNoise() {
		return floorNoise;
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
		return informationOutside(x, y, scale, width, height, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
	}

	/**
	 * @return whether the frame cuts off at least {@code share} of the information on the centre ({@link
	 *         #informationOutside} {@code >= share}): settled by {@link #edgeShares}' bounds where they lie clear of
	 *         {@code share}, else by the sum over the pixels (a centre near a corner, or one cut by about {@code share})
	 */
	public boolean cutOff(final double x, final double y, final double scale, final int width, final int height,
		final double share)
	{
		return !(informationOutside(x, y, scale, width, height, share - EDGE_MARGIN, share + EDGE_MARGIN) < share);
	}

	/**
	 * How far (as a share) {@link #edgeShares}' bounds, from integrals, must lie from a share for {@link #cutOff} to
	 * take them: on the profiles whose check passes ({@link #boundsServe}) the sums over the pixels differ from the
	 * integrals by under a hundredth (EmpiricalProfileTest), so twice that.
	 */
	static final double EDGE_MARGIN = 0.02;

	/**
	 * @return whether {@link #cutOff} takes the bounds at this scale: a profile smooth on the scale of a pixel, whose
	 *         sums the check of {@link #edgeShares} found within a quarter of {@link #EDGE_MARGIN} of the integrals
	 */
	boolean boundsServe(final double scale) {
		return scale >= EDGE_SCALE && edgeShares()[0] <= EDGE_MARGIN / 4;
	}

	/**
	 * The least scale at which {@link #cutOff} takes the bounds: a smaller one draws the profile's slope on fewer
	 * pixels than the check of {@link #edgeShares} (at scale 1) saw.
	 */
	private static final double EDGE_SCALE = 0.9;

	/**
	 * {@link #informationOutside}, or, where the bounds from the integrals ({@link #edgeShares}) lie below {@code
	 * below} or above {@code above}, that bound: whatever the sum would give beyond them, their side is known.
	 */
	private double informationOutside(final double x, final double y, final double scale, final int width,
		final int height, final double below, final double above)
	{
		final double reach = radius * scale;
		if (x - reach >= -0.5 && y - reach >= -0.5 && x + reach <= width - 0.5 && y + reach <= height - 0.5) return 0;
		if ((below > Double.NEGATIVE_INFINITY || above < Double.POSITIVE_INFINITY) && boundsServe(scale)) {
			final double[] bounds = edgeBounds(x, y, scale, width, height);
			final double least = bounds[0], most = bounds[1];
			if (most < below) return most;
			if (least > above) return least;
		}
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

	/**
	 * @return bounds on {@link #informationOutside} from the integrals ({@link #edgeShares}): each edge's cut as a
	 *         share of the information on x and on y, beyond a line at distance h (negative: the centre outside), is
	 *         a half-plane's; the frame's outside is their union, so its share lies between the largest of them and
	 *         their sum (the integrals stand for the sums over the pixels to within {@link #EDGE_MARGIN})
	 */
	double[] edgeBounds(final double x, final double y, final double scale, final int width, final int height) {
		return edgeBounds(edgeShares(), x, y, scale, width, height);
	}

	private static double[] edgeBounds(final double[] t, final double x, final double y, final double scale,
		final int width, final int height)
	{
		final double left = (x + 0.5) / scale, right = (width - 0.5 - x) / scale;
		final double top = (y + 0.5) / scale, bottom = (height - 0.5 - y) / scale;
		final double xl = edgeShare(t, 0, left), xr = edgeShare(t, 0, right), xt = edgeShare(t, 1, top), xb =
			edgeShare(t, 1, bottom);
		final double yl = edgeShare(t, 1, left), yr = edgeShare(t, 1, right), yt = edgeShare(t, 0, top), yb =
			edgeShare(t, 0, bottom);
		final double least = Math.max(Math.max(Math.max(xl, xr), Math.max(xt, xb)), Math.max(Math.max(yl, yr), Math
			.max(yt, yb)));
		return new double[] { least, Math.min(1, Math.max(xl + xr + xt + xb, yl + yr + yt + yb)) };
	}

	/**
	 * Step (px at scale 1) of the columns {@link #edgeShares} integrates over: half a pixel, finer than the pixels whose
	 * sums the integrals stand for (the check of {@link #edgeShares} says where they do not).
	 */
	private static final double EDGE_STEP = 0.5;

	/** {@link #edgeShares}, made on first use (a profile whose particles never near the edge needs none). */
	private transient volatile double[] edgeShares;

	/**
	 * The share of the information on a centre's x and on its y beyond a line px from it (at scale 1) that runs along
	 * y: the integrals of {@code P'(r)^2 (x / r)^2} and {@code P'(r)^2 (y / r)^2} over the half-plane beyond it over
	 * those over the plane, by columns {@link #EDGE_STEP} wide, cumulative ({@link #edgeShare} reads them). A line
	 * along x swaps the two. First, at index 0, how far the sums over the pixels lie from these integrals where a
	 * frame's edge cuts about {@link #EDGE_PROBE} of the information on x: the largest difference over four centres a
	 * quarter pixel apart. A profile sharp on the scale of a pixel differs more: its bounds are not taken.
	 */
	private double[] edgeShares() {
		double[] t = edgeShares;
		if (t != null) return t;
		final int half = (int) Math.ceil(radius / EDGE_STEP), n = 2 * half + 1;
		final double[] colX = new double[n], colY = new double[n];
		// the columns' centres at c = (i - half) EDGE_STEP, the rows' alike; the share beyond h then sums columns.
		// The integrands are even in x and in y: one quadrant is summed, each cell standing for its mirror images
		for (int i = half; i < n; i++) {
			final double cx = (i - half) * EDGE_STEP;
			for (int j = half; j < n; j++) {
				final double cy = (j - half) * EDGE_STEP, r2 = cx * cx + cy * cy;
				if (!(r2 < radius * radius) || r2 == 0) continue;
				final double slope = interpolated(tableDerivative, Math.sqrt(r2)), g = (j > half ? 2 : 1) * slope * slope
					/ r2;
				colX[i] += g * cx * cx;
				colY[i] += g * cy * cy;
			}
			colX[n - 1 - i] = colX[i];
			colY[n - 1 - i] = colY[i];
		}
		t = new double[1 + 2 * (n + 1)];
		// cumulative from the far side beyond the line (x < -h): t[i] is the share of the columns left of column i's
		// left edge, at x = (i - half - 1/2) EDGE_STEP, i = 0..n
		double allX = 0, allY = 0;
		for (int i = 0; i < n; i++) {
			allX += colX[i];
			allY += colY[i];
		}
		double sx = 0, sy = 0;
		for (int i = 0; i <= n; i++) {
			t[1 + i] = allX > 0 ? sx / allX : 0;
			t[1 + n + 1 + i] = allY > 0 ? sy / allY : 0;
			if (i < n) {
				sx += colX[i];
				sy += colY[i];
			}
		}
		t[0] = edgeError(t);
		edgeShares = t;
		return t;
	}

	/** The share of the information on x cut off near which {@link #edgeShares} checks the sums. */
	private static final double EDGE_PROBE = 0.05;

	/** @return the largest difference of the sums over the pixels from the shares {@code t} near {@link #EDGE_PROBE} */
	private double edgeError(final double[] t) {
		// the line's distance where the integral's share on x is the probe's (it falls as the line moves out)
		double lo = -radius, hi = radius;
		for (int i = 0; i < 50; i++) {
			final double mid = 0.5 * (lo + hi);
			if (edgeShare(t, 0, mid) > EDGE_PROBE) lo = mid;
			else hi = mid;
		}
		final int size = (int) Math.ceil(4 * radius) + 4;
		double worst = 0;
		for (int k = 0; k < 4; k++) {
			final double h = lo + 0.25 * k, x = h - 0.5, y = 0.5 * size + 0.25 * k;
			final double exact = informationOutside(x, y, 1, size, size, Double.NEGATIVE_INFINITY,
				Double.POSITIVE_INFINITY);
			final double[] b = edgeBounds(t, x, y, 1, size, size);
			worst = Math.max(worst, Math.max(b[0] - exact, exact - b[1]));
		}
		return worst;
	}

	/**
	 * @param which 0: the information on the coordinate across the line, 1: along it
	 * @param h the line's distance from the centre (px at scale 1; negative: the centre beyond it)
	 * @return the share of that information beyond the line ({@link #edgeShares}), linearly interpolated
	 */
	private static double edgeShare(final double[] t, final int which, final double h) {
		final int m = (t.length - 1) / 2, n = m - 1, half = (n - 1) / 2;
		// the line at x = -h, at index (-h / EDGE_STEP + half + 1/2) of the cumulative sums
		final double u = -h / EDGE_STEP + half + 0.5;
		if (!(u > 0)) return 0;
		if (u >= n) return 1;
		final int i = (int) u;
		final double f = u - i;
		final int o = 1 + which * m;
		return t[o + i] + f * (t[o + i + 1] - t[o + i]);
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
