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

import io.github.contacttracker.core.image.Plane;

/**
 * A band-pass filter at the particles' scale (Crocker and Grier, J. Colloid Interface Sci. 179, 298, 1996): the
 * image smoothed by a Gaussian of standard deviation {@code sigma} (it takes out the pixel noise) minus its mean
 * over a square of side {@code 2 w + 1} (the local background, so that a ramp, vignetting or a background clipped
 * at 0 does not decide where particles are). A particle of about that size becomes a peak whose height does not
 * depend on the background around it. Edges are continued by their last pixel. The filter is linear, so its
 * output's noise is the input's times {@link #noiseGain}: detection levels are set in units of it.
 */
public final class BandPass {

	private BandPass() {}

	/**
	 * @param plane the frame
	 * @param sigma the smoothing's standard deviation (px, {@code > 0})
	 * @param halfWidth half the side of the background's square (px, {@code >= 1})
	 * @return the filtered frame, row-major, {@code width} per row
	 */
	public static float[] of(final Plane plane, final double sigma, final int halfWidth) {
		return of(pixels(plane), plane.width(), plane.height(), sigma, halfWidth);
	}

	/** @return the frame's pixels as an array, row-major */
	public static float[] pixels(final Plane plane) {
		final int w = plane.width(), h = plane.height();
		final float[] in = new float[w * h];
		final double[] row = new double[w];
		for (int y = 0; y < h; y++) {
			plane.read(0, w - 1, y, y, row, 0);
			for (int x = 0; x < w; x++)
				in[y * w + x] = (float) row[x];
		}
		return in;
	}

	/** The same on an image given as an array (row-major), e.g. a fit's residuals; {@code image} is not changed. */
	public static float[] of(final float[] image, final int w, final int h, final double sigma, final int halfWidth) {
		final float[] smooth = smooth(image, w, h, sigma);
		final float[] mean = boxMean(image, w, h, halfWidth);
		for (int i = 0; i < smooth.length; i++)
			smooth[i] -= mean[i];
		return smooth;
	}

	/**
	 * @return the standard deviation of the filter's output for white noise of standard deviation 1 (away from
	 *         the edges): the square root of the sum of the squared weights of its 2D kernel
	 */
	public static double noiseGain(final double sigma, final int halfWidth) {
		final float[] g = gaussian(sigma);
		final int rg = g.length / 2, n = Math.max(rg, halfWidth);
		final double box = 1.0 / ((2.0 * halfWidth + 1) * (2.0 * halfWidth + 1));
		double sum = 0;
		for (int y = -n; y <= n; y++)
			for (int x = -n; x <= n; x++) {
				final double gv = Math.abs(x) <= rg && Math.abs(y) <= rg ? g[x + rg] * g[y + rg] : 0;
				final double bv = Math.abs(x) <= halfWidth && Math.abs(y) <= halfWidth ? box : 0;
				sum += (gv - bv) * (gv - bv);
			}
		return Math.sqrt(sum);
	}

	/** @return the image blurred by a Gaussian of standard deviation {@code sigma} (px, edges continued) */
	static float[] blur(final float[] image, final int w, final int h, final double sigma) {
		return smooth(image, w, h, sigma);
	}

	/**
	 * Beyond this standard deviation (px) the Gaussian is {@value #BOXES} successive box means of the same variance
	 * ({@link #boxRadii}): a kernel 6 sigma wide costs that many operations a pixel, the boxes' running sums a few
	 * whatever their width. Particles of a diameter above 8 times it (128 px) are filtered so: a diameter of 1,500 px
	 * on a 2000 x 2000 frame would take a minute of Gaussian passes. The boxes' kernel is within 6% of the Gaussian's peak
	 * everywhere.
	 */
	static final double BOXES_FROM_SIGMA = 16;

	/** How many boxes stand for the Gaussian: 3 leave 10% of its peak in the difference, 5 leave 5%. */
	static final int BOXES = 5;

	/** @return the image blurred by a Gaussian of standard deviation {@code sigma}, or beyond {@link #BOXES_FROM_SIGMA} its likeness in boxes */
	private static float[] smooth(final float[] image, final int w, final int h, final double sigma) {
		if (!(sigma > BOXES_FROM_SIGMA)) return separable(image, w, h, gaussian(sigma));
		float[] out = image;
		for (final int r : boxRadii(sigma))
			out = boxMean(out, w, h, r);
		return out;
	}

