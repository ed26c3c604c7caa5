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
package io.github.contacttracker.core.fit;

import io.github.contacttracker.core.profile.EmpiricalProfile;

/**
 * The residuals' variance of a fit on few pixels, corrected for the part of the noise the fit takes up. A fit reports
 * a centre's error from the residuals' variance weighted by where that centre's information lies
 * ({@link NormalEquations}); but the residuals are smaller than the noise by what the fit absorbs, a pixel's
 * residual variance {@code (1 - h)} times its noise's, with {@code h = g^T (J^T J)^-1 g} its leverage ({@code g} its
 * row of J). Over a large particle the leverages are tiny; over a spot of a few pixels, where the centre's
 * information lies on a dozen of them, they are not, and the centre's error was understated. Dividing the weighted
 * sum of squared residuals by {@code sum w (1 - h)} instead of {@code sum w} undoes that (the
 * heteroscedasticity-consistent "HC2" correction), in the errors reported ({@code Estimate#coupledX}): the fit's own
 * stay the scale its iterations and rounds settle by. On the detection study's dim spots (a peak signal to noise of 3
 * to 5) the reported errors grew from 0.85 to 0.92 of the Cramer-Rao bound, the errors over them from 1.64-1.69 to
 * 1.46-1.48 (the rest: the spread itself 1.13 times the bound, and a few spots far off); over large particles the
 * leverages are tiny and nothing changes.
 */
final class Leverage {

	/** The leverages are summed over about this many of a fit's pixels at most (a regular sample: they are smooth). */
	static final int SAMPLED = 64;

	private Leverage() {}

	/**
	 * @param packed the fit's pixels ({@link FitPixels#packed}), {@code count} of them
	 * @param p the fitted parameters (per member x, y, amplitude, scale; then the background plane's three)
	 * @param inv the inverse of the fit's J^T J (the background's rows and columns the identity's where it was held)
	 * @param held whether the background was held (its terms then take up none of the noise)
	 * @param dof the correction for all pixels together that the reported variance already carries
	 *        ({@code count / (count - parameters)})
	 * @return per member, the factors (x, y) by which its reported errors widen, at least 1
	 */
	static double[] factors(final double[] packed, final int count, final double[] p, final int n,
		final EmpiricalProfile[] members, final double[][] inv, final boolean held, final double dof)
	{
		final int per = GroupFit.PER_PARTICLE, np = p.length, b0 = np - GroupFit.BACKGROUND;
		final double[] w = new double[2 * n], wh = new double[2 * n]; // per member: sum w_x, w_y; sum w h
		final double[] g = new double[np], one = new double[per];
		final int[] lit = new int[n];
		final int stride = Math.max(1, count / SAMPLED);
		for (int i = 0, o = 0; i < count; i += stride, o += stride * FitPixels.PACKED) {
			final double x = packed[o], y = packed[o + 1];
			java.util.Arrays.fill(g, 0);
			int m = 0;
			for (int q = 0; q < n; q++) {
				final int b = per * q;
				if (!Coupling.gradient(x, y, p[b], p[b + 1], p[b + 2], p[b + 3], members[q], one)) continue;
				System.arraycopy(one, 0, g, b, per);
				lit[m++] = q;
			}
			if (m == 0) continue;
			if (!held) {
				g[b0] = 1;
				g[b0 + 1] = packed[o + 2];
				g[b0 + 2] = packed[o + 3];
			}
			// the leverage g^T inv g, over the parameters this pixel's row holds
			double h = 0;
			for (int a = 0; a < np; a++) {
				if (g[a] == 0) continue;
				double row = 0;
				for (int c = 0; c < np; c++)
					row += inv[a][c] * g[c];
				h += g[a] * row;
			}
			for (int t = 0; t < m; t++) {
				final int q = lit[t], b = per * q;
				final double wx = g[b] * g[b], wy = g[b + 1] * g[b + 1];
				w[2 * q] += wx;
				w[2 * q + 1] += wy;
				wh[2 * q] += wx * h;
				wh[2 * q + 1] += wy * h;
			}
		}
		final double[] f = new double[2 * n];
		for (int c = 0; c < f.length; c++) {
			final double kept = w[c] - wh[c]; // sum w (1 - h)
			f[c] = w[c] > 0 && kept > 0 ? Math.max(1, Math.sqrt(w[c] / kept / dof)) : 1;
		}
		return f;
	}
}
