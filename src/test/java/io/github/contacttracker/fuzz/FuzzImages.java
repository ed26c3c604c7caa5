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
 * Two movies in three are {@linkplain #trackable trackable} (particles clear of the border, of a size the tracker
 * measures), so that most cases reach the computation and not only its checks; the third is {@linkplain #hostile
 * hostile}.
 */
final class FuzzImages {

	/** The property of a movie whose particles are darker than the background ({@link Boolean#TRUE}). */
	static final String DARK = "fuzz.dark";
	/** The property holding the particles' Gaussian sigma in pixels (a {@link Double}). */
	static final String SIGMA = "fuzz.sigma";

	private FuzzImages() {}

	/**
	 * @param types how many pixel types to draw from: 3 for 8-, 16- and 32-bit, 4 with RGB
	 * @return a random movie: trackable (two in three) or hostile
	 */
	static ImagePlus image(final SplittableRandom r, final int types) {
		return r.nextInt(3) > 0 ? trackable(r, types) : hostile(r, types);
	}

	/**
	 * @return a movie a user would track: 32 to 120 px a side, one to three frames, one to twenty particles (one
	 *         in five movies dark ones on a bright background) of 1.2 to 3.5 px sigma at least 8 px from the border,
	 *         some touching, little noise
	 */
	static ImagePlus trackable(final SplittableRandom r, final int types) {
		final int w = 32 + r.nextInt(89), h = 32 + r.nextInt(89), frames = 1 + r.nextInt(3), type = r.nextInt(types);
		final int n = 1 + r.nextInt(Math.min(20, Math.max(1, w * h / 400)));
		final double[] cx = new double[n], cy = new double[n];
		for (int k = 0; k < n; k++) {
			cx[k] = 8 + r.nextDouble() * (w - 16);
			cy[k] = 8 + r.nextDouble() * (h - 16);
		}
		final boolean dark = r.nextInt(5) == 0;
		final ImagePlus imp = paint(r, w, h, frames, type, dark ? 3 : 2, cx, cy, 1.2 + r.nextDouble() * 2.3);
		imp.setProperty(DARK, dark);
		return imp;
	}

	/**
	 * @return a movie a tracker is not made for, but must refuse in one line or track: a size from 1x1 (a quarter
	 *         of the sides 1 to 4 px), constant, noise, particles anywhere (bright or dark, 1 to 9 px), floats with
	 *         NaN and infinities
	 */
	static ImagePlus hostile(final SplittableRandom r, final int types) {
		final int w = size(r), h = size(r), frames = 1 + r.nextInt(3), type = r.nextInt(types), content = r.nextInt(5);
		final int n = 1 + r.nextInt(20);
		final double radius = 1 + r.nextDouble() * 8;
		final double[] cx = new double[n], cy = new double[n];
		for (int k = 0; k < n; k++) {
			cx[k] = r.nextDouble() * w;
			cy[k] = r.nextDouble() * h;
		}
		final ImagePlus imp = paint(r, w, h, frames, type, content, cx, cy, radius);
		imp.setProperty(DARK, content == 3);
		return imp;
	}

	/**
	 * @param type 0 to 3: 8, 16, 32 bits, RGB
	 * @param content 0 constant, 1 noise, 2 bright particles, 3 dark particles, 4 bright particles with (in floats)
	 *        NaN and infinite pixels
	 */
	private static ImagePlus paint(final SplittableRandom r, final int w, final int h, final int frames, final int type,
		final int content, final double[] cx, final double[] cy, final double radius)
	{
		final ImageStack stack = new ImageStack(w, h);
		for (int t = 0; t < frames; t++) {
			final ImageProcessor ip = type == 0 ? new ByteProcessor(w, h) : type == 1 ? new ShortProcessor(w, h)
				: type == 2 ? new FloatProcessor(w, h) : new ColorProcessor(w, h);
			final double max = max(type);
			final double sign = content == 3 ? -1 : 1, base = content == 3 ? 0.8 * max : 0.1 * max;
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					double light = 0;
					for (int k = 0; k < cx.length; k++)
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
		final ImagePlus imp = new ImagePlus("fuzz", stack);
		imp.setProperty(SIGMA, radius);
		return imp;
	}

	private static double max(final int type) {
		return type == 0 || type == 3 ? 255 : type == 1 ? 65535 : 1e4;
	}

	/** @return whether the movie's particles are darker than its background */
	static boolean dark(final ImagePlus imp) {
		return Boolean.TRUE.equals(imp.getProperty(DARK));
	}

	/**
	 * @return a threshold the tracker would be given for this movie: halfway between the first frame's least and
	 *         greatest finite value (within the selection's bounds, if it has one on the image), in the values it
	 *         tracks (the inverted ones for dark particles); 50 when there is no finite value
	 */
	static double threshold(final ImagePlus imp) {
		final ImageProcessor ip = imp.getStack().getProcessor(1);
		java.awt.Rectangle area = new java.awt.Rectangle(0, 0, ip.getWidth(), ip.getHeight());
		if (imp.getRoi() != null && imp.getRoi().getBounds().intersects(area)) area = area.intersection(imp.getRoi()
			.getBounds());
		double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
		for (int y = area.y; y < area.y + area.height; y++)
			for (int x = area.x; x < area.x + area.width; x++) {
				final double v = ip.getPixelValue(x, y);
				if (Double.isFinite(v)) {
					lo = Math.min(lo, v);
					hi = Math.max(hi, v);
				}
			}
		if (lo > hi) return 50;
		final double mid = Math.rint((lo + hi) / 2);
		if (!dark(imp)) return mid;
		final int bits = imp.getBitDepth();
		return bits == 8 || bits == 24 ? 255 - mid : bits == 16 ? 65535 - mid : -mid;
	}

	/** @return the particles' diameter a user would give: four sigmas, in whole pixels */
	static long diameter(final ImagePlus imp) {
		return Math.round(4 * (Double) imp.getProperty(SIGMA));
	}

	/** @return the r_out a user would give: where the profile is back at the background (3 sigmas), plus 2 px */
	static long rOut(final ImagePlus imp) {
		return Math.round(3 * (Double) imp.getProperty(SIGMA)) + 2;
	}

	/** @return a side: a quarter of them thin (1 to 4 px), the others 8 to 120 */
	static int size(final SplittableRandom r) {
		return r.nextInt(4) == 0 ? 1 + r.nextInt(4) : 8 + r.nextInt(113);
	}
}
