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

import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.profile.EmpiricalProfile;

/**
 * The passes of {@link GroupFit}'s least squares over a group's pixels ({@link FitPixels}): J^T J, J^T r and the
 * residuals at given parameters, in the layout per member x, y, amplitude, scale, then the background plane. One
 * pass for groups of more than one, and two for groups of one (with and without J^T J, their sums in local variables,
 * bit for bit the same): large groups are fitted member by member, so on dense footage groups of one are most of the work,
 * and sums kept in local variables spare that pass the array traffic of the general one (its speed: speed.md).
 * <p>
 * Where the floor is linked ({@link Censoring#mean}), a pixel whose model comes near it is fitted through the link:
 * its residual against the clipped noise's mean, its gradient (the background plane's too) times the link's slope.
 * The passes find those pixels as they go (a comparison a pixel; none on a frame without the link) and correct the
 * sums over them alone, so the loops of every other pixel stay as they are.
 */
final class NormalEquations {

	/** A group of one's J^T J pass: each pixel's gradient and residual ({@value #GRADIENT} numbers), grown on demand. */
	private double[] gradients = new double[0];

	/** The link at the floor (null: none), and the model value below which a pixel goes through it. */
	private final Censoring link;
	private final double linkTop;

	/** A group of one's pixels fitted through the link in its latest pass: their index and slope, grown on demand. */
	private int[] linkedAt = new int[0];
	private double[] linkedSlope = new double[0];
	private int linked;
	/** The link's mean and slope at the pixel in hand ({@link Censoring#link}). */
	private final double[] linkAt = new double[2];

	/** Passes with their own work array: one per fit (not shared between threads). */
	NormalEquations() {
		this(null);
	}

	/** Passes with the floor linked where {@code censoring} links it (null: nowhere). */
	NormalEquations(final Censoring censoring) {
		link = censoring != null && censoring.linked() ? censoring : null;
		linkTop = link == null ? Double.NEGATIVE_INFINITY : link.linkTop();
	}

	/** The numbers per pixel of a group of one's first loop: the gradient's four and the residual. */
	private static final int GRADIENT = 5;

	/**
	 * Fills J^T J (every entry; unless {@code jtj} is null) and J^T r at parameters {@code p}; returns the residual
	 * sum of squares. With {@code noise} (not null), adds per member {@code b = 4 q}: {@code sum w_x}, {@code sum w_x
	 * r^2}, {@code sum w_y}, {@code sum w_y r^2}, with {@code w_x, w_y} the squares of the model's derivatives with
	 * respect to the member's x and y: their ratios are the residuals' variance weighted by where each coordinate's
	 * information lies. That variance, rather than one for all pixels, gives the centres' standard errors: the same
	 * for uniform noise, right also when the noise grows with the light (photon noise), where one variance for all
	 * pixels, mostly background, understates the spread of the centres. This is the fit's inner
	 * loop (most of {@code fit}'s time), so it is written for speed: a pixel's gradient is non-zero only for the
	 * members within their profile's reach (usually one or two) and the background plane, so only their blocks are
	 * updated, on a flat lower triangle; the background's own block does not depend on {@code p} and was summed once
	 * ({@link FitPixels#backgroundBlock}).
	 */
	double accumulate(final FitPixels px, final double[] p, final int n, final EmpiricalProfile[] profile,
		final double[][] jtj, final double[] jtr, final double[] noise, final double[] models)
	{
		if (n > 1) return accumulateGroup(px, p, n, profile, jtj, jtr, noise, models);
		if (jtj == null) return residualsOne(px, p, profile[0], jtr, noise, models);
		return normalEquationsOne(px, p, profile[0], jtj, jtr, noise, models);
	}

