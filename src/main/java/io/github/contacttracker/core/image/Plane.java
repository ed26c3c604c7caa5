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

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

import io.github.contacttracker.core.InvalidInputException;
import net.imglib2.RandomAccess;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.blocks.PrimitiveBlocks.OnFallback;
import net.imglib2.blocks.PrimitiveBlocks;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;
import net.imglib2.img.planar.PlanarImg;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.IntegerType;
import net.imglib2.type.numeric.RealType;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;
import net.imglib2.type.numeric.real.FloatType;

/**
 * Read access to one 2D frame in local coordinates {@code 0 <= x < width, 0 <= y < height}.
 * <p>
 * {@link #of(RandomAccessibleInterval)} picks a fast path that reads the primitive array behind an
 * {@link ArrayImg} or single-plane {@link PlanarImg} of unsigned bytes, unsigned shorts or floats, copies any other
 * view of those types into a primitive array with imglib2's {@link PrimitiveBlocks}, and falls back to a generic
 * {@link RandomAccess} over any other {@link RealType}. Both return the same values as
 * {@code double}, so every algorithm gives identical results on either (tested).
 * <p>
 * Not thread-safe: one plane per thread.
 */
public abstract class Plane {

	protected final int width;
	protected final int height;
	private final long minX;
	private final long minY;

	protected Plane(final int width, final int height, final long minX, final long minY) {
		this.width = width;
		this.height = height;
		this.minX = minX;
		this.minY = minY;
	}

	/** @return the grey value at local (x, y) */
	public abstract double get(int x, int y);

	/** @return the pixels of an 8-bit unsigned plane (row-major, {@code width} per row), else null */
	public byte[] unsignedBytes() {
		return null;
	}

