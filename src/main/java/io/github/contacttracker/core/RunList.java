package io.github.contacttracker.core;

import java.util.Arrays;

/** A growable list of horizontal runs {@code (y, x0..x1)}, inclusive, appended in raster order. */
final class RunList {
	int size;
	int[] y = new int[64];
	int[] x0 = new int[64];
	int[] x1 = new int[64];

	/** Appends the runs of pixels {@code x0..x1} of {@code row} for which {@code inside} holds. */
	void addWhere(final int row, final int x0, final int x1, final java.util.function.IntPredicate inside) {
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
	Region toRegion() {
		return new Region(Arrays.copyOf(y, size), Arrays.copyOf(x0, size), Arrays.copyOf(x1, size));
	}

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
