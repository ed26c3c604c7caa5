package io.github.contacttracker.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** The least-squares passes of {@link GroupFit} ({@link NormalEquations}): the fast path for a group of one against the general one. */
class NormalEquationsTest {

	/** A ringed profile (bright core, dark ring) reaching 30 px, and a noisy particle on a plane with others' light. */
	private static FitPixels pixels(final EmpiricalProfile profile, final double cx, final double cy) {
		final Random random = new Random(11);
		final int w = 70, h = 64, n = w * h;
		final int[] xs = new int[n], ys = new int[n];
		final double[] values = new double[n], fixed = new double[n];
		for (int y = 0, i = 0; y < h; y++)
			for (int x = 0; x < w; x++, i++) {
				xs[i] = x;
				ys[i] = y;
				fixed[i] = 0.01 * x;
				values[i] = 40 + 0.05 * x + fixed[i] + 1.1 * profile.value(Math.hypot(x - cx, y - cy) / 0.97) + 3 *
					random.nextGaussian();
			}
		return new FitPixels(xs, ys, values, fixed, n, 0.5 * (w - 1), 0.5 * (h - 1), 0.5 * (w - 1));
	}

	private static EmpiricalProfile ringed() {
		final double[] c = new double[29];
		for (int j = 0; j < c.length; j++)
			c[j] = 120 * Math.exp(-j * j / 60.0) - 25 * Math.exp(-(j - 14) * (j - 14) / 8.0);
		return new EmpiricalProfile(1, c, 40, 1000);
	}

	/** Same J^T J, J^T r, residuals, noise weights and model values, bit for bit, with and without J^T J. */
	@Test
	void singleMemberFastPathIsIdentical() {
		final EmpiricalProfile profile = ringed();
		final FitPixels px = pixels(profile, 34.3, 31.8);
		final double[] p = { 34.1, 32.0, 1.05, 0.98, 39, 0.4, -0.2 };
		for (final boolean hessian : new boolean[] { true, false }) {
			final double[][] jg = hessian ? new double[7][7] : null, js = hessian ? new double[7][7] : null;
			final double[] rg = new double[7], rs = new double[7], ng = new double[4], ns = new double[4];
			final double[] mg = new double[px.count()], ms = new double[px.count()];
			final double rssGroup = NormalEquations.accumulateGroup(px, p, 1, profile, jg, rg, ng, mg);
			final double rssSingle = NormalEquations.accumulateSingle(px, p, profile, js, rs, ns, ms);
			assertEquals(rssGroup, rssSingle, 0);
			assertArrayEquals(rg, rs, 0);
			assertArrayEquals(ng, ns, 0);
			assertArrayEquals(mg, ms, 0);
			if (hessian) for (int r = 0; r < 7; r++)
				assertArrayEquals(jg[r], js[r], 0, "row " + r);
		}
	}
}