	/**
	 * Copies the grey values of the rectangle {@code x0..x1} by {@code y0..y1} (inclusive) to {@code out}, row after
	 * row from index {@code at}: what {@link #get} gives, in one call and tight loops (row spans of the fit's pixels,
	 * the gradient operators' rows, the noise estimate's neighbourhoods).
	 */
	public void read(final int x0, final int x1, final int y0, final int y1, final double[] out, final int at) {
		for (int y = y0, j = at; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				out[j++] = get(x, y);
	}

	/**
	 * @return the grey level at which the pixel type clips (255 for 8 bits, 65535 for 16 bits), infinite for
	 *         floating-point data: pixels at this level are saturated, their true value unknown (censored)
	 */
	public double saturation() {
		return Double.POSITIVE_INFINITY;
	}

	/**
	 * @return the grey level at which the pixel type clips from below (0 for unsigned integers), minus infinity for
	 *         floating-point data: a dark ring brighter particles push below 0 reads 0 there, its true value unknown
	 *         (censored) like a saturated pixel's
	 */
	public double floor() {
		return Double.NEGATIVE_INFINITY;
	}

	/** @return whether pixels can be NaN or infinite (floating-point data) */
	protected abstract boolean floatingPoint();

	public final int width() {
		return width;
	}

	public final int height() {
		return height;
	}

	/** @return the source interval's minimum x: add it to local x to get the source's coordinate */
	public final long minX() {
		return minX;
	}

	/** @return the source interval's minimum y */
	public final long minY() {
		return minY;
	}

	/**
	 * Appends the runs of row {@code y} whose pixels are {@code >= threshold} to {@code runs}.
	 *
	 * @throws IllegalArgumentException if the row holds a NaN or infinite pixel
	 */
	void scanRow(final int y, final double threshold, final RunList runs) {
		final boolean checkFinite = floatingPoint();
		int start = -1;
		for (int x = 0; x < width; x++) {
			final double v = get(x, y);
			if (checkFinite && !Double.isFinite(v)) throw nonFinite(x, y, v);
			if (v >= threshold) {
				if (start < 0) start = x;
			}
			else if (start >= 0) {
				runs.add(y, start, x - 1);
				start = -1;
			}
		}
		if (start >= 0) runs.add(y, start, width - 1);
	}

	IllegalArgumentException nonFinite(final int x, final int y, final double v) {
		return new InvalidInputException("pixel (" + (x + minX) + ", " + (y + minY) + ") is " + v +
			": images with NaN or infinite pixels cannot be tracked");
	}

	/**
	 * Wraps a 2D interval, choosing the array fast path where it applies.
	 *
	 * @throws IllegalArgumentException if the interval is not 2D or too large for int indexing
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public static <T extends RealType<T>> Plane of(final RandomAccessibleInterval<T> frame) {
		checkShape(frame);
		final int w = (int) frame.dimension(0), h = (int) frame.dimension(1);
		final T type = frame.getType();
		Object storage = null;
		if (frame instanceof ArrayImg) storage = ((ArrayImg) frame).update(null);
		else if (frame instanceof PlanarImg && ((PlanarImg) frame).numSlices() == 1)
			storage = ((PlanarImg) frame).getPlane(0);
		if (storage != null) {
			final long mx = frame.min(0), my = frame.min(1);
			if (type instanceof UnsignedByteType && storage instanceof ByteArray)
				return new UnsignedBytePlane(((ByteArray) storage).getCurrentStorageArray(), w, h, mx, my);
			if (type instanceof UnsignedShortType && storage instanceof ShortArray)
				return new UnsignedShortPlane(((ShortArray) storage).getCurrentStorageArray(), w, h, mx, my);
			if (type instanceof FloatType && storage instanceof FloatArray)
				return new FloatPlane(((FloatArray) storage).getCurrentStorageArray(), w, h, mx, my);
		}
		// Any other view of those types (a slice of a stack, a crop: what TrackMate and hyperstacks hand over):
		// one bulk copy into a primitive array, far cheaper than a RandomAccess per pixel read
		final long mx = frame.min(0), my = frame.min(1);
		if (type instanceof UnsignedByteType) {
			final byte[] data = new byte[w * h];
			copy((RandomAccessibleInterval) frame, data);
			return new UnsignedBytePlane(data, w, h, mx, my);
		}
		if (type instanceof UnsignedShortType) {
			final short[] data = new short[w * h];
			copy((RandomAccessibleInterval) frame, data);
			return new UnsignedShortPlane(data, w, h, mx, my);
		}
		if (type instanceof FloatType) {
			final float[] data = new float[w * h];
			copy((RandomAccessibleInterval) frame, data);
			return new FloatPlane(data, w, h, mx, my);
		}
		return generic(frame);
	}

	/**
	 * Copies a 2D interval of a native type into {@code dest}, row by row, with imglib2's {@link PrimitiveBlocks}. A
	 * view it cannot copy in blocks is copied pixel by pixel through its {@code RandomAccess} (the same values,
	 * slower): {@link OnFallback#ACCEPT} says so here, where the default ({@code WARN}) printed a line to stderr for
	 * every frame that took that path.
	 */
	private static <T extends NativeType<T>> void copy(final RandomAccessibleInterval<T> frame, final Object dest) {
		PrimitiveBlocks.of(frame, OnFallback.ACCEPT).copy(frame, dest);
	}

	/** Wraps a 2D interval through a {@link RandomAccess}, never the fast path (for any {@link RealType}; package-private for tests). */
	static <T extends RealType<T>> Plane generic(final RandomAccessibleInterval<T> frame) {
		checkShape(frame);
		return new GenericPlane<>(frame);
	}

	private static void checkShape(final RandomAccessibleInterval<?> frame) {
		if (frame.numDimensions() != 2)
			throw new InvalidInputException("a frame must be 2D, not " + frame.numDimensions() + "D");
		if (frame.dimension(0) * frame.dimension(1) > Integer.MAX_VALUE - 8)
			throw new InvalidInputException("frame of " + frame.dimension(0) + " x " + frame.dimension(1) +
				" pixels is too large");
	}

	private static final class GenericPlane<T extends RealType<T>> extends Plane {
		private final RandomAccess<T> access;
		private final boolean floating;

		GenericPlane(final RandomAccessibleInterval<T> frame) {
			super((int) frame.dimension(0), (int) frame.dimension(1), frame.min(0), frame.min(1));
			access = frame.randomAccess();
			floating = !(frame.getType() instanceof IntegerType);
		}

		@Override
		public double get(final int x, final int y) {
			access.setPosition(x + minX(), 0);
			access.setPosition(y + minY(), 1);
			return access.get().getRealDouble();
		}

		@Override
		protected boolean floatingPoint() {
			return floating;
		}
	}

	/** Unsigned integer pixels in a primitive array: thresholds by integer compare, no NaN check needed. */
	private abstract static class IntegerArrayPlane extends Plane {
		private final int maxValue;

		IntegerArrayPlane(final int w, final int h, final long mx, final long my, final int maxValue) {
			super(w, h, mx, my);
			this.maxValue = maxValue;
		}

		/** @return the unsigned value at linear index {@code i} */
		abstract int at(int i);

		@Override
		public final double get(final int x, final int y) {
			return at(y * width + x);
		}

		@Override
		protected final boolean floatingPoint() {
			return false;
		}

		@Override
		public final double saturation() {
			return maxValue;
		}

		@Override
		public final double floor() {
			return 0;
		}

		@Override
		void scanRow(final int y, final double threshold, final RunList runs) {
			final int t = integerThreshold(threshold);
			if (t < 0) return;
			final int off = y * width;
			int start = -1;
			for (int x = 0; x < width; x++) {
				if (at(off + x) >= t) {
					if (start < 0) start = x;
				}
				else if (start >= 0) {
					runs.add(y, start, x - 1);
					start = -1;
				}
			}
			if (start >= 0) runs.add(y, start, width - 1);
		}

		/** For integer v: v >= threshold  <=>  v >= ceil(threshold); -1 if no value reaches it. */
		final int integerThreshold(final double threshold) {
			final double c = Math.ceil(threshold);
			return c > maxValue ? -1 : (int) Math.max(c, 0);
		}
	}

	private static final class UnsignedBytePlane extends IntegerArrayPlane {
		private final byte[] data;

		UnsignedBytePlane(final byte[] data, final int w, final int h, final long mx, final long my) {
			super(w, h, mx, my, 0xff);
			this.data = data;
		}

		@Override
		int at(final int i) {
			return data[i] & 0xff;
		}

		@Override
		public byte[] unsignedBytes() {
			return data;
		}

		@Override
		public void read(final int x0, final int x1, final int y0, final int y1, final double[] out, final int at) {
			final byte[] d = data;
			for (int y = y0, j = at; y <= y1; y++)
				for (int i = y * width + x0, end = y * width + x1; i <= end; i++, j++)
					out[j] = d[i] & 0xff;
		}

		/** Eight bytes of a row as one long (byte order irrelevant: only "is any of them bright" is asked). */
		private static final VarHandle EIGHT = MethodHandles.byteArrayViewVarHandle(long[].class,
			ByteOrder.LITTLE_ENDIAN);
		private static final long HIGH_BITS = 0x8080808080808080L, ONES = 0x0101010101010101L;

		/**
		 * As the general scan, on the bytes directly, skipping eight dark pixels at once: the scan reads every pixel
		 * of every frame, and a short job runs on code from the client compiler (scripts/contact-tracker), which
		 * neither inlines the call per pixel nor vectorises.
		 */
		@Override
		void scanRow(final int y, final double threshold, final RunList runs) {
			final int t = integerThreshold(threshold);
			if (t < 0) return;
			final byte[] d = data;
			final int off = y * width;
			// a word of eight bytes holds one >= t only if its test is non-zero: for t <= 128, each byte below 128
			// plus (128 - t) sets its high bit exactly when it is >= t (a carry from a byte >= 128, whose own high
			// bit is set anyway, can only add false alarms); for t > 128 such a byte has its high bit set
			final long add = t <= 128 ? (128L - t) * ONES : 0;
			final boolean skips = t >= 1;
			int start = -1;
			for (int x = 0; x < width; x++) {
				if (skips && start < 0) {
					while (x + 8 <= width) {
						final long w = (long) EIGHT.get(d, off + x);
						if ((((w + add) | w) & HIGH_BITS) != 0) break;
						x += 8;
					}
					if (x >= width) break;
				}
				if ((d[off + x] & 0xff) >= t) {
					if (start < 0) start = x;
				}
				else if (start >= 0) {
					runs.add(y, start, x - 1);
					start = -1;
				}
			}
			if (start >= 0) runs.add(y, start, width - 1);
		}
	}

	private static final class UnsignedShortPlane extends IntegerArrayPlane {
		private final short[] data;

		UnsignedShortPlane(final short[] data, final int w, final int h, final long mx, final long my) {
			super(w, h, mx, my, 0xffff);
			this.data = data;
		}

		@Override
		int at(final int i) {
			return data[i] & 0xffff;
		}

		@Override
		public void read(final int x0, final int x1, final int y0, final int y1, final double[] out, final int at) {
			final short[] d = data;
			for (int y = y0, j = at; y <= y1; y++)
				for (int i = y * width + x0, end = y * width + x1; i <= end; i++, j++)
					out[j] = d[i] & 0xffff;
		}
	}

	private static final class FloatPlane extends Plane {
		private final float[] data;

		FloatPlane(final float[] data, final int w, final int h, final long mx, final long my) {
			super(w, h, mx, my);
			this.data = data;
		}

		@Override
		public double get(final int x, final int y) {
			return data[y * width + x];
		}

		@Override
		public void read(final int x0, final int x1, final int y0, final int y1, final double[] out, final int at) {
			final float[] d = data;
			for (int y = y0, j = at; y <= y1; y++)
				for (int i = y * width + x0, end = y * width + x1; i <= end; i++, j++)
					out[j] = d[i];
		}

		@Override
		protected boolean floatingPoint() {
			return true;
		}
	}
}
