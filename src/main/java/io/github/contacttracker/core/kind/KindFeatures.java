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
package io.github.contacttracker.core.kind;

import java.io.Serializable;
import java.util.Arrays;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/**
 * What a particle looks like, for telling kinds of particle apart ({@link Kinds}): its radial profile around its
 * centre, the median of each 1 px ring of pixels (so that neighbours, which cover a part of each ring only, do not
 * move it), and three numbers read off it. Immutable.
 *
 * @param coreRadius where the profile first falls to half its central contrast (px): the radius of the bright core,
 *        the particle's size in the image whatever the threshold (NaN when the particle has no bright core)
 * @param peak the central contrast: the profile at the centre minus the frame's background (grey levels)
 * @param ringDepth how far the dark ring around the core dips below the background (grey levels, 0 without one)
 * @param ringRadius where it is darkest (px; NaN without a dark ring)
 * @param activeRadius the equivalent radius of the active area, {@code sqrt(area / pi)} (px; NaN if not known)
 * @param profile the profile minus the background, one value per radius 0, 1, 2, ... px (NaN where fewer than
 *        {@value #MIN_RING_PIXELS} pixels of a ring beyond 1.5 px lie in the frame)
 */
public record KindFeatures(double coreRadius, double peak, double ringDepth, double ringRadius,
	double activeRadius, double[] profile) implements Serializable
{
	/** Fewest pixels of a ring for its median. */
	public static final int MIN_RING_PIXELS = 3;

	/** Copies the profile. */
	public KindFeatures {
		profile = profile.clone();
	}

	@Override
	public double[] profile() {
		return profile.clone();
	}

	/** @return whether the features can place the particle among kinds: it has a bright core */
	public boolean usable() {
		return coreRadius > 0 && peak > 0;
	}

	/**
	 * The background of a frame: the median of its pixels (sampled every other row and column). The particles'
	 * bright cores and dark rings lie on either side of it, and on the real movies they cover less than half of the
	 * frame, so the median is the background's level.
	 */
	public static double background(final Plane plane) {
		final int w = plane.width(), h = plane.height();
		final double[] v = new double[((w + 1) / 2) * ((h + 1) / 2)];
		int n = 0;
		for (int y = 0; y < h; y += 2)
			for (int x = 0; x < w; x += 2)
				v[n++] = plane.get(x, y);
		return Statistics.median(v, n);
	}

	/**
	 * Measures the particles of a frame at the centres a method left them (the paper's or the iterative pass: the
	 * nearer the true centre, the sharper the profile), with the frame's {@link #background(Plane)}.
	 *
	 * @param plane the frame
	 * @param particles its particles (first pass done; their active areas give {@link #activeRadius()})
	 * @param estimates their centres, same order
	 * @param reach the outermost radius of the profiles (px): {@code r_out} serves
	 * @return the features, same order
	 */
	public static KindFeatures[] measure(final Plane plane, final Particle[] particles, final Estimate[] estimates,
		final double reach)
	{
		return measure(plane, particles, estimates, reach, false);
	}

	/**
	 * As {@link #measure(Plane, Particle[], Estimate[], double)}, the spots a tracker found in the frame (at their
	 * centres, in the frame's coordinates, with their active areas).
	 */
	public static KindFeatures[] measure(final Plane plane, final List<Localization> spots, final double reach) {
		final double background = background(plane);
		final KindFeatures[] out = new KindFeatures[spots.size()];
		for (int k = 0; k < out.length; k++) {
			final Localization s = spots.get(k);
			out[k] = measure(plane, s.x() - plane.minX(), s.y() - plane.minY(), s.activeArea(), background, reach);
		}
		return out;
	}

	/** The particles measured wholly, or only for their kind ({@code coreOnly}), with the frame's background. */
	private static KindFeatures[] measure(final Plane plane, final Particle[] particles, final Estimate[] estimates,
		final double reach, final boolean coreOnly)
	{
		if (particles.length != estimates.length)
			throw new IllegalArgumentException(particles.length + " particles but " + estimates.length + " estimates");
		final double background = background(plane);
		final KindFeatures[] out = new KindFeatures[particles.length];
		for (int k = 0; k < out.length; k++) {
			final double x = estimates[k].x(), y = estimates[k].y();
			final int area = particles[k].region().area();
			out[k] = coreOnly ? measureCore(plane, x, y, area, background, reach) : measure(plane, x, y, area,
				background, reach);
		}
		return out;
	}

	/**
	 * Measures a particle.
	 *
	 * @param plane the frame
	 * @param x the particle's centre in the plane's local coordinates (px)
	 * @param y its centre y
	 * @param activeArea its active area (pixels; 0 if not known)
	 * @param background the frame's background ({@link #background(Plane)})
	 * @param reach the outermost radius of the profile (px; e.g. {@code r_out})
	 * @return the features
	 */
	public static KindFeatures measure(final Plane plane, final double x, final double y, final int activeArea,
		final double background, final double reach)
	{
		final double[] profile = profile(plane, x, y, background, reach);
		final double peak = profile.length > 0 ? profile[0] : Double.NaN;
		final double activeRadius = activeArea > 0 ? Math.sqrt(activeArea / Math.PI) : Double.NaN;
		final int k = peak > 0 ? coreEnd(profile, peak) : -1;
		final double core = k > 0 ? coreRadius(profile, k, peak) : Double.NaN;
		if (Double.isNaN(core)) return new KindFeatures(Double.NaN, peak, 0, Double.NaN, activeRadius, profile);
		// the dark ring: the lowest point between the core and the next rise back above the background (the halo),
		// within four core radii plus 4 px (a neighbour's core lies farther)
		double depth = 0, ring = Double.NaN;
		final int last = (int) Math.min(profile.length - 1, Math.ceil(4 * core + 4));
		for (int j = k; j <= last && !Double.isNaN(profile[j]); j++) {
			if (-profile[j] > depth) {
				depth = -profile[j];
				ring = j;
			}
			else if (depth > 0 && profile[j] > 0) break;
		}
		return new KindFeatures(core, peak, depth, ring, activeRadius, profile);
	}

	/**
	 * {@link #measureCore(Plane, double, double, int, double, double)} for the particles of a frame at centres
	 * {@code estimates}, with the frame's {@link #background(Plane)}: what places them among known kinds.
	 */
	public static KindFeatures[] measureCore(final Plane plane, final Particle[] particles,
		final Estimate[] estimates, final double reach)
	{
		return measure(plane, particles, estimates, reach, true);
	}

	/**
	 * Measures what places a particle among known kinds ({@link Kinds#kindOf}): its {@link #coreRadius()} and
	 * {@link #peak()}, exactly as {@link #measure(Plane, double, double, int, double, double)} finds them, from the
	 * rings out to the core's edge only (about a tenth of the pixels out to {@code r_out} in a dense field, whose
	 * medians would cost a sixth of {@code fit}'s time); the ring and the profile beyond are not measured ({@link
	 * #ringDepth()} 0, {@link #ringRadius()} NaN, the profile cut there).
	 */
	public static KindFeatures measureCore(final Plane plane, final double x, final double y, final int activeArea,
		final double background, final double reach)
	{
		final double activeRadius = activeArea > 0 ? Math.sqrt(activeArea / Math.PI) : Double.NaN;
		// twice the active radius holds the core of most particles; failing that, twice as far, up to the reach
		double r = Math.min(reach, Double.isNaN(activeRadius) ? reach : Math.max(CORE_REACH, 2 * activeRadius + 2));
		while (true) {
			// (every ring of it is read whole, as out to the reach: a pixel outside the box read, of whole pixels
			// from floor(x - r) to ceil(x + r), lies r + 1 or more from the centre, beyond the last ring's reach)
			final double[] profile = profile(plane, x, y, background, r);
			final double peak = profile.length > 0 ? profile[0] : Double.NaN;
			final int k = peak > 0 ? coreEnd(profile, peak) : -1;
			if (k != 0 || !(r < reach)) {
				final double core = k > 0 ? coreRadius(profile, k, peak) : Double.NaN;
				return new KindFeatures(core, peak, 0, Double.NaN, activeRadius, profile);
			}
			r = Math.min(reach, 2 * r);
		}
	}

	/** The least radius (px) out to which {@link #measureCore} first reads. */
	private static final double CORE_REACH = 6;

	/**
	 * @return the first ring of {@code profile} (whose centre is {@code peak > 0}) at or below half the peak; -1 if a
	 *         ring beyond the first has no value before it (no core can be told); 0 if none falls that low
	 */
	private static int coreEnd(final double[] profile, final double peak) {
		// (ring 1 holds no pixel when the centre sits on a pixel corner: then from ring 0 to ring 2)
		for (int k = 1; k < profile.length; k++) {
			if (Double.isNaN(profile[k])) {
				if (k == 1) continue;
				return -1;
			}
			if (profile[k] <= 0.5 * peak) return k;
		}
		return 0;
	}

	/**
	 * @return the core's radius: where the profile falls to half the peak, linear between ring {@code k} and the
	 *         last ring before it with a value
	 */
	private static double coreRadius(final double[] profile, final int k, final double peak) {
		final int inner = k >= 2 && Double.isNaN(profile[k - 1]) ? k - 2 : k - 1;
		return inner + (k - inner) * (profile[inner] - 0.5 * peak) / (profile[inner] - profile[k]);
	}

	/**
	 * The radial profile about (x, y) minus the background: per radius {@code k} px, the median of the pixels at
	 * distances {@code [k - 0.5, k + 0.5)} (the centre's: {@code [0, 0.75)}, at least the nearest pixel; ring 1 from
	 * 0.75 px).
	 */
	static double[] profile(final Plane plane, final double x, final double y, final double background,
		final double reach)
	{
		final int rings = (int) Math.floor(reach + 0.5) + 1;
		final int x0 = Math.max(0, (int) Math.floor(x - reach)), x1 = Math.min(plane.width() - 1, (int) Math.ceil(x +
			reach));
		final int y0 = Math.max(0, (int) Math.floor(y - reach)), y1 = Math.min(plane.height() - 1, (int) Math.ceil(y +
			reach));
		if (x0 > x1 || y0 > y1) return new double[0];
		// counts per ring, then the values in one array, ring after ring (each pixel's ring computed once;
		// Math.hypot, exact to the last bit, would cost a tenth of a fit in a dense field)
		final int w = x1 - x0 + 1;
		final int[] ringOf = new int[w * (y1 - y0 + 1)];
		final int[] count = new int[rings + 1];
		for (int yy = y0, i = 0; yy <= y1; yy++)
			for (int xx = x0; xx <= x1; xx++, i++) {
				final double dx = xx - x, dy = yy - y;
				final int ring = ring(Math.sqrt(dx * dx + dy * dy));
				ringOf[i] = ring;
				if (ring < rings) count[ring]++;
			}
		final int[] start = new int[rings + 1];
		for (int r = 0; r < rings; r++)
			start[r + 1] = start[r] + count[r];
		final double[] values = new double[start[rings]];
		final int[] fill = Arrays.copyOf(start, rings);
		final double[] row = new double[w];
		for (int yy = y0, i = 0; yy <= y1; yy++) {
			plane.read(x0, x1, yy, yy, row, 0);
			for (int xx = 0; xx < w; xx++, i++)
				if (ringOf[i] < rings) values[fill[ringOf[i]]++] = row[xx];
		}
		final double[] out = new double[rings];
		for (int r = 0; r < rings; r++) {
			final int n = count[r];
			out[r] = n >= (r <= 1 ? 1 : MIN_RING_PIXELS)
				? Statistics.median(Arrays.copyOfRange(values, start[r], start[r + 1]), n) - background : Double.NaN;
		}
		return out;
	}

	/**
	 * Ring 0 holds distances below 0.75 px (at least the pixel nearest the centre), ring 1 those in [0.75, 1.5), ring
	 * k >= 2 those in [k - 0.5, k + 0.5).
	 */
	private static int ring(final double d) {
		return d < 0.75 ? 0 : (int) Math.floor(d + 0.5);
	}
}
