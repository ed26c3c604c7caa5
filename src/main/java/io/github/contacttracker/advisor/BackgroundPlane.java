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
package io.github.contacttracker.advisor;

import java.util.Arrays;

import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.math.SymmetricSolver;

/**
 * A particle's local background: the plane {@code a + b x + c y} (coordinates relative to the particle's centre)
 * through the pixels of its background annulus, robust to a neighbour's light in part of it. A background that
 * drifts across the frame is removed with it.
 */
final class BackgroundPlane {

	/** Fewest pixels accepted in the background annulus. */
	static final int MIN_BACKGROUND_PIXELS = 20;

	private BackgroundPlane() {}

	/**
	 * The plane {@code a + b x + c y} through the points by least squares, refitted once without the points more
	 * than 3 robust sigmas off (a neighbour's light in part of the annulus).
	 */
	static double[] robust(final DoubleList x, final DoubleList y, final DoubleList v) {
		final boolean[] use = new boolean[x.size];
		Arrays.fill(use, true);
		double[] p = fitPlane(x, y, v, use);
		final double[] dev = new double[x.size];
		for (int i = 0; i < dev.length; i++)
			dev[i] = Math.abs(v.get(i) - p[0] - p[1] * x.get(i) - p[2] * y.get(i));
		final double cut = 3 * Statistics.MAD_TO_SIGMA * Statistics.quantile(dev.clone(), 0.5);
		int kept = 0;
		for (int i = 0; i < dev.length; i++)
			if (use[i] = dev[i] <= cut) kept++;
		if (kept >= MIN_BACKGROUND_PIXELS) p = fitPlane(x, y, v, use);
		return p;
	}

	/**
	 * The least-squares plane through the points in use, its 3x3 normal equations solved by Cholesky; their mean where
	 * they lie on a line (an annulus cut to a sliver by the border), or there are none.
	 */
	private static double[] fitPlane(final DoubleList x, final DoubleList y, final DoubleList v, final boolean[] use) {
		double n = 0, sx = 0, sy = 0, sv = 0, sxx = 0, sxy = 0, syy = 0, sxv = 0, syv = 0;
		for (int i = 0; i < x.size; i++) {
			if (!use[i]) continue;
			final double a = x.get(i), b = y.get(i), c = v.get(i);
			n++;
			sx += a;
			sy += b;
			sv += c;
			sxx += a * a;
			sxy += a * b;
			syy += b * b;
			sxv += a * c;
			syv += b * c;
		}
		final double[] p = SymmetricSolver.solve(new double[][] { { n, sx, sy }, { sx, sxx, sxy }, { sy, sxy, syy } },
			new double[] { sv, sxv, syv });
		return p != null ? p : new double[] { sv / Math.max(n, 1), 0, 0 };
	}
}