	/** {@link #accumulate} for a group of more than one. */
	private double accumulateGroup(final FitPixels px, final double[] p, final int n,
		final EmpiricalProfile[] profile, final double[][] jtj, final double[] jtr, final double[] noise,
		final double[] models)
	{
		final int np = GroupFit.PER_PARTICLE * n + GroupFit.BACKGROUND, b0 = np - GroupFit.BACKGROUND;
		// each member's profile (its kind's): the tables, and its reach
		final double[][] tvs = new double[n][], tds = new double[n][];
		final double[] Rs = new double[n];
		for (int q = 0; q < n; q++) {
			tvs[q] = profile[q].valueTable();
			tds[q] = profile[q].derivativeTable();
			Rs[q] = profile[q].radius();
		}
		final double perStep = 1 / EmpiricalProfile.TABLE_STEP;
		final double[] pixels = px.packed();
		final int count = px.count();
		java.util.Arrays.fill(jtr, 0);
		final boolean hessian = jtj != null;
		final double[] h = hessian ? new double[np * np] : null;
		final double[] g = new double[GroupFit.PER_PARTICLE * n];
		final int[] within = new int[n];
		final double pb = p[b0], pu = p[b0 + 1], pv = p[b0 + 2];
		// per member: the profile's reach squared and the inverse scale, so that pixels out of reach cost no root
		final double[] reach2 = new double[n], perScale = new double[n];
		for (int q = 0; q < n; q++) {
			final double sc = p[GroupFit.PER_PARTICLE * q + 3], R = Rs[q];
			reach2[q] = R * sc * (R * sc);
			perScale[q] = 1 / sc;
		}
		double rss = 0, r0 = 0, ru = 0, rv = 0;
		// the background's own block over the linked pixels: (s^2 - 1) times {1, u, v} x {1, u, v}, row by row
		double[] linkedBlock = null;
		for (int i = 0, o = 0; i < count; i++, o += FitPixels.PACKED) {
			final double x = pixels[o], y = pixels[o + 1], u = pixels[o + 2], v = pixels[o + 3];
			double model = pb + pu * u + pv * v + pixels[o + 5];
			int m = 0;
			for (int q = 0; q < n; q++) {
				final int b = GroupFit.PER_PARTICLE * q;
				final double dx = x - p[b], dy = y - p[b + 1], r2 = dx * dx + dy * dy;
				if (!(r2 < reach2[q])) continue;
				final double r = Math.sqrt(r2), rs = r * perScale[q];
				if (!(rs < Rs[q])) continue; // (rounding at the very edge)
				final double[] tv = tvs[q], td = tds[q];
				// the profile's tables, linearly interpolated (as EmpiricalProfile.lookup, inlined)
				final double t = rs * perStep;
				final int k = (int) t;
				final double f = t - k;
				final double val = tv[k] + f * (tv[k + 1] - tv[k]);
				final double a = p[b + 2], d = a * (td[k] + f * (td[k + 1] - td[k])) * perScale[q];
				model += a * val;
				final double radial = r > 1e-12 ? -d / r : 0;
				final int c = GroupFit.PER_PARTICLE * m;
				g[c] = radial * dx;
				g[c + 1] = radial * dy;
				g[c + 2] = val;
				g[c + 3] = -d * rs;
				within[m++] = b;
			}
			if (models != null) models[i] = model;
			double res = pixels[o + 4] - model, one = 1, su = u, sv = v;
			if (model < linkTop) { // through the link: the clipped noise's mean, every gradient times its slope
				link.link(model, linkAt);
				one = linkAt[1];
				res = pixels[o + 4] - linkAt[0];
				su = one * u;
				sv = one * v;
				for (int c = 0; c < GroupFit.PER_PARTICLE * m; c++)
					g[c] *= one;
				if (hessian) {
					if (linkedBlock == null) linkedBlock = new double[GroupFit.BACKGROUND * GroupFit.BACKGROUND];
					addBackgroundBlock(linkedBlock, one * one - 1, u, v);
				}
			}
			rss += res * res;
			r0 += res * one;
			ru += res * su;
			rv += res * sv;
			for (int ma = 0; ma < m; ma++) {
				final int ba = within[ma], c = GroupFit.PER_PARTICLE * ma;
				final double g0 = g[c], g1 = g[c + 1], g2 = g[c + 2], g3 = g[c + 3];
				jtr[ba] += g0 * res;
				jtr[ba + 1] += g1 * res;
				jtr[ba + 2] += g2 * res;
				jtr[ba + 3] += g3 * res;
				if (noise != null) {
					final double r2 = res * res, wx = g0 * g0, wy = g1 * g1;
					noise[ba] += wx;
					noise[ba + 1] += wx * r2;
					noise[ba + 2] += wy;
					noise[ba + 3] += wy * r2;
				}
				if (!hessian) continue;
				ownBlock(h, np, b0, ba, su, sv, g0, g1, g2, g3);
				if (one != 1) backgroundRows(h, np, b0, ba, one - 1, 0, 0, g0, g1, g2, g3);
				// with the members before it within reach (their columns lie left of the diagonal)
				for (int mb = 0; mb < ma; mb++) {
					final int e = GroupFit.PER_PARTICLE * mb;
					crossBlock(h, np, ba, within[mb], g0, g1, g2, g3, g[e], g[e + 1], g[e + 2], g[e + 3]);
				}
			}
		}
		jtr[b0] = r0;
		jtr[b0 + 1] = ru;
		jtr[b0 + 2] = rv;
		if (hessian) {
			finish(px, np, h, jtj);
			if (linkedBlock != null) addToBackground(jtj, b0, linkedBlock);
		}
		return rss;
	}

