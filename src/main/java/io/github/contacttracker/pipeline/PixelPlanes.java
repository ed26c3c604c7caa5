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
package io.github.contacttracker.pipeline;

import java.lang.reflect.Array;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.RealType;

/**
 * A movie handed over from another language as one primitive array per frame, wrapped as ImgLib2 images without
 * copying: {@code byte[]} planes are 8-bit unsigned, {@code short[]} 16-bit unsigned and {@code float[]} 32-bit
 * float pixels, as ImageJ stores them, so that the tracker sees exactly the values and types it sees when
 * {@code track} reads the same frames from a file. A Python caller passes numpy's buffers (JPype copies each
 * plane once into a Java array); nothing is written to disk.
 */
public final class PixelPlanes {

	private final Object[] planes;
	private final int width, height;
	private final boolean integerData;

	/**
	 * @param planes one array per frame, row after row, all {@code byte[]}, all {@code short[]} or all
	 *        {@code float[]}, each of {@code width * height} pixels
	 * @throws InvalidInputException naming what does not fit
	 */
	public PixelPlanes(final Object[] planes, final int width, final int height) {
		if (planes == null || planes.length == 0) throw new InvalidInputException("no frame given");
		if (width < 1 || height < 1) throw new InvalidInputException("a frame must be at least 1 x 1 pixels, not " +
			width + " x " + height);
		final Class<?> type = planes[0] == null ? null : planes[0].getClass();
		if (type != byte[].class && type != short[].class && type != float[].class) throw new InvalidInputException(
			"pixels must be 8-bit or 16-bit unsigned integers or 32-bit floats, not " + (type == null ? "null" : type
				.getSimpleName()));
		final long n = (long) width * height;
		for (int t = 0; t < planes.length; t++) {
			if (planes[t] == null || planes[t].getClass() != type) throw new InvalidInputException("frame " + (t + 1) +
				" is not of the first frame's pixel type (" + type.getSimpleName() + ")");
			final int length = Array.getLength(planes[t]);
			if (length != n) throw new InvalidInputException("frame " + (t + 1) + " has " + length + " pixels, not " +
				width + " x " + height + " = " + n);
		}
		this.planes = planes.clone();
		this.width = width;
		this.height = height;
		this.integerData = type != float[].class;
	}

	/** @return the number of frames */
	public int frameCount() {
		return planes.length;
	}

	/** @return whether the pixels are integers (a measured threshold is then a whole number, as for such files) */
	public boolean integerData() {
		return integerData;
	}

	/** @return frame {@code t} (0-based), 2D, sharing the given array */
	public RandomAccessibleInterval<? extends RealType<?>> frame(final int t) {
		final Object p = planes[t];
		if (p instanceof byte[] b) return ArrayImgs.unsignedBytes(b, width, height);
		if (p instanceof short[] s) return ArrayImgs.unsignedShorts(s, width, height);
		return ArrayImgs.floats((float[]) p, width, height);
	}

	/**
	 * @param name the movie's name, for messages
	 * @return the frames as a source in pixel units, the threshold checked against their data range (NaN and
	 *         infinite pixels refused, naming the frame)
	 */
	public FrameSource source(final String name) {
		return FrameSource.of(planes.length, this::frame, Calibration.PIXELS, name, t -> ImagePlusFrames.range(frame(t),
			t));
	}
}