	/**
	 * @return the radii of {@value #BOXES} boxes whose successive means have the variance {@code sigma^2} (a box of odd width
	 *         {@code b} has the variance {@code (b^2 - 1) / 12}; the widths are the two odd ones about the ideal
	 *         width, as many of each as brings the sum nearest, after W. M. Wells, IEEE PAMI 8(2), 1986, and P.
	 *         Kovesi, Fast almost-Gaussian filtering, DICTA 2010)
	 */
	static int[] boxRadii(final double sigma) {
		final int n = BOXES;
		final double variance = sigma * sigma;
		int lower = (int) Math.floor(Math.sqrt(12 * variance / n + 1));
		if (lower % 2 == 0) lower--;
		final int upper = lower + 2;
		final int ofLower = (int) Math.round((12 * variance - n * (double) lower * lower - 4.0 * n * lower - 3.0 * n) /
			(-4.0 * lower - 4));
		final int[] r = new int[n];
		for (int i = 0; i < n; i++)
			r[i] = ((i < ofLower ? lower : upper) - 1) / 2;
		return r;
	}

	/** @return a normalised Gaussian kernel of standard deviation {@code sigma}, out to 3 sigma (at least 1 px) */
	static float[] gaussian(final double sigma) {
		final int r = Math.max(1, (int) Math.ceil(3 * sigma));
		final float[] k = new float[2 * r + 1];
		double sum = 0;
		for (int i = -r; i <= r; i++)
			sum += Math.exp(-0.5 * i * i / (sigma * sigma));
		for (int i = -r; i <= r; i++)
			k[i + r] = (float) (Math.exp(-0.5 * i * i / (sigma * sigma)) / sum);
		return k;
	}

	/** @return the image convolved with {@code kernel} along x, then along y (edges continued) */
	private static float[] separable(final float[] image, final int w, final int h, final float[] kernel) {
		final int r = kernel.length / 2;
		final float[] tmp = new float[w * h], out = new float[w * h];
		for (int y = 0; y < h; y++) {
			final int row = y * w;
			for (int x = 0; x < w; x++) {
				float s = 0;
				if (x >= r && x < w - r) for (int i = -r; i <= r; i++) // inside: no clamping
					s += kernel[i + r] * image[row + x + i];
				else for (int i = -r; i <= r; i++)
					s += kernel[i + r] * image[row + clamp(x + i, w)];
				tmp[row + x] = s;
			}
		}
		// along y, row by row, so that the inner loop runs along memory
		for (int y = 0; y < h; y++) {
			final int row = y * w;
			for (int i = -r; i <= r; i++) {
				final float k = kernel[i + r];
				final int src = clamp(y + i, h) * w;
				for (int x = 0; x < w; x++)
					out[row + x] += k * tmp[src + x];
			}
		}
		return out;
	}

	/** @return the mean over the square of side {@code 2 r + 1} around each pixel (edges continued), by running sums */
	private static float[] boxMean(final float[] image, final int w, final int h, final int r) {
		final float[] tmp = new float[w * h], out = new float[w * h];
		final double norm = 1.0 / (2 * r + 1);
		for (int y = 0; y < h; y++) {
			final int row = y * w;
			double s = 0;
			for (int i = -r; i <= r; i++)
				s += image[row + clamp(i, w)];
			for (int x = 0; x < w; x++) {
				tmp[row + x] = (float) (s * norm);
				s += image[row + clamp(x + r + 1, w)] - image[row + clamp(x - r, w)];
			}
		}
		for (int x = 0; x < w; x++) {
			double s = 0;
			for (int i = -r; i <= r; i++)
				s += tmp[clamp(i, h) * w + x];
			for (int y = 0; y < h; y++) {
				out[y * w + x] = (float) (s * norm);
				s += tmp[clamp(y + r + 1, h) * w + x] - tmp[clamp(y - r, h) * w + x];
			}
		}
		return out;
	}

	private static int clamp(final int i, final int n) {
		return i < 0 ? 0 : i >= n ? n - 1 : i;
	}
}
