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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import net.imglib2.RandomAccess;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;
import net.imglib2.util.Intervals;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;

class QuantiserTest {

	private static int at(final ArrayImg<? extends net.imglib2.type.numeric.IntegerType<?>, ?> img, final int x,
		final int y)
	{
		final RandomAccess<? extends net.imglib2.type.numeric.IntegerType<?>> ra = img.randomAccess();
		ra.setPosition(new long[] { x, y });
		return ra.get().getInteger();
	}

	static int[] pixels(final RandomAccessibleInterval<? extends RealType<?>> img) {
		final int[] out = new int[(int) Intervals.numElements(img)];
		int i = 0;
		for (final RealType<?> v : img)
			out[i++] = (int) v.getRealDouble();
		return out;
	}

	@Test
	void roundsToNearestAndClipsCountingBothEnds() {
		final NoiseFreeImage exact = new NoiseFreeImage(4, 2, new double[] { -3, -0.4, 0.5, 254.49, 254.5, 300, 17.2,
			99.7 });
		final QuantisedFrame<UnsignedByteType> frame = Quantiser.toUnsignedBytes(exact, NoiseModel.none(),
			new SplittableRandom(1));
		final int[] expected = { 0, 0, 1, 254, 255, 255, 17, 100 };
		for (int i = 0; i < expected.length; i++)
			assertEquals(expected[i], at(frame.image(), i % 4, i / 4), "pixel " + i);
		assertEquals(1, frame.clippedLow());
		assertEquals(1, frame.clippedHigh());
		assertEquals(2, frame.clippedPixels());
		assertEquals(4, frame.image().dimension(0));
		assertEquals(2, frame.image().dimension(1));
	}

	@Test
	void sixteenBitKeepsTheFullRange() {
		final NoiseFreeImage exact = new NoiseFreeImage(3, 1, new double[] { 300, 65535.2, 70000 });
		final QuantisedFrame<UnsignedShortType> frame = Quantiser.toUnsignedShorts(exact, NoiseModel.none(),
			new SplittableRandom(1));
		assertEquals(300, at(frame.image(), 0, 0));
		assertEquals(65535, at(frame.image(), 1, 0));
		assertEquals(65535, at(frame.image(), 2, 0));
		assertEquals(0, frame.clippedLow());
		assertEquals(1, frame.clippedHigh());
		assertThrows(IllegalArgumentException.class, () -> Quantiser.quantise(exact, NoiseModel.none(),
			new SplittableRandom(1), 12));
	}

	@Test
	void noiseIsAddedBeforeRoundingAndIsSeeded() {
		final NoiseFreeImage exact = NoiseFreeImage.uniform(200, 100, 2);
		final QuantisedFrame<?> a = Quantiser.quantise(exact, NoiseModel.uniform(5), new SplittableRandom(3), 8);
		final QuantisedFrame<?> b = Quantiser.quantise(exact, NoiseModel.uniform(5), new SplittableRandom(3), 8);
		// 2 + U[-5, 5] rounds below 0 when the noise is below -2.5: probability 0.25
		assertEquals(0.25, a.clippedLow() / 20000.0, 0.015);
		assertEquals(a.clippedLow(), b.clippedLow());
		final int[] pa = pixels(a.image());
		assertArrayEquals(pa, pixels(b.image()));
		double mean = 0;
		for (final int v : pa)
			mean += v / 20000.0;
		// E[max(0, round(2 + U))]: values 0 (p .25 + clipped), 1..7 each p 0.1, minus half-steps at the ends
		assertEquals(0.1 * (1 + 2 + 3 + 4 + 5 + 6) + 0.05 * 7, mean, 0.05);
		// the exact image is untouched
		assertEquals(2, exact.get(10, 10), 0);
	}
}
