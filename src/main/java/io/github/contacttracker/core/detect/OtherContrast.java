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
 * stand in the frame itself (the median of the band-passed frame at their centres), lie farther than a diameter
 * from every particle tracked, and dip below the background at least {@value #AS_STRONG} times as far as the tracked
 * particles rise above it (the background: a low quantile of the pixels clear of both). The band-pass measures
 * against the local mean, so a gap in a dense monolayer, a particle missing among packed bright ones, stands out in the
 * inverted frame as a particle would; but it only reads the background the bright particles stand on, and the dip
 * leaves it out. A run tracks one contrast; a field of bright and dark particles (a bright-field movie
 * of two materials, or of particles in and out of focus) gives the other contrast's particles no spot, and nothing
 * else says so. The distance leaves out what the particles tracked wear around them: the dark ring of a bright
 * particle, the bright halo of a dark one; the height leaves out the background's texture.
 */
public final class OtherContrast {

	/** A blob of the other contrast counts from this share of the tracked particles' typical height. */
	public static final double AS_STRONG = 0.5;

	/** The background is read this many diameters from every particle and blob, clear of their light. */
	static final double CLEAR = 0.75;
	/**
	 * The background is this quantile of the pixels clear of them: in a packed field those pixels also hold the
	 * particles the run did not find, and only its gaps, the background itself, lie as low.
	 */
	static final double LOW = 0.05;

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
		final double[] bx = new double[other.count()], by = new double[other.count()];
		int candidates = 0;
		for (int p = 0; p < other.count(); p++) {
			if (!(other.height()[p] >= AS_STRONG * typical)) continue;
			boolean away = true;
			for (int k = 0; k < n && away; k++)
				away = Math.hypot(other.x()[p] - x[k], other.y()[p] - y[k]) > diameter;
			if (!away) continue;
			bx[candidates] = other.x()[p];
			by[candidates++] = other.y()[p];
		}
		if (candidates == 0) return 0;
		final double background = background(frame, x, y, bx, by, candidates, diameter);
		if (Double.isNaN(background)) return 0;
		final double r = Math.max(1, diameter / 6);
		final double[] level = new double[n];
		int measured = 0;
		for (int k = 0; k < n; k++) {
			final double v = mean(frame, x[k], y[k], r);
			if (!Double.isNaN(v)) level[measured++] = v;
		}
		if (measured == 0) return 0;
		final double rise = Statistics.median(level, measured) - background;
		if (!(rise > 0)) return 0;
		int count = 0;
		for (int c = 0; c < candidates; c++)
			if (background - mean(frame, bx[c], by[c], r) >= AS_STRONG * rise) count++;
		return count;
	}

	/**
	 * @return the {@value #LOW} quantile of the frame's pixels farther than {@value #CLEAR} diameters from every
	 *         particle tracked and every blob of the other contrast: the background both stand on; NaN where no pixel
	 *         is that clear (a field packed edge to edge, whose gaps are the background and no other particles)
	 */
	private static double background(final Plane frame, final double[] x, final double[] y, final double[] bx,
		final double[] by, final int blobs, final double diameter)
	{
		final int w = frame.width(), h = frame.height();
		final boolean[] covered = new boolean[w * h];
		final double reach = CLEAR * diameter;
		for (int k = 0; k < x.length; k++)
			cover(covered, w, h, x[k], y[k], reach);
		for (int c = 0; c < blobs; c++)
			cover(covered, w, h, bx[c], by[c], reach);
		int free = 0;
		for (final boolean c : covered)
			if (!c) free++;
		if (free == 0) return Double.NaN;
		final double[] v = new double[free];
		for (int py = 0, j = 0; py < h; py++)
			for (int px = 0; px < w; px++)
				if (!covered[py * w + px]) v[j++] = frame.get(px, py);
		return Statistics.quantile(v, free, LOW);
	}

	private static void cover(final boolean[] covered, final int w, final int h, final double cx, final double cy,
		final double reach)
	{
		final int x0 = Math.max(0, (int) Math.floor(cx - reach)), x1 = Math.min(w - 1, (int) Math.ceil(cx + reach));
		final int y0 = Math.max(0, (int) Math.floor(cy - reach)), y1 = Math.min(h - 1, (int) Math.ceil(cy + reach));
		for (int py = y0; py <= y1; py++)
			for (int px = x0; px <= x1; px++)
				if ((px - cx) * (px - cx) + (py - cy) * (py - cy) <= reach * reach) covered[py * w + px] = true;
	}

	/** @return the frame's mean within {@code r} of (cx, cy), NaN where no pixel is */
	private static double mean(final Plane frame, final double cx, final double cy, final double r) {
		final int x0 = Math.max(0, (int) Math.ceil(cx - r)), x1 = Math.min(frame.width() - 1, (int) Math.floor(cx + r));
		final int y0 = Math.max(0, (int) Math.ceil(cy - r)), y1 = Math.min(frame.height() - 1, (int) Math.floor(cy + r));
		double sum = 0;
		int n = 0;
		for (int py = y0; py <= y1; py++)
			for (int px = x0; px <= x1; px++)
				if ((px - cx) * (px - cx) + (py - cy) * (py - cy) <= r * r) {
					sum += frame.get(px, py);
					n++;
				}
		return n == 0 ? Double.NaN : sum / n;
	}
}
