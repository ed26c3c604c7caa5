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

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;
import net.imglib2.type.numeric.RealType;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.view.Views;

/**
 * Dark particles (darker than the background where they are centred) made bright: {@code 255 - v} for 8-bit pixels,
 * as ImageJ 1.54p's <i>Edit › Invert</i> does; {@code 65535 - v} for 16-bit ones (ImageJ's "full range" 16-bit
 * inversion: by default it inverts within the image's own minimum and maximum, which would make the threshold's
 * meaning depend on each frame's extremes); {@code -v} for any other type (as 32-bit floats; ImageJ inverts those
 * within their range too). A fixed value minus {@code v} for every frame, so a threshold means the same in each.
 * The clip levels trade places with the values (a pixel saturated white reads 0, the floor), so the censoring of
 * clipped pixels still applies. The frame is copied, never changed.
 */
public final class Inversion {

	private Inversion() {}

	/** @return a copy of {@code frame} (2D), inverted, at the same position */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public static RandomAccessibleInterval<? extends RealType<?>> of(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		final Plane plane = Plane.of((RandomAccessibleInterval) frame);
		final int w = plane.width(), h = plane.height();
		final double[] row = new double[w];
		final Object type = frame.getType();
		final ArrayImg<?, ?> out;
		if (type instanceof UnsignedByteType) {
			final ArrayImg<UnsignedByteType, ByteArray> img = ArrayImgs.unsignedBytes(w, h);
			final byte[] px = img.update(null).getCurrentStorageArray();
			for (int y = 0; y < h; y++) {
				plane.read(0, w - 1, y, y, row, 0);
				for (int x = 0; x < w; x++)
					px[y * w + x] = (byte) (255 - (int) row[x]);
			}
			out = img;
		}
		else if (type instanceof UnsignedShortType) {
			final ArrayImg<UnsignedShortType, ShortArray> img = ArrayImgs.unsignedShorts(w, h);
			final short[] px = img.update(null).getCurrentStorageArray();
			for (int y = 0; y < h; y++) {
				plane.read(0, w - 1, y, y, row, 0);
				for (int x = 0; x < w; x++)
					px[y * w + x] = (short) (65535 - (int) row[x]);
			}
			out = img;
		}
		else {
			final ArrayImg<FloatType, FloatArray> img = ArrayImgs.floats(w, h);
			final float[] px = img.update(null).getCurrentStorageArray();
			for (int y = 0; y < h; y++) {
				plane.read(0, w - 1, y, y, row, 0);
				for (int x = 0; x < w; x++)
					px[y * w + x] = (float) -row[x];
			}
			out = img;
		}
		return (RandomAccessibleInterval) (frame.min(0) == 0 && frame.min(1) == 0 ? out : Views.translate(
			(RandomAccessibleInterval) out, frame.min(0), frame.min(1)));
	}
}
