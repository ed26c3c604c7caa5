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

import java.util.function.IntFunction;

import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * A movie to track: its frames by index, its calibration, and a name for messages. Frames are asked for one at a
 * time, as the worker threads need them, so a source backed by a file (a virtual stack) lets a movie of any
 * length be tracked in a fixed heap.
 */
public interface FrameSource {

	/** @return the number of frames */
	int frameCount();

	/**
	 * @param t the 0-based frame index
	 * @return frame {@code t}, 2D; called from several threads at once, so implementations must be thread-safe
	 */
	RandomAccessibleInterval<? extends RealType<?>> frame(int t);

	/** @return pixel size, units and frame interval */
	Calibration calibration();

	/** @return the movie's name, for messages ({@code triple.tif}) */
	String name();

	/** @return whether the threshold is to be checked against the data ({@link #frameRange(int)}) */
	default boolean checksDataRange() {
		return false;
	}

	/**
	 * @param t the 0-based frame index
	 * @return the smallest and largest pixel value of frame {@code t}, for the threshold check; read frame by frame
	 *         so that the check never needs the whole movie in memory
	 * @throws io.github.contacttracker.core.InvalidInputException naming a NaN or infinite pixel
	 */
	default double[] frameRange(final int t) {
		return ImagePlusFrames.range(frame(t), t);
	}

	/** @return frame {@code t} of this source alone (a preview's), its data range not checked */
	default FrameSource only(final int t) {
		return of(1, i -> frame(t), calibration(), name(), null);
	}

	/**
	 * @return these frames inverted ({@link Inversion}: dark particles made bright), the data range that of the
	 *         inverted frames
	 */
	default FrameSource inverted() {
		return of(frameCount(), t -> Inversion.of(frame(t)), calibration(), name(), checksDataRange() ? t -> ImagePlusFrames
			.range(Inversion.of(frame(t)), t) : null);
	}

	/**
	 * @param region the part of each frame to track (x and y, pixel indices; the Fiji selection), or
	 *        {@code null} for all
	 * @return these frames cut to {@code region}: spots keep the frame's coordinates, a particle cut by the region's
	 *         edge is flagged as one cut by the frame's, and the data range is the region's
	 */
	default FrameSource within(final Interval region) {
		if (region == null) return this;
		return of(frameCount(), t -> ImagePlusFrames.within(frame(t), region), calibration(), name(), checksDataRange()
			? t -> ImagePlusFrames.range(ImagePlusFrames.within(frame(t), region), t) : null);
	}

	/** @return an ImageJ image's frames as a source, read when needed, the data range checked */
	static FrameSource of(final ImagePlusFrames frames, final String name) {
		return of(frames.frameCount(), frames::frame, frames.calibration(), name, frames::frameRange);
	}

	/**
	 * @param count the number of frames
	 * @param frames frame {@code t} (thread-safe)
	 * @param calibration pixel size, units and frame interval
	 * @param name the movie's name, for messages
	 * @param frameRange {min, max} of frame {@code t}, to check the threshold against, or {@code null} for no check
	 * @return a source of those frames
	 */
	static FrameSource of(final int count, final IntFunction<? extends RandomAccessibleInterval<? extends RealType<?>>> frames,
		final Calibration calibration, final String name, final IntFunction<double[]> frameRange)
	{
		return new FrameSource() {

			@Override
			public int frameCount() {
				return count;
			}

			@Override
			public RandomAccessibleInterval<? extends RealType<?>> frame(final int t) {
				return frames.apply(t);
			}

			@Override
			public Calibration calibration() {
				return calibration;
			}

			@Override
			public String name() {
				return name;
			}

			@Override
			public boolean checksDataRange() {
				return frameRange != null;
			}

			@Override
			public double[] frameRange(final int t) {
				return frameRange == null ? FrameSource.super.frameRange(t) : frameRange.apply(t);
			}
		};
	}
}
