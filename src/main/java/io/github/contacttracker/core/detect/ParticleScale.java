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

import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;

/**
 * The particles' diameter read from a frame without isolating any particle: the scale at which the frame's bright
 * blobs answer a scale-normalised Laplacian of Gaussian most strongly (Lindeberg's scale selection). For a disc of
 * radius {@code R} the response {@code -s^2 (Laplacian of G_s * I)} at its centre is largest at {@code s = R / sqrt 2},
 * for a Gaussian spot of standard deviation {@code s0} at {@code s = s0}; both hold for particles that touch, whose
 * centres stay maxima of the response at their own scale. The blobs are the maxima of the response over position
 * and scale together; the diameter is {@code 2 sqrt 2} times the median scale of the strong ones (at least half as
 * strong as the 90th percentile), so that a dense monolayer, a cluster and a sparse field are all measured the same
 * way, and the noise's small maxima do not count.
 * <p>
 * Where the pixel noise is strong against the particles (a confocal slice, whose photon noise makes a speckle inside
 * every particle), the speckle's small blobs answer as strongly as the particles: on a stack of polydisperse spheres
 * 12 px apart, 120 of 200 blobs were 2-6 px across, and the median 5.7 px. So the blobs counted are those that stand
 * out from the noise ({@value #SIGNIFICANT} times the response white noise of the frame's {@link NoiseEstimate sigma}
 * gives at their scale, {@code sigma_n / (s sqrt(2 pi))}), where any does; that stack's blobs then measure 8 px, the
 * spheres' bright cores. Frames whose noise is faint against their particles lose no blob by it.
 * <p>
 * Large scales are computed on the frame averaged down by powers of two (the blur at each scale is then at most a
 * few pixels wide), so that the cost stays a few passes over the frame.
 */
public final class ParticleScale {

	private ParticleScale() {}

	/** The smallest scale looked at (px): a particle 2.8 px across. */
	static final double SMALLEST = 1;
	/** Scales a factor {@code 2^(1/STEPS)} apart. */
	static final int STEPS = 4;
	/** The side of the central crop the scale is measured on (px). */
	static final int CROP = 512;
	/** A blob counts when its response is at least this share of the strong blobs' (90th percentile). */
	static final double STRONG = 0.5;
	/**
	 * A blob stands out from the noise when its response is at least this many times the standard deviation of white
	 * noise's at its scale.
	 */
	static final double SIGNIFICANT = 5;

	/**
	 * @param plane a frame of bright particles (a frame of dark ones inverted first)
	 * @return the particles' diameter (px), or NaN where the frame holds no blob (constant, or too small to hold one
	 *         with its surroundings)
	 */
	public static double diameter(final Plane plane) {
		// a central crop of at most CROP x CROP pixels holds particles enough, and bounds the cost on large frames
		final int w = Math.min(CROP, plane.width()), h = Math.min(CROP, plane.height());
		final int x0 = (plane.width() - w) / 2, y0 = (plane.height() - h) / 2;
		final float[] data = new float[w * h];
		final double[] row = new double[w];
		for (int y = 0; y < h; y++) {
			plane.read(x0, x0 + w - 1, y0 + y, y0 + y, row, 0);
			for (int x = 0; x < w; x++)
				data[y * w + x] = (float) row[x];
		}
		for (final float v : data)
			if (!Float.isFinite(v)) return Double.NaN;
		final double largest = Math.min(w, h) / 8.0;
		if (largest < SMALLEST) return Double.NaN;
		final int count = (int) Math.floor(STEPS * Math.log(largest / SMALLEST) / Math.log(2)) + 1;
		if (count < 3) return Double.NaN;
		double[] found = new double[64], strength = new double[64], weight = new double[64];
		int n = 0;
		// three consecutive scales at a time, each response on the full frame's grid (nearest level pixel)
		float[] below = null, at = null;
		for (int s = 0; s < count; s++) {
			final double sigma = SMALLEST * Math.pow(2, s / (double) STEPS);
			final float[] above = response(data, w, h, sigma);
			if (below != null) {
				final double scale = SMALLEST * Math.pow(2, (s - 1) / (double) STEPS);
				final int margin = (int) Math.ceil(2 * scale) + 1;
				for (int y = margin; y < h - margin; y++)
					for (int x = margin; x < w - margin; x++) {
						final int i = y * w + x;
						final float v = at[i];
						if (!(v > 0) || !(v >= above[i]) || !(v >= below[i])) continue;
						if (!localMax(at, w, i, v) || !localMax(above, w, i, v) || !localMax(below, w, i, v)) continue;
						if (n == found.length) {
							found = Arrays.copyOf(found, 2 * n);
							strength = Arrays.copyOf(strength, 2 * n);
							weight = Arrays.copyOf(weight, 2 * n);
						}
						// a blob found on a level averaged down by f is found at each of the f^2 frame pixels its
						// level pixel covers
						weight[n] = 1.0 / (level(scale) * level(scale));
						// the peak over scale, between the three scales, by a parabola in log scale
						final double curvature = below[i] - 2.0 * v + above[i];
						final double offset = curvature < 0 ? 0.5 * (below[i] - above[i]) / curvature : 0;
						found[n] = scale * Math.pow(2, Math.max(-0.5, Math.min(0.5, offset)) / STEPS);
						strength[n++] = v;
					}
			}
			below = at;
			at = above;
		}
		if (n == 0) return Double.NaN;
		n = significant(found, strength, weight, n, NoiseEstimate.sigma(plane));
		final double least = STRONG * Statistics.weightedQuantile(strength, weight, n, 0.9);
		final double[] scales = new double[n], weights = new double[n];
		int m = 0;
		for (int i = 0; i < n; i++)
			if (strength[i] >= least) {
				scales[m] = found[i];
				weights[m++] = weight[i];
			}
		return 2 * Math.sqrt(2) * Statistics.weightedQuantile(scales, weights, m, 0.5);
	}

