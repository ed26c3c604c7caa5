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
package io.github.contacttracker.core.image;

import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.math.SymmetricSolver;

/**
 * A frame's pixels relative to its illumination: a smooth surface (a quadratic in x and y: a ramp, the falling
 * edge of a tweezer's or a lamp's light, vignetting) fitted to a regular sample of its pixels by least squares,
 * robustly: refitted {@value #ROUNDS} times without the pixels more than {@value #OUTLIER} robust standard deviations
 * from the last fit, so that particles covering a minority of the frame do not pull it. Where the light falls
 * across the frame, the median and the extremes of the raw pixels are the light's, not the particles': on a
 * simulated pair of dark-cored particles on a 16-bit ramp of 1,800 grey levels the darkest pixel was the ramp's dark
 * corner, and the particles' contrast could not be read from the levels.
 */
public final class Illumination {

	private Illumination() {}

	/** The sample holds about this many pixels. */
	static final int SAMPLES = 1_000_000;
	/** Robust refits. */
	static final int ROUNDS = 3;
	/** Pixels this many robust standard deviations from the fit are left out of the next one. */
	static final double OUTLIER = 3;
	/** The surface's terms: 1, u, v, u^2, u v, v^2 (u, v the position from the frame's centre, in half sides). */
	private static final int TERMS = 6;

	/**
	 * @param plane a frame
	 * @return its pixels on a regular grid (at most about {@value #SAMPLES}), each minus the fitted illumination at it; the
	 *         raw pixels where the frame is too small to fit a surface (fewer than 3 pixels a side)
	 */
	public static double[] residuals(final Plane plane) {
		final int w = plane.width(), h = plane.height();
		final int stride = (int) Math.max(1, Math.ceil(Math.sqrt((double) w * h / SAMPLES)));
		final int nx = (w + stride - 1) / stride, ny = (h + stride - 1) / stride;
		final double[] v = new double[nx * ny], u = new double[v.length], t = new double[v.length];
		int n = 0;
		for (int y = 0; y < h; y += stride)
			for (int x = 0; x < w; x += stride) {
				v[n] = plane.get(x, y);
				u[n] = (x - 0.5 * (w - 1)) / Math.max(1, 0.5 * (w - 1));
				t[n++] = (y - 0.5 * (h - 1)) / Math.max(1, 0.5 * (h - 1));
			}
		if (w < 3 || h < 3) return v;
		final double[] r = new double[n], abs = new double[n];
		double[] c = null;
		double cut = Double.POSITIVE_INFINITY;
		for (int round = 0; round <= ROUNDS; round++) {
			final double[] next = fit(v, u, t, n, r, cut);
			if (next == null) break;
			c = next;
			for (int i = 0; i < n; i++) {
				r[i] = v[i] - surface(c, u[i], t[i]);
				abs[i] = Math.abs(r[i]);
			}
			cut = OUTLIER * Statistics.MAD_TO_SIGMA * Statistics.median(abs, n); // (abs is rewritten each round)
			if (!(cut > 0)) break;
		}
		if (c == null) return v;
		return r;
	}

	/**
	 * @return the least-squares surface through the pixels whose last residual {@code r} is within {@code cut} (all
	 *         on the first fit, when {@code cut} is infinite), or null where too few remain or they do not determine it
	 */
	private static double[] fit(final double[] v, final double[] u, final double[] t, final int n, final double[] r,
		final double cut)
	{
		final double[][] a = new double[TERMS][TERMS];
		final double[] b = new double[TERMS], f = new double[TERMS];
		int used = 0;
		for (int i = 0; i < n; i++) {
			if (!(Math.abs(r[i]) <= cut)) continue;
			terms(u[i], t[i], f);
			for (int j = 0; j < TERMS; j++) {
				b[j] += f[j] * v[i];
				for (int k = 0; k <= j; k++)
					a[j][k] += f[j] * f[k];
			}
			used++;
		}
		return used < 4 * TERMS ? null : SymmetricSolver.solve(a, b);
	}

	private static void terms(final double u, final double t, final double[] f) {
		f[0] = 1;
		f[1] = u;
		f[2] = t;
		f[3] = u * u;
		f[4] = u * t;
		f[5] = t * t;
	}

	private static double surface(final double[] c, final double u, final double t) {
		return c[0] + c[1] * u + c[2] * t + c[3] * u * u + c[4] * u * t + c[5] * t * t;
	}
}
