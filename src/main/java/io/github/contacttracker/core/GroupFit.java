package io.github.contacttracker.core;

import java.util.ArrayList;
import java.util.List;

/**
 * The {@code fit} method: particles closer than {@code 2 r_out} form a group (their significant light
 * overlaps), and each group is fitted jointly by least squares to the pixels within {@code R} (the measured
 * profile's reach) of its members: {@code I(x) = B + sum_k a_k P(|x - c_k|) + F(x)} with the measured profile
 * {@code P}, free centres {@code c_k}, amplitudes {@code a_k} and local background {@code B}
 * (Levenberg-Marquardt); {@code F} is the faint light of particles of other groups (all farther than
 * {@code 2 r_out}), held at their current estimates: only its tail reaches the group, where a centre error of
 * a few hundredths of a pixel changes nothing that matters. All the light of every particle is used, which is what the
 * Cramer-Rao bound assumes. Unreliable particles (suspected merges, degenerate) are left as they are and are
 * not modelled.
 */
final class GroupFit {

	static final int MAX_ITERATIONS = 50;
	/** Converged when no centre moves more than this in an iteration (px). */
	static final double TOLERANCE = 1e-5;

	private GroupFit() {}

	/**
	 * Refines the centres of the reliable particles, starting from {@code start}, group by group; a group's
	 * neighbours are held at their latest estimates (those of groups already fitted included).
	 *
	 * @return the new estimates (the others unchanged; the members of a group that could not be fitted, too few
	 *         pixels left or a singular system, keep theirs flagged {@code FELL_BACK}) and the largest number of
	 *         iterations a group needed, negative if a group hit the limit
	 */
	static ProfileRefinement.Refined refine(final Plane plane, final Particle[] particles, final Estimate[] start,
		final EmpiricalProfile profile, final double groupDistance, final double window, final Censoring censoring)
	{
		final Estimate[] e = start.clone();
		final List<int[]> groups = groups(particles, e, groupDistance);
		int worst = 0;
		for (final int[] group : groups) {
			final int it = fitGroup(plane, particles, e, group, profile, window, censoring);
			if (it == 0) for (final int k : group)
				e[k] = e[k].withFlags(e[k].flags() | Flag.FELL_BACK.bit());
			if (it < 0) worst = Math.min(worst, it);
			else if (worst >= 0) worst = Math.max(worst, it);
		}
		return new ProfileRefinement.Refined(e, worst);
	}

	/** Groups of reliable particles closer than {@code distance} (transitively), at centres {@code e}. */
	static List<int[]> groups(final Particle[] ps, final Estimate[] e, final double distance) {
		final int n = ps.length;
		final int[] parent = new int[n];
		for (int i = 0; i < n; i++)
			parent[i] = i;
		for (int i = 0; i < n; i++)
			for (int j = i + 1; j < n; j++)
				if (ps[i].reliable() && ps[j].reliable() && e[i].distanceTo(e[j]) < distance) {
					final int ri = root(parent, i), rj = root(parent, j);
					if (ri != rj) parent[Math.max(ri, rj)] = Math.min(ri, rj);
				}
		final List<int[]> groups = new ArrayList<>();
		for (int r = 0; r < n; r++) {
			if (root(parent, r) != r || !ps[r].reliable()) continue;
			int size = 0;
			for (int i = 0; i < n; i++)
				if (root(parent, i) == r) size++;
			final int[] g = new int[size];
			int f = 0;
			for (int i = 0; i < n; i++)
				if (root(parent, i) == r) g[f++] = i;
			groups.add(g);
		}
		return groups;
	}

	private static boolean contains(final int[] group, final int k) {
		for (final int g : group)
			if (g == k) return true;
		return false;
	}

	private static int root(final int[] parent, int i) {
		while (parent[i] != i)
			i = parent[i];
		return i;
	}

	/** Parameters per particle: x, y, amplitude, radial scale. */
	static final int PER_PARTICLE = 4;
	/** Background terms per group: B, bx, by (a plane). */
	static final int BACKGROUND = 3;
	/** Radial scales outside this range are not accepted as steps (a particle of another kind entirely). */
	static final double MIN_SCALE = 0.5, MAX_SCALE = 2;

	private static double amplitudeOf(final Estimate e) {
		return Double.isFinite(e.amplitude()) ? e.amplitude() : 1;
	}

	private static double scaleOf(final Estimate e) {
		return e.scale() > 0 ? e.scale() : 1;
	}

