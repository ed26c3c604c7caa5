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
package io.github.contacttracker.core.detect;

import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;

/**
 * The particles of the contrast a run did not track: the blobs of the frame inverted ({@link ImageDetection#seeds},
 * band-passed at the particles' scale) that stand at least {@value #AS_STRONG} times as high as the particles tracked
 * stand in the frame itself (the median of the band-passed frame at their centres), and lie farther than a diameter
 * from every particle tracked. A run tracks one contrast; a field of bright and dark particles (a bright-field movie
 * of two materials, or of particles in and out of focus) gives the other contrast's particles no spot, and nothing
 * else says so. The distance leaves out what the particles tracked wear around them: the dark ring of a bright
 * particle, the bright halo of a dark one; the height leaves out the background's texture.
 */
public final class OtherContrast {

	/** A blob of the other contrast counts from this share of the tracked particles' typical height. */
	public static final double AS_STRONG = 0.5;

	private OtherContrast() {}

	/**
	 * @param frame the frame as it was tracked
	 * @param inverted the same frame inverted
	 * @param x the centres of the particles tracked on it (the frame's local coordinates)
	 * @param y their y
	 * @param diameter the particles' diameter (px, {@code > 0})
	 * @return how many blobs of the other contrast stand out as the tracked particles do, away from them (0 where
	 *         nothing was tracked)
	 */
	public static int blobs(final Plane frame, final Plane inverted, final double[] x, final double[] y,
		final double diameter)
	{
		final int n = x.length, w = frame.width(), h = frame.height();
		if (n == 0 || !(diameter > 0) || diameter > Math.hypot(w, h)) return 0;
		final ImageDetection.Scale scale = ImageDetection.Scale.of(diameter);
		final float[] own = BandPass.of(frame, scale.sigma(), scale.halfWidth());
		final double[] at = new double[n];
		int inside = 0;
		for (int k = 0; k < n; k++) {
			final int px = (int) Math.round(x[k]), py = (int) Math.round(y[k]);
			if (px >= 0 && py >= 0 && px < w && py < h) at[inside++] = own[py * w + px];
		}
		if (inside == 0) return 0;
		final double typical = Statistics.median(at, inside);
		if (!(typical > 0)) return 0;
		final Peaks other = ImageDetection.seeds(inverted, diameter, NoiseEstimate.sigma(inverted));
		int count = 0;
		for (int p = 0; p < other.count(); p++) {
			if (!(other.height()[p] >= AS_STRONG * typical)) continue;
			boolean away = true;
			for (int k = 0; k < n && away; k++)
				away = Math.hypot(other.x()[p] - x[k], other.y()[p] - y[k]) > diameter;
			if (away) count++;
		}
		return count;
	}
}
