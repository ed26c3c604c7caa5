package io.github.contacttracker.pipeline;

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
		final FrameSource all = this;
		return new FrameSource() {

			@Override
			public int frameCount() {
				return 1;
			}

			@Override
			public RandomAccessibleInterval<? extends RealType<?>> frame(final int i) {
				return all.frame(t);
			}

			@Override
			public Calibration calibration() {
				return all.calibration();
			}

			@Override
			public String name() {
				return all.name();
			}
		};
	}

	/** @return an ImageJ image's frames as a source, the data range checked */
	static FrameSource of(final ImagePlusFrames frames, final String name) {
		return new FrameSource() {

			@Override
			public int frameCount() {
				return frames.frameCount();
			}

			@Override
			public RandomAccessibleInterval<? extends RealType<?>> frame(final int t) {
				return frames.frames().get(t);
			}

			@Override
			public Calibration calibration() {
				return frames.calibration();
			}

			@Override
			public String name() {
				return name;
			}

			@Override
			public double[] dataRange() {
				return frames.dataRange();
			}
		};
	}
}
