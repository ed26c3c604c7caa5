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

import java.util.Arrays;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.image.RunList;

/**
 * The paper's second pass: each particle solved again on its active area outside the other particles' discs of
 * radius {@code r_out}. {@link #PAPER} does it once, around the first-pass centres; {@link #ITERATIVE} repeats it
 * with the discs around the latest centres until no centre moves more than {@value #TOLERANCE} px.
 */
public final class SecondPass {

	/** Upper bound on the passes of the iterative method. */
	static final int MAX_ITERATIONS = 100;
	/** The iterative method stops when no centre moves more than this between passes (px). */
	static final double TOLERANCE = 1e-4;

	/** The {@code paper} method. */
	public static final Refinement PAPER = (plane, ps, params, profile, noise) -> {
		final double[][] discs = centres(firsts(ps));
		return new Refinement.Outcome(passes(ps, discs, params), discs);
	};

	/** The {@code iterative} method. */
	public static final Refinement ITERATIVE = (plane, ps, params, profile, noise) -> iterate(ps, params);

	private SecondPass() {}

	static Estimate[] firsts(final Particle[] ps) {
		final Estimate[] e = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++)
			e[k] = ps[k].first();
		return e;
	}

	static double[][] centres(final Estimate[] e) {
		final double[][] c = new double[2][e.length];
		for (int k = 0; k < e.length; k++) {
			c[0][k] = e[k].x();
			c[1][k] = e[k].y();
		}
		return c;
	}

	/** One second pass for every particle, with discs around {@code discs}. */
	private static Estimate[] passes(final Particle[] ps, final double[][] discs, final TrackerParameters params) {
		final Estimate[] e = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++)
			e[k] = pass(ps[k], k, discs[0], discs[1], params);
		return e;
	}

	/** The iterative method: second passes with discs around the latest centres until they settle. */
	public static Refinement.Outcome iterate(final Particle[] ps, final TrackerParameters params) {
		Estimate[] current = firsts(ps);
		double[][] discs = centres(current);
		for (int it = 1; it <= MAX_ITERATIONS; it++) {
			final Estimate[] next = passes(ps, discs, params);
			double move = 0;
			for (int k = 0; k < ps.length; k++) {
				move = Math.max(move, next[k].distanceTo(current[k]));
				if (next[k].has(Flag.SECOND_PASS)) next[k] = next[k].withIterations(it + 1);
			}
			current = next;
			if (move < TOLERANCE) return new Refinement.Outcome(current, discs);
			discs = centres(current);
		}
		for (int k = 0; k < ps.length; k++)
			if (current[k].has(Flag.SECOND_PASS)) current[k] = current[k].withFlags(current[k].flags() | Flag.NOT_CONVERGED
				.bit());
		return new Refinement.Outcome(current, discs);
	}

	/**
	 * The second pass of particle {@code self} with discs around (cx, cy): its first-pass centre when nothing is
	 * excluded or the pass falls back (flagged), else the solve on the pixels outside the discs.
	 */
	private static Estimate pass(final Particle p, final int self, final double[] cx, final double[] cy,
		final TrackerParameters params)
	{
		final Estimate first = p.first();
		final int area = p.region().area();
		final double exclusion = params.exclusionRadius();
		final int[] near = neighboursReaching(p.region(), self, cx, cy, exclusion);
		if (near.length == 0) return first; // nothing to exclude: the first centre is final
		final double r2 = exclusion * exclusion;
		final int secondArea = countOutside(p.region(), near, cx, cy, r2);
		if (secondArea == area) return first;
		if (secondArea < params.minSecondArea())
			return new Estimate(first.x(), first.y(), first.flags() | Flag.FELL_BACK.bit(), secondArea, first.iterations(),
				first.solve(), Double.NaN, Double.NaN);
		final GradientField field = p.field();
		final boolean[] use = new boolean[field.size];
		for (int i = 0; i < field.size; i++)
			use[i] = outside(field.x[i], field.y[i], near, cx, cy, r2);
		final Solve s = p.solve(use);
		if (!s.ok()) return new Estimate(first.x(), first.y(), first.flags() | Flag.FELL_BACK.bit() | Flag.DEGENERATE
			.bit(), secondArea, first.iterations(), first.solve(), Double.NaN, Double.NaN);
		return new Estimate(s.solution().x(), s.solution().y(), first.flags() | Flag.SECOND_PASS.bit(), secondArea, 2, s,
			Double.NaN, Double.NaN);
	}

	/** @return indices of the other particles whose disc can reach the region's bounding box */
	private static int[] neighboursReaching(final Region region, final int self, final double[] cx,
		final double[] cy, final double r)
	{
		int[] out = new int[4];
		int n = 0;
		for (int h = 0; h < cx.length; h++) {
			if (h == self) continue;
			final double dx = Math.max(0, Math.max(region.minX() - cx[h], cx[h] - region.maxX()));
			final double dy = Math.max(0, Math.max(region.minY() - cy[h], cy[h] - region.maxY()));
			if (dx * dx + dy * dy <= r * r) {
				if (n == out.length) out = Arrays.copyOf(out, 2 * n);
				out[n++] = h;
			}
		}
		return Arrays.copyOf(out, n);
	}

	private static boolean outside(final int x, final int y, final int[] near, final double[] cx, final double[] cy,
		final double r2)
	{
		for (final int h : near) {
			final double dx = x - cx[h], dy = y - cy[h];
			if (dx * dx + dy * dy <= r2) return false;
		}
		return true;
	}

	private static int countOutside(final Region region, final int[] near, final double[] cx, final double[] cy,
		final double r2)
	{
		int count = 0;
		for (int r = 0; r < region.runCount(); r++)
			for (int x = region.runStart(r); x <= region.runEnd(r); x++)
				if (outside(x, region.runY(r), near, cx, cy, r2)) count++;
		return count;
	}

	/**
	 * The part of particle {@code self}'s active area outside the other particles' discs, for display.
	 *
	 * @param exclusion the discs' radius (px): {@link TrackerParameters#exclusionRadius()}
	 */
	public static Region secondRegion(final Region region, final int self, final double[][] discs,
		final double exclusion)
	{
		if (discs == null) return region;
		final double[] cx = discs[0], cy = discs[1];
		final int[] near = neighboursReaching(region, self, cx, cy, exclusion);
		final double r2 = exclusion * exclusion;
		final RunList runs = new RunList();
		for (int r = 0; r < region.runCount(); r++) {
			final int y = region.runY(r);
			runs.addWhere(y, region.runStart(r), region.runEnd(r), x -> outside(x, y, near, cx, cy, r2));
		}
		return runs.toRegion();
	}
}
