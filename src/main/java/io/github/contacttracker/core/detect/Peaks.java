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
package io.github.contacttracker.core.detect;

import java.util.Arrays;

import io.github.contacttracker.core.math.Statistics;

/**
 * The peaks of a (band-passed) image that stand out: local maxima at least {@code level} high whose
 * <em>prominence</em>, the drop from the peak to the highest saddle over which a higher peak is reached, is at least
 * {@code prominence}. Two touching particles keep their two peaks as long as the image dips between them by the
 * prominence, however close they are and whatever a global threshold would do; the noise on a particle's flat top
 * makes bumps of little prominence, which are not peaks. Computed by flooding the pixels above {@code floor} from
 * the highest down (union-find): when two lit areas meet at a pixel, the lower peak's prominence is its height
 * above that pixel. Peaks are returned highest first, at sub-pixel positions (a parabola through the peak pixel
 * and its neighbours along each axis).
 *
 * @param x the peaks' x (px)
 * @param y the peaks' y (px)
 * @param height the image's value at each peak's pixel
 * @param prominence each peak's prominence (a peak never joined to a higher one: its height above the floor)
 */
public record Peaks(double[] x, double[] y, double[] height, double[] prominence) {

	/** No peak. */
	static final Peaks NONE = new Peaks(new double[0], new double[0], new double[0], new double[0]);

	/** Which quantile of the heights is a typical strong peak's: high, but not the single highest of many. */
	public static final double STRONG_QUANTILE = 0.9;

	/**
	 * @return the height of a typical strong peak: the 90th percentile of the heights ({@link Statistics#quantile});
	 *         0 without peaks
	 */
	public double typicalHeight() {
		return height.length == 0 ? 0 : Statistics.quantile(height.clone(), STRONG_QUANTILE);
	}

	/**
	 * @return the peaks at least {@code least} high with no higher peak within {@code within} px, highest first
	 *         (peaks are kept in order, each against those kept before it)
	 */
	public Peaks sparse(final double within, final double least) {
		final boolean[] keep = new boolean[x.length];
		int n = 0;
		for (int i = 0; i < x.length; i++) {
			if (!(height[i] >= least)) continue;
			boolean free = true;
			for (int j = 0; j < i && free; j++)
				free = !keep[j] || (x[j] - x[i]) * (x[j] - x[i]) + (y[j] - y[i]) * (y[j] - y[i]) >= within * within;
			if (free) {
				keep[i] = true;
				n++;
			}
		}
		final double[] kx = new double[n], ky = new double[n], kh = new double[n], kp = new double[n];
		for (int i = 0, k = 0; i < x.length; i++)
			if (keep[i]) {
				kx[k] = x[i];
				ky[k] = y[i];
				kh[k] = height[i];
				kp[k++] = prominence[i];
			}
		return new Peaks(kx, ky, kh, kp);
	}

	/**
	 * @param quantile which of the distances (0.5: the median)
	 * @return that quantile of the distances from a peak to its nearest neighbour among the peaks (px): the
	 *         particles' spacing where each peak is one; infinite with fewer than two peaks
	 */
	public double spacing(final double quantile) {
		final int n = x.length;
		if (n < 2) return Double.POSITIVE_INFINITY;
		final double[] nearest = new double[n];
		for (int i = 0; i < n; i++) {
			double best = Double.POSITIVE_INFINITY;
			for (int j = 0; j < n; j++)
				if (j != i) best = Math.min(best, (x[i] - x[j]) * (x[i] - x[j]) + (y[i] - y[j]) * (y[i] - y[j]));
			nearest[i] = Math.sqrt(best);
		}
		return Statistics.quantile(nearest, quantile);
	}

	/**
	 * @param ratio how many times higher the strong peaks stand than every other ({@code > 1})
	 * @return the height of the peaks that stand apart ({@link #standingApart}): where some do, the
	 *         {@link #STRONG_QUANTILE} quantile of theirs (a tweezer's one bead among the background's bumps: its own
	 *         height, where the quantile of all its seeds lies between the two highest); else {@link #typicalHeight}
	 */
	public double standingHeight(final double ratio) {
		final int apart = standingApart(ratio);
		return apart < height.length ? Statistics.quantile(Arrays.copyOf(height, apart), STRONG_QUANTILE)
			: typicalHeight();
	}

	/**
	 * @param ratio how many times higher the strong peaks stand than every other ({@code > 1})
	 * @return how many of the highest peaks stand at least {@code ratio} times as high as each lower one (the
	 *         peaks being highest first): where the heights fall by that factor from one peak to the next, the count
	 *         above the first such fall; every peak where none falls that far
	 */
	public int standingApart(final double ratio) {
		for (int i = 1; i < height.length; i++)
			if (height[i - 1] > ratio * height[i]) return i;
		return height.length;
	}

