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

import java.util.Arrays;

/** A growable list of horizontal runs {@code (y, x0..x1)}, inclusive, appended in raster order. */
public final class RunList {
	int size;
	int[] y = new int[64];
	int[] x0 = new int[64];
	int[] x1 = new int[64];

	/** Appends the runs of pixels {@code x0..x1} of {@code row} for which {@code inside} holds. */
	public void addWhere(final int row, final int x0, final int x1, final java.util.function.IntPredicate inside) {
		int start = -1;
		for (int x = x0; x <= x1; x++) {
			if (inside.test(x)) {
				if (start < 0) start = x;
			}
			else if (start >= 0) {
				add(row, start, x - 1);
				start = -1;
			}
		}
		if (start >= 0) add(row, start, x1);
	}

	/** @return the runs as a region (they must be in raster order) */
	public Region toRegion() {
		return new Region(Arrays.copyOf(y, size), Arrays.copyOf(x0, size), Arrays.copyOf(x1, size));
	}

	public void add(final int row, final int start, final int end) {
		if (size == y.length) {
			final int n = size * 2;
			y = Arrays.copyOf(y, n);
			x0 = Arrays.copyOf(x0, n);
			x1 = Arrays.copyOf(x1, n);
		}
		y[size] = row;
		x0[size] = start;
		x1[size] = end;
		size++;
	}
}
