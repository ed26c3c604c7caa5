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

/**
 * An immutable set of pixels stored as horizontal runs in raster order (row by row, left to right): an active
 * area, a second active area, a labelled component. Coordinates are pixel indices.
 */
public final class Region {

	/** Receives the pixels of a region. */
	@FunctionalInterface
	public interface PixelConsumer {
		void accept(int x, int y);
	}

	private final int[] ys;
	private final int[] x0s;
	private final int[] x1s;
	private final int area;

	/** Runs must be in raster order and not overlap; arrays are copied. */
	public Region(final int[] ys, final int[] x0s, final int[] x1s) {
		if (ys.length != x0s.length || ys.length != x1s.length)
			throw new IllegalArgumentException("run arrays differ in length");
		this.ys = ys.clone();
		this.x0s = x0s.clone();
		this.x1s = x1s.clone();
		int a = 0;
		for (int i = 0; i < ys.length; i++) {
			if (x1s[i] < x0s[i]) throw new IllegalArgumentException("empty run at row " + ys[i]);
			if (i > 0 && (ys[i] < ys[i - 1] || ys[i] == ys[i - 1] && x0s[i] <= x1s[i - 1]))
				throw new IllegalArgumentException("runs not in raster order at row " + ys[i]);
			a += x1s[i] - x0s[i] + 1;
		}
		area = a;
	}

	/** Trusted constructor: takes ownership of the arrays. */
	Region(final int[] ys, final int[] x0s, final int[] x1s, final int area) {
		this.ys = ys;
		this.x0s = x0s;
		this.x1s = x1s;
		this.area = area;
	}

	/** @return the number of pixels */
	public int area() {
		return area;
	}

	/** @return the number of runs */
	public int runCount() {
		return ys.length;
	}

	/** @return the row of run {@code i} */
	public int runY(final int i) {
		return ys[i];
	}

	/** @return the first column of run {@code i} */
	public int runStart(final int i) {
		return x0s[i];
	}

	/** @return the last column of run {@code i} (inclusive) */
	public int runEnd(final int i) {
		return x1s[i];
	}

	/** @return whether the pixel belongs to the region */
	public boolean contains(final int x, final int y) {
		// Binary search for the first run of row y.
		int lo = 0, hi = ys.length;
		while (lo < hi) {
			final int mid = (lo + hi) >>> 1;
			if (ys[mid] < y) lo = mid + 1;
			else hi = mid;
		}
		for (int i = lo; i < ys.length && ys[i] == y; i++)
			if (x >= x0s[i] && x <= x1s[i]) return true;
		return false;
	}

	/** Calls {@code consumer} for every pixel in raster order. */
	public void forEachPixel(final PixelConsumer consumer) {
		for (int i = 0; i < ys.length; i++)
			for (int x = x0s[i]; x <= x1s[i]; x++)
				consumer.accept(x, ys[i]);
	}

	/** @return the smallest x, or 0 for an empty region */
	public int minX() {
		int m = Integer.MAX_VALUE;
		for (final int v : x0s)
			m = Math.min(m, v);
		return ys.length == 0 ? 0 : m;
	}

	/** @return the largest x, or -1 for an empty region */
	public int maxX() {
		int m = Integer.MIN_VALUE;
		for (final int v : x1s)
			m = Math.max(m, v);
		return ys.length == 0 ? -1 : m;
	}

	/** @return the smallest y, or 0 for an empty region */
	public int minY() {
		return ys.length == 0 ? 0 : ys[0];
	}

	/** @return the largest y, or -1 for an empty region */
	public int maxY() {
		return ys.length == 0 ? -1 : ys[ys.length - 1];
	}

	/** @return this region moved by (dx, dy) pixels */
	public Region translate(final int dx, final int dy) {
		final int[] y = ys.clone(), a = x0s.clone(), b = x1s.clone();
		for (int i = 0; i < y.length; i++) {
			y[i] += dy;
			a[i] += dx;
			b[i] += dx;
		}
		return new Region(y, a, b, area);
	}
}
