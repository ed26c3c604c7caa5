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
package io.github.contacttracker.io;

import ij.process.ByteProcessor;
import ij.process.ImageProcessor;

/**
 * Colour pixels as ImageJ holds them (one {@code int} a pixel, red, green and blue packed): each component, how much
 * each varies over a picture, and whether a colour picture is in fact grey. Colour cameras and JPEG and MJPEG files
 * store even grey pictures in colour; the readers ({@link FolderMovie}) and the tracking of a colour image (which
 * channel holds the particles) both ask.
 */
public final class RgbPixels {

	private RgbPixels() {}

	/**
	 * @return null when every pixel has red, green and blue equal (a grey image stored in colour), else each
	 *         component's standard deviation over the frame (grey levels)
	 */
	public static double[] spread(final int[] rgb) {
		boolean grey = true;
		for (final int p : rgb)
			if (((p >> 16) & 0xff) != (p & 0xff) || ((p >> 8) & 0xff) != (p & 0xff)) {
				grey = false;
				break;
			}
		if (grey) return null;
		final double[] spread = new double[3];
		for (int c = 0; c < 3; c++) {
			final int shift = 16 - 8 * c;
			double sum = 0, sum2 = 0;
			for (final int p : rgb) {
				final int v = (p >> shift) & 0xff;
				sum += v;
				sum2 += (double) v * v;
			}
			final double mean = sum / rgb.length;
			spread[c] = Math.sqrt(Math.max(0, sum2 / rgb.length - mean * mean));
		}
		return spread;
	}

	/**
	 * @return an RGB picture whose red, green and blue are equal at every pixel as an 8-bit one of those grey levels;
	 *         null for any other
	 */
	public static ImageProcessor grey(final ImageProcessor ip) {
		if (!(ip.getPixels() instanceof int[] rgb) || spread(rgb) != null) return null;
		return new ByteProcessor(ip.getWidth(), ip.getHeight(), component(rgb, 3));
	}

	/** @return the RGB pixels' component {@code colour} (1 red, 2 green, 3 blue; 0 the rounded mean of the three) */
	public static byte[] component(final int[] rgb, final int colour) {
		final byte[] out = new byte[rgb.length];
		if (colour == 0) for (int i = 0; i < rgb.length; i++) {
			final int p = rgb[i];
			out[i] = (byte) ((((p >> 16) & 0xff) + ((p >> 8) & 0xff) + (p & 0xff) + 1) / 3);
		}
		else {
			final int shift = 24 - 8 * colour;
			for (int i = 0; i < rgb.length; i++)
				out[i] = (byte) (rgb[i] >> shift);
		}
		return out;
	}
}
