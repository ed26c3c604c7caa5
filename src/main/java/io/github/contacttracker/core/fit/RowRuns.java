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

/**
 * A fit's pixels, in row order, as runs: the pixels of one row at consecutive x. The light of a particle outside the
 * fit is drawn on them row by row, over the x range within the particle's reach only: found once a row rather than
 * tested at every pixel, and without reading each pixel's position. On a dense field this drawing, every neighbour
 * on every member's pixels, is most of the fit's work. The pixels drawn and the sums are those of a test per pixel, to
 * the last bit.
 */
final class RowRuns {

	/** Per run: its row, the x of its first pixel, the index of its first pixel, its length. */
	private final int[] runs;

	private RowRuns(final int[] runs) {
		this.runs = runs;
	}

	/** @return the runs of pixels {@code 0 .. count-1} at {@code (px, py)}, in row order */
	static RowRuns of(final int[] px, final int[] py, final int count) {
		int m = 0;
		for (int i = 0; i < count; i++)
			if (starts(px, py, i)) m++;
		final int[] runs = new int[4 * m];
		for (int i = 0, r = -4; i < count; i++) {
			if (starts(px, py, i)) {
				r += 4;
				runs[r] = py[i];
				runs[r + 1] = px[i];
				runs[r + 2] = i;
			}
			runs[r + 3]++;
		}
		return new RowRuns(runs);
	}

	private static boolean starts(final int[] px, final int[] py, final int i) {
		return i == 0 || py[i] != py[i - 1] || px[i] != px[i - 1] + 1;
	}

	/**
	 * Adds to {@code light} (one value per pixel) the light of a particle at {@code (kx, ky)}, scale {@code ks} and
	 * amplitude {@code ka} on the pixels within {@code reach} (px) of it: {@code ka P(d / ks)}, P read from the
	 * profile's table as {@link EmpiricalProfile#lookup} reads it.
	 */
	void draw(final double[] light, final double kx, final double ky, final double ks, final double ka,
		final double reach, final EmpiricalProfile profile)
	{
		final double reach2 = reach * reach, perStep = 1 / (ks * EmpiricalProfile.TABLE_STEP);
		final double[] table = profile.valueTable();
		final int[] ends = new int[2];
		for (int r = 0; r < runs.length; r += 4) {
			final double dy = runs[r] - ky, dy2 = dy * dy;
			final int x0 = runs[r + 1];
			if (chord(kx, dy2, reach2, x0, x0 + runs[r + 3] - 1, ends)) row(light, runs[r + 2] - x0, ends[0], ends[1], kx,
				dy2, perStep, ka, table);
		}
	}

	/**
	 * The pixels of a row within a disc, where they meet {@code [lo, hi]}: the x with {@code (x - cx)^2 + dy2 <
	 * reach2}, the very test of a pixel, which holds on one range of x (the test grows with {@code |x - cx|}). Its ends
	 * come from the root, then are made exact by the test itself (a step or none: the root errs by far less than a
	 * pixel).
	 *
	 * @param dy2 the row's squared distance from the disc's centre
	 * @param ends receives the first and the last x
	 * @return whether any pixel of {@code [lo, hi]} is within
	 */
	static boolean chord(final double cx, final double dy2, final double reach2, final int lo, final int hi,
		final int[] ends)
	{
		if (!(dy2 < reach2)) return false; // (every pixel of the row is out of reach)
		final double half = Math.sqrt(reach2 - dy2);
		int a = (int) Math.max(lo, Math.min(hi + 1, Math.ceil(cx - half)));
		int b = (int) Math.min(hi, Math.max(lo - 1, Math.floor(cx + half)));
		while (a > lo && within(a - 1, cx, dy2, reach2))
			a--;
		while (b < hi && within(b + 1, cx, dy2, reach2))
			b++;
		while (a <= b && !within(a, cx, dy2, reach2))
			a++;
		while (b >= a && !within(b, cx, dy2, reach2))
			b--;
		ends[0] = a;
		ends[1] = b;
		return a <= b;
	}

	/** The test of a pixel at {@code x} on a row {@code dy2} (squared) from the centre: within reach. */
	private static boolean within(final int x, final double cx, final double dy2, final double reach2) {
		final double dx = x - cx;
		return dx * dx + dy2 < reach2;
	}

	/** Adds the light to the pixels at {@code x = a .. b} of one row, pixel {@code x} at {@code offset + x}. */
	private static void row(final double[] light, final int offset, final int a, final int b, final double kx,
		final double dy2, final double perStep, final double ka, final double[] table)
	{
		final int last = table.length - 1;
		// x also counted as a double, exactly (any pixel index is): the server compiler of Java 17 converts an int to
		// a double by writing half a register, which made each pixel wait for the last one's root, and this loop five
		// times slower (24 against 4.5 ns a pixel; Java 25's compiler does not). Every pixel loop that takes a root
		// counts so.
		double xd = a;
		for (int x = a; x <= b; x++, xd++) {
			final double dx = xd - kx, d2 = dx * dx + dy2;
			final double t = Math.sqrt(d2) * perStep;
			final int k = (int) t;
			if (k < last) light[offset + x] += ka * (table[k] + (t - k) * (table[k + 1] - table[k]));
		}
	}
}
