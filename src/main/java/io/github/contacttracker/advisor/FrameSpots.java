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
package io.github.contacttracker.advisor;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.track.ContactTracker;

/**
 * The frame's spots the profile helper chooses its particles among, in the plane's coordinates, with their
 * nearest-neighbour distances: the bright spots at half height between the frame's median and its brightest pixels,
 * each localized by one radial-symmetry pass. Their spacing is what the diameter is estimated from
 * ({@link DiameterEstimate}), and the most isolated of them are profiled ({@link ProfiledParticles}).
 *
 * @param spots the spots, in the frame's coordinates
 * @param xy their centres {@code {x, y}} in the plane's coordinates
 * @param nn each spot's distance to its nearest neighbour (px)
 * @param near how far from a point given its particle's brightest pixel is looked for (px)
 * @param level the grey level the spots were found at
 */
record FrameSpots(List<Localization> spots, double[][] xy, double[] nn, double near, double level) {

	/**
	 * A frame's grey levels as the helper reads them.
	 *
	 * @param median the median of its sampled pixels ({@link #sample})
	 * @param noise its pixel noise (at least 1e-6)
	 * @param top the level of its brightest pixels: the 20th highest sampled (at most a 10,000th of them from the top)
	 * @param bottom the level of its darkest pixels, counted the same way from the bottom
	 */
	record Levels(double median, double noise, double top, double bottom) {

		static Levels of(final Plane plane) {
			final double[] sample = sample(plane);
			final double median = Statistics.quantile(sample, 0.5);
			final double noise = Math.max(NoiseEstimate.sigma(plane), 1e-6);
			final double tail = Math.max(1e-4, 20.0 / sample.length);
			return new Levels(median, noise, Statistics.quantile(sample, 1 - tail), Statistics.quantile(sample, tail));
		}

		/**
		 * @return whether its brightest pixels stand more than {@link Margins#THRESHOLD_MARGIN_SIGMAS} noise sigmas
		 *         above its median
		 */
		boolean brighterThanNoise() {
			return top - median > Margins.THRESHOLD_MARGIN_SIGMAS * noise;
		}

		/** @return whether its darkest pixels lie more than that below it */
		boolean darkerThanNoise() {
			return median - bottom > Margins.THRESHOLD_MARGIN_SIGMAS * noise;
		}
	}

	/**
	 * Step 1: the spots at half height between the frame's median and its brightest pixels, by one radial-symmetry
	 * pass: the same spots with a point as without, so that the frame's values (its diameter, its most isolated
	 * particles) do not depend on where the point was given. A particle at the point fainter than that half height
	 * (its brightest pixel below it) is found by a second pass at half its own height and added: only the spot of
	 * that pass nearest to the point, within {@link #near} of it; a point on the background or on a halo adds none
	 * and is then no particle's ({@link ProfiledParticles#measure} says so).
	 *
	 * @param point the point given, in the frame's coordinates ({@code null} if none)
	 * @param at the same point in the plane's coordinates
	 * @throws InvalidInputException if nothing is brighter than the noise
	 */
	static FrameSpots find(final Plane plane, final double[] point, final double[] at,
		final double diameterGiven)
	{
		final Levels levels = Levels.of(plane);
		final double median0 = levels.median(), noise0 = levels.noise(), frameTop = levels.top();
		final double near = diameterGiven > 0 ? Math.max(2, diameterGiven / 4) : 5;
		final double own = point != null ? peak(plane, at[0], at[1], near) : frameTop;
		if (point != null && !(own - median0 > Margins.THRESHOLD_MARGIN_SIGMAS * noise0))
			throw new InvalidInputException(String.format(Locale.ROOT, "no bright particle at (%s, %s): the brightest " +
				"pixel within %s px is %s, within %s noise sigmas (%s) of the background %s", HelperFormat.fmt(
					point[0]), HelperFormat.fmt(point[1]), HelperFormat.fmt(near), HelperFormat.fmt(own),
				HelperFormat.fmt(Margins.THRESHOLD_MARGIN_SIGMAS), HelperFormat.fmt(noise0), HelperFormat.fmt(
					median0)));
		if (!levels.brighterThanNoise())
			throw new InvalidInputException("no particle brighter than the noise in the frame");
		final double level = median0 + 0.5 * (frameTop - median0);
		final List<Localization> spots = new ArrayList<>(spotsAt(plane, level));
		// a particle at the point fainter than the frame's half height: found at half its own height, and added
		if (point != null && own < level && nearest(spots, plane, at, near) < 0) {
			final List<Localization> faint = spotsAt(plane, median0 + 0.5 * (own - median0));
			final int k = nearest(faint, plane, at, near);
			if (k >= 0) spots.add(faint.get(k));
		}
		final double[][] xy = new double[spots.size()][];
		for (int k = 0; k < xy.length; k++)
			xy[k] = new double[] { spots.get(k).x() - plane.minX(), spots.get(k).y() - plane.minY() };
		return new FrameSpots(spots, xy, nearestNeighbourDistances(xy), near, level);
	}

	/** @return the spots of the frame at grey level {@code level}, by one radial-symmetry pass */
	private static List<Localization> spotsAt(final Plane plane, final double level) {
		final TrackerParameters find = new TrackerParameters(level, 10, 5, Connectivity.EIGHT,
			TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.FIRST);
		return new ContactTracker(find).analyse(plane, 0, false).spots();
	}

	/** @return the index of the spot nearest to {@code at} (plane coordinates) within {@code near} of it, or -1 */
	private static int nearest(final List<Localization> spots, final Plane plane, final double[] at,
		final double near)
	{
		int best = -1;
		double d = near;
		for (int k = 0; k < spots.size(); k++) {
			final double e = Math.hypot(spots.get(k).x() - plane.minX() - at[0], spots.get(k).y() - plane.minY() - at[1]);
			if (e <= d) {
				d = e;
				best = k;
			}
		}
		return best;
	}

	/** Distance of each point to its nearest other point (infinite for a lone point). */
	static double[] nearestNeighbourDistances(final double[][] xy) {
		final double[] nn = new double[xy.length];
		Arrays.fill(nn, Double.POSITIVE_INFINITY);
		for (int i = 0; i < xy.length; i++)
			for (int j = i + 1; j < xy.length; j++) {
				final double d = Math.hypot(xy[i][0] - xy[j][0], xy[i][1] - xy[j][1]);
				nn[i] = Math.min(nn[i], d);
				nn[j] = Math.min(nn[j], d);
			}
		return nn;
	}

	/** Up to about a million pixels of the frame on a regular grid. */
	static double[] sample(final Plane plane) {
		final long n = (long) plane.width() * plane.height();
		final int stride = (int) Math.max(1, Math.ceil(Math.sqrt(n / 1e6)));
		final DoubleList s = new DoubleList();
		for (int y = 0; y < plane.height(); y += stride)
			for (int x = 0; x < plane.width(); x += stride)
				s.add(plane.get(x, y));
		return s.toArray();
	}

	static double peak(final Plane plane, final double cx, final double cy, final double within) {
		double peak = Double.NEGATIVE_INFINITY;
		final int x0 = (int) Math.max(0, Math.floor(cx - within)), x1 = (int) Math.min(plane.width() - 1, Math.ceil(cx +
			within));
		final int y0 = (int) Math.max(0, Math.floor(cy - within)), y1 = (int) Math.min(plane.height() - 1, Math.ceil(
			cy + within));
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				if (Math.hypot(x - cx, y - cy) <= within) peak = Math.max(peak, plane.get(x, y));
		return peak;
	}
}