	/** Adds {@code w} times {1, u, v} x {1, u, v} to the background's 3 x 3 block {@code block}, row by row. */
	private static void addBackgroundBlock(final double[] block, final double w, final double u, final double v) {
		final double wu = w * u, wv = w * v;
		block[0] += w;
		block[1] += wu;
		block[2] += wv;
		block[3] += wu;
		block[4] += wu * u;
		block[5] += wu * v;
		block[6] += wv;
		block[7] += wv * u;
		block[8] += wv * v;
	}

	/** Adds the 3 x 3 {@code block} to the background's block of the full J^T J (from row and column {@code b0}). */
	private static void addToBackground(final double[][] jtj, final int b0, final double[] block) {
		for (int a = 0; a < GroupFit.BACKGROUND; a++)
			for (int b = 0; b < GroupFit.BACKGROUND; b++)
				jtj[b0 + a][b0 + b] += block[a * GroupFit.BACKGROUND + b];
	}

	/**
	 * {@link #accumulate} without J^T J for a group of one, with the same sums in the same order (the same results to
	 * the last bit): a pass that evaluates a step. As the J^T J pass, first each pixel's gradient and residual, then
	 * the sums: one loop for both kept a root, a table's reading and a dozen sums waiting on each other at every
	 * pixel (12.4 against 10.2 ns a pixel, speed.md).
	 */
	private double residualsOne(final FitPixels px, final double[] p, final EmpiricalProfile profile,
		final double[] jtr, final double[] noise, final double[] models)
	{
		final double[] gr = gradientsOne(px, p, profile, models);
		final double rss = sumsOne(gr, px, jtr, noise);
		if (linked > 0) linkedOne(gr, px, jtr, null, GroupFit.PER_PARTICLE + GroupFit.BACKGROUND);
		return rss;
	}

	/**
	 * {@link #accumulate} with J^T J for a group of one, with the same sums in the same order (the same results to the
	 * last bit): J^T J's member block and its rows against the background plane, J^T r and the residuals' sums in
	 * local variables. First each pixel's gradient and residual (0 out of reach: they add nothing below), then the
	 * sums, each in a small loop: one loop for all would keep more sums than the processor has registers.
	 */
	private double normalEquationsOne(final FitPixels px, final double[] p, final EmpiricalProfile profile,
		final double[][] jtj, final double[] jtr, final double[] noise, final double[] models)
	{
		final int np = GroupFit.PER_PARTICLE + GroupFit.BACKGROUND, b0 = GroupFit.PER_PARTICLE;
		final double[] gr = gradientsOne(px, p, profile, models);
		final double rss = sumsOne(gr, px, jtr, noise);
		final double[] h = new double[np * np]; // laid out as accumulate's flat lower triangle
		ownBlockOne(h, np, b0, gr, px.packed(), px.count());
		final double[] linkedBlock = linked > 0 ? linkedOne(gr, px, jtr, h, np) : null;
		finish(px, np, h, jtj);
		if (linkedBlock != null) addToBackground(jtj, b0, linkedBlock);
		return rss;
	}

	/**
	 * A group of one's sums corrected over its pixels fitted through the link in the latest {@link #gradientsOne}
	 * (whose gradients it scaled by the slope {@code s} already): the background plane's J^T r by {@code s - 1} times
	 * its terms and, where {@code h} is not null, its rows against the member likewise; returns the correction of
	 * the background's own block (null without {@code h}).
	 */
	private double[] linkedOne(final double[] gr, final FitPixels px, final double[] jtr, final double[] h,
		final int np)
	{
		final int b0 = GroupFit.PER_PARTICLE;
		final double[] pixels = px.packed();
		final double[] block = h == null ? null : new double[GroupFit.BACKGROUND * GroupFit.BACKGROUND];
		for (int j = 0; j < linked; j++) {
			final int i = linkedAt[j], q = GRADIENT * i, o = FitPixels.PACKED * i;
			final double s = linkedSlope[j], u = pixels[o + 2], v = pixels[o + 3], res = gr[q + 4];
			jtr[b0] += (s - 1) * res;
			jtr[b0 + 1] += (s - 1) * res * u;
			jtr[b0 + 2] += (s - 1) * res * v;
			if (h == null) continue;
			backgroundRows(h, np, b0, 0, s - 1, (s - 1) * u, (s - 1) * v, gr[q], gr[q + 1], gr[q + 2], gr[q + 3]);
			addBackgroundBlock(block, s * s - 1, u, v);
		}
		return block;
	}

