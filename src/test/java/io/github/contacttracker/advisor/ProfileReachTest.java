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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.InvalidInputException;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * A profile that starts beyond the particle's radius measured the space around something else: the helper says so
 * instead of suggesting values from it.
 */
class ProfileReachTest {

	/** Five bright spots 25 px apart, a cross in 200 x 200 px (a bead's texture, or dust, found as particles). */
	private static ArrayImg<UnsignedByteType, ByteArray> cross() {
		final int w = 200, h = 200;
		final byte[] px = new byte[w * h];
		final double[][] spots = { { 100, 100 }, { 125, 100 }, { 75, 100 }, { 100, 125 }, { 100, 75 } };
		final SplittableRandom rnd = new SplittableRandom(1);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				double v = 30 + 2 * rnd.nextGaussian();
				for (final double[] s : spots)
					v += 150 * Math.exp(-((x - s[0]) * (x - s[0]) + (y - s[1]) * (y - s[1])) / 32.0);
				px[y * w + x] = (byte) Math.max(0, Math.min(255, Math.round(v)));
			}
		return ArrayImgs.unsignedBytes(px, w, h);
	}

	/**
	 * Given a diameter of 60 px, the spots 25 px apart mask each other's pixels out to well beyond a particle's radius:
	 * the profile holds no pixel within 30 px of the spot profiled (it was refused for an r_out of 2 px, the message
	 * naming a method and a size that had nothing to do with the frame).
	 */
	@Test
	void aProfileWithNoPixelWithinTheParticlesRadiusIsRefusedSayingWhy() {
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> ProfileAnalysis.analyse(cross(),
			60, 0));
		assertTrue(e.getMessage().contains("holds no pixel within the particle's radius (30.0 px) of its centre"), e
			.getMessage());
		assertTrue(e.getMessage().endsWith("give a point on a particle"), "the diameter was given: " + e.getMessage());
	}
}
