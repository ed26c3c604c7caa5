package io.github.contacttracker.core;

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
final class CentreUncertainty {

	private CentreUncertainty() {}

	/**
	 * @param f the gradient field
	 * @param used which pixels of {@code f} took part in the solve ({@code null}: all)
	 * @param cx solved centre x
	 * @param cy solved centre y
	 * @param m the solve's normal matrix {mxx, mxy, myy}
	 * @return {var x, var y, cov xy} per unit pixel-noise variance
	 */
	static double[] covariancePerUnitNoise(final GradientField f, final boolean[] used, final double cx,
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
		final int m2 = GradientOperator.MARGIN;
		final int ox = x0 - m2, oy = y0 - m2, w = x1 - x0 + 1 + 2 * m2, h = y1 - y0 + 1 + 2 * m2;
		// Per gradient pixel: d(A r)/dgx and d(A r)/dgy, two 2-vectors, placed on the pixel grid.
		final double[] fxa = new double[w * h], fxb = new double[w * h], fya = new double[w * h],
			fyb = new double[w * h];
		for (int i = 0; i < f.size; i++) {
			if (used != null && !used[i]) continue;
			final double gx = f.gx[i], gy = f.gy[i];
			final double g2 = gx * gx + gy * gy;
			if (g2 == 0) continue;
			final double g = Math.sqrt(g2), g3 = g2 * g;
			final double rx = f.x[i] - cx, ry = f.y[i] - cy;
			final double ux = -gy, uy = gx, s = ux * rx + uy * ry;
			final int k = (f.y[i] - oy) * w + (f.x[i] - ox);
			fxa[k] = ux * ry / g - ux * s * gx / g3;
			fxb[k] = (s + uy * ry) / g - uy * s * gx / g3;
			fya[k] = (-s - ux * rx) / g - ux * s * gy / g3;
			fyb[k] = -uy * rx / g - uy * s * gy / g3;
		}
		// gx_i depends on I_p with sign h(px - ix) for |py - iy| <= 1 (h = -1,-1,0,+1,+1): box over y, then
		// difference over x; gy_i the transpose.
		final double[] bxa = boxY(fxa, w, h), bxb = boxY(fxb, w, h);
		final double[] bya = boxX(fya, w, h), byb = boxX(fyb, w, h);
		double sxx = 0, sxy = 0, syy = 0;
		for (int y = 0; y < h; y++) {
			for (int x = 0; x < w; x++) {
				final double va = diffX(bxa, x, y, w) + diffY(bya, x, y, w, h);
				final double vb = diffX(bxb, x, y, w) + diffY(byb, x, y, w, h);
				sxx += va * va;
				sxy += va * vb;
				syy += vb * vb;
			}
		}
		final double det = m[0] * m[2] - m[1] * m[1];
		final double ixx = m[2] / det, ixy = -m[1] / det, iyy = m[0] / det;
		// M^-1 S M^-1 for symmetric 2x2 matrices.
		final double axx = ixx * sxx + ixy * sxy, axy = ixx * sxy + ixy * syy;
		final double ayx = ixy * sxx + iyy * sxy, ayy = ixy * sxy + iyy * syy;
		return new double[] { axx * ixx + axy * ixy, ayx * ixy + ayy * iyy, axx * ixy + axy * iyy };
	}

	private static double[] boxY(final double[] a, final int w, final int h) {
		final double[] out = new double[a.length];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				double s = a[y * w + x];
				if (y > 0) s += a[(y - 1) * w + x];
				if (y < h - 1) s += a[(y + 1) * w + x];
				out[y * w + x] = s;
			}
		return out;
	}

	private static double[] boxX(final double[] a, final int w, final int h) {
		final double[] out = new double[a.length];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				double s = a[y * w + x];
				if (x > 0) s += a[y * w + x - 1];
				if (x < w - 1) s += a[y * w + x + 1];
				out[y * w + x] = s;
			}
		return out;
	}

	/** B(x-1) + B(x-2) - B(x+1) - B(x+2), zero outside the buffer. */
	private static double diffX(final double[] b, final int x, final int y, final int w) {
		final int row = y * w;
		double s = 0;
		if (x >= 1) s += b[row + x - 1];
		if (x >= 2) s += b[row + x - 2];
		if (x + 1 < w) s -= b[row + x + 1];
		if (x + 2 < w) s -= b[row + x + 2];
		return s;
	}

	private static double diffY(final double[] b, final int x, final int y, final int w, final int h) {
		double s = 0;
		if (y >= 1) s += b[(y - 1) * w + x];
		if (y >= 2) s += b[(y - 2) * w + x];
		if (y + 1 < h) s -= b[(y + 1) * w + x];
		if (y + 2 < h) s -= b[(y + 2) * w + x];
		return s;
	}
}
