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
package io.github.contacttracker.core.image;

import io.github.contacttracker.core.math.UnionFind;

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Connectivity;

/**
 * Connected-component labelling of a binary image by runs: each row is cut into runs of foreground pixels,
 * runs touching a run of the row above (by an edge for 4-connectivity, also by a corner for 8) are joined with
 * union-find. Cost grows with the number of runs, not of pixels, once the rows are scanned.
 * <p>
 * Components are returned in raster order of their first pixel (top row first, then leftmost).
 */
public final class ComponentLabeling {

	private ComponentLabeling() {}

	/** Labels the pixels {@code >= threshold} of a plane, in the plane's local coordinates. */
	public static List<Region> label(final Plane plane, final double threshold, final Connectivity connectivity) {
		final RunList runs = new RunList();
		for (int y = 0; y < plane.height(); y++)
			plane.scanRow(y, threshold, runs);
		return label(runs, connectivity);
	}

	/** Groups runs in raster order into components. */
	static List<Region> label(final RunList runs, final Connectivity connectivity) {
		final int n = runs.size;
		final int[] parent = UnionFind.singletons(n);
		final int slack = connectivity == Connectivity.EIGHT ? 1 : 0;
		final int[] ys = runs.y, a = runs.x0, b = runs.x1;
		int prevStart = 0, prevEnd = 0; // runs of the previous row: [prevStart, prevEnd)
		int i = 0;
		while (i < n) {
			final int row = ys[i];
			int end = i;
			while (end < n && ys[end] == row)
				end++;
			if (prevEnd > prevStart && ys[prevStart] == row - 1) {
				int p = prevStart, c = i;
				while (p < prevEnd && c < end) {
					if (a[p] <= b[c] + slack && a[c] <= b[p] + slack) UnionFind.union(parent, p, c);
					// The run that ends first cannot touch any later run of the other row.
					if (b[p] < b[c]) p++;
					else c++;
				}
			}
			prevStart = i;
			prevEnd = end;
			i = end;
		}
		// Number the components in order of their first run; count runs and pixels.
		final int[] componentOfRoot = new int[n];
		java.util.Arrays.fill(componentOfRoot, -1);
		final int[] componentOfRun = new int[n];
		int count = 0;
		for (int r = 0; r < n; r++) {
			final int root = UnionFind.find(parent, r);
			if (componentOfRoot[root] < 0) componentOfRoot[root] = count++;
			componentOfRun[r] = componentOfRoot[root];
		}
		final int[] runCount = new int[count], area = new int[count];
		for (int r = 0; r < n; r++) {
			runCount[componentOfRun[r]]++;
			area[componentOfRun[r]] += b[r] - a[r] + 1;
		}
		final int[][] cy = new int[count][], c0 = new int[count][], c1 = new int[count][];
		for (int k = 0; k < count; k++) {
			cy[k] = new int[runCount[k]];
			c0[k] = new int[runCount[k]];
			c1[k] = new int[runCount[k]];
		}
		final int[] fill = new int[count];
		for (int r = 0; r < n; r++) {
			final int k = componentOfRun[r], f = fill[k]++;
			cy[k][f] = ys[r];
			c0[k][f] = a[r];
			c1[k][f] = b[r];
		}
		final List<Region> regions = new ArrayList<>(count);
		for (int k = 0; k < count; k++)
			regions.add(new Region(cy[k], c0[k], c1[k], area[k]));
		return regions;
	}
}