	/**
	 * A group of one's first loop: each pixel's gradient and residual into {@link #gradients} (0 out of reach), and
	 * the model where asked ({@code models} not null).
	 *
	 * @return {@link #gradients}
	 */
	private double[] gradientsOne(final FitPixels px, final double[] p, final EmpiricalProfile profile,
		final double[] models)
	{
		final int b0 = GroupFit.PER_PARTICLE;
		final double[] tv = profile.valueTable(), td = profile.derivativeTable();
		final double R = profile.radius(), perStep = 1 / EmpiricalProfile.TABLE_STEP;
		final double[] pixels = px.packed();
		final int count = px.count();
		final double cx = p[0], cy = p[1], a = p[2], sc = p[3], pb = p[b0], pu = p[b0 + 1], pv = p[b0 + 2];
		final double reach2 = R * sc * (R * sc), perScale = 1 / sc;
		if (gradients.length < GRADIENT * count) gradients = new double[GRADIENT * count];
		final double[] gr = gradients;
		linked = 0;
		for (int i = 0, o = 0, q = 0; i < count; i++, o += FitPixels.PACKED, q += GRADIENT) {
			final double u = pixels[o + 2], v = pixels[o + 3];
			double model = pb + pu * u + pv * v + pixels[o + 5];
			final double dx = pixels[o] - cx, dy = pixels[o + 1] - cy, r2 = dx * dx + dy * dy;
			double g0 = 0, g1 = 0, g2 = 0, g3 = 0;
			if (r2 < reach2) {
				final double r = Math.sqrt(r2), rs = r * perScale;
				if (rs < R) {
					final double t = rs * perStep;
					final int k = (int) t;
					final double f = t - k;
					final double val = tv[k] + f * (tv[k + 1] - tv[k]);
					final double d = a * (td[k] + f * (td[k + 1] - td[k])) * perScale;
					model += a * val;
					final double radial = r > 1e-12 ? -d / r : 0;
					g0 = radial * dx;
					g1 = radial * dy;
					g2 = val;
					g3 = -d * rs;
				}
			}
			if (models != null) models[i] = model;
			if (model < linkTop) {
				linkedPixel(gr, q, i, model, pixels[o + 4], g0, g1, g2, g3);
				continue;
			}
			gr[q] = g0;
			gr[q + 1] = g1;
			gr[q + 2] = g2;
			gr[q + 3] = g3;
			gr[q + 4] = pixels[o + 4] - model;
		}
		return gr;
	}

	/**
	 * A group of one's pixel {@code i} (at {@code q} in {@code gr}) of model {@code model} and value {@code value},
	 * fitted through the link: its gradient times the slope, its residual against the clipped noise's mean; noted for
	 * {@link #linkedOne}.
	 */
	private void linkedPixel(final double[] gr, final int q, final int i, final double model, final double value,
		final double g0, final double g1, final double g2, final double g3)
	{
		link.link(model, linkAt);
		final double s = linkAt[1];
		gr[q] = s * g0;
		gr[q + 1] = s * g1;
		gr[q + 2] = s * g2;
		gr[q + 3] = s * g3;
		gr[q + 4] = value - linkAt[0];
		if (linked == linkedAt.length) {
			linkedAt = java.util.Arrays.copyOf(linkedAt, Math.max(16, 2 * linked));
			linkedSlope = java.util.Arrays.copyOf(linkedSlope, linkedAt.length);
		}
		linkedAt[linked] = i;
		linkedSlope[linked++] = s;
	}

