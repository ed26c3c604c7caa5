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
package io.github.contacttracker.lab.sim;

/**
 * An exact (real-valued, noise-free) simulated image, row-major: pixel {@code (x, y)} is
 * {@code pixels[y * width + x]}. The array is shared, not copied, so that rendering and re-noising stay cheap.
 *
 * @param width image width (px)
 * @param height image height (px)
 * @param pixels grey levels, {@code width * height} of them
 */
public record NoiseFreeImage(int width, int height, double[] pixels) {

	/** @throws IllegalArgumentException when the array does not match the size */
	public NoiseFreeImage {
		if (width <= 0 || height <= 0 || pixels.length != (long) width * height)
			throw new IllegalArgumentException("image of " + width + " x " + height + " px needs " + (long) width * height
				+ " pixels, not " + pixels.length);
	}

	/** @return a uniform image at {@code background} */
	public static NoiseFreeImage uniform(final int width, final int height, final double background) {
		if (width <= 0 || height <= 0)
			throw new IllegalArgumentException("image size must be positive, not " + width + " x " + height);
		final double[] pixels = new double[Math.multiplyExact(width, height)];
		java.util.Arrays.fill(pixels, background);
		return new NoiseFreeImage(width, height, pixels);
	}

	/** @return the grey level of pixel {@code (x, y)} */
	public double get(final int x, final int y) {
		return pixels[y * width + x];
	}

	/** @return an independent copy */
	public NoiseFreeImage copy() {
		return new NoiseFreeImage(width, height, pixels.clone());
	}
}
