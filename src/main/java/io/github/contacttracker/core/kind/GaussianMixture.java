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
package io.github.contacttracker.core.kind;

import java.io.Serializable;
import java.util.Arrays;

/**
 * A mixture of two-dimensional Gaussians fitted by expectation-maximisation, immutable: the clusters behind
 * {@link Kinds}. Each component has a full covariance, widened by a floor on each axis (the features' own
 * measurement scatter) so that a tight cluster cannot collapse to a point and win the likelihood.
 */
final class GaussianMixture implements Serializable {

	private static final long serialVersionUID = 1L;

	/** Most EM rounds; the likelihood has settled long before on every sample tried. */
	static final int MAX_ROUNDS = 500;
	/** EM stops when a round raises the log-likelihood by less than this. */
	static final double TOLERANCE = 1e-9;

	final int k;
	final double[] weight;
	final double[][] mean; // [component][axis]
	final double[][] cov; // [component][xx, xy, yy]
	final double logLikelihood;

	private GaussianMixture(final double[] weight, final double[][] mean, final double[][] cov,
		final double logLikelihood)
	{
		this.k = weight.length;
		this.weight = weight;
		this.mean = mean;
		this.cov = cov;
		this.logLikelihood = logLikelihood;
	}

	/** Free parameters: per component 2 means and 3 covariances, and {@code k - 1} weights. */
	int parameters() {
		return 6 * k - 1;
	}

	/** The Bayesian information criterion of this fit to {@code n} points: lower is better. */
	double bic(final int n) {
		return -2 * logLikelihood + parameters() * Math.log(n);
	}

	/**
	 * Fits {@code k} components to the points, starting from three deterministic partitions (the points split into
	 * {@code k} equal groups in order of x, in order of y, and by farthest-point seeding) and keeping the fit of the
	 * highest likelihood.
	 *
	 * @param x the points' first coordinates
	 * @param y their second coordinates
	 * @param floor the smallest standard deviation of a component along each axis: {x, y}
	 */
	static GaussianMixture fit(final double[] x, final double[] y, final int k, final double[] floor) {
		GaussianMixture best = null;
		for (final int[] start : new int[][] { byOrder(x, k), byOrder(y, k), farthest(x, y, k, floor) }) {
			final GaussianMixture m = em(x, y, start, k, floor);
			if (m != null && (best == null || m.logLikelihood > best.logLikelihood)) best = m;
		}
		return best;
	}

	/** @return the component most likely to hold (px, py): the largest weighted density */
	int component(final double px, final double py) {
		int best = 0;
		double bestLog = Double.NEGATIVE_INFINITY;
		for (int c = 0; c < k; c++) {
			final double l = Math.log(weight[c]) + logDensity(c, px, py);
			if (l > bestLog) {
				bestLog = l;
				best = c;
			}
		}
		return best;
	}

	/**
	 * Ashman's D of components a and b along the line through their means: {@code sqrt(2) |m_a - m_b| /
	 * sqrt(s_a^2 + s_b^2)}, with {@code s} each one's standard deviation along that line. Above 2 the two are
	 * cleanly apart (for equal widths, their mixture is bimodal above 2); below it they are one spread-out group.
	 */
	double separation(final int a, final int b) {
		final double dx = mean[b][0] - mean[a][0], dy = mean[b][1] - mean[a][1];
		final double len = Math.hypot(dx, dy);
		if (len == 0) return 0;
		final double ex = dx / len, ey = dy / len;
		final double va = along(cov[a], ex, ey), vb = along(cov[b], ex, ey);
		return Math.sqrt(2) * len / Math.sqrt(va + vb);
	}

	private static double along(final double[] c, final double ex, final double ey) {
		return c[0] * ex * ex + 2 * c[1] * ex * ey + c[2] * ey * ey;
	}

	double logDensity(final int c, final double px, final double py) {
		final double[] s = cov[c];
		final double det = s[0] * s[2] - s[1] * s[1];
		final double dx = px - mean[c][0], dy = py - mean[c][1];
		final double q = (s[2] * dx * dx - 2 * s[1] * dx * dy + s[0] * dy * dy) / det;
		return -0.5 * q - Math.log(2 * Math.PI) - 0.5 * Math.log(det);
	}

	/** @return the k-th group of each point when the points are split into k equal groups in order of v */
	private static int[] byOrder(final double[] v, final int k) {
		final Integer[] order = new Integer[v.length];
		for (int i = 0; i < order.length; i++)
			order[i] = i;
		Arrays.sort(order, (a, b) -> Double.compare(v[a], v[b]));
		final int[] group = new int[v.length];
		for (int r = 0; r < order.length; r++)
			group[order[r]] = (int) ((long) r * k / order.length);
		return group;
	}