	/**
	 * A group of one's sums from its gradients and residuals {@code gr}: J^T r (the member's four, then the
	 * background plane's three: the residuals' sums against 1, u, v) into {@code jtr} and, where asked, the
	 * residuals' variance sums into {@code noise}.
	 *
	 * @return the residual sum of squares
	 */
	private static double sumsOne(final double[] gr, final FitPixels px, final double[] jtr, final double[] noise) {
		final double[] pixels = px.packed();
		final int count = px.count();
		double rss = 0, r0 = 0, ru = 0, rv = 0, j0 = 0, j1 = 0, j2 = 0, j3 = 0;
		for (int o = 0, q = 0; q < GRADIENT * count; o += FitPixels.PACKED, q += GRADIENT) {
			final double res = gr[q + 4];
			rss += res * res;
			r0 += res;
			ru += res * pixels[o + 2];
			rv += res * pixels[o + 3];
			j0 += gr[q] * res;
			j1 += gr[q + 1] * res;
			j2 += gr[q + 2] * res;
			j3 += gr[q + 3] * res;
		}
		final boolean weights = noise != null;
		double n0 = weights ? noise[0] : 0, n1 = weights ? noise[1] : 0, n2 = weights ? noise[2] : 0, n3 = weights ?
			noise[3] : 0;
		if (weights) for (int q = 0; q < GRADIENT * count; q += GRADIENT) {
			final double res = gr[q + 4], rr = res * res, wx = gr[q] * gr[q], wy = gr[q + 1] * gr[q + 1];
			n0 += wx;
			n1 += wx * rr;
			n2 += wy;
			n3 += wy * rr;
		}
		store(jtr, noise, j0, j1, j2, j3, n0, n1, n2, n3);
		final int b0 = GroupFit.PER_PARTICLE;
		jtr[b0] = r0;
		jtr[b0 + 1] = ru;
		jtr[b0 + 2] = rv;
		return rss;
	}

	/**
	 * A group of one's block of J^T J (lower triangle) and its rows against the background plane's 1, u, v, summed
	 * from the gradients {@code gr} onto the flat {@code h}.
	 */
	private static void ownBlockOne(final double[] h, final int np, final int b0, final double[] gr,
		final double[] pixels, final int count)
	{
		double h00 = 0, h10 = 0, h11 = 0, h20 = 0, h21 = 0, h22 = 0, h30 = 0, h31 = 0, h32 = 0, h33 = 0;
		for (int q = 0; q < GRADIENT * count; q += GRADIENT) {
			final double g0 = gr[q], g1 = gr[q + 1], g2 = gr[q + 2], g3 = gr[q + 3];
			h00 += g0 * g0;
			h10 += g1 * g0;
			h11 += g1 * g1;
			h20 += g2 * g0;
			h21 += g2 * g1;
			h22 += g2 * g2;
			h30 += g3 * g0;
			h31 += g3 * g1;
			h32 += g3 * g2;
			h33 += g3 * g3;
		}
		double c0 = 0, c1 = 0, c2 = 0, c3 = 0, cu0 = 0, cu1 = 0, cu2 = 0, cu3 = 0, cv0 = 0, cv1 = 0, cv2 = 0, cv3 = 0;
		for (int o = 0, q = 0; q < GRADIENT * count; o += FitPixels.PACKED, q += GRADIENT) {
			final double g0 = gr[q], g1 = gr[q + 1], g2 = gr[q + 2], g3 = gr[q + 3], u = pixels[o + 2], v = pixels[o + 3];
			c0 += g0;
			c1 += g1;
			c2 += g2;
			c3 += g3;
			cu0 += u * g0;
			cu1 += u * g1;
			cu2 += u * g2;
			cu3 += u * g3;
			cv0 += v * g0;
			cv1 += v * g1;
			cv2 += v * g2;
			cv3 += v * g3;
		}
		final double[] own = { h00, h10, h11, h20, h21, h22, h30, h31, h32, h33 };
		for (int r = 0, o = 0; r < GroupFit.PER_PARTICLE; r++)
			for (int c = 0; c <= r; c++)
				h[r * np + c] = own[o++];
		final double[][] plane = { { c0, c1, c2, c3 }, { cu0, cu1, cu2, cu3 }, { cv0, cv1, cv2, cv3 } };
		for (int r = 0; r < GroupFit.BACKGROUND; r++)
			System.arraycopy(plane[r], 0, h, (b0 + r) * np, GroupFit.PER_PARTICLE);
	}

