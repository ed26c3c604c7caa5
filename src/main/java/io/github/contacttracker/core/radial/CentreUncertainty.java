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
package io.github.contacttracker.core.radial;

/**
 * First-order error propagation from pixel noise to a radial-symmetry centre.
 * <p>
 * The centre solves {@code sum_i A_i (p_i - c) = 0} with {@code A_i = w_i n_i n_i^T}, {@code w_i = |g_i|}. A
 * change of the gradients moves it by {@code dc = M^-1 sum_i dA_i (p_i - c)}; each gradient is a fixed linear
 * combination of 12 pixels (the 5x3 operators), so every pixel's influence {@code dc/dI_p} follows, including
 * the correlations the overlapping operators create between neighbouring gradients. With independent pixel
 * noise of standard deviation {@code s}: {@code cov(c) = s^2 M^-1 (sum_p V_p V_p^T) M^-1}, {@code V_p =
 * sum_i dA_i r_i / dI_p}. Changes of the thresholded mask itself are neglected.
 */
public final class CentreUncertainty {

	private CentreUncertainty() {}

	/**
	 * @param f the gradient field
	 * @param used which pixels of {@code f} took part in the solve ({@code null}: all)
	 * @param cx solved centre x
	 * @param cy solved centre y
	 * @param m the solve's normal matrix {mxx, mxy, myy}
	 * @return {var x, var y, cov xy} per unit pixel-noise variance
	 */
	public static double[] covariancePerUnitNoise(final GradientField f, final boolean[] used, final double cx,
		final double cy, final double[] m)
	{
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (int i = 0; i < f.size; i++) {
			if (used != null && !used[i]) continue;
			x0 = Math.min(x0, f.x[i]);
			x1 = Math.max(x1, f.x[i]);
			y0 = Math.min(y0, f.y[i]);
			y1 = Math.max(y1, f.y[i]);
		}
		if (x0 > x1) return new double[] { Double.NaN, Double.NaN, Double.NaN };
		// The influences live on the used pixels' box grown by the operators' reach (MARGIN); the buffers have two
		// more pixels of zeros all round, so the stencils below read no bounds (a zero adds nothing: the sums are
		// those of the stencils clipped at the box).
		final int m2 = GradientOperator.MARGIN, pad = 2;
		final int w = x1 - x0 + 1 + 2 * m2, h = y1 - y0 + 1 + 2 * m2, W = w + 2 * pad, H = h + 2 * pad;
		final int ox = x0 - m2 - pad, oy = y0 - m2 - pad, size = W * H;
		final Scratch s = SCRATCH.get().fit(size);
		// Per gradient pixel: d(A r)/dgx and d(A r)/dgy, two 2-vectors, placed on the pixel grid.
		final double[] fxa = s.fxa, fxb = s.fxb, fya = s.fya, fyb = s.fyb;
		for (int i = 0; i < f.size; i++) {
			if (used != null && !used[i]) continue;
			final double gx = f.gx[i], gy = f.gy[i];
			final double g2 = gx * gx + gy * gy;
			if (g2 == 0) continue;
			final double g = Math.sqrt(g2), g3 = g2 * g;
			final double rx = f.x[i] - cx, ry = f.y[i] - cy;
			final double ux = -gy, uy = gx, t = ux * rx + uy * ry;
			final int k = (f.y[i] - oy) * W + (f.x[i] - ox);
			fxa[k] = ux * ry / g - ux * t * gx / g3;
			fxb[k] = (t + uy * ry) / g - uy * t * gx / g3;
			fya[k] = (-t - ux * rx) / g - ux * t * gy / g3;
			fyb[k] = -uy * rx / g - uy * t * gy / g3;
		}
		// gx_i depends on I_p with sign h(px - ix) for |py - iy| <= 1 (h = -1,-1,0,+1,+1): box over y, then
		// difference over x; gy_i the transpose. Box sums where the differences will read them: over y on the
		// rows of the influences (every column), over x on their columns (every row).
		final double[] bxa = s.bxa, bxb = s.bxb, bya = s.bya, byb = s.byb;
		for (int y = pad; y < pad + h; y++)
			for (int x = 0, k = y * W; x < W; x++, k++) {
				bxa[k] = fxa[k] + fxa[k - W] + fxa[k + W];
				bxb[k] = fxb[k] + fxb[k - W] + fxb[k + W];
			}
		for (int y = 0; y < H; y++)
			for (int x = pad, k = y * W + pad; x < pad + w; x++, k++) {
				bya[k] = fya[k] + fya[k - 1] + fya[k + 1];
				byb[k] = fyb[k] + fyb[k - 1] + fyb[k + 1];
			}
		double sxx = 0, sxy = 0, syy = 0;
		final int W2 = 2 * W;
		for (int y = pad; y < pad + h; y++)
			for (int x = pad, k = y * W + pad; x < pad + w; x++, k++) {
				// B(x-1) + B(x-2) - B(x+1) - B(x+2), then the same over y
				final double va = bxa[k - 1] + bxa[k - 2] - bxa[k + 1] - bxa[k + 2] + (bya[k - W] + bya[k - W2] - bya[k +
					W] - bya[k + W2]);
				final double vb = bxb[k - 1] + bxb[k - 2] - bxb[k + 1] - bxb[k + 2] + (byb[k - W] + byb[k - W2] - byb[k +
					W] - byb[k + W2]);
				sxx += va * va;
				sxy += va * vb;
				syy += vb * vb;
			}
		// leave the coefficient buffers zero for the next spot (the box sums are always written before read)
		for (int i = 0; i < f.size; i++) {
			if (used != null && !used[i]) continue;
			final int k = (f.y[i] - oy) * W + (f.x[i] - ox);
			fxa[k] = fxb[k] = fya[k] = fyb[k] = 0;
		}
		final double det = m[0] * m[2] - m[1] * m[1];
		final double ixx = m[2] / det, ixy = -m[1] / det, iyy = m[0] / det;
		// M^-1 S M^-1 for symmetric 2x2 matrices.
		final double axx = ixx * sxx + ixy * sxy, axy = ixx * sxy + ixy * syy;
		final double ayx = ixy * sxx + iyy * sxy, ayy = ixy * sxy + iyy * syy;
		return new double[] { axx * ixx + axy * ixy, ayx * ixy + ayy * iyy, axx * ixy + axy * iyy };
	}

	/** Per-thread buffers: a spot's influences would otherwise allocate (and zero) eight arrays of its box. */
	private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

	/** The buffers of one thread; the coefficient ones are all zero between calls. */
	private static final class Scratch {
		double[] fxa = new double[0], fxb = fxa, fya = fxa, fyb = fxa, bxa = fxa, bxb = fxa, bya = fxa, byb = fxa;

		Scratch fit(final int size) {
			if (fxa.length < size) {
				fxa = new double[size];
				fxb = new double[size];
				fya = new double[size];
				fyb = new double[size];
				bxa = new double[size];
				bxb = new double[size];
				bya = new double[size];
				byb = new double[size];
			}
			return this;
		}
	}
}
