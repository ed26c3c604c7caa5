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
import io.github.contacttracker.core.radial.Estimate;

import java.util.Arrays;

/**
 * A frame's particles binned by their current centres on a square grid, so that a member fitted in turn
 * ({@link MemberSweeps}) finds the particles whose light may reach its pixels among a few cells instead of among
 * every particle of the frame: in a packed field of 1,600 particles each member's fit scanned them all, several times
 * a fit, which made the sweeps' cost grow as the square of the field. Its owner keeps it current as centres move
 * ({@link #moved}).
 * <p>
 * What it gives is a superset, in increasing order, of the particles whose centre lies within a box grown by the
 * largest reach of any particle's light ({@link #reach}): the callers apply their own tests to it, so that their
 * tests and sums run over the same particles in the same order as over every particle, to the last bit. A centre that
 * is not a finite number (or a particle without an estimate) is always a candidate (no test excludes it).
 */
final class Nearby {

	/**
	 * From this many particles in a frame the grid pays: below it a scan of every particle costs no more than the
	 * grid's lookups (the paper authors' {@code 1.avi}, about 90 particles a frame: no faster with it; a public
	 * monolayer of 474: 0.88 of the time; a simulated one of 1,578: half).
	 */
	static final int WORTH = 200;

	private final double cell;
	private final int nx, ny;
	/** per cell, its first particle (-1: none); per particle, the next and previous in its cell, and its cell */
	private final int[] head, next, previous, cellOf;
	private final double[] radius;
	/** particles whose centre is not finite (cell -1), in increasing order */
	private int[] loose = new int[0];
	private double reach;
	private int[] buffer = new int[16];

	/**
	 * @param e each particle's estimate
	 * @param profile each particle's profile (its kind's): its light reaches {@code radius() * scale}
	 * @param width the frame's width (px): centres beyond the frame fall in its edge cells
	 * @param height the frame's height (px)
	 */
	Nearby(final Estimate[] e, final EmpiricalProfile[] profile, final int width, final int height) {
		final int n = e.length;
		radius = new double[n];
		for (int k = 0; k < n; k++) {
			radius[k] = profile[k].radius();
			reach = Math.max(reach, reach(k, e[k]));
		}
		// cells as wide as the widest reach (a box's neighbours lie in the cells around it), and no more cells than
		// particles (a large frame of small particles: memory as the particles', not the frame's)
		cell = Math.max(Math.max(1, reach), Math.sqrt((double) Math.max(1, width) * Math.max(1, height) / Math.max(1,
			n)));
		nx = (int) Math.ceil(Math.max(1, width) / cell);
		ny = (int) Math.ceil(Math.max(1, height) / cell);
		head = new int[nx * ny];
		Arrays.fill(head, -1);
		next = new int[n];
		previous = new int[n];
		cellOf = new int[n];
		for (int k = n - 1; k >= 0; k--)
			insert(k, e[k]);
	}

	/** @return how far the light of particle {@code k} at estimate {@code at} reaches, as the fit computes it */
	private double reach(final int k, final Estimate at) {
		return at == null ? 0 : radius[k] * GroupFit.scaleOf(at);
	}

	/**
	 * @return at least the largest reach of any particle's light since this grid was made ({@code radius() * scale}):
	 *         a particle farther than this from a box sheds no light into it
	 */
	double reach() {
		return reach;
	}

	/** Particle {@code k} is now at {@code now}. */
	void moved(final int k, final Estimate now) {
		reach = Math.max(reach, reach(k, now));
		final int c = cellOf(now);
		if (c == cellOf[k] && c >= 0) return;
		remove(k);
		insert(k, now);
	}

	/**
	 * @return the particles whose centre may lie within {@code [x0 - grow, x1 + grow] x [y0 - grow, y1 + grow]}, in
	 *         increasing order: every one that does, and others near it
	 */
	int[] near(final double x0, final double x1, final double y0, final double y1, final double grow) {
		final int m = gather(x0, x1, y0, y1, grow);
		Arrays.sort(buffer, 0, m);
		return Arrays.copyOf(buffer, m);
	}

	/** @return {@link #near}'s particles in no particular order (for a test whose verdict does not depend on it) */
	int[] nearInAnyOrder(final double x0, final double x1, final double y0, final double y1, final double grow) {
		return Arrays.copyOf(buffer, gather(x0, x1, y0, y1, grow));
	}

	/** @return how many particles {@link #near} gives, put in the buffer's first places */
	private int gather(final double x0, final double x1, final double y0, final double y1, final double grow) {
		final double a = x0 - grow, b = x1 + grow, c = y0 - grow, d = y1 + grow;
		final boolean box = !Double.isNaN(a + b + c + d); // (a bound not a number: the whole grid)
		final int cx0 = box ? column(a) : 0, cx1 = box ? column(b) : nx - 1, cy0 = box ? row(c) : 0, cy1 = box ? row(d)
			: ny - 1;
		int m = 0;
		for (final int k : loose)
			m = add(k, m);
		for (int cy = cy0; cy <= cy1; cy++)
			for (int cx = cx0; cx <= cx1; cx++)
				for (int k = head[cy * nx + cx]; k >= 0; k = next[k])
					m = add(k, m);
		return m;
	}

	private int add(final int k, final int m) {
		if (m == buffer.length) buffer = Arrays.copyOf(buffer, 2 * m);
		buffer[m] = k;
		return m + 1;
	}

	/** @return the cell of a centre, or -1 where it is not finite (clamped to the grid: monotone in x and y) */
	private int cellOf(final Estimate at) {
		if (at == null) return -1;
		final double x = at.x(), y = at.y();
		if (!Double.isFinite(x) || !Double.isFinite(y)) return -1;
		return row(y) * nx + column(x);
	}

	private int column(final double x) {
		return clamp(Math.floor(x / cell), nx);
	}

	private int row(final double y) {
		return clamp(Math.floor(y / cell), ny);
	}

	private static int clamp(final double c, final int n) {
		return c >= n - 1 ? n - 1 : c >= 0 ? (int) c : 0;
	}

	private void insert(final int k, final Estimate at) {
		final int c = cellOf(at);
		cellOf[k] = c;
		if (c < 0) {
			final int[] more = Arrays.copyOf(loose, loose.length + 1);
			more[loose.length] = k;
			Arrays.sort(more);
			loose = more;
			return;
		}
		previous[k] = -1;
		next[k] = head[c];
		if (head[c] >= 0) previous[head[c]] = k;
		head[c] = k;
	}

	private void remove(final int k) {
		final int c = cellOf[k];
		if (c < 0) {
			int i = 0;
			while (loose[i] != k)
				i++;
			final int[] fewer = new int[loose.length - 1];
			System.arraycopy(loose, 0, fewer, 0, i);
			System.arraycopy(loose, i + 1, fewer, i, fewer.length - i);
			loose = fewer;
			return;
		}
		if (previous[k] >= 0) next[previous[k]] = next[k];
		else head[c] = next[k];
		if (next[k] >= 0) previous[next[k]] = previous[k];
	}
}
