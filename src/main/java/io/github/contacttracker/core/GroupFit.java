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
	/**
	 * Converged when no centre moves more than this in an iteration (px); that step is taken, unevaluated. The
	 * iterations converge at least tenfold per step near the solution (on the bench stack: steps of about 5e-2,
	 * 1e-4, 1e-7 px), so the centres end within about 1e-4 px of the exact least-squares point: a hundredth of a
	 * nanometre at usual pixel sizes, two orders below the Cramer-Rao bound. A tighter tolerance costs a pass over
	 * every pixel per group for nothing measurable.
	 */
	static final double TOLERANCE = 1e-3;

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
		final Pixels candidates = candidates(plane, ps, e, group, profile, window, censoring);
		if (candidates.count() <= np) return 0;
		final double[] p = new double[np];
		for (int q = 0; q < n; q++) {
			final Estimate s = e[group[q]];
			p[PER_PARTICLE * q] = s.x();
			p[PER_PARTICLE * q + 1] = s.y();
			p[PER_PARTICLE * q + 2] = amplitudeOf(s);
			p[PER_PARTICLE * q + 3] = scaleOf(s);
		}
		p[np - BACKGROUND] = profile.background();
		final boolean[] use = censoring.active() ? new boolean[candidates.count()] : null;
		final double[][] jtj = new double[np][np];
		final double[] jtr = new double[np];
		double rss;
		Pixels pixels = candidates;
		if (use == null || allUsable(candidates, p, n, profile, censoring, use))
			rss = accumulate(candidates, p, n, profile, jtj, jtr, null, null);
		else {
			// The first pass over every candidate chooses the pixels from the model it computes, and the pixels left
			// out are then taken out of its sums (a pass over them alone): one pass, not a choice and a pass.
			final double[] models = new double[candidates.count()];
			rss = accumulate(candidates, p, n, profile, jtj, jtr, null, models);
			final boolean[] out = new boolean[use.length];
			for (int i = 0; i < use.length; i++) {
				use[i] = censoring.usable(models[i]);
				out[i] = !use[i];
			}
			pixels = candidates.subset(use);
			if (pixels != candidates) {
				final double[][] outJtj = new double[np][np];
				final double[] outJtr = new double[np];
				rss -= accumulate(candidates.subset(out), p, n, profile, outJtj, outJtr, null, null);
				for (int a = 0; a < np; a++) {
					jtr[a] -= outJtr[a];
					for (int b = 0; b < np; b++)
						jtj[a][b] -= outJtj[a][b];
				}
			}
		}
		if (pixels.count() <= np) return 0;
		int selections = 1;
		double mu = 1e-3;
		int it = 1;
		boolean converged = false;
		// Whether J^T J was computed at p. A step is evaluated by the residuals alone (a third of the cost of J^T J);
		// once accepted, the next step comes from the previous J^T J with the new J^T r (a chord step): near the
		// solution J^T J hardly changes, so that step is as good, and when it is below TOLERANCE the fit has
		// settled. Otherwise J^T J is computed at p first.
		boolean hessianAtP = true;
		// per member, the residuals' variance where its centre's information lies (see accumulate), from the latest
		// residual pass; null: none, one variance for all pixels
		double[] noise = null;
		// the model on the pixels at the latest point accepted by a residual pass, for the re-choice of the pixels
		Evaluated evaluated = null;
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
			if (allowed && move < TOLERANCE) {
				// Settled: the step is taken without evaluating the model there (a pass over every pixel, a third of
				// the fit's time); J^T J and the residuals at p serve the uncertainties as well. Where the pixel type
				// clips, the pixels are chosen again at the settled model, and if the choice changed the fit goes on.
				System.arraycopy(trial, 0, p, 0, np);
				// chosen at the point of the latest residual pass, whose model is known on the pixels in use (the
				// settled point is within TOLERANCE of it)
				if (use != null && selections < MAX_SELECTIONS && (evaluated == null ? select(candidates, p, n, profile,
					censoring, use) : select(candidates, evaluated.p(), n, profile, censoring, use, evaluated.pixels(),
						evaluated.models()))) {
					selections++;
					final Pixels chosen = candidates.subset(use);
					if (chosen.count() <= np) break;
					pixels = chosen;
					rss = accumulate(pixels, p, n, profile, jtj, jtr, null, null);
					hessianAtP = true;
					noise = null;
					evaluated = null;
					mu = 1e-3;
					continue;
				}
				converged = true;
				break;
			}
			if (!hessianAtP) { // a chord step that was not small: J^T J at p, and the step again from it
				rss = accumulate(pixels, p, n, profile, jtj, jtr, null, null);
				hessianAtP = true;
				noise = null;
				evaluated = null;
				continue;
			}
			final double[] tr = new double[np], trialNoise = new double[PER_PARTICLE * n];
			final double[] trialModels = use != null ? new double[pixels.count()] : null;
			final double trialRss = allowed ? accumulate(pixels, trial, n, profile, null, tr, trialNoise, trialModels)
				: Double.POSITIVE_INFINITY;
			if (trialRss <= rss) {
				System.arraycopy(trial, 0, p, 0, np);
				System.arraycopy(tr, 0, jtr, 0, np);
				hessianAtP = false;
				noise = trialNoise;
				evaluated = new Evaluated(pixels, trial, trialModels);
				rss = trialRss;
				mu = Math.max(mu / 10, 1e-9);
			}
			else mu *= 10;
		}
		final double[][] inv = SymmetricSolver.invert(jtj);
		if (inv == null) return 0;
		final double dof = pixels.count() / (double) (pixels.count() - np), s2 = rss / (pixels.count() - np);
		for (int q = 0; q < n; q++) {
			final Estimate old = e[group[q]];
			final int b = PER_PARTICLE * q;
			final double vx = noise != null && noise[b] > 0 ? dof * noise[b + 1] / noise[b] : s2;
			final double vy = noise != null && noise[b + 2] > 0 ? dof * noise[b + 3] / noise[b + 2] : s2;
			e[group[q]] = new Estimate(p[b], p[b + 1], old.flags(), old.secondArea(), old.iterations(), old.solve(), Math
				.sqrt(vx * inv[b][b]), Math.sqrt(vy * inv[b + 1][b + 1]), p[b + 2], p[b + 3]);
		}
		return converged ? it : -it;
	}

	/**
	 * The pixels a group's fit may use: within each member's window (at its starting centre and scale), not clipped,
	 * with the light of the reliable particles outside the group at their current centres, amplitudes and scales.
	 * (Apart from the fit's loop, so that the compiler sees small methods, each with its own pixel loop.)
	 */
	private static Pixels candidates(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile profile, final double window, final Censoring censoring)
	{
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
		final int n = group.length;
		final double[] gx = new double[n], gy = new double[n], reach2 = new double[n];
		for (int q = 0; q < n; q++) {
			final Estimate m = e[group[q]];
			final double reach = W * scaleOf(m);
			gx[q] = m.x();
			gy[q] = m.y();
			reach2[q] = reach * reach;
		}
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				boolean inside = false;
				for (int q = 0; q < n && !inside; q++) {
					final double dx = x - gx[q], dy = y - gy[q];
					inside = dx * dx + dy * dy < reach2[q];
				}
				if (!inside) continue;
				final double v = plane.get(x, y);
				if (censoring.clipped(v)) continue; // censored: its true value is unknown
				px[count] = x;
				py[count] = y;
				pv[count++] = v;
			}
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
		return new Pixels(px, py, pv, fixed, count, mx, my, unit);
	}

	/** The model on a fit's pixels at parameters {@code p}, as a residual pass computed it. */
	private record Evaluated(Pixels pixels, double[] p, double[] models) {}

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
		return select(candidates, p, n, profile, censoring, use, null, null);
	}

	/**
	 * Marks every candidate used and returns true if cheap bounds on the model show that all are usable; else returns
	 * false and leaves {@code use} unchanged (the caller chooses from the model itself).
	 */
	private static boolean allUsable(final Pixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring, final boolean[] use)
	{
		if (!withinBounds(candidates, p, n, profile, censoring)) return false;
		java.util.Arrays.fill(use, true);
		return true;
	}

	/**
	 * As {@link #select(Pixels, double[], int, EmpiricalProfile, Censoring, boolean[])}, with the model at {@code p}
	 * already known on the pixels {@code known} (a subset of the candidates; {@code knownModels} in its order) from
	 * the fit's latest pass: only the other candidates are evaluated.
	 */
	private static boolean select(final Pixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring, final boolean[] use, final Pixels known,
		final double[] knownModels)
	{
		final int b0 = PER_PARTICLE * n;
		boolean changed = false;
		// usually no model value comes near a clip level (a shortcut where the model is not known already)
		if (known == null && withinBounds(candidates, p, n, profile, censoring)) {
			for (int i = 0; i < candidates.count(); i++) {
				changed |= !use[i];
				use[i] = true;
			}
			return changed;
		}
		final double[] models = new double[candidates.count()];
		java.util.Arrays.fill(models, Double.NaN);
		if (known != null) for (int j = 0; j < known.count(); j++)
			models[known.candidate(j)] = knownModels[j];
		for (int i = 0; i < candidates.count(); i++) {
			if (!Double.isNaN(models[i])) {
				final boolean usable = censoring.usable(models[i]);
				changed |= usable != use[i];
				use[i] = usable;
				continue;
			}
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
	 * @return whether bounds on the model over all candidates, cheap to get (no root, no lookup), lie where the
	 *         censoring rule keeps every pixel: background plane and other groups' light at their extremes, each
	 *         member's light between its amplitude times the profile's least and greatest values (or 0)
	 */
	private static boolean withinBounds(final Pixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring)
	{
		final int b0 = PER_PARTICLE * n;
		double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
		for (int i = 0; i < candidates.count(); i++) {
			final double plane = p[b0] + p[b0 + 1] * candidates.u()[i] + p[b0 + 2] * candidates.v()[i] + candidates
				.fixed()[i];
			lo = Math.min(lo, plane);
			hi = Math.max(hi, plane);
		}
		for (int q = 0; q < n; q++) {
			final double a = p[PER_PARTICLE * q + 2], least = a * profile.leastValue(), greatest = a * profile
				.greatestValue();
			lo += Math.min(0, Math.min(least, greatest));
			hi += Math.max(0, Math.max(least, greatest));
		}
		return censoring.usable(lo) && censoring.usable(hi);
	}

	/**
	 * {@link #accumulateGroup} for a group of one (an isolated particle: about half of all groups), with the same
	 * sums added in the same order, but kept in local variables rather than array entries: the client compiler, on
	 * which short runs go (scripts/contact-tracker), keeps no array entry in a register and checks every index.
	 * Identical results ({@code GroupFitTest}).
	 */
	static double accumulateSingle(final Pixels px, final double[] p, final EmpiricalProfile profile,
		final double[][] jtj, final double[] jtr, final double[] noise, final double[] models)
	{
		final double R = profile.radius();
		final double[] tv = profile.valueTable(), td = profile.derivativeTable();
		final double perStep = 1 / EmpiricalProfile.TABLE_STEP;
		final int[] xs = px.x(), ys = px.y();
		final double[] us = px.u(), vs = px.v(), values = px.value(), fixed = px.fixed();
		final int count = px.count();
		final boolean hessian = jtj != null;
		final double cx = p[0], cy = p[1], a = p[2], sc = p[3], pb = p[4], pu = p[5], pv = p[6];
		final double reach2 = R * sc * (R * sc), perScale = 1 / sc;
		double rss = 0, r0 = 0, ru = 0, rv = 0, j0 = 0, j1 = 0, j2 = 0, j3 = 0, wx = 0, wxr = 0, wy = 0, wyr = 0;
		double h00 = 0, h10 = 0, h11 = 0, h20 = 0, h21 = 0, h22 = 0, h30 = 0, h31 = 0, h32 = 0, h33 = 0;
		double c0 = 0, c1 = 0, c2 = 0, c3 = 0, u0 = 0, u1 = 0, u2 = 0, u3 = 0, v0 = 0, v1 = 0, v2 = 0, v3 = 0;
		for (int i = 0; i < count; i++) {
			final double u = us[i], v = vs[i];
			double model = pb + pu * u + pv * v + fixed[i];
			final double dx = xs[i] - cx, dy = ys[i] - cy, r2 = dx * dx + dy * dy;
			boolean within = false;
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
					within = true;
				}
			}
			if (models != null) models[i] = model;
			final double res = values[i] - model;
			rss += res * res;
			r0 += res;
			ru += res * u;
			rv += res * v;
			if (!within) continue;
			j0 += g0 * res;
			j1 += g1 * res;
			j2 += g2 * res;
			j3 += g3 * res;
			if (noise != null) {
				final double e2 = res * res, ex = g0 * g0, ey = g1 * g1;
				wx += ex;
				wxr += ex * e2;
				wy += ey;
				wyr += ey * e2;
			}
			if (!hessian) continue;
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
			c0 += g0;
			c1 += g1;
			c2 += g2;
			c3 += g3;
			u0 += u * g0;
			u1 += u * g1;
			u2 += u * g2;
			u3 += u * g3;
			v0 += v * g0;
			v1 += v * g1;
			v2 += v * g2;
			v3 += v * g3;
		}
		final double[] sums = { j0, j1, j2, j3, r0, ru, rv };
		System.arraycopy(sums, 0, jtr, 0, sums.length);
		if (noise != null) {
			noise[0] += wx;
			noise[1] += wxr;
			noise[2] += wy;
			noise[3] += wyr;
		}
		if (!hessian) return rss;
		final double[] bg = px.backgroundBlock();
		final double[][] lower = { { h00 }, { h10, h11 }, { h20, h21, h22 }, { h30, h31, h32, h33 }, { c0, c1, c2, c3,
			bg[0] }, { u0, u1, u2, u3, bg[3], bg[4] }, { v0, v1, v2, v3, bg[6], bg[7], bg[8] } };
		for (int r = 0; r < lower.length; r++)
			for (int c = 0; c <= r; c++)
				jtj[r][c] = jtj[c][r] = lower[r][c];
		return rss;
	}

	/**
	 * The pixels of a group's fit: positions, values, other groups' light, their coordinates {@code u, v} in the
	 * background plane's frame (origin and unit of the group's box) and the plane's block of J^T J, computed once
	 * for every iteration.
	 */
	record Pixels(int[] x, int[] y, double[] value, double[] fixed, int count, double[] u, double[] v,
		double[] backgroundBlock, int[] candidates)
	{

		Pixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
			final double mx, final double my, final double unit)
		{
			this(x, y, value, fixed, count, planeCoordinate(x, count, mx, unit), planeCoordinate(y, count, my, unit),
				null);
		}

		/** @return the index among the candidates of pixel {@code j} (a subset's; the candidates' own: j) */
		int candidate(final int j) {
			return candidates == null ? j : candidates[j];
		}

		private Pixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
			final double[] u, final double[] v, final int[] candidates)
		{
			this(x, y, value, fixed, count, u, v, backgroundBlock(u, v, count), candidates);
		}

		/** The background plane's block of J^T J, {1, u, v} x {1, u, v} row by row: the same at every step. */
		private static double[] backgroundBlock(final double[] u, final double[] v, final int count) {
			double su = 0, sv = 0, suu = 0, suv = 0, svv = 0;
			for (int i = 0; i < count; i++) {
				su += u[i];
				sv += v[i];
				suu += u[i] * u[i];
				suv += u[i] * v[i];
				svv += v[i] * v[i];
			}
			return new double[] { count, su, sv, su, suu, suv, sv, suv, svv };
		}

		/** @return the pixels marked in {@code keep}, in the same order (these pixels if all are) */
		Pixels subset(final boolean[] keep) {
			int m = 0;
			for (int i = 0; i < count; i++)
				if (keep[i]) m++;
			if (m == count) return this;
			final int[] sx = new int[m], sy = new int[m];
			final double[] sv = new double[m], sf = new double[m], su = new double[m], sw = new double[m];
			final int[] from = new int[m];
			for (int i = 0, j = 0; i < count; i++) {
				if (!keep[i]) continue;
				from[j] = candidate(i);
				sx[j] = x[i];
				sy[j] = y[i];
				sv[j] = value[i];
				sf[j] = fixed[i];
				su[j] = u[i];
				sw[j++] = v[i];
			}
			return new Pixels(sx, sy, sv, sf, m, su, sw, from);
		}

		private static double[] planeCoordinate(final int[] c, final int count, final double origin, final double unit) {
			final double[] out = new double[count];
			for (int i = 0; i < count; i++)
				out[i] = (c[i] - origin) / unit;
			return out;
		}
	}

	/**
	 * Fills J^T J (every entry; unless {@code jtj} is null) and J^T r at parameters {@code p}; returns the residual
	 * sum of squares. With {@code noise} (not null), adds per member {@code b = 4 q}: {@code sum w_x}, {@code sum w_x
	 * r^2}, {@code sum w_y}, {@code sum w_y r^2}, with {@code w_x, w_y} the squares of the model's derivatives with
	 * respect to the member's x and y: their ratios are the residuals' variance weighted by where each coordinate's
	 * information lies. That variance, rather than one for all pixels, gives the centres' standard errors: the same
	 * for uniform noise, right also when the noise grows with the light (photon noise), where one variance for all
	 * pixels, mostly background, understates the spread of the centres. This is the fit's inner
	 * loop (most of {@code fit}'s time), so it is written for speed: a pixel's gradient is non-zero only for the
	 * members within the profile's reach (usually one or two) and the background plane, so only their blocks are
	 * updated, on a flat lower triangle; the background's own block does not depend on {@code p} and was summed once
	 * ({@link Pixels#backgroundBlock}).
	 */
	private static double accumulate(final Pixels px, final double[] p, final int n, final EmpiricalProfile profile,
		final double[][] jtj, final double[] jtr, final double[] noise, final double[] models)
	{
		return n == 1 ? accumulateSingle(px, p, profile, jtj, jtr, noise, models) : accumulateGroup(px, p, n, profile,
			jtj, jtr, noise, models);
	}

	/** {@link #accumulate} for any group (package-private for the test of {@link #accumulateSingle}). */
	static double accumulateGroup(final Pixels px, final double[] p, final int n, final EmpiricalProfile profile,
		final double[][] jtj, final double[] jtr, final double[] noise, final double[] models)
	{
		final int np = PER_PARTICLE * n + BACKGROUND, b0 = np - BACKGROUND;
		final double R = profile.radius();
		final double[] tv = profile.valueTable(), td = profile.derivativeTable();
		final double perStep = 1 / EmpiricalProfile.TABLE_STEP;
		final int[] xs = px.x(), ys = px.y();
		final double[] us = px.u(), vs = px.v(), values = px.value(), fixed = px.fixed();
		final int count = px.count();
		java.util.Arrays.fill(jtr, 0);
		final boolean hessian = jtj != null;
		final double[] h = hessian ? new double[np * np] : null;
		final double[] g = new double[PER_PARTICLE * n];
		final int[] within = new int[n];
		final double pb = p[b0], pu = p[b0 + 1], pv = p[b0 + 2];
		// per member: the profile's reach squared and the inverse scale, so that pixels out of reach cost no root
		final double[] reach2 = new double[n], perScale = new double[n];
		for (int q = 0; q < n; q++) {
			final double sc = p[PER_PARTICLE * q + 3];
			reach2[q] = R * sc * (R * sc);
			perScale[q] = 1 / sc;
		}
		double rss = 0, r0 = 0, ru = 0, rv = 0;
		for (int i = 0; i < count; i++) {
			final double u = us[i], v = vs[i];
			double model = pb + pu * u + pv * v + fixed[i];
			int m = 0;
			for (int q = 0; q < n; q++) {
				final int b = PER_PARTICLE * q;
				final double dx = xs[i] - p[b], dy = ys[i] - p[b + 1], r2 = dx * dx + dy * dy;
				if (!(r2 < reach2[q])) continue;
				final double r = Math.sqrt(r2), rs = r * perScale[q];
				if (!(rs < R)) continue; // (rounding at the very edge)
				// the profile's tables, linearly interpolated (as EmpiricalProfile.lookup, inlined)
				final double t = rs * perStep;
				final int k = (int) t;
				final double f = t - k;
				final double val = tv[k] + f * (tv[k + 1] - tv[k]);
				final double a = p[b + 2], d = a * (td[k] + f * (td[k + 1] - td[k])) * perScale[q];
				model += a * val;
				final double radial = r > 1e-12 ? -d / r : 0;
				final int c = PER_PARTICLE * m;
				g[c] = radial * dx;
				g[c + 1] = radial * dy;
				g[c + 2] = val;
				g[c + 3] = -d * rs;
				within[m++] = b;
			}
			if (models != null) models[i] = model;
			final double res = values[i] - model;
			rss += res * res;
			r0 += res;
			ru += res * u;
			rv += res * v;
			for (int ma = 0; ma < m; ma++) {
				final int ba = within[ma], c = PER_PARTICLE * ma;
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
				// the member's own block (lower triangle)
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
				// with the members before it within reach (their columns lie left of the diagonal)
				for (int mb = 0; mb < ma; mb++) {
					final int bb = within[mb], e = PER_PARTICLE * mb;
					final double e0 = g[e], e1 = g[e + 1], e2 = g[e + 2], e3 = g[e + 3];
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
				// the background rows (gradients 1, u, v)
				final int bg0 = b0 * np + ba, bg1 = bg0 + np, bg2 = bg1 + np;
				h[bg0] += g0;
				h[bg0 + 1] += g1;
				h[bg0 + 2] += g2;
				h[bg0 + 3] += g3;
				h[bg1] += u * g0;
				h[bg1 + 1] += u * g1;
				h[bg1 + 2] += u * g2;
				h[bg1 + 3] += u * g3;
				h[bg2] += v * g0;
				h[bg2 + 1] += v * g1;
				h[bg2 + 2] += v * g2;
				h[bg2 + 3] += v * g3;
			}
		}
		jtr[b0] = r0;
		jtr[b0 + 1] = ru;
		jtr[b0 + 2] = rv;
		if (!hessian) return rss;
		final double[] bg = px.backgroundBlock();
		for (int a = 0; a < BACKGROUND; a++)
			for (int b = 0; b <= a; b++)
				h[(b0 + a) * np + b0 + b] = bg[a * BACKGROUND + b];
		for (int a = 0; a < np; a++)
			for (int b = 0; b <= a; b++)
				jtj[a][b] = jtj[b][a] = h[a * np + b];
		return rss;
	}
}