	/**
	 * @return each point's nearest seed, the seeds chosen farthest-first (in units of the floor): the first the
	 *         point farthest from the mean, each next the point farthest from all seeds so far
	 */
	private static int[] farthest(final double[] x, final double[] y, final int k, final double[] floor) {
		final int n = x.length;
		double mx = 0, my = 0;
		for (int i = 0; i < n; i++) {
			mx += x[i] / n;
			my += y[i] / n;
		}
		final double[] nearest = new double[n];
		Arrays.fill(nearest, Double.POSITIVE_INFINITY);
		final int[] group = new int[n];
		double far = -1;
		int seed = 0;
		for (int i = 0; i < n; i++) {
			final double d = dist2(x[i] - mx, y[i] - my, floor);
			if (d > far) {
				far = d;
				seed = i;
			}
		}
		for (int c = 0; c < k; c++) {
			final int s = seed;
			far = -1;
			for (int i = 0; i < n; i++) {
				final double d = dist2(x[i] - x[s], y[i] - y[s], floor);
				if (d < nearest[i]) {
					nearest[i] = d;
					group[i] = c;
				}
				if (nearest[i] > far) {
					far = nearest[i];
					seed = i;
				}
			}
		}
		return group;
	}

	private static double dist2(final double dx, final double dy, final double[] floor) {
		return dx * dx / (floor[0] * floor[0]) + dy * dy / (floor[1] * floor[1]);
	}

	/** EM from a hard partition; null if a group of the partition is empty. */
	private static GaussianMixture em(final double[] x, final double[] y, final int[] start, final int k,
		final double[] floor)
	{
		final int n = x.length;
		final double[][] resp = new double[k][n];
		for (int i = 0; i < n; i++)
			resp[start[i]][i] = 1;
		GaussianMixture m = mStep(x, y, resp, floor);
		if (m == null) return null;
		double previous = Double.NEGATIVE_INFINITY;
		for (int round = 0; round < MAX_ROUNDS; round++) {
			final double ll = eStep(m, x, y, resp);
			m = mStep(x, y, resp, floor);
			if (m == null) return null;
			if (ll - previous < TOLERANCE) break;
			previous = ll;
		}
		final double ll = eStep(m, x, y, resp);
		return new GaussianMixture(m.weight, m.mean, m.cov, ll);
	}

	/** Fills the responsibilities; @return the log-likelihood */
	private static double eStep(final GaussianMixture m, final double[] x, final double[] y, final double[][] resp) {
		double ll = 0;
		final double[] l = new double[m.k];
		for (int i = 0; i < x.length; i++) {
			double top = Double.NEGATIVE_INFINITY;
			for (int c = 0; c < m.k; c++) {
				l[c] = Math.log(m.weight[c]) + m.logDensity(c, x[i], y[i]);
				top = Math.max(top, l[c]);
			}
			double sum = 0;
			for (int c = 0; c < m.k; c++)
				sum += Math.exp(l[c] - top);
			for (int c = 0; c < m.k; c++)
				resp[c][i] = Math.exp(l[c] - top) / sum;
			ll += top + Math.log(sum);
		}
		return ll;
	}

	/** Weights, means and floored covariances from the responsibilities; null if a component holds no weight. */
	private static GaussianMixture mStep(final double[] x, final double[] y, final double[][] resp,
		final double[] floor)
	{
		final int k = resp.length, n = x.length;
		final double[] weight = new double[k];
		final double[][] mean = new double[k][2], cov = new double[k][3];
		for (int c = 0; c < k; c++) {
			double w = 0, sx = 0, sy = 0;
			for (int i = 0; i < n; i++) {
				w += resp[c][i];
				sx += resp[c][i] * x[i];
				sy += resp[c][i] * y[i];
			}
			if (!(w > 1e-9)) return null;
			final double mx = sx / w, my = sy / w;
			double xx = 0, xy = 0, yy = 0;
			for (int i = 0; i < n; i++) {
				final double dx = x[i] - mx, dy = y[i] - my;
				xx += resp[c][i] * dx * dx;
				xy += resp[c][i] * dx * dy;
				yy += resp[c][i] * dy * dy;
			}
			weight[c] = w / n;
			mean[c][0] = mx;
			mean[c][1] = my;
			cov[c][0] = xx / w + floor[0] * floor[0];
			cov[c][1] = xy / w;
			cov[c][2] = yy / w + floor[1] * floor[1];
		}
		return new GaussianMixture(weight, mean, cov, Double.NaN);
	}
}
