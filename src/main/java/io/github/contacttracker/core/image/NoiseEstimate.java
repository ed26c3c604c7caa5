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

import io.github.contacttracker.core.math.Statistics;

/**
 * Standard deviation of a frame's pixel noise, by Immerkaer's method (Computer Vision and Image
 * Understanding 64, 1996): the mask {@code [1 -2 1; -2 4 -2; 1 -2 1]} cancels smooth signal up to second
 * order, and for Gaussian noise {@code E|response| = 6 s sqrt(2/pi)}. Evaluated on a regular grid of about
 * {@value #SAMPLES} positions, which bounds both cost and the estimate's own scatter (about 1.5%).
 */
public final class NoiseEstimate {

	/** Number of grid positions sampled. */
	public static final int SAMPLES = 4096;

	private NoiseEstimate() {}

	/** @return the estimated noise standard deviation (grey levels), 0 for frames smaller than 3x3 */
	public static double sigma(final Plane p) {
		final int w = p.width(), h = p.height();
		if (w < 3 || h < 3) return 0;
		final long inner = (long) (w - 2) * (h - 2);
		final int stride = (int) Math.max(1, Math.floor(Math.sqrt((double) inner / SAMPLES)));
		double sum = 0;
		long n = 0;
		final byte[] bytes = p.unsignedBytes();
		final double[] b = new double[9];
		for (int y = 1; y < h - 1; y += stride)
			for (int x = 1 + (y / stride) % stride; x < w - 1; x += stride) {
				final double r;
				if (bytes != null) {
					// 8-bit pixels straight from the array, in integers: the sum is exact either way, so identical
					final int i = y * w + x, up = i - w, down = i + w;
					r = (bytes[up - 1] & 0xff) - 2 * (bytes[up] & 0xff) + (bytes[up + 1] & 0xff) //
						- 2 * (bytes[i - 1] & 0xff) + 4 * (bytes[i] & 0xff) - 2 * (bytes[i + 1] & 0xff) //
						+ (bytes[down - 1] & 0xff) - 2 * (bytes[down] & 0xff) + (bytes[down + 1] & 0xff);
				}
				else {
					// the 3x3 neighbourhood in one read (Plane.read), not nine pixel reads
					p.read(x - 1, x + 1, y - 1, y + 1, b, 0);
					r = b[0] - 2 * b[1] + b[2] //
						- 2 * b[3] + 4 * b[4] - 2 * b[5] //
						+ b[6] - 2 * b[7] + b[8];
				}
				sum += Math.abs(r);
				n++;
			}
		final double immerkaer = Math.sqrt(Math.PI / 2) * sum / (6.0 * n);
		return Math.max(immerkaer, clipped(p, stride));
	}

	/** A frame whose background is clipped at the pixel type's floor has at least this share of its pixels there. */
	static final double CLIPPED_SHARE = 0.2;

	/**
	 * The noise of a background clipped at the pixel type's floor (confocal images: a background of 0 with its
	 * noise's lower half cut off), which the differences of neighbours underestimate (half the pixels are equal): the
	 * pixels above the floor near it are the upper half of the background's noise, a half-normal distribution whose
	 * median is 0.6745 sigma. Its median over the sampled pixels above the floor, the particles' pixels among them
	 * (they raise it, so a frame of many particles gets a larger estimate, never a smaller one); 0 when fewer than
	 * {@link #CLIPPED_SHARE} of the sampled pixels sit at the floor.
	 */
	private static double clipped(final Plane p, final int stride) {
		final double floor = p.floor();
		if (!Double.isFinite(floor)) return 0;
		final int w = p.width(), h = p.height();
		int at = 0, n = 0;
		double[] above = new double[64];
		int m = 0;
		for (int y = 0; y < h; y += stride)
			for (int x = (y / stride) % stride; x < w; x += stride) {
				final double v = p.get(x, y);
				n++;
				if (v <= floor) at++;
				else {
					if (m == above.length) above = java.util.Arrays.copyOf(above, 2 * m);
					above[m++] = v - floor;
				}
			}
		if (n == 0 || at < CLIPPED_SHARE * n || m == 0) return 0;
		return Statistics.median(above, m) * Statistics.MAD_TO_SIGMA;
	}
}
