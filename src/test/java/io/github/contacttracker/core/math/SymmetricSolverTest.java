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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SymmetricSolverTest {

	@Test
	void solvesAndInverts() {
		final double[][] a = { { 4, 1, 0.5 }, { 1, 3, 0.2 }, { 0.5, 0.2, 2 } };
		final double[] x = { 1, -2, 3 };
		final double[] b = new double[3];
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++)
				b[i] += a[i][j] * x[j];
		assertArrayEquals(x, SymmetricSolver.solve(a, b), 1e-12);
		final double[][] inv = SymmetricSolver.invert(a);
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++) {
				double s = 0;
				for (int k = 0; k < 3; k++)
					s += a[i][k] * inv[k][j];
				assertEquals(i == j ? 1 : 0, s, 1e-12);
			}
	}

	/**
	 * The factor of {@code A + damping diag(A)} on flat work arrays solves the damped system (as the allocating solve
	 * of that matrix does, to the last bit), with work arrays longer than needed and reused.
	 */
	@Test
	void dampedFactorOnWorkArraysSolvesTheDampedSystem() {
		final double[][] a = { { 4, 1, 0.5, 0 }, { 1, 3, 0.2, 0.1 }, { 0.5, 0.2, 2, -0.3 }, { 0, 0.1, -0.3, 1.5 } };
		final double damping = 0.25;
		final double[][] damped = new double[4][];
		for (int i = 0; i < 4; i++) {
			damped[i] = a[i].clone();
			damped[i][i] += damping * a[i][i];
		}
		final double[] x = { 1, -2, 3, 0.5 }, b = new double[4];
		for (int i = 0; i < 4; i++)
			for (int j = 0; j < 4; j++)
				b[i] += damped[i][j] * x[j];
		final double[] l = new double[16], y = new double[4], out = new double[4];
		for (int round = 0; round < 2; round++) {
			assertTrue(SymmetricSolver.factor(a, damping, 4, l));
			SymmetricSolver.solveFactored(l, 4, b, y, out);
			assertArrayEquals(x, out, 1e-12);
			assertArrayEquals(SymmetricSolver.solve(damped, b), out, 0);
		}
		assertFalse(SymmetricSolver.factor(new double[][] { { 1, 2 }, { 2, 4 } }, 0, 2, l));
	}

	@Test
	void singularMatrixIsReported() {
		assertNull(SymmetricSolver.solve(new double[][] { { 1, 2 }, { 2, 4 } }, new double[] { 1, 2 }));
	}

	/**
	 * The sum of squares a least-squares fit explains is that of the columns that add something: a column of 0s and a
	 * column equal to another's leave it as it is, where a plain solve finds the system singular; it equals that of
	 * the independent columns by the normal equations (2 x 2, solved by hand).
	 */
	@Test
	void aColumnThatAddsNothingLeavesTheExplainedSumAsItIs() {
		final java.util.Random random = new java.util.Random(3);
		final int pixels = 50;
		final double[][] f = new double[pixels][4];
		final double[] y = new double[pixels];
		for (int i = 0; i < pixels; i++) {
			f[i][0] = 1;
			f[i][1] = random.nextGaussian();
			f[i][2] = 0; // a column of 0s
			f[i][3] = f[i][1]; // a column equal to another
			y[i] = 2 + 3 * f[i][1] + random.nextGaussian();
		}
		final double two = explained(f, y, new int[] { 0, 1 });
		assertEquals(two, explained(f, y, new int[] { 0, 1, 2 }), 1e-9 * two, "with a column of 0s");
		assertEquals(two, explained(f, y, new int[] { 0, 1, 3 }), 1e-9 * two, "with a column equal to another");
		// the explained sum of two columns, by the normal equations solved by hand (2 x 2)
		double n = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
		for (int i = 0; i < pixels; i++) {
			n++;
			sx += f[i][1];
			sxx += f[i][1] * f[i][1];
			sy += y[i];
			sxy += f[i][1] * y[i];
		}
		final double det = n * sxx - sx * sx;
		final double p0 = (sxx * sy - sx * sxy) / det, p1 = (n * sxy - sx * sy) / det;
		assertEquals(p0 * sy + p1 * sxy, two, 1e-9 * two, "two independent columns");
	}

	/** @return {@link SymmetricSolver#explained} of columns {@code use} of {@code f} against {@code y} */
	private static double explained(final double[][] f, final double[] y, final int[] use) {
		final int np = use.length;
		final double[][] a = new double[np][np];
		final double[] b = new double[np];
		for (int i = 0; i < f.length; i++)
			for (int r = 0; r < np; r++) {
				b[r] += f[i][use[r]] * y[i];
				for (int c = 0; c < np; c++)
					a[r][c] += f[i][use[r]] * f[i][use[c]];
			}
		return SymmetricSolver.explained(a, b, np);
	}
}
