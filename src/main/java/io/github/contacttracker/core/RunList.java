package io.github.contacttracker.core;

import java.util.Arrays;

/** A growable list of horizontal runs {@code (y, x0..x1)}, inclusive, appended in raster order. */
final class RunList {
	int size;
	int[] y = new int[64];
	int[] x0 = new int[64];
	int[] x1 = new int[64];

	void add(final int row, final int start, final int end) {
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