	/**
	 * Moves the blobs that stand out from the noise ({@link #SIGNIFICANT}) to the front of the arrays, in their order.
	 *
	 * @param noise the frame's pixel noise (standard deviation)
	 * @return how many stand out, or {@code n} (all kept) where none does or the noise is not known
	 */
	static int significant(final double[] scale, final double[] strength, final double[] weight, final int n,
		final double noise)
	{
		if (!(noise > 0)) return n;
		int m = 0;
		for (int i = 0; i < n; i++)
			if (strength[i] * scale[i] * Math.sqrt(2 * Math.PI) >= SIGNIFICANT * noise) {
				scale[m] = scale[i];
				strength[m] = strength[i];
				weight[m++] = weight[i];
			}
		return m == 0 ? n : m;
	}

	/** @return the factor the frame is averaged down by for scale {@code sigma} (see {@link #response}) */
	static int level(final double sigma) {
		int f = 1;
		while (sigma / (2 * f) >= 2)
			f *= 2;
		return f;
	}

	/** @return whether {@code v} is at least every value of {@code r} in the 3x3 neighbourhood of pixel {@code i} */
	private static boolean localMax(final float[] r, final int w, final int i, final float v) {
		return v >= r[i - w - 1] && v >= r[i - w] && v >= r[i - w + 1] && v >= r[i - 1] && v >= r[i + 1] && v >= r[i +
			w - 1] && v >= r[i + w] && v >= r[i + w + 1];
	}

	/**
	 * @return the scale-normalised response {@code -sigma^2} times the Laplacian of the frame blurred by a Gaussian of
	 *         {@code sigma}, on the frame's grid: computed on the frame averaged down by {@code f = 2^k} (the largest
	 *         with {@code sigma / f >= 2}), where the Laplacian's step is {@code f}
	 */
	static float[] response(final float[] data, final int w, final int h, final double sigma) {
		final int target = level(sigma);
		int f = 1;
		float[] img = data;
		int lw = w, lh = h;
		while (f < target) { // (each level at least 16 px a side: sigma is at most an eighth of the frame's side)
			final int nw = lw / 2, nh = lh / 2;
			final float[] down = new float[nw * nh];
			for (int y = 0; y < nh; y++)
				for (int x = 0; x < nw; x++)
					down[y * nw + x] = 0.25f * (img[2 * y * lw + 2 * x] + img[2 * y * lw + 2 * x + 1] + img[(2 * y + 1) * lw +
						2 * x] + img[(2 * y + 1) * lw + 2 * x + 1]);
			img = down;
			lw = nw;
			lh = nh;
			f *= 2;
		}
		final float[] g = BandPass.blur(img, lw, lh, sigma / f);
		final float[] out = new float[w * h];
		final double norm = sigma * sigma / ((double) f * f);
		for (int y = 0; y < h; y++) {
			// the level's pixel k covers the frame's pixels f k .. f k + f - 1: its centre at f k + (f - 1) / 2
			final int ly = clamp((int) Math.round((y - (f - 1) / 2.0) / f), lh);
			final int up = Math.max(0, ly - 1), down = Math.min(lh - 1, ly + 1);
			for (int x = 0; x < w; x++) {
				final int lx = clamp((int) Math.round((x - (f - 1) / 2.0) / f), lw);
				final int left = Math.max(0, lx - 1), right = Math.min(lw - 1, lx + 1);
				final int c = ly * lw + lx;
				final double lap = g[ly * lw + left] + g[ly * lw + right] + g[up * lw + lx] + g[down * lw + lx] - 4 * g[c];
				out[y * w + x] = (float) (-norm * lap);
			}
		}
		return out;
	}

	private static int clamp(final int v, final int n) {
		return v < 0 ? 0 : v >= n ? n - 1 : v;
	}
}