	/** @return the number of peaks */
	public int count() {
		return x.length;
	}

	/**
	 * @param image the image, row-major
	 * @param w its width
	 * @param h its height
	 * @param floor pixels at or below it take no part (a saddle that low separates peaks for good)
	 * @param level the least height of a peak
	 * @param prominence the least prominence of a peak
	 * @return the peaks, highest first
	 */
	public static Peaks find(final float[] image, final int w, final int h, final double floor, final double level,
		final double prominence)
	{
		// a peak of at least `level` whose saddle lies below level - prominence is prominent enough whatever that
		// saddle is: flooding from there on decides the same peaks, on far fewer pixels
		return flood(image, w, h, Math.max(floor, level - prominence), level, prominence);
	}

	private static Peaks flood(final float[] image, final int w, final int h, final double floor, final double level,
		final double prominence)
	{
		// the pixels above the floor, sorted by value, highest first: a float's bits (positive values order as ints,
		// so shifted to be positive) above its index, in one long each
		int n = 0;
		for (final float v : image)
			if (v > floor) n++;
		final long[] order = new long[n];
		n = 0;
		for (int i = 0; i < image.length; i++)
			if (image[i] > floor) order[n++] = (long) sortable(image[i]) << 32 | i;
		Arrays.sort(order);
		final int[] parent = new int[image.length];
		Arrays.fill(parent, -1); // -1: not yet flooded
		// per root: the pixel of its peak
		final int[] peakOf = new int[image.length];
		final float[] prom = new float[image.length];
		Arrays.fill(prom, Float.NaN);
		for (int o = n - 1; o >= 0; o--) {
			final int i = (int) order[o];
			final int x = i % w, y = i / w;
			parent[i] = i;
			peakOf[i] = i;
			for (int dy = -1; dy <= 1; dy++) {
				final int yy = y + dy;
				if (yy < 0 || yy >= h) continue;
				for (int dx = -1; dx <= 1; dx++) {
					final int xx = x + dx;
					if (xx < 0 || xx >= w || dx == 0 && dy == 0) continue;
					final int j = yy * w + xx;
					if (parent[j] < 0) continue;
					final int a = root(parent, i), b = root(parent, j);
					if (a == b) continue;
					// the lower of the two peaks ends here: its prominence is its height above this saddle
					final int pa = peakOf[a], pb = peakOf[b];
					final boolean aHigher = image[pa] > image[pb] || image[pa] == image[pb] && pa < pb;
					final int low = aHigher ? pb : pa;
					prom[low] = image[low] - image[i];
					if (aHigher) parent[b] = a;
					else parent[a] = b;
				}
			}
		}
		// the peaks never joined to a higher one
		for (int o = 0; o < n; o++) {
			final int i = (int) order[o];
			if (root(parent, i) == i) prom[peakOf[i]] = (float) (image[peakOf[i]] - floor);
		}
		int count = 0;
		for (int o = n - 1; o >= 0; o--) {
			final int i = (int) order[o];
			if (!Float.isNaN(prom[i]) && prom[i] >= prominence && image[i] >= level) count++;
		}
		final double[] px = new double[count], py = new double[count], ph = new double[count], pp = new double[count];
		int k = 0;
		for (int o = n - 1; o >= 0 && k < count; o--) {
			final int i = (int) order[o];
			if (Float.isNaN(prom[i]) || prom[i] < prominence || image[i] < level) continue;
			final int x = i % w, y = i / w;
			px[k] = x + vertex(image, i, x > 0 ? i - 1 : i, x < w - 1 ? i + 1 : i);
			py[k] = y + vertex(image, i, y > 0 ? i - w : i, y < h - 1 ? i + w : i);
			ph[k] = image[i];
			pp[k] = prom[i];
			k++;
		}
		return new Peaks(px, py, ph, pp);
	}

	/** @return the offset (within half a pixel) of the vertex of the parabola through three samples */
	private static double vertex(final float[] image, final int at, final int before, final int after) {
		final double a = image[before], b = image[at], c = image[after];
		final double curvature = a - 2 * b + c;
		if (!(curvature < 0)) return 0;
		return Math.max(-0.5, Math.min(0.5, 0.5 * (a - c) / curvature));
	}

	private static int root(final int[] parent, int i) {
		while (parent[i] != i) {
			parent[i] = parent[parent[i]];
			i = parent[i];
		}
		return i;
	}

	/** @return an int that orders as the float does (for any finite float) */
	private static int sortable(final float v) {
		final int bits = Float.floatToIntBits(v);
		return bits >= 0 ? bits : bits ^ 0x7fffffff;
	}
}
