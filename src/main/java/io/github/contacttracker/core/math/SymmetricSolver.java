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

/**
 * Solves small symmetric positive-definite systems by Cholesky decomposition. Besides the allocating
 * {@link #solve(double[][], double[])} and {@link #invert}, a factor-then-solve pair on a caller's flat work arrays
 * ({@link #factor}, {@link #solveFactored}) serves an iteration that solves one such system per step (a
 * Levenberg-Marquardt fit) without allocating: the same arithmetic in the same order, so the same results to the last
 * bit. {@link #explained} gives the sum of squares a least squares explains, leaving out columns that add nothing.
 */
public final class SymmetricSolver {

	private SymmetricSolver() {}

	/**
	 * Solves {@code A x = b} for symmetric positive-definite {@code A} (only the lower triangle is read).
	 *
	 * @return x, or null if {@code A} is not numerically positive definite
	 */
	public static double[] solve(final double[][] a, final double[] b) {
		final int n = b.length;
		final double[] l = new double[n * n];
		if (!factor(a, 0, n, l)) return null;
		final double[] x = new double[n];
		solveFactored(l, n, b, new double[n], x);
		return x;
	}

	/** @return the inverse of a symmetric positive-definite matrix, or null if it is not */
	public static double[][] invert(final double[][] a) {
		final int n = a.length;
		final double[] l = new double[n * n];
		if (!factor(a, 0, n, l)) return null;
		final double[][] inv = new double[n][n];
		final double[] e = new double[n], y = new double[n], col = new double[n];
		for (int j = 0; j < n; j++) {
			e[j] = 1;
			solveFactored(l, n, e, y, col);
			e[j] = 0;
			for (int i = 0; i < n; i++)
				inv[i][j] = col[i];
		}
		return inv;
	}

	/**
	 * The Cholesky factor of {@code A + damping diag(A)} (the lower triangle of {@code a}, {@code n x n}) into the
	 * flat lower triangle {@code l} (row-major, {@code n} per row, at least {@code n * n} long).
	 *
	 * @return false if the matrix is not numerically positive definite ({@code l} then holds nothing of use)
	 */
	public static boolean factor(final double[][] a, final double damping, final int n, final double[] l) {
		for (int i = 0; i < n; i++) {
			final double[] ai = a[i];
			final int ri = i * n;
			for (int j = 0; j < i; j++) {
				final int rj = j * n;
				double s = ai[j];
				for (int k = 0; k < j; k++)
					s -= l[ri + k] * l[rj + k];
				l[ri + j] = s / l[rj + j];
			}
			final double d = damping == 0 ? ai[i] : ai[i] + damping * ai[i];
			double s = d;
			for (int k = 0; k < i; k++)
				s -= l[ri + k] * l[ri + k];
			// Relative pivot test: a pivot that lost all but ~1e-12 of its diagonal is singular.
			if (!(s > 1e-12 * Math.abs(d)) || !Double.isFinite(s)) return false;
			l[ri + i] = Math.sqrt(s);
		}
		return true;
	}

	/**
	 * Solves {@code L L^T x = b} for the factor {@code l} of {@link #factor}; {@code y} ({@code n} long) is work space.
	 */
	public static void solveFactored(final double[] l, final int n, final double[] b, final double[] y,
		final double[] x)
	{
		for (int i = 0; i < n; i++) {
			final int ri = i * n;
			double s = b[i];
			for (int k = 0; k < i; k++)
				s -= l[ri + k] * y[k];
			y[i] = s / l[ri + i];
		}
		for (int i = n - 1; i >= 0; i--) {
			double s = y[i];
			for (int k = i + 1; k < n; k++)
				s -= l[k * n + i] * x[k];
			x[i] = s / l[i * n + i];
		}
	}

	/**
	 * @return {@code b . A^-1 b} over the columns of {@code A} (a Gram matrix {@code F^T F}, order {@code np}, with
	 *         {@code b = F^T y}) that are independent of those before them: the sum of squares a least-squares fit of
	 *         {@code y} explains. A column that adds nothing (all 0s, or a combination of earlier ones) is left out,
	 *         where {@link #solve} would find the system singular.
	 */
	public static double explained(final double[][] a, final double[] b, final int np) {
		// Cholesky factor, column by column; a pivot that is (to rounding) 0 marks a column that depends on the earlier ones
		final double[][] l = new double[np][np];
		final double[] z = new double[np];
		double explained = 0;
		for (int i = 0; i < np; i++) {
			double pivot = a[i][i];
			for (int k = 0; k < i; k++)
				pivot -= l[i][k] * l[i][k];
			if (!(pivot > DEPENDENT * a[i][i])) continue; // (its column of l stays 0: left out)
			final double root = Math.sqrt(pivot);
			l[i][i] = root;
			for (int j = i + 1; j < np; j++) {
				double v = a[j][i];
				for (int k = 0; k < i; k++)
					v -= l[j][k] * l[i][k];
				l[j][i] = v / root;
			}
			double zi = b[i];
			for (int k = 0; k < i; k++)
				zi -= l[i][k] * z[k];
			z[i] = zi / root;
			explained += z[i] * z[i];
		}
		return explained;
	}

	/** A column whose Cholesky pivot is below this share of its diagonal depends on the earlier columns. */
	private static final double DEPENDENT = 1e-9;
}
