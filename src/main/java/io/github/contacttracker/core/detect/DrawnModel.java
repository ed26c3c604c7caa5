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

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * The members' light as the model draws it: which estimates it draws, their light added to or taken from an image,
 * the pixels it reaches, and the robust spread of an image's values there. The moves of {@link ModelSelection}, the
 * member test ({@link MemberTests}) and the background's texture ({@link BackgroundTexture}) read the frame through it.
 */
final class DrawnModel {

	private DrawnModel() {}

	/** @return whether a fitted estimate is drawn in the model (a finite amplitude and a positive scale) */
	static boolean drawn(final Estimate e) {
		return Double.isFinite(e.amplitude()) && e.scale() > 0 && Double.isFinite(e.x()) && Double.isFinite(e.y()) &&
			!e.has(Flag.MERGED);
	}

	/** Adds {@code sign} times the particle's light, {@code a P(r / s)}, to the image (within its profile's radius). */
	static void draw(final float[] image, final int w, final int h, final Estimate e, final EmpiricalProfile p,
		final int sign)
	{
		final double s = e.scale(), a = sign * e.amplitude(), reach = p.radius() * s;
		final int x0 = Math.max(0, (int) Math.floor(e.x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e.x() + reach));
		final int y0 = Math.max(0, (int) Math.floor(e.y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e.y() + reach));
		for (int y = y0; y <= y1; y++) {
			final double dy = y - e.y();
			double xd = x0; // (x counted as a double too, exactly: RowRuns#row says why)
			for (int x = x0; x <= x1; x++, xd++) {
				final double dx = xd - e.x();
				image[y * w + x] += (float) (a * p.lookup(Math.sqrt(dx * dx + dy * dy) / s));
			}
		}
	}

	/** @return which pixels lie within reach of a drawn member's light (its profile's radius times its scale) */
	static boolean[] near(final int w, final int h, final Estimate[] e, final EmpiricalProfile[] of) {
		final boolean[] near = new boolean[w * h];
		for (int k = 0; k < e.length; k++) {
			if (!drawn(e[k])) continue;
			final double reach = of[k].radius() * e[k].scale();
			final int x0 = Math.max(0, (int) Math.floor(e[k].x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e[k].x() +
				reach));
			final int y0 = Math.max(0, (int) Math.floor(e[k].y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e[k].y() +
				reach));
			for (int y = y0; y <= y1; y++)
				for (int x = x0; x <= x1; x++)
					if (MemberTests.dist(x - e[k].x(), y - e[k].y()) <= reach) near[y * w + x] = true;
		}
		return near;
	}

	/**
	 * @return {@link Statistics#MAD_TO_SIGMA} times the median absolute deviation from the median of the values where
	 *         {@code where} holds (all when none does), on a sample of at most 65536 of them: the spread of the
	 *         residuals where the model draws particles, which its mismatch with real particles raises
	 */
	static double robustSpread(final float[] v, final boolean[] where) {
		int count = 0;
		for (final boolean b : where)
			if (b) count++;
		final boolean all = count == 0;
		if (all) count = v.length;
		final int step = Math.max(1, count / 65536);
		final int n = (count + step - 1) / step;
		if (n == 0) return 0;
		final double[] s = new double[n];
		for (int i = 0, seen = 0, j = 0; i < v.length && j < n; i++)
			if (all || where[i]) {
				if (seen++ % step == 0) s[j++] = v[i];
			}
		final double median = Statistics.median(s);
		for (int j = 0; j < n; j++)
			s[j] = Math.abs(s[j] - median);
		return Statistics.MAD_TO_SIGMA * Statistics.median(s);
	}
}
