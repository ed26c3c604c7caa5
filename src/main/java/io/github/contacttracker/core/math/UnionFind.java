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
package io.github.contacttracker.core.math;

/**
 * Disjoint sets over {@code 0..n-1} in a plain {@code int[]} of parents, each set's root its smallest member (so a
 * numbering by roots keeps the members' order): the connected runs of a labelling, the groups of a fit.
 */
public final class UnionFind {

	private UnionFind() {}

	/** @return {@code n} singletons */
	public static int[] singletons(final int n) {
		final int[] parent = new int[n];
		for (int i = 0; i < n; i++)
			parent[i] = i;
		return parent;
	}

	/** @return the root (smallest member) of {@code i}'s set; halves the path on the way */
	public static int find(final int[] parent, int i) {
		while (parent[i] != i) {
			parent[i] = parent[parent[i]];
			i = parent[i];
		}
		return i;
	}

	/** Joins the sets of {@code i} and {@code j}, the smaller root becoming the root of both. */
	public static void union(final int[] parent, final int i, final int j) {
		final int ri = find(parent, i), rj = find(parent, j);
		if (ri < rj) parent[rj] = ri;
		else if (rj < ri) parent[ri] = rj;
	}
}
