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
package io.github.contacttracker.io;

import java.io.Serializable;

import io.github.contacttracker.core.InvalidInputException;

/**
 * Physical scale of an image: positions are {@code index * pixelWidth} (TrackMate's convention, no origin
 * offset), times are {@code frame * frameInterval}.
 *
 * @param pixelWidth size of a pixel along x, in {@code unit}
 * @param pixelHeight size of a pixel along y, in {@code unit}
 * @param unit spatial unit ("pixel" when uncalibrated)
 * @param frameInterval time between frames, in {@code timeUnit}
 * @param timeUnit time unit ("frame" when unknown)
 */
public record Calibration(double pixelWidth, double pixelHeight, String unit, double frameInterval, String timeUnit)
	implements Serializable
{

	/** One pixel per unit, one frame per time unit. */
	public static final Calibration PIXELS = new Calibration(1, 1, "pixel", 1, "frame");

	/** @throws IllegalArgumentException when a size is not a positive finite number */
	public Calibration {
		if (!(pixelWidth > 0) || !Double.isFinite(pixelWidth) || !(pixelHeight > 0) || !Double.isFinite(pixelHeight))
			throw new InvalidInputException("pixel size must be positive, not " + pixelWidth + " x " + pixelHeight);
		if (!(frameInterval > 0) || !Double.isFinite(frameInterval))
			throw new InvalidInputException("frame interval must be positive, not " + frameInterval);
		if (unit == null || unit.isBlank()) unit = "pixel";
		if (timeUnit == null || timeUnit.isBlank()) timeUnit = "frame";
	}

	/** @return a spatial calibration with isotropic pixels of {@code size} {@code unit}, time in frames */
	public static Calibration ofPixelSize(final double size, final String unit) {
		return new Calibration(size, size, unit, 1, "frame");
	}
}
