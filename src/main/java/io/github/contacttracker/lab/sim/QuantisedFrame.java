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
package io.github.contacttracker.lab.sim;

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
