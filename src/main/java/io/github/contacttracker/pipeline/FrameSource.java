package io.github.contacttracker.pipeline;

import java.util.function.IntFunction;
import java.util.function.Supplier;

import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImagePlusFrames;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/** A movie to track: its frames by index, its calibration, and a name for messages. */
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

	/**
	 * @return the smallest and largest pixel value over all frames, to check the threshold against; {@code null}
	 *         when the front end does not check it
	 */
	default double[] dataRange() {
		return null;
	}

	/** @return frame {@code t} of this source alone (a preview's), its data range not checked */
	default FrameSource only(final int t) {
		return of(1, i -> frame(t), calibration(), name(), null);
	}

	/** @return an ImageJ image's frames as a source, the data range checked */
	static FrameSource of(final ImagePlusFrames frames, final String name) {
		return of(frames.frameCount(), frames.frames()::get, frames.calibration(), name, frames::dataRange);
	}

	/**
	 * @param count the number of frames
	 * @param frames frame {@code t} (thread-safe)
	 * @param calibration pixel size, units and frame interval
	 * @param name the movie's name, for messages
	 * @param dataRange computes the data range to check the threshold against, or {@code null} for no check
	 * @return a source of those frames
	 */
	static FrameSource of(final int count, final IntFunction<? extends RandomAccessibleInterval<? extends RealType<?>>> frames,
		final Calibration calibration, final String name, final Supplier<double[]> dataRange)
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
			public double[] dataRange() {
				return dataRange == null ? null : dataRange.get();
			}
		};
	}
}
