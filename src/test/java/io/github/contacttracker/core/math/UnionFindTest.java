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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

class UnionFindTest {

	/** Every member finds its set's smallest member, whatever the order of the unions. */
	@Test
	void rootsAreTheSmallestMembers() {
		final int[] parent = UnionFind.singletons(7);
		UnionFind.union(parent, 5, 3);
		UnionFind.union(parent, 6, 5);
		UnionFind.union(parent, 4, 1);
		UnionFind.union(parent, 6, 1);
		final int[] roots = new int[7];
		for (int i = 0; i < 7; i++)
			roots[i] = UnionFind.find(parent, i);
		assertArrayEquals(new int[] { 0, 1, 2, 1, 1, 1, 1 }, roots);
	}
}
