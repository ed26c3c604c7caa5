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
package io.github.contacttracker.core;

import java.util.Random;
import java.util.function.DoubleUnaryOperator;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.DoubleArray;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;
import net.imglib2.type.numeric.real.DoubleType;
import net.imglib2.type.numeric.real.FloatType;

/** Small synthetic images for the core's tests, independent of the simulator package. */
public final class TestImages {

	private TestImages() {}

	/** A Gaussian bump: value(r) = amplitude * exp(-r^2 / (2 sigma^2)). */
	public static DoubleUnaryOperator gaussian(final double amplitude, final double sigma) {
		return r -> amplitude * Math.exp(-r * r / (2 * sigma * sigma));
	}

	/**
	 * Renders particles (centres in px, pixel (i,j) centred at (i,j)) of a radial profile on a background,
	 * averaging 8x8 sub-samples per pixel.
	 */
	public static double[] render(final int w, final int h, final double background, final DoubleUnaryOperator profile,
		final double[]... centres)
	{
		final double[] img = new double[w * h];
		final int ss = 8;
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				double sum = 0;
				for (int sy = 0; sy < ss; sy++)
					for (int sx = 0; sx < ss; sx++) {
						final double px = x - 0.5 + (sx + 0.5) / ss, py = y - 0.5 + (sy + 0.5) / ss;
						for (final double[] c : centres)
							sum += profile.applyAsDouble(Math.hypot(px - c[0], py - c[1]));
					}
				img[y * w + x] = background + sum / (ss * ss);
			}
		return img;
	}

	/** Adds seeded uniform noise in [-amplitude, amplitude]. */
	public static double[] withUniformNoise(final double[] img, final double amplitude, final long seed) {
		final Random rnd = new Random(seed);
		final double[] out = img.clone();
		for (int i = 0; i < out.length; i++)
			out[i] += amplitude * (2 * rnd.nextDouble() - 1);
		return out;
	}

	public static ArrayImg<UnsignedByteType, ByteArray> bytes(final double[] img, final int w, final int h) {
		final byte[] b = new byte[img.length];
		for (int i = 0; i < img.length; i++)
			b[i] = (byte) Math.max(0, Math.min(255, Math.round(img[i])));
		return ArrayImgs.unsignedBytes(b, w, h);
	}

	public static ArrayImg<UnsignedShortType, ShortArray> shorts(final double[] img, final int w, final int h) {
		final short[] s = new short[img.length];
		for (int i = 0; i < img.length; i++)
			s[i] = (short) Math.max(0, Math.min(65535, Math.round(img[i])));
		return ArrayImgs.unsignedShorts(s, w, h);
	}

	public static ArrayImg<FloatType, FloatArray> floats(final double[] img, final int w, final int h) {
		final float[] f = new float[img.length];
		for (int i = 0; i < img.length; i++)
			f[i] = (float) img[i];
		return ArrayImgs.floats(f, w, h);
	}

	public static ArrayImg<DoubleType, DoubleArray> doubles(final double[] img, final int w, final int h) {
		return ArrayImgs.doubles(img.clone(), w, h);
	}
}