	/**
	 * Fits one group, replacing its members' estimates in {@code e} on success; returns the iterations (0: not
	 * fitted). The pixels fitted lie within {@code window} (px, times each member's scale) of a member: out to
	 * {@code r_out}, where a particle's image has returned to the background, not to the profile's full reach
	 * (1.5 {@code r_out}), whose faint tail carries almost no information on the centre but more than doubles the
	 * pixels. The model itself
	 * keeps the full reach: every member's and neighbour's tail is in the light of the pixels fitted. Where the
	 * pixel type clips, the pixels used are those the {@code censoring} rule keeps at the model's current
	 * parameters: chosen again when the fit has settled, and the fit continued, until the choice stays put.
	 */
	private static int fitGroup(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile profile, final double window, final Censoring censoring)
	{
		final int n = group.length, np = PER_PARTICLE * n + BACKGROUND;
		final double R = profile.radius(), W = Math.min(R, window);
		// The pixels: within each member's window (at its starting centre and scale), not clipped.
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (final int k : group) {
			final double reach = W * scaleOf(e[k]);
			x0 = Math.min(x0, (int) Math.floor(e[k].x() - reach));
			x1 = Math.max(x1, (int) Math.ceil(e[k].x() + reach));
			y0 = Math.min(y0, (int) Math.floor(e[k].y() - reach));
			y1 = Math.max(y1, (int) Math.ceil(e[k].y() + reach));
		}
		x0 = Math.max(0, x0);
		y0 = Math.max(0, y0);
		x1 = Math.min(plane.width() - 1, x1);
		y1 = Math.min(plane.height() - 1, y1);
		final double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1), unit = Math.max(1, 0.5 * (x1 - x0));
		int count = 0;
		final int cap = (x1 - x0 + 1) * (y1 - y0 + 1);
		final int[] px = new int[cap], py = new int[cap];
		final double[] pv = new double[cap];
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				boolean inside = false;
				for (final int k : group) {
					final double dx = x - e[k].x(), dy = y - e[k].y(), reach = W * scaleOf(e[k]);
					if (dx * dx + dy * dy < reach * reach) {
						inside = true;
						break;
					}
				}
				if (!inside) continue;
				final double v = plane.get(x, y);
				if (censoring.clipped(v)) continue; // censored: its true value is unknown
				px[count] = x;
				py[count] = y;
				pv[count++] = v;
			}
		if (count <= np) return 0;
		// The light of reliable particles outside the group, at their current centres, amplitudes and scales.
		final double[] fixed = new double[count];
		for (int k = 0; k < ps.length; k++) {
			if (!ps[k].reliable() || contains(group, k)) continue;
			final double kx = e[k].x(), ky = e[k].y(), ks = scaleOf(e[k]), ka = amplitudeOf(e[k]), reach = R * ks;
			if (kx < x0 - reach || kx > x1 + reach || ky < y0 - reach || ky > y1 + reach) continue;
			for (int i = 0; i < count; i++) {
				final double dx = px[i] - kx, dy = py[i] - ky, d2 = dx * dx + dy * dy;
				if (d2 < reach * reach) fixed[i] += ka * profile.lookup(Math.sqrt(d2) / ks);
			}
		}
		final double[] p = new double[np];
		for (int q = 0; q < n; q++) {
			final Estimate s = e[group[q]];
			p[PER_PARTICLE * q] = s.x();
			p[PER_PARTICLE * q + 1] = s.y();
			p[PER_PARTICLE * q + 2] = amplitudeOf(s);
			p[PER_PARTICLE * q + 3] = scaleOf(s);
		}
		p[np - BACKGROUND] = profile.background();
		final Pixels candidates = new Pixels(px, py, pv, fixed, count, mx, my, unit);
		final boolean[] use = censoring.active() ? new boolean[count] : null;
		if (use != null) select(candidates, p, n, profile, censoring, use);
		Pixels pixels = use == null ? candidates : candidates.subset(use);
		if (pixels.count() <= np) return 0;
		int selections = 1;
		final double[][] jtj = new double[np][np];
		final double[] jtr = new double[np];
		double rss = accumulate(pixels, p, n, profile, jtj, jtr);
		double mu = 1e-3;
		int it = 1;
		boolean converged = false;
		for (; it <= MAX_ITERATIONS; it++) {
			final double[][] a = new double[np][np];
			for (int i = 0; i < np; i++) {
				a[i] = jtj[i].clone();
				a[i][i] += mu * jtj[i][i];
			}
			final double[] step = SymmetricSolver.solve(a, jtr);
			if (step == null) break;
			final double[] trial = p.clone();
			boolean allowed = true;
			for (int i = 0; i < np; i++)
				trial[i] += step[i];
			for (int q = 0; q < n; q++) {
				final double sc = trial[PER_PARTICLE * q + 3];
				if (!(sc >= MIN_SCALE && sc <= MAX_SCALE)) allowed = false;
			}
			double move = 0;
			for (int q = 0; q < n; q++)
				move = Math.max(move, Math.hypot(step[PER_PARTICLE * q], step[PER_PARTICLE * q + 1]));
			final double[][] tj = new double[np][np];
			final double[] tr = new double[np];
			final double trialRss = allowed ? accumulate(pixels, trial, n, profile, tj, tr) : Double.POSITIVE_INFINITY;
			if (trialRss <= rss) {
				System.arraycopy(trial, 0, p, 0, np);
				for (int i = 0; i < np; i++) {
					jtj[i] = tj[i];
					jtr[i] = tr[i];
				}
				rss = trialRss;
				mu = Math.max(mu / 10, 1e-9);
			}
			else mu *= 10;
			if (move < TOLERANCE && allowed) { // settled (rejected: no better point within a negligible distance)
				if (use != null && selections < MAX_SELECTIONS && select(candidates, p, n, profile, censoring, use)) {
					selections++;
					final Pixels chosen = candidates.subset(use);
					if (chosen.count() <= np) break;
					pixels = chosen;
					for (int i = 0; i < np; i++) {
						jtj[i] = new double[np];
						jtr[i] = 0;
					}
					rss = accumulate(pixels, p, n, profile, jtj, jtr);
					mu = 1e-3;
					continue;
				}
				converged = true;
				break;
			}
		}
		final double[][] inv = SymmetricSolver.invert(jtj);
		if (inv == null) return 0;
		final double s2 = rss / (pixels.count() - np);
		for (int q = 0; q < n; q++) {
			final Estimate old = e[group[q]];
			final int b = PER_PARTICLE * q;
			e[group[q]] = new Estimate(p[b], p[b + 1], old.flags(), old.secondArea(), old.iterations(), old.solve(), Math
				.sqrt(s2 * inv[b][b]), Math.sqrt(s2 * inv[b + 1][b + 1]), p[b + 2], p[b + 3]);
		}
		return converged ? it : -it;
	}

	/** The usable pixels are chosen at most this many times per fit (one pixel could flip back and forth). */
	static final int MAX_SELECTIONS = 5;

	/**
	 * Marks in {@code use} the candidates whose model value at parameters {@code p} the censoring rule keeps.
	 *
	 * @return whether any mark changed
	 */
	private static boolean select(final Pixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring, final boolean[] use)
	{
		final int b0 = PER_PARTICLE * n;
		boolean changed = false;
		for (int i = 0; i < candidates.count(); i++) {
			double model = p[b0] + p[b0 + 1] * candidates.u()[i] + p[b0 + 2] * candidates.v()[i] + candidates.fixed()[i];
			for (int q = 0; q < n; q++) {
				final int b = PER_PARTICLE * q;
				final double dx = candidates.x()[i] - p[b], dy = candidates.y()[i] - p[b + 1];
				model += p[b + 2] * profile.lookup(Math.sqrt(dx * dx + dy * dy) / p[b + 3]);
			}
			final boolean usable = censoring.usable(model);
			changed |= usable != use[i];
			use[i] = usable;
		}
		return changed;
	}

	/**
	 * The pixels of a group's fit: positions, values, other groups' light, and their coordinates {@code u, v} in
	 * the background plane's frame (origin and unit of the group's box), computed once for every iteration.
	 */
	private record Pixels(int[] x, int[] y, double[] value, double[] fixed, int count, double[] u, double[] v) {

		Pixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
			final double mx, final double my, final double unit)
		{
			this(x, y, value, fixed, count, planeCoordinate(x, count, mx, unit), planeCoordinate(y, count, my, unit));
		}

		/** @return the pixels marked in {@code keep}, in the same order (these pixels if all are) */
		Pixels subset(final boolean[] keep) {
			int m = 0;
			for (int i = 0; i < count; i++)
				if (keep[i]) m++;
			if (m == count) return this;
			final int[] sx = new int[m], sy = new int[m];
			final double[] sv = new double[m], sf = new double[m], su = new double[m], sw = new double[m];
			for (int i = 0, j = 0; i < count; i++) {
				if (!keep[i]) continue;
				sx[j] = x[i];
				sy[j] = y[i];
				sv[j] = value[i];
				sf[j] = fixed[i];
				su[j] = u[i];
				sw[j++] = v[i];
			}
			return new Pixels(sx, sy, sv, sf, m, su, sw);
		}

		private static double[] planeCoordinate(final int[] c, final int count, final double origin, final double unit) {
			final double[] out = new double[count];
			for (int i = 0; i < count; i++)
				out[i] = (c[i] - origin) / unit;
			return out;
		}
	}

	/**
	 * Fills J^T J (lower triangle mirrored) and J^T r at parameters {@code p}; returns the residual sum of squares.
	 * A pixel's gradient is non-zero only for the background plane and the members within reach, so J^T J is
	 * updated block by block for those: every entry receives the same terms, in the same pixel order, as a dense
	 * update would add where they are non-zero. This is the fit's inner loop (most of {@code fit}'s time).
	 */
	private static double accumulate(final Pixels px, final double[] p, final int n, final EmpiricalProfile profile,
		final double[][] jtj, final double[] jtr)
	{
		final int np = PER_PARTICLE * n + BACKGROUND, b0 = np - BACKGROUND;
		final double R = profile.radius();
		final int[] xs = px.x(), ys = px.y();
		final double[] us = px.u(), vs = px.v(), values = px.value(), fixed = px.fixed();
		final int count = px.count();
		final double[] grad = new double[np];
		final boolean[] within = new boolean[n];
		final double[] vd = new double[2];
		double rss = 0;
		for (int i = 0; i < count; i++) {
			final double u = us[i], v = vs[i];
			double model = p[b0] + p[b0 + 1] * u + p[b0 + 2] * v + fixed[i];
			grad[b0] = 1;
			grad[b0 + 1] = u;
			grad[b0 + 2] = v;
			for (int q = 0; q < n; q++) {
				final int b = PER_PARTICLE * q;
				final double dx = xs[i] - p[b], dy = ys[i] - p[b + 1], sc = p[b + 3];
				final double r = Math.sqrt(dx * dx + dy * dy), rs = r / sc;
				within[q] = rs < R;
				if (!within[q]) continue;
				final double a = p[b + 2];
				profile.lookupBoth(rs, vd);
				final double val = vd[0];
				model += a * val;
				final double d = a * vd[1];
				grad[b] = r > 1e-12 ? -d / sc * dx / r : 0;
				grad[b + 1] = r > 1e-12 ? -d / sc * dy / r : 0;
				grad[b + 2] = val;
				grad[b + 3] = -d * rs / sc;
			}
			final double res = values[i] - model;
			rss += res * res;
			// rows of the members within reach, then the background's; columns up to the diagonal
			for (int qa = 0; qa < n; qa++) {
				if (!within[qa]) continue;
				final int ba = PER_PARTICLE * qa;
				for (int a = ba; a < ba + PER_PARTICLE; a++)
					addRow(jtj[a], jtr, a, grad, res, within, qa, ba, a);
			}
			for (int a = b0; a < np; a++)
				addRow(jtj[a], jtr, a, grad, res, within, n, b0, a);
		}
		for (int a = 0; a < np; a++)
			for (int b = a + 1; b < np; b++)
				jtj[a][b] = jtj[b][a];
		return rss;
	}

	/**
	 * Adds one pixel's terms to row {@code a}: the columns of the members {@code 0..before-1} within reach, then
	 * {@code from..to} of the row's own block.
	 */
	private static void addRow(final double[] row, final double[] jtr, final int a, final double[] grad,
		final double res, final boolean[] within, final int before, final int from, final int to)
	{
		final double ga = grad[a];
		jtr[a] += ga * res;
		for (int qb = 0; qb < before; qb++) {
			if (!within[qb]) continue;
			final int bb = PER_PARTICLE * qb;
			row[bb] += ga * grad[bb];
			row[bb + 1] += ga * grad[bb + 1];
			row[bb + 2] += ga * grad[bb + 2];
			row[bb + 3] += ga * grad[bb + 3];
		}
		for (int c = from; c <= to; c++)
			row[c] += ga * grad[c];
	}
}
