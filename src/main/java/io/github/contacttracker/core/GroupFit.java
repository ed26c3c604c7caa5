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
	 * @return the new estimates (the others unchanged) and the largest number of iterations a group needed,
	 *         negative if a group hit the limit
	 */
	static ProfileRefinement.Refined refine(final Plane plane, final Particle[] particles, final Estimate[] start,
		final EmpiricalProfile profile, final double groupDistance)
	{
		final Estimate[] e = start.clone();
		final List<int[]> groups = groups(particles, e, groupDistance);
		int worst = 0;
		for (final int[] group : groups) {
			final int it = fitGroup(plane, particles, e, group, profile);
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

	/** Fits one group, replacing its members' estimates in {@code e} on success; returns the iterations. */
	private static int fitGroup(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile profile)
	{
		final int n = group.length, np = 3 * n + 1;
		final double R = profile.radius(), r2 = R * R;
		// The pixels: within R of any member (taken at the starting centres).
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (final int k : group) {
			x0 = Math.min(x0, (int) Math.floor(e[k].x() - R));
			x1 = Math.max(x1, (int) Math.ceil(e[k].x() + R));
			y0 = Math.min(y0, (int) Math.floor(e[k].y() - R));
			y1 = Math.max(y1, (int) Math.ceil(e[k].y() + R));
		}
		x0 = Math.max(0, x0);
		y0 = Math.max(0, y0);
		x1 = Math.min(plane.width() - 1, x1);
		y1 = Math.min(plane.height() - 1, y1);
		int count = 0;
		final int cap = (x1 - x0 + 1) * (y1 - y0 + 1);
		final int[] px = new int[cap], py = new int[cap];
		final double[] pv = new double[cap];
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				boolean inside = false;
				for (final int k : group) {
					final double dx = x - e[k].x(), dy = y - e[k].y();
					if (dx * dx + dy * dy < r2) {
						inside = true;
						break;
					}
				}
				if (!inside) continue;
				px[count] = x;
				py[count] = y;
				pv[count++] = plane.get(x, y);
			}
		if (count <= np) return 0;
		// The light of reliable particles outside the group, at their current centres and amplitude 1.
		final double[] fixed = new double[count];
		for (int k = 0; k < ps.length; k++) {
			if (!ps[k].reliable() || contains(group, k)) continue;
			final double kx = e[k].x(), ky = e[k].y();
			if (kx < x0 - R || kx > x1 + R || ky < y0 - R || ky > y1 + R) continue;
			for (int i = 0; i < count; i++) {
				final double dx = px[i] - kx, dy = py[i] - ky, d2 = dx * dx + dy * dy;
				if (d2 < r2) fixed[i] += profile.lookup(Math.sqrt(d2));
			}
		}
		final double[] p = new double[np];
		for (int q = 0; q < n; q++) {
			p[3 * q] = e[group[q]].x();
			p[3 * q + 1] = e[group[q]].y();
			p[3 * q + 2] = 1;
		}
		p[np - 1] = profile.background();
		final double[][] jtj = new double[np][np];
		final double[] jtr = new double[np];
		double rss = accumulate(px, py, pv, fixed, count, p, n, profile, jtj, jtr);
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
			for (int i = 0; i < np; i++)
				trial[i] += step[i];
			final double[][] tj = new double[np][np];
			final double[] tr = new double[np];
			final double trialRss = accumulate(px, py, pv, fixed, count, trial, n, profile, tj, tr);
			double move = 0;
			for (int q = 0; q < n; q++)
				move = Math.max(move, Math.hypot(step[3 * q], step[3 * q + 1]));
			if (trialRss <= rss) {
				System.arraycopy(trial, 0, p, 0, np);
				for (int i = 0; i < np; i++) {
					jtj[i] = tj[i];
					jtr[i] = tr[i];
				}
				rss = trialRss;
				mu = Math.max(mu / 10, 1e-9);
				if (move < TOLERANCE) {
					converged = true;
					break;
				}
			}
			else {
				mu *= 10;
				if (move < TOLERANCE) {
					converged = true; // no better point within a negligible distance
					break;
				}
			}
		}
		final double[][] inv = SymmetricSolver.invert(jtj);
		if (inv == null) return converged ? it : -it;
		final double s2 = rss / (count - np);
		for (int q = 0; q < n; q++) {
			final Estimate old = e[group[q]];
			e[group[q]] = new Estimate(p[3 * q], p[3 * q + 1], old.flags(), old.secondArea(), old.iterations(), old.solve(),
				Math.sqrt(s2 * inv[3 * q][3 * q]), Math.sqrt(s2 * inv[3 * q + 1][3 * q + 1]));
		}
		return converged ? it : -it;
	}

	/** Fills J^T J and J^T r at parameters {@code p}; returns the residual sum of squares. */
	private static double accumulate(final int[] px, final int[] py, final double[] pv, final double[] fixed,
		final int count,
		final double[] p, final int n, final EmpiricalProfile profile, final double[][] jtj, final double[] jtr)
	{
		final int np = 3 * n + 1;
		final double R = profile.radius();
		final double[] grad = new double[np];
		double rss = 0;
		for (int i = 0; i < count; i++) {
			double model = p[np - 1] + fixed[i];
			java.util.Arrays.fill(grad, 0);
			grad[np - 1] = 1;
			for (int q = 0; q < n; q++) {
				final double dx = px[i] - p[3 * q], dy = py[i] - p[3 * q + 1];
				final double r = Math.sqrt(dx * dx + dy * dy);
				if (r >= R) continue;
				final double a = p[3 * q + 2], v = profile.lookup(r);
				model += a * v;
				grad[3 * q + 2] = v;
				if (r > 1e-12) {
					final double d = a * profile.lookupDerivative(r) / r;
					grad[3 * q] = -d * dx;
					grad[3 * q + 1] = -d * dy;
				}
			}
			final double res = pv[i] - model;
			rss += res * res;
			for (int a = 0; a < np; a++) {
				if (grad[a] == 0) continue;
				jtr[a] += grad[a] * res;
				for (int b = 0; b <= a; b++)
					jtj[a][b] += grad[a] * grad[b];
			}
		}
		for (int a = 0; a < np; a++)
			for (int b = a + 1; b < np; b++)
				jtj[a][b] = jtj[b][a];
		return rss;
	}
}
