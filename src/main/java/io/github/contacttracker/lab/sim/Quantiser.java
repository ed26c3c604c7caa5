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

import java.util.random.RandomGenerator;

import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;

/**
 * Turns an exact image into a camera frame: adds noise, rounds to the nearest integer (halves up) and clips to
 * the pixel type's range, counting the clipped pixels so that none are lost silently.
 */
public final class Quantiser {

	/** Largest grey level of an 8-bit pixel. */
	public static final int MAX_8_BIT = 255;
	/** Largest grey level of a 16-bit pixel. */
	public static final int MAX_16_BIT = 65535;

	private Quantiser() {}

	/** Receives one quantised pixel. */
	@FunctionalInterface
	private interface PixelSink {
		void set(int index, int value);
	}

	/**
	 * @param image the exact image (not modified)
	 * @param noise the noise to add
	 * @param random the noise source, advanced by one draw per pixel (none for {@link NoiseModel#none()})
	 * @return an 8-bit frame, values in [0, 255]
	 */
	public static QuantisedFrame<UnsignedByteType> toUnsignedBytes(final NoiseFreeImage image, final NoiseModel noise,
		final RandomGenerator random)
	{
		final byte[] out = new byte[image.pixels().length];
		final int[] clipped = quantise(image, noise, random, MAX_8_BIT, (i, v) -> out[i] = (byte) v);
		return new QuantisedFrame<>(ArrayImgs.unsignedBytes(out, image.width(), image.height()), clipped[0],
			clipped[1]);
	}

	/**
	 * @param image the exact image (not modified)
	 * @param noise the noise to add
	 * @param random the noise source, advanced by one draw per pixel (none for {@link NoiseModel#none()})
	 * @return a 16-bit frame, values in [0, 65535]
	 */
	public static QuantisedFrame<UnsignedShortType> toUnsignedShorts(final NoiseFreeImage image,
		final NoiseModel noise, final RandomGenerator random)
	{
		final short[] out = new short[image.pixels().length];
		final int[] clipped = quantise(image, noise, random, MAX_16_BIT, (i, v) -> out[i] = (short) v);
		return new QuantisedFrame<>(ArrayImgs.unsignedShorts(out, image.width(), image.height()), clipped[0],
			clipped[1]);
	}

	/**
	 * @param bitDepth 8 or 16
	 * @return {@link #toUnsignedBytes} or {@link #toUnsignedShorts}
	 * @throws IllegalArgumentException for another bit depth
	 */
	public static QuantisedFrame<?> quantise(final NoiseFreeImage image, final NoiseModel noise,
		final RandomGenerator random, final int bitDepth)
	{
		return switch (bitDepth) {
			case 8 -> toUnsignedBytes(image, noise, random);
			case 16 -> toUnsignedShorts(image, noise, random);
			default -> throw new IllegalArgumentException("bit depth must be 8 or 16, not " + bitDepth);
		};
	}

	/** @return {clipped below 0, clipped above max} */
	private static int[] quantise(final NoiseFreeImage image, final NoiseModel noise, final RandomGenerator random,
		final int max, final PixelSink sink)
	{
		final double[] pixels = image.pixels();
		final boolean noisy = noise != NoiseModel.none();
		int low = 0;
		int high = 0;
		for (int i = 0; i < pixels.length; i++) {
			final double v = noisy ? pixels[i] + noise.sample(random) : pixels[i];
			final double rounded = Math.floor(v + 0.5);
			final int q;
			if (rounded < 0) {
				q = 0;
				low++;
			}
			else if (rounded > max) {
				q = max;
				high++;
			}
			else q = (int) rounded;
			sink.set(i, q);
		}
		return new int[] { low, high };
	}
}
