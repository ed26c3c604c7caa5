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
package io.github.contacttracker.core.radial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.Plane;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.type.numeric.real.FloatType;
import org.junit.jupiter.api.Test;

class GradientOperatorTest {

	/** The paper's kernels, as printed (rows = image rows). */
	private static final double[][] KX = { { 1, 1, 0, -1, -1 }, { 1, 1, 0, -1, -1 }, { 1, 1, 0, -1, -1 } };
	private static final double[][] KY = { { 1, 1, 1 }, { 1, 1, 1 }, { 0, 0, 0 }, { -1, -1, -1 }, { -1, -1, -1 } };

	/** A textbook 2D convolution (kernel flipped) at one pixel: out(x,y) = sum k(i,j) I(x - j + cj, y - i + ci). */
	private static double convolve(final double[] img, final int w, final double[][] k, final int x, final int y) {
		final int ci = k.length / 2, cj = k[0].length / 2;
		double s = 0;
		for (int i = 0; i < k.length; i++)
			for (int j = 0; j < k[0].length; j++)
				s += k[i][j] * img[(y - i + ci) * w + (x - j + cj)];
		return s;
	}

	private static double[] randomImage(final int w, final int h, final long seed, final boolean integer) {
		final Random rnd = new Random(seed);
		final double[] img = new double[w * h];
		for (int i = 0; i < img.length; i++)
			img[i] = integer ? rnd.nextInt(256) : rnd.nextDouble() * 1000;
		return img;
	}

	@Test
	void runGradientsEqualDirectConvolutionOnIntegerImage() {
		final int w = 23, h = 17;
		final double[] img = randomImage(w, h, 1, true);
		final Plane plane = Plane.of(TestImages.bytes(img, w, h));
		final double[] gx = new double[w], gy = new double[w];
		final double[] scratch = new double[GradientOperator.scratchLength(w)];
		for (int y = 2; y < h - 2; y++) {
			GradientOperator.alongRun(plane, y, 2, w - 3, gx, gy, 0, scratch);
			for (int x = 2; x < w - 2; x++) {
				assertEquals(convolve(img, w, KX, x, y), gx[x - 2], 0.0, "gx at " + x + "," + y);
				assertEquals(convolve(img, w, KY, x, y), gy[x - 2], 0.0, "gy at " + x + "," + y);
				assertEquals(convolve(img, w, KX, x, y), GradientOperator.gx(plane, x, y), 0.0);
				assertEquals(convolve(img, w, KY, x, y), GradientOperator.gy(plane, x, y), 0.0);
			}
			// a run inside the row, written at an offset (the 8-bit path reads the array itself)
			GradientOperator.alongRun(plane, y, 7, w - 5, gx, gy, 2, scratch);
			for (int x = 7; x <= w - 5; x++) {
				assertEquals(convolve(img, w, KX, x, y), gx[2 + x - 7], 0.0, "gx at " + x + "," + y);
				assertEquals(convolve(img, w, KY, x, y), gy[2 + x - 7], 0.0, "gy at " + x + "," + y);
			}
		}
	}

	@Test
	void runGradientsEqualDirectConvolutionOnFloatImage() {
		final int w = 19, h = 11;
		final double[] img = randomImage(w, h, 2, false);
		final ArrayImg<FloatType, FloatArray> f = TestImages.floats(img, w, h);
		final double[] asFloat = new double[w * h];
		for (int i = 0; i < asFloat.length; i++)
			asFloat[i] = (float) img[i];
		final Plane plane = Plane.of(f);
		final double[] gx = new double[w], gy = new double[w];
		final double[] scratch = new double[GradientOperator.scratchLength(w)];
		for (int y = 2; y < h - 2; y++) {
			// A run that does not start at the left margin, to exercise the offsets.
			GradientOperator.alongRun(plane, y, 4, w - 3, gx, gy, 1, scratch);
			for (int x = 4; x < w - 2; x++) {
				assertEquals(convolve(asFloat, w, KX, x, y), gx[1 + x - 4], 1e-9);
				assertEquals(convolve(asFloat, w, KY, x, y), gy[1 + x - 4], 1e-9);
			}
		}
	}

	@Test
	void gradientPointsUphillWithYDown() {
		// Intensity grows with x and with y (downwards).
		final int w = 9, h = 9;
		final float[] data = new float[w * h];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				data[y * w + x] = 2 * x + 5 * y;
		final Plane plane = Plane.of(ArrayImgs.floats(data, w, h));
		// gx: 3 rows x (2 + 2 - (-1) - (-2)) x 2 = 36; gy: 3 columns x 6 x 5 = 90
		assertArrayEquals(new double[] { 36, 90 }, new double[] { GradientOperator.gx(plane, 4, 4), GradientOperator
			.gy(plane, 4, 4) }, 1e-12);
	}

	@Test
	void borderRuleLeavesTwoPixelMargin() {
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(10, 8));
		assertFalse(GradientOperator.hasGradient(plane, 1, 4));
		assertFalse(GradientOperator.hasGradient(plane, 8, 4));
		assertFalse(GradientOperator.hasGradient(plane, 4, 6));
		assertTrue(GradientOperator.hasGradient(plane, 2, 2));
		assertTrue(GradientOperator.hasGradient(plane, 7, 5));
	}
}
