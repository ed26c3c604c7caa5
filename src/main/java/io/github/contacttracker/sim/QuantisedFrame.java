package io.github.contacttracker.sim;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * A camera-like integer image and how many of its pixels hit the limits of the pixel type.
 *
 * @param <T> the pixel type
 * @param image the image
 * @param clippedLow pixels that would have been below 0
 * @param clippedHigh pixels that would have been above the type's maximum
 */
public record QuantisedFrame<T extends RealType<T> & NativeType<T>>(ArrayImg<T, ?> image, int clippedLow,
	int clippedHigh)
{

	/** @return all clipped pixels */
	public int clippedPixels() {
		return clippedLow + clippedHigh;
	}
}
