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
package io.github.contacttracker.fuzz;

import java.util.SplittableRandom;

import ij.ImagePlus;
import ij.ImageStack;
import ij.process.ByteProcessor;
import ij.process.ColorProcessor;
import ij.process.FloatProcessor;
import ij.process.ImageProcessor;
import ij.process.ShortProcessor;

/**
 * Random movies for the fuzz tests of every front end: every size from 1x1, 8, 16 and 32 bits (and RGB), constant,
 * noisy or holding particles (bright or dark, some touching), floats with NaN and infinities, one to three frames.
 */
final class FuzzImages {

	private FuzzImages() {}

	/**
	 * @param types how many pixel types to draw from: 3 for 8-, 16- and 32-bit, 4 with RGB
	 * @return a random movie: a size from 1x1, a pixel type, a content
	 */
	static ImagePlus image(final SplittableRandom r, final int types) {
		final int w = size(r), h = size(r), frames = 1 + r.nextInt(3), type = r.nextInt(types), content = r.nextInt(5);
		final ImageStack stack = new ImageStack(w, h);
		for (int t = 0; t < frames; t++) {
			final ImageProcessor ip = type == 0 ? new ByteProcessor(w, h) : type == 1 ? new ShortProcessor(w, h)
				: type == 2 ? new FloatProcessor(w, h) : new ColorProcessor(w, h);
			final double max = type == 0 || type == 3 ? 255 : type == 1 ? 65535 : 1e4;
			// particles: one to twenty of one size, some touching; dark ones on a bright background for content 3
			final int n = 1 + r.nextInt(20);
			final double radius = 1 + r.nextDouble() * 8;
			final double[] cx = new double[n], cy = new double[n];
			for (int k = 0; k < n; k++) {
				cx[k] = r.nextDouble() * w;
				cy[k] = r.nextDouble() * h;
			}
			final double sign = content == 3 ? -1 : 1, base = content == 3 ? 0.8 * max : 0.1 * max;
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					double light = 0;
					for (int k = 0; k < n; k++)
						light += Math.exp(-((x - cx[k]) * (x - cx[k]) + (y - cy[k]) * (y - cy[k])) / (2 * radius * radius));
					double v = switch (content) {
						case 0 -> max / 3; // constant
						case 1 -> r.nextDouble() * max; // noise
						default -> base + sign * 0.6 * max * Math.min(1, light) + 0.02 * max * r.nextGaussian();
					};
					if (type == 2 && content == 4 && r.nextInt(50) == 0) v = r.nextBoolean() ? Double.NaN : Double.POSITIVE_INFINITY;
					if (type == 3) { // colour: the particles in red, half as bright in green, noise in blue
						final int g = (int) Math.max(0, Math.min(255, v));
						ip.set(x, y, g << 16 | g / 2 << 8 | (content == 0 ? 40 : r.nextInt(256)));
					}
					else ip.putPixelValue(x, y, type == 2 ? v : Math.max(0, Math.min(max, v)));
				}
			stack.addSlice(ip);
		}
		return new ImagePlus("fuzz", stack);
	}

	/** @return a side: a quarter of them thin (1 to 4 px), the others 8 to 120 */
	static int size(final SplittableRandom r) {
		return r.nextInt(4) == 0 ? 1 + r.nextInt(4) : 8 + r.nextInt(113);
	}
}
