package io.github.contacttracker.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

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

	@Test
	void singularMatrixIsReported() {
		assertNull(SymmetricSolver.solve(new double[][] { { 1, 2 }, { 2, 4 } }, new double[] { 1, 2 }));
	}
}
