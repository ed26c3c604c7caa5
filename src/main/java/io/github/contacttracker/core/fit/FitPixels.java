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
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/**
 * The pixels of a group's fit: positions, values, other groups' light, their coordinates {@code u, v} in the
 * background plane's frame (origin and unit of the group's box) and the plane's block of J^T J, computed once
 * for every iteration.
 * <p>
 * Also where they come from ({@link #gather}) and which of them a fit uses where the pixel type clips
 * ({@link #select}): the pixels of {@link GroupFit}'s least squares, whose passes are {@link NormalEquations}.
 */
record FitPixels(int[] x, int[] y, double[] value, double[] fixed, int count, double[] u, double[] v,
	double[] backgroundBlock, double[] extent, int[] candidates, double[] packed)
{

	/** The numbers per pixel in {@link #packed}: x, y, u, v, value, other groups' light. */
	static final int PACKED = 6;

	/**
	 * @param packed each pixel's x, y, u, v, value and light together ({@value #PACKED} numbers a pixel), as the fit's
	 *        passes read them: one array rather than six, so that a pass's loop keeps its sums in registers rather
	 *        than the arrays' addresses; null: made here from the others
	 */
	FitPixels {
		if (packed == null) packed = pack(x, y, value, fixed, count, u, v);
	}

	FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double[] u, final double[] v, final double[] backgroundBlock, final double[] extent, final int[] candidates)
	{
		this(x, y, value, fixed, count, u, v, backgroundBlock, extent, candidates, null);
	}

	private static double[] pack(final int[] x, final int[] y, final double[] value, final double[] fixed,
		final int count, final double[] u, final double[] v)
	{
		final double[] out = new double[PACKED * count];
		for (int i = 0, o = 0; i < count; i++, o += PACKED) {
			out[o] = x[i];
			out[o + 1] = y[i];
			out[o + 2] = u[i];
			out[o + 3] = v[i];
			out[o + 4] = value[i];
			out[o + 5] = fixed[i];
		}
		return out;
	}

	FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double mx, final double my, final double unit)
	{
		this(x, y, value, fixed, count, planeCoordinate(x, count, mx, unit), planeCoordinate(y, count, my, unit),
			null);
	}

	/** @return the index among the candidates of pixel {@code j} (a subset's; the candidates' own: j) */
	int candidate(final int j) {
		return candidates == null ? j : candidates[j];
	}

	private FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double[] u, final double[] v, final int[] candidates)
	{
		this(x, y, value, fixed, count, u, v, candidates, pack(x, y, value, fixed, count, u, v));
	}

	private FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double[] u, final double[] v, final int[] candidates, final double[] packed)
	{
		this(x, y, value, fixed, count, u, v, summary(packed, count), candidates, packed);
	}

	private FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double[] u, final double[] v, final double[] summary, final int[] candidates, final double[] packed)
	{
		this(x, y, value, fixed, count, u, v, java.util.Arrays.copyOf(summary, 9), java.util.Arrays.copyOfRange(
			summary, 9, 15), candidates, packed);
	}

	/**
	 * In one pass: the background plane's block of J^T J, {1, u, v} x {1, u, v} row by row (the same at every
	 * step), then the least and greatest u, v and other groups' light ({@link #extent}).
	 */
	private static double[] summary(final double[] packed, final int count) {
		double su = 0, sv = 0, suu = 0, suv = 0, svv = 0;
		double u0 = Double.POSITIVE_INFINITY, u1 = Double.NEGATIVE_INFINITY, v0 = u0, v1 = u1, f0 = u0, f1 = u1;
		for (int i = 0, o = 0; i < count; i++, o += PACKED) {
			final double ui = packed[o + 2], vi = packed[o + 3], fi = packed[o + 5];
			su += ui;
			sv += vi;
			suu += ui * ui;
			suv += ui * vi;
			svv += vi * vi;
			// comparisons, not Math.min/max: no NaN here, and the client compiler calls those
			if (ui < u0) u0 = ui;
			if (ui > u1) u1 = ui;
			if (vi < v0) v0 = vi;
			if (vi > v1) v1 = vi;
			if (fi < f0) f0 = fi;
			if (fi > f1) f1 = fi;
		}
		return new double[] { count, su, sv, su, suu, suv, sv, suv, svv, u0, u1, v0, v1, f0, f1 };
	}

	/**
	 * @return these pixels as candidates in their own right, numbered from 0 (a subset kept for good), with their
	 *         positions, values, light and plane coordinates unpacked (a subset has them packed only)
	 */
	FitPixels asCandidates() {
		if (candidates == null) return this;
		final int[] ux = new int[count], uy = new int[count];
		final double[] uu = new double[count], uv = new double[count], uValue = new double[count], uFixed =
			new double[count];
		for (int i = 0, o = 0; i < count; i++, o += PACKED) {
			ux[i] = (int) packed[o];
			uy[i] = (int) packed[o + 1];
			uu[i] = packed[o + 2];
			uv[i] = packed[o + 3];
			uValue[i] = packed[o + 4];
			uFixed[i] = packed[o + 5];
		}
		return new FitPixels(ux, uy, uValue, uFixed, count, uu, uv, backgroundBlock, extent, null, packed);
	}

	/**
	 * @return the pixels marked in {@code keep}, in the same order (these pixels if all are): packed only, as the
	 *         passes read them (their separate arrays null until {@link #asCandidates})
	 */
	FitPixels subset(final boolean[] keep) {
		final FitPixels s = subsetToPass(keep);
		if (s == this) return this;
		final double[] summary = summary(s.packed, s.count);
		return new FitPixels(null, null, null, null, s.count, null, null, java.util.Arrays.copyOf(summary, 9), java.util
			.Arrays.copyOfRange(summary, 9, 15), s.candidates, s.packed);
	}

	/**
	 * The background's block of J^T J in a subset only passed over with the background held: {@link GroupFit}'s
	 * hold replaces that block with the identity's, so that what it holds is never read.
	 */
	private static final double[] HELD_BLOCK = new double[9];

	/**
	 * @return the subset of these pixels that {@code keep} says, as {@link #subset}, for a fit with the background held
	 *         that only passes over it: without the background's block of J^T J or the {@link #extent} (a pass over its
	 *         pixels each), which such a fit never reads; never made candidates ({@link #asCandidates}) or lit again
	 */
	FitPixels subsetToPass(final boolean[] keep) {
		int m = 0;
		for (int i = 0; i < count; i++)
			if (keep[i]) m++;
		if (m == count) return this;
		final int[] from = new int[m];
		final double[] sp = new double[PACKED * m]; // (the packed numbers copied as they are, not packed again)
		for (int i = 0, j = 0; i < count; i++) {
			if (!keep[i]) continue;
			from[j] = candidate(i);
			// (six numbers: copied in place, a call per pixel would cost more than the copy)
			final int a = PACKED * i, b = PACKED * j;
			sp[b] = packed[a];
			sp[b + 1] = packed[a + 1];
			sp[b + 2] = packed[a + 2];
			sp[b + 3] = packed[a + 3];
			sp[b + 4] = packed[a + 4];
			sp[b + 5] = packed[a + 5];
			j++;
		}
		return new FitPixels(null, null, null, null, m, null, null, HELD_BLOCK, null, from, sp);
	}

	private static double[] planeCoordinate(final int[] c, final int count, final double origin, final double unit) {
		// one division per distinct coordinate (a row or column of the group's box), not one per pixel
		int lo = Integer.MAX_VALUE, hi = Integer.MIN_VALUE;
		for (int i = 0; i < count; i++) {
			if (c[i] < lo) lo = c[i];
			if (c[i] > hi) hi = c[i];
		}
		final double[] table = new double[count == 0 ? 0 : hi - lo + 1];
		for (int k = 0; k < table.length; k++)
			table[k] = (lo + k - origin) / unit;
		final double[] out = new double[count];
		for (int i = 0; i < count; i++)
			out[i] = table[c[i] - lo];
		return out;
	}

	/**
	 * The pixels a group's fit may use: within each member's window (at its starting centre and scale), not clipped,
	 * with the light of the reliable particles outside the group at their current centres, amplitudes and scales.
	 * Read row by row, each row as the spans the members' windows cover: no membership test per pixel.
	 * (Apart from the fit's loop, so that the compiler sees small methods, each with its own pixel loop.)
	 */
	static FitPixels gather(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile[] profile, final double window, final Censoring censoring)
	{
		return gather(plane, ps, e, group, profile, window, censoring, null);
	}

	/** {@link #gather}, the particles outside the group looked up in {@code nearby} (null: every one scanned) */
	static FitPixels gather(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile[] profile, final double window, final Censoring censoring, final Nearby nearby)
	{
		double R = 0;
		for (final int k : group)
			R = Math.max(R, profile[k].radius());
		final double W = Math.min(R, window);
		// The pixels: within each member's window (at its starting centre and scale), not clipped.
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (final int k : group) {
			final double reach = W * GroupFit.scaleOf(e[k]);
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
		final int n = group.length;
		final double[] gx = new double[n], gy = new double[n], reach2 = new double[n];
		for (int q = 0; q < n; q++) {
			final Estimate m = e[group[q]];
			final double reach = W * GroupFit.scaleOf(m);
			gx[q] = m.x();
			gy[q] = m.y();
			reach2[q] = reach * reach;
		}
		final int cap = Math.max(0, (x1 - x0 + 1) * (y1 - y0 + 1));
		final int[] px = new int[cap], py = new int[cap];
		final double[] pv = new double[cap];
		final int[] spans = new int[2 * n];
		int count = 0;
		for (int y = y0; y <= y1; y++) {
			final int m = spans(y, x0, x1, gx, gy, reach2, spans);
			for (int s = 0; s < m; s += 2) {
				final int a = spans[s], b = spans[s + 1];
				plane.read(a, b, y, y, pv, count);
				count = keep(censoring, y, a, b, px, py, pv, count);
			}
		}
		if (count == 0) return new FitPixels(px, py, pv, new double[0], 0, mx, my, unit); // (none: not fitted)
		return new FitPixels(px, py, pv, otherLight(RowRuns.of(px, py, count), count, x0, x1, py, ps, e, group, profile,
			nearby), count, mx, my, unit);
	}

	/**
	 * @return these pixels with the light of the particles outside {@code group} at their estimates {@code e} now
	 *         (the candidates of a member fitted in turn, from one sweep to the next): only the light of those whose
	 *         estimate changed since {@code lit} (the estimates the present light was drawn at, per particle; updated)
	 *         is taken out and drawn again, unless most changed. Most neighbours of a member have settled after a sweep
	 *         or two.
	 */
	FitPixels relit(final Particle[] ps, final Estimate[] e, final int[] group, final EmpiricalProfile[] profile,
		final Lit lit, final Nearby nearby, final RowRuns rows)
	{
		final Estimate[] at = lit.at();
		final int[] which = lit.which();
		int changed = 0;
		for (final int k : which)
			if (at[k] != e[k]) changed++;
		final double[] light;
		// most have moved: drawn afresh, once each rather than taken out and drawn again
		if (2 * changed > which.length) {
			final int[] xs = xRange();
			light = otherLight(rows, count, xs[0], xs[1], y, ps, e, group, profile, nearby);
			for (final int k : which)
				at[k] = e[k];
		}
		else {
			light = fixed.clone();
			for (final int k : which) {
				if (at[k] == e[k]) continue;
				light(rows, light, at[k], -1, profile[k]);
				light(rows, light, e[k], 1, profile[k]);
				at[k] = e[k];
			}
		}
		return withLight(light);
	}

	/**
	 * @return these pixels with other groups' light {@code light}: the plane's block and the extent of u, v kept, only
	 *         that of the light found again
	 */
	private FitPixels withLight(final double[] light) {
		double f0 = Double.POSITIVE_INFINITY, f1 = Double.NEGATIVE_INFINITY;
		final double[] relit = packed.clone(); // (only the light changes)
		for (int i = 0, o = PACKED - 1; i < count; i++, o += PACKED) {
			final double f = light[i];
			relit[o] = f;
			if (f < f0) f0 = f;
			if (f > f1) f1 = f;
		}
		final double[] e = extent.clone();
		e[4] = f0;
		e[5] = f1;
		return new FitPixels(x, y, value, light, count, u, v, backgroundBlock, e, candidates, relit);
	}

	/** Adds {@code sign} times the light of a particle at estimate {@code est} to {@code light}. */
	private static void light(final RowRuns rows, final double[] light, final Estimate est, final double sign,
		final EmpiricalProfile profile)
	{
		final double ks = GroupFit.scaleOf(est);
		rows.draw(light, est.x(), est.y(), ks, sign * GroupFit.amplitudeOf(est), profile.radius() * ks, profile);
	}

	/**
	 * @return the estimates the light of the particles outside {@code group} was drawn at by {@link #gather}, for
	 *         those near enough to matter (the others null)
	 */
	Lit litAt(final Particle[] ps, final Estimate[] e, final int[] group, final EmpiricalProfile[] profile,
		final Nearby nearby)
	{
		final Estimate[] lit = new Estimate[ps.length];
		if (count == 0) return new Lit(lit, new int[0]);
		final int[] xs = xRange();
		final int x0 = xs[0], x1 = xs[1], y0 = y[0], y1 = y[count - 1];
		final int[] near = nearby == null ? null : nearby.near(x0, x1, y0, y1, nearby.reach() + MOVE_IN + 1);
		final int[] which = new int[near == null ? ps.length : near.length];
		int m = 0;
		for (int i = 0; i < which.length; i++) {
			final int k = near == null ? i : near[i];
			if (!ps[k].reliable() || GroupFit.contains(group, k)) continue;
			// those whose light can reach these pixels at all (as in otherLight; a neighbour may move into reach)
			final double reach = profile[k].radius() * GroupFit.scaleOf(e[k]) + MOVE_IN;
			if (e[k].x() >= x0 - reach && e[k].x() <= x1 + reach && e[k].y() >= y0 - reach && e[k].y() <= y1 + reach) {
				lit[k] = e[k];
				which[m++] = k;
			}
		}
		return new Lit(lit, java.util.Arrays.copyOf(which, m));
	}

	/**
	 * The estimates the light of the particles outside a group was drawn at, per particle ({@code at}: null for
	 * those too far to matter), and the particles lit ({@code which}, in increasing order).
	 */
	record Lit(Estimate[] at, int[] which) {}

	/** @return the least and greatest x of the pixels (the rows are in order: their y are the first's and last's) */
	private int[] xRange() {
		int x0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE;
		for (int i = 0; i < count; i++) {
			if (x[i] < x0) x0 = x[i];
			if (x[i] > x1) x1 = x[i];
		}
		return new int[] { x0, x1 };
	}

	/** How far (px) a neighbour out of reach of a member's pixels may move towards them and still be followed. */
	private static final double MOVE_IN = 5;

	/**
	 * The light of the reliable particles outside the group, at their current centres, amplitudes and scales, on
	 * pixels in row order (x within {@code [x0, x1]}): each particle on the rows within its reach only.
	 */
	private static double[] otherLight(final RowRuns rows, final int count, final int x0, final int x1, final int[] py,
		final Particle[] ps, final Estimate[] e, final int[] group, final EmpiricalProfile[] profile,
		final Nearby nearby)
	{
		final double[] fixed = new double[count];
		if (count == 0) return fixed;
		final int y0 = py[0], y1 = py[count - 1];
		final int[] near = nearby == null ? null : nearby.near(x0, x1, y0, y1, nearby.reach() + 1);
		final int m = near == null ? ps.length : near.length;
		for (int i = 0; i < m; i++) {
			final int k = near == null ? i : near[i];
			if (!ps[k].reliable() || GroupFit.contains(group, k)) continue;
			final double kx = e[k].x(), ky = e[k].y(), ks = GroupFit.scaleOf(e[k]);
			final double reach = profile[k].radius() * ks;
			if (kx < x0 - reach || kx > x1 + reach || ky < y0 - reach || ky > y1 + reach) continue;
			rows.draw(fixed, kx, ky, ks, GroupFit.amplitudeOf(e[k]), reach, profile[k]);
		}
		return fixed;
	}

	/**
	 * The x ranges of row {@code y} within {@code [x0, x1]} where some member's window holds a pixel ({@code (x -
	 * gx)^2 + (y - gy)^2 < reach2}, the very test of a pixel: {@link RowRuns#chord}), merged and in increasing order,
	 * as pairs of inclusive ends in {@code out}; returns twice their number.
	 */
	private static int spans(final int y, final int x0, final int x1, final double[] gx, final double[] gy,
		final double[] reach2, final int[] out)
	{
		int m = 0;
		final int[] ends = new int[2];
		for (int q = 0; q < gx.length; q++) {
			final double dy = y - gy[q];
			if (!RowRuns.chord(gx[q], dy * dy, reach2[q], x0, x1, ends)) continue;
			int a = ends[0], b = ends[1];
			// insert [a, b] in order of start, merging overlapping or adjacent spans
			int i = 0;
			while (i < m && out[i + 1] < a - 1)
				i += 2;
			int j = i;
			while (j < m && out[j] <= b + 1) {
				a = Math.min(a, out[j]);
				b = Math.max(b, out[j + 1]);
				j += 2;
			}
			// spans i .. j-2 are merged into [a, b]
			System.arraycopy(out, j, out, i + 2, m - j);
			m += i + 2 - j;
			out[i] = a;
			out[i + 1] = b;
		}
		return m;
	}

	/**
	 * Keeps, of the values just read into {@code pv} from index {@code count} (row {@code y}, x from {@code a} to
	 * {@code b}), the unclipped ones with their positions, in order; returns the new count.
	 */
	private static int keep(final Censoring censoring, final int y, final int a, final int b, final int[] px,
		final int[] py, final double[] pv, int count)
	{
		for (int x = a, i = count; x <= b; x++, i++) {
			final double v = pv[i];
			if (censoring.clipped(v)) continue; // censored: its true value is unknown
			px[count] = x;
			py[count] = y;
			pv[count++] = v;
		}
		return count;
	}

	/**
	 * Marks every candidate used and returns true if cheap bounds on the model show that all are usable; else returns
	 * false and leaves {@code use} unchanged (the caller chooses from the model itself).
	 */
	static boolean allUsable(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile[] profile, final Censoring censoring, final boolean[] use)
	{
		if (!withinBounds(candidates, p, n, profile, censoring)) return false;
		java.util.Arrays.fill(use, true);
		return true;
	}

	/**
	 * Marks in {@code use} the candidates whose model value at parameters {@code p} the censoring rule keeps. Where
	 * the model at {@code p} is already known, on the pixels {@code known} (a subset of the candidates; {@code
	 * knownModels} in its order) from the fit's latest pass, only the other candidates are evaluated; both null: none
	 * known.
	 *
	 * @return whether any mark changed
	 */
	static boolean select(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile[] profile, final Censoring censoring, final boolean[] use, final FitPixels known,
		final double[] knownModels)
	{
		final int b0 = GroupFit.PER_PARTICLE * n;
		boolean changed = false;
		// usually no model value comes near a clip level (a shortcut where the model is not known already)
		if (known == null && withinBounds(candidates, p, n, profile, censoring)) {
			for (int i = 0; i < candidates.count(); i++) {
				changed |= !use[i];
				use[i] = true;
			}
			return changed;
		}
		final double[] models;
		if (known != null && known.count() == candidates.count()) models = knownModels; // known everywhere
		else {
			models = new double[candidates.count()];
			java.util.Arrays.fill(models, Double.NaN);
			if (known != null) for (int j = 0; j < known.count(); j++)
				models[known.candidate(j)] = knownModels[j];
		}
		for (int i = 0; i < candidates.count(); i++) {
			if (!Double.isNaN(models[i])) {
				final boolean usable = censoring.usable(models[i]);
				changed |= usable != use[i];
				use[i] = usable;
				continue;
			}
			double model = p[b0] + p[b0 + 1] * candidates.u()[i] + p[b0 + 2] * candidates.v()[i] + candidates.fixed()[i];
			for (int q = 0; q < n; q++) {
				final int b = GroupFit.PER_PARTICLE * q;
				final double dx = candidates.x()[i] - p[b], dy = candidates.y()[i] - p[b + 1];
				model += p[b + 2] * profile[q].lookup(Math.sqrt(dx * dx + dy * dy) / p[b + 3]);
			}
			final boolean usable = censoring.usable(model);
			changed |= usable != use[i];
			use[i] = usable;
		}
		return changed;
	}

	/**
	 * @return whether bounds on the model over all candidates, at no cost per pixel, lie where the censoring rule
	 *         keeps every pixel: the background plane at its extremes over the pixels' extent plus other groups'
	 *         light at its extremes, each member's light between its amplitude times the profile's least and
	 *         greatest values (or 0). Looser than the extremes of their sum; where they do not settle it, the caller
	 *         chooses from the model itself, with the same result.
	 */
	private static boolean withinBounds(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile[] profile, final Censoring censoring)
	{
		final int b0 = GroupFit.PER_PARTICLE * n;
		final double[] x = candidates.extent(); // u0, u1, v0, v1, f0, f1
		final double pu = p[b0 + 1], pv = p[b0 + 2];
		double lo = p[b0] + Math.min(pu * x[0], pu * x[1]) + Math.min(pv * x[2], pv * x[3]) + x[4];
		double hi = p[b0] + Math.max(pu * x[0], pu * x[1]) + Math.max(pv * x[2], pv * x[3]) + x[5];
		for (int q = 0; q < n; q++) {
			lo += profile[q].leastLight(p[GroupFit.PER_PARTICLE * q + 2]);
			hi += profile[q].greatestLight(p[GroupFit.PER_PARTICLE * q + 2]);
		}
		return censoring.usableBetween(lo, hi);
	}
}
