package io.github.contacttracker.io;

import io.github.contacttracker.core.InvalidInputException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import ij.ImagePlus;
import ij.ImageStack;
import ij.process.ImageProcessor;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.RealType;

/**
 * The frames of an ImageJ image as ImgLib2 planes, wrapped without copying (so the core takes its
 * primitive-array fast path).
 * <p>
 * Every time point is a frame. A plain stack of 2D planes (one channel, slices only) is a time series. In a
 * multi-channel image one channel is tracked. An image with both Z and T above 1 is refused: the method is
 * 2D.
 *
 * @param frames one 2D plane per frame
 * @param calibration pixel size, units and frame interval
 * @param width image width (px)
 * @param height image height (px)
 * @param channel the 1-based channel taken
 */
public record ImagePlusFrames(List<RandomAccessibleInterval<? extends RealType<?>>> frames, Calibration calibration,
	int width, int height, int channel)
{
	public ImagePlusFrames {
		frames = Collections.unmodifiableList(new ArrayList<>(frames));
	}

	/**
	 * @param imp the image
	 * @param channel the 1-based channel to track; 0 accepts only single-channel images
	 * @throws IllegalArgumentException with a one-line message when the image cannot be tracked
	 */
	public static ImagePlusFrames of(final ImagePlus imp, final int channel) {
		if (imp == null) throw new InvalidInputException("no image");
		final String name = "'" + imp.getTitle() + "'";
		final int bits = imp.getBitDepth();
		if (bits == 24)
			throw new InvalidInputException(name + " is an RGB image: convert it to 8-bit, 16-bit or 32-bit grey " +
				"(Image > Type) or split the channels first");
		if (bits != 8 && bits != 16 && bits != 32)
			throw new InvalidInputException(name + " has an unsupported bit depth: " + bits);
		final int nc = imp.getNChannels(), nz = imp.getNSlices(), nt = imp.getNFrames();
		if (nz > 1 && nt > 1)
			throw new InvalidInputException(name + " has " + nz + " Z slices and " + nt +
				" time frames: the method is 2D; make a projection or pick one slice first");
		if (channel < 0 || channel > nc)
			throw new InvalidInputException("channel " + channel + " does not exist: " + name + " has " + nc +
				" channel" + (nc == 1 ? "" : "s"));
		if (channel == 0 && nc > 1)
			throw new InvalidInputException(name + " has " + nc + " channels: choose one to track (channel = 1.." +
				nc + ")");
		final int c = Math.max(channel, 1);
		final int count = Math.max(nz, nt); // Z slices of a plain stack are frames
		final ImageStack stack = imp.getStack();
		final int w = imp.getWidth(), h = imp.getHeight();
		final List<RandomAccessibleInterval<? extends RealType<?>>> frames = new ArrayList<>(count);
		for (int t = 1; t <= count; t++) {
			final int index = nt > 1 ? imp.getStackIndex(c, 1, t) : imp.getStackIndex(c, t, 1);
			frames.add(wrap(stack.getProcessor(index), w, h));
		}
		final ij.measure.Calibration cal = imp.getCalibration();
		final double pw = cal.pixelWidth > 0 ? cal.pixelWidth : 1, ph = cal.pixelHeight > 0 ? cal.pixelHeight : 1;
		final double dt = cal.frameInterval > 0 ? cal.frameInterval : 1;
		final String unit = cal.scaled() ? cal.getXUnit() : "pixel";
		final String timeUnit = cal.frameInterval > 0 ? cal.getTimeUnit() : "frame";
		return new ImagePlusFrames(frames, new Calibration(cal.scaled() ? pw : 1, cal.scaled() ? ph : 1, unit, dt,
			timeUnit), w, h, c);
	}

	private static RandomAccessibleInterval<? extends RealType<?>> wrap(final ImageProcessor ip, final int w,
		final int h)
	{
		final Object pixels = ip.getPixels();
		if (pixels instanceof byte[]) return ArrayImgs.unsignedBytes((byte[]) pixels, w, h);
		if (pixels instanceof short[]) return ArrayImgs.unsignedShorts((short[]) pixels, w, h);
		if (pixels instanceof float[]) return ArrayImgs.floats((float[]) pixels, w, h);
		throw new InvalidInputException("unsupported pixel type " + pixels.getClass().getSimpleName());
	}

	/** @return the number of frames */
	public int frameCount() {
		return frames.size();
	}

	/**
	 * The smallest and largest pixel value over all frames.
	 *
	 * @return {min, max}
	 * @throws IllegalArgumentException naming the first NaN or infinite pixel
	 */
	public double[] dataRange() {
		double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
		for (int t = 0; t < frames.size(); t++) {
			final var cursor = frames.get(t).localizingCursor();
			while (cursor.hasNext()) {
				final double v = cursor.next().getRealDouble();
				if (!Double.isFinite(v))
					throw new InvalidInputException("frame " + (t + 1) + ", pixel (" + cursor.getLongPosition(0) +
						", " + cursor.getLongPosition(1) + ") is " + v + ": images with NaN or infinite pixels cannot be " +
						"tracked");
				if (v < min) min = v;
				if (v > max) max = v;
			}
		}
		return new double[] { min, max };
	}
}