	/** A group of one's J^T r and, where asked ({@code noise} not null), its residuals' variance sums. */
	private static void store(final double[] jtr, final double[] noise, final double j0, final double j1,
		final double j2, final double j3, final double n0, final double n1, final double n2, final double n3)
	{
		jtr[0] = j0;
		jtr[1] = j1;
		jtr[2] = j2;
		jtr[3] = j3;
		if (noise == null) return;
		noise[0] = n0;
		noise[1] = n1;
		noise[2] = n2;
		noise[3] = n3;
	}

	/**
	 * Adds one pixel's terms of a member's own block of J^T J (lower triangle) and of its rows against the background
	 * plane (gradients 1, u, v): {@code g0..g3} its gradient, {@code ba} its first parameter, on the flat {@code h}.
	 */
	private static void ownBlock(final double[] h, final int np, final int b0, final int ba, final double u,
		final double v, final double g0, final double g1, final double g2, final double g3)
	{
		final int row0 = ba * np + ba, row1 = row0 + np, row2 = row1 + np, row3 = row2 + np;
		h[row0] += g0 * g0;
		h[row1] += g1 * g0;
		h[row1 + 1] += g1 * g1;
		h[row2] += g2 * g0;
		h[row2 + 1] += g2 * g1;
		h[row2 + 2] += g2 * g2;
		h[row3] += g3 * g0;
		h[row3 + 1] += g3 * g1;
		h[row3 + 2] += g3 * g2;
		h[row3 + 3] += g3 * g3;
		backgroundRows(h, np, b0, ba, 1, u, v, g0, g1, g2, g3);
	}

	/**
	 * Adds a member's terms {@code g0..g3} (from parameter {@code ba}) to the background plane's three rows of J^T J on
	 * the flat {@code h}, times {@code one}, {@code u} and {@code v}.
	 */
	private static void backgroundRows(final double[] h, final int np, final int b0, final int ba, final double one,
		final double u, final double v, final double g0, final double g1, final double g2, final double g3)
	{
		final int bg0 = b0 * np + ba, bg1 = bg0 + np, bg2 = bg1 + np;
		h[bg0] += one * g0;
		h[bg0 + 1] += one * g1;
		h[bg0 + 2] += one * g2;
		h[bg0 + 3] += one * g3;
		h[bg1] += u * g0;
		h[bg1 + 1] += u * g1;
		h[bg1 + 2] += u * g2;
		h[bg1 + 3] += u * g3;
		h[bg2] += v * g0;
		h[bg2 + 1] += v * g1;
		h[bg2 + 2] += v * g2;
		h[bg2 + 3] += v * g3;
	}

	/**
	 * Adds one pixel's terms of the block of J^T J between member {@code ba} (gradient {@code g0..g3}) and an earlier
	 * member {@code bb} (gradient {@code e0..e3}), left of the diagonal.
	 */
	private static void crossBlock(final double[] h, final int np, final int ba, final int bb, final double g0,
		final double g1, final double g2, final double g3, final double e0, final double e1, final double e2,
		final double e3)
	{
		int row = ba * np + bb;
		h[row] += g0 * e0;
		h[row + 1] += g0 * e1;
		h[row + 2] += g0 * e2;
		h[row + 3] += g0 * e3;
		row += np;
		h[row] += g1 * e0;
		h[row + 1] += g1 * e1;
		h[row + 2] += g1 * e2;
		h[row + 3] += g1 * e3;
		row += np;
		h[row] += g2 * e0;
		h[row + 1] += g2 * e1;
		h[row + 2] += g2 * e2;
		h[row + 3] += g2 * e3;
		row += np;
		h[row] += g3 * e0;
		h[row + 1] += g3 * e1;
		h[row + 2] += g3 * e2;
		h[row + 3] += g3 * e3;
	}

	/**
	 * The background's own block (summed once: {@link FitPixels#backgroundBlock}) and the full symmetric J^T J from
	 * {@code h}.
	 */
	private static void finish(final FitPixels px, final int np, final double[] h, final double[][] jtj) {
		final int b0 = np - GroupFit.BACKGROUND;
		final double[] bg = px.backgroundBlock();
		for (int a = 0; a < GroupFit.BACKGROUND; a++)
			for (int b = 0; b <= a; b++)
				h[(b0 + a) * np + b0 + b] = bg[a * GroupFit.BACKGROUND + b];
		for (int a = 0; a < np; a++)
			for (int b = 0; b <= a; b++)
				jtj[a][b] = jtj[b][a] = h[a * np + b];
	}
}
