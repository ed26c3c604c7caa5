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
package io.github.contacttracker.ij;

import java.util.List;

import ij.ImagePlus;
import ij.ImageStack;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.Calibration;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;

/**
 * ImgLib2 frames as an ImageJ time series, sharing their pixel arrays: the way simulated movies become an
 * {@link ImagePlus} to save as TIFF ({@code io.ImageFiles.saveTiff}) or to hand to a Fiji command. The reverse of
 * {@link ImagePlusFrames}.
 */
public final class TimeSeries {

	private TimeSeries() {}

	/**
	 * Builds an ImageJ time series (T = number of frames) sharing the frames' pixel arrays.
	 *
	 * @param frames 2D unsigned-byte, unsigned-short or float {@link ArrayImg}s of equal size
	 * @param cal the calibration to set (pixel size, unit, frame interval)
	 */
	public static ImagePlus of(final String title, final List<? extends ArrayImg<?, ?>> frames,
		final Calibration cal)
	{
		if (frames.isEmpty()) throw new InvalidInputException("no frames");
		final int w = (int) frames.get(0).dimension(0), h = (int) frames.get(0).dimension(1);
		final ImageStack stack = new ImageStack(w, h);
		for (final ArrayImg<?, ?> f : frames) {
			final Object access = f.update(null);
			if (access instanceof ByteArray) stack.addSlice(null, ((ByteArray) access).getCurrentStorageArray());
			else if (access instanceof ShortArray) stack.addSlice(null, ((ShortArray) access).getCurrentStorageArray());
			else if (access instanceof FloatArray) stack.addSlice(null, ((FloatArray) access).getCurrentStorageArray());
			else throw new InvalidInputException("unsupported pixel storage " + access.getClass().getSimpleName());
		}
		final ImagePlus imp = new ImagePlus(title, stack);
		imp.setDimensions(1, 1, frames.size());
		final ij.measure.Calibration c = imp.getCalibration();
		c.pixelWidth = cal.pixelWidth();
		c.pixelHeight = cal.pixelHeight();
		c.pixelDepth = 1;
		c.setUnit(cal.unit());
		c.frameInterval = cal.frameInterval();
		c.setTimeUnit(cal.timeUnit());
		return imp;
	}
}
