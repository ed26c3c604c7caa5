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
package io.github.contacttracker.core.math;

/** Solves small symmetric positive-definite systems by Cholesky decomposition. */
public final class SymmetricSolver {

	private SymmetricSolver() {}

	/**
	 * Solves {@code A x = b} for symmetric positive-definite {@code A} (only the lower triangle is read).
	 *
	 * @return x, or null if {@code A} is not numerically positive definite
	 */
	public static double[] solve(final double[][] a, final double[] b) {
		final double[][] l = cholesky(a);
		if (l == null) return null;
		final int n = b.length;
		final double[] y = new double[n];
		for (int i = 0; i < n; i++) {
			double s = b[i];
			for (int k = 0; k < i; k++)
				s -= l[i][k] * y[k];
			y[i] = s / l[i][i];
		}
		final double[] x = new double[n];
		for (int i = n - 1; i >= 0; i--) {
			double s = y[i];
			for (int k = i + 1; k < n; k++)
				s -= l[k][i] * x[k];
			x[i] = s / l[i][i];
		}
		return x;
	}

	/** @return the inverse of a symmetric positive-definite matrix, or null if it is not */
	public static double[][] invert(final double[][] a) {
		final int n = a.length;
		final double[][] inv = new double[n][n];
		for (int j = 0; j < n; j++) {
			final double[] e = new double[n];
			e[j] = 1;
			final double[] col = solve(a, e);
			if (col == null) return null;
			for (int i = 0; i < n; i++)
				inv[i][j] = col[i];
		}
		return inv;
	}

	private static double[][] cholesky(final double[][] a) {
		final int n = a.length;
		final double[][] l = new double[n][n];
		for (int i = 0; i < n; i++) {
			for (int j = 0; j <= i; j++) {
				double s = a[i][j];
				for (int k = 0; k < j; k++)
					s -= l[i][k] * l[j][k];
				if (i == j) {
					// Relative pivot test: a pivot that lost all but ~1e-12 of its diagonal is singular.
					if (!(s > 1e-12 * Math.abs(a[i][i])) || !Double.isFinite(s)) return null;
					l[i][i] = Math.sqrt(s);
				}
				else l[i][j] = s / l[j][j];
			}
		}
		return l;
	}
}
