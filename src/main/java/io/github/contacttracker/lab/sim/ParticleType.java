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

import java.util.Objects;

/**
 * Everything needed to simulate images of one kind of particle, and the tracking parameters that suit them.
 *
 * @param name short label, e.g. for reports
 * @param diameterMicrons particle diameter (um), which sets the contact distance
 * @param pixelSizeNm size of one image pixel (nm)
 * @param profile the single-particle image above background
 * @param background background grey level {@code I0}
 * @param threshold suggested active-area threshold {@code th} (grey level)
 * @param rOut suggested range parameter {@code R_out} (px)
 * @param noise per-pixel noise added before quantisation
 */
public record ParticleType(String name, double diameterMicrons, double pixelSizeNm, RadialProfile profile,
	double background, double threshold, double rOut, NoiseModel noise)
{

	/** @throws IllegalArgumentException for a missing part or a non-positive size */
	public ParticleType {
		Objects.requireNonNull(name, "name");
		Objects.requireNonNull(profile, "profile");
		Objects.requireNonNull(noise, "noise");
		if (!(diameterMicrons > 0) || !Double.isFinite(diameterMicrons) || !(pixelSizeNm > 0)
			|| !Double.isFinite(pixelSizeNm))
			throw new IllegalArgumentException("particle type " + name + " needs a positive diameter and pixel size, not "
				+ diameterMicrons + " um and " + pixelSizeNm + " nm");
		if (!Double.isFinite(background) || !Double.isFinite(threshold) || !(rOut > 0) || !Double.isFinite(rOut))
			throw new IllegalArgumentException("particle type " + name + " needs a finite background and threshold and "
				+ "a positive rOut, not " + background + ", " + threshold + ", " + rOut);
	}

	/** @return the diameter in pixels: the centre distance at contact */
	public double diameterPx() {
		return diameterMicrons * 1000 / pixelSizeNm;
	}

	/** @return the pixel size in micrometres */
	public double pixelSizeMicrons() {
		return pixelSizeNm / 1000;
	}
}
