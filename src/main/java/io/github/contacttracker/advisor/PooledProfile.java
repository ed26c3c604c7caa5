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
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;

/**
 * The radial profile pooled over particles: each particle's pixels in 1 px wide rings about its centre, as heights
 * above its local background ({@link BackgroundPlane}), the other spots masked; the interquartile mean of each
 * ring's heights over all particles, and the noise of the background annuli about their planes. With it, where the
 * profile meets the background (its reach) and where the particles' own image ends.
 *
 * @param radius mean distance of each ring's pixels from the centres (px)
 * @param height each ring's interquartile mean height above the local backgrounds (NaN for an empty ring)
 * @param count pixels in each ring
 * @param background mean of the local backgrounds at the centres
 * @param noise the robust standard deviation of the background annuli's pixels about their planes
 * @param centres the centres pooled (those with enough background pixels)
 */
record PooledProfile(double[] radius, double[] height, int[] count, double background, double noise,
	List<double[]> centres)
{

	/** The background is measured in this outer part of {@code max_radius} (percent). */
	static final int BACKGROUND_ANNULUS_PERCENT = 20;
	/** Values further than this many sigmas from the mean do not count in the noise. */
	static final double CLIP_SIGMAS = 3.5;

	/**
	 * Where the particle's own image ends: the outer edge of its dark ring (where the profile, past its minimum,
	 * comes back within the noise of the background) when it has one deeper than
	 * {@value Margins#THRESHOLD_MARGIN_SIGMAS} noise sigmas, as bright-field particles do; otherwise the reach.
	 * A faint halo beyond the ring is light the particle scatters, not the particle: in bright field it can reach
	 * beyond a neighbour at contact, so taking it for the particle's image would make every particle of a dense field
	 * look touched (figures: fiji.md).
	 */
	static double imageEdge(final PooledProfile p, final double reach) {
		final double ring = ringEdge(p, reach);
		return Double.isNaN(ring) ? reach : ring;
	}

	/** @return the outer edge of the profile's dark ring ({@link #imageEdge}); NaN where it has none */
	private static double ringEdge(final PooledProfile p, final double reach) {
		int deepest = -1;
		for (int k = 0; k < p.radius().length && p.radius()[k] < reach; k++)
			if (p.count()[k] > 0 && (deepest < 0 || p.height()[k] < p.height()[deepest])) deepest = k;
		if (deepest < 0 || !(p.height()[deepest] < -Margins.THRESHOLD_MARGIN_SIGMAS * p.noise())) return Double.NaN;
		int previous = deepest;
		for (int k = deepest + 1; k < p.radius().length; k++) {
			if (p.count()[k] == 0) continue;
			if (p.height()[k] >= -p.noise()) return p.radius()[previous] + (p.radius()[k] - p.radius()[previous]) *
				(-p.noise() - p.height()[previous]) / (p.height()[k] - p.height()[previous]);
			previous = k;
		}
		return reach;
	}


	/**
	 * The particle's rim, as far as its image shows it: the outer edge of its dark ring where it has one
	 * ({@link #imageEdge}); else, if the profile has a plateau, the radius at which it falls, past its peak, to
	 * half the peak's height. A sphere's image blurred by the optics falls from its plateau to the background across
	 * its rim, the blur spreading the light evenly about the rim, so half the height lies on it whatever the blur. The
	 * reach (where the light meets the noise) would instead grow with the signal-to-noise ratio: a blurred 12 px disc
	 * at 40 noise sigmas reaches 8.6 px out, and two such particles 9 px apart would count as one.
	 * A plateau: the profile falls from 90 to 10 per cent of its peak over less than its half-height radius (a
	 * Gaussian's fall is 1.4 times its half-height radius; a disc of radius R blurred by sigma falls over 2.6 sigma,
	 * less than R from R = 2.6 sigma up). A particle without one is no wider than its blur, and its light, out to the
	 * reach, is the particle's image: the reach is returned (as it is where the profile does not fall to a tenth
	 * within the reach).
	 */
	static double rim(final PooledProfile p, final double reach) {
		final double ring = ringEdge(p, reach);
		if (!Double.isNaN(ring)) return ring;
		int peak = -1;
		for (int k = 0; k < p.radius().length && p.radius()[k] < reach; k++)
			if (p.count()[k] > 0 && (peak < 0 || p.height()[k] > p.height()[peak])) peak = k;
		if (peak < 0 || !(p.height()[peak] > 0)) return reach;
		final double top = p.height()[peak];
		final double r90 = fallsTo(p, peak, 0.9 * top, reach), r50 = fallsTo(p, peak, 0.5 * top, reach), r10 = fallsTo(
			p, peak, 0.1 * top, reach);
		return r10 - r90 < r50 ? r50 : reach;
	}

	/**
	 * @return the radius (interpolated between rings) at which the profile, past ring {@code peak}, first falls to
	 *         {@code level}; infinite if it does not within the reach
	 */
	private static double fallsTo(final PooledProfile p, final int peak, final double level, final double reach) {
		int previous = peak;
		for (int k = peak + 1; k < p.radius().length && p.radius()[k] < reach; k++) {
			if (p.count()[k] == 0) continue;
			if (p.height()[k] <= level) return p.radius()[previous] + (p.radius()[k] - p.radius()[previous]) * (p
				.height()[previous] - level) / (p.height()[previous] - p.height()[k]);
			previous = k;
		}
		return Double.POSITIVE_INFINITY;
	}

	/**
	 * {@link #pool}, the mask narrowed (by {@value #MASK_NARROWING} at a time, down to {@code narrowest}) while no
	 * particle has background pixels left around it: in a dense field of particles that do not touch (spaced a
	 * little more than a diameter apart), every pixel lies within a diameter of some neighbour. Narrowed, it is
	 * reported in {@code findings} (when not null).
	 *
	 * @param narrowest the narrowest mask tried (half the diameter; infinite: the mask as it is)
	 * @throws InvalidInputException naming the particle tried first when no mask down to {@code narrowest} leaves
	 *         background
	 */
	static PooledProfile poolNarrowing(final Plane plane, final List<double[]> centres, final double[][] spots,
		final double mask, final double radiusCap, final double narrowest, final List<Finding> findings)
	{
		NoBackground first = null;
		// (never narrower than a pixel: a diameter of 0 would otherwise narrow a mask of 0 for ever)
		final double floor = Math.max(narrowest, NARROWEST_MASK_PX);
		for (double m = mask; ; m *= MASK_NARROWING) {
			try {
				final PooledProfile pooled = pool(plane, centres, spots, m, radiusCap);
				if (first != null && findings != null) findings.add(new Finding.NeighboursMaskedCloser(m, mask));
				return pooled;
			}
			catch (final NoBackground e) {
				if (first == null) first = e;
			}
			if (!(m * MASK_NARROWING >= floor)) throw first;
		}
	}

	/** The narrowest mask {@link #poolNarrowing} tries (px). */
	static final double NARROWEST_MASK_PX = 1;

	/** Each step of {@link #poolNarrowing} multiplies the mask by this. */
	static final double MASK_NARROWING = 0.8;

	/** No particle pooled has enough background pixels around it: the message names the first one tried. */
	private static final class NoBackground extends InvalidInputException {

		static final long serialVersionUID = 1L;

		NoBackground(final String message) {
			super(message);
		}
	}

	/**
	 * Pools the pixels around {@code centres} within {@code radiusCap}, masking pixels within {@code mask} of every
	 * other spot of {@code spots}; each particle's local background is a plane fitted robustly to its annulus.
	 *
	 * @throws NoBackground when no particle has enough background pixels
	 */
	static PooledProfile pool(final Plane plane, final List<double[]> centres, final double[][] spots,
		final double mask, final double radiusCap)
	{
		final int bins = (int) Math.floor(radiusCap + 0.5) + 1;
		final DoubleList[] rings = new DoubleList[bins];
		for (int k = 0; k < bins; k++)
			rings[k] = new DoubleList();
		final double[] sumR = new double[bins];
		final DoubleList residuals = new DoubleList();
		final double inner = innerBackgroundRadius(radiusCap);
		final int w = plane.width(), h = plane.height();
		double backgroundSum = 0;
		String failure = null;
		final List<double[]> used = new ArrayList<>();
		for (final double[] c : centres) {
			final int x0 = (int) Math.max(0, Math.floor(c[0] - radiusCap)), x1 = (int) Math.min(w - 1, Math.ceil(c[0] +
				radiusCap));
			final int y0 = (int) Math.max(0, Math.floor(c[1] - radiusCap)), y1 = (int) Math.min(h - 1, Math.ceil(c[1] +
				radiusCap));
			// the other spots that can reach into this window
			final List<double[]> others = new ArrayList<>();
			for (final double[] s : spots)
				if (Math.hypot(s[0] - c[0], s[1] - c[1]) > 1 && Math.hypot(s[0] - c[0], s[1] - c[1]) < radiusCap + mask)
					others.add(s);
			final DoubleList ax = new DoubleList(), ay = new DoubleList(), av = new DoubleList();
			for (int y = y0; y <= y1; y++)
				for (int x = x0; x <= x1; x++) {
					final double r = Math.sqrt((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]));
					if (r < inner || r > radiusCap || masked(others, x, y, mask)) continue;
					ax.add(x - c[0]);
					ay.add(y - c[1]);
					av.add(plane.get(x, y));
				}
			if (ax.size < BackgroundPlane.MIN_BACKGROUND_PIXELS) {
				// neighbours all round (a dense monolayer) or the border: the next particle may do
				if (failure == null) failure = String.format(Locale.ROOT, "only %d background pixels lie between %s " +
					"and %s px from the particle at (%s, %s) inside the image and away from its neighbours: too few " +
					"to measure the background; use a larger max_radius or another particle", ax.size, HelperFormat
						.fmt2(inner), HelperFormat.fmt2(radiusCap), HelperFormat.fmt2(c[0] + plane.minX()), HelperFormat
							.fmt2(c[1] + plane.minY()));
				continue;
			}
			used.add(c);
			final double[] plane3 = BackgroundPlane.robust(ax, ay, av);
			backgroundSum += plane3[0];
			for (int i = 0; i < ax.size; i++)
				residuals.add(av.get(i) - plane3[0] - plane3[1] * ax.get(i) - plane3[2] * ay.get(i));
			for (int y = y0; y <= y1; y++)
				for (int x = x0; x <= x1; x++) {
					final double r = Math.sqrt((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]));
					final int k = (int) Math.floor(r + 0.5);
					if (r > radiusCap || k >= bins || masked(others, x, y, mask)) continue;
					rings[k].add(plane.get(x, y) - plane3[0] - plane3[1] * (x - c[0]) - plane3[2] * (y - c[1]));
					sumR[k] += r;
				}
		}
		if (used.isEmpty()) throw new NoBackground(failure);
		final double noise = Statistics.clippedSigma(residuals.toArray(), CLIP_SIGMAS);
		int filled = bins;
		while (filled > 0 && rings[filled - 1].size == 0)
			filled--;
		final double[] radius = new double[filled], height = new double[filled];
		final int[] count = new int[filled];
		for (int k = 0; k < filled; k++) {
			count[k] = rings[k].size;
			radius[k] = count[k] > 0 ? sumR[k] / count[k] : k;
			height[k] = count[k] > 0 ? Statistics.interquartileMean(rings[k].toArray(), count[k]) : Double.NaN;
		}
		return new PooledProfile(radius, height, count, backgroundSum / used.size(), noise, used);
	}

	static boolean masked(final List<double[]> others, final int x, final int y, final double mask) {
		final double m2 = mask * mask; // (squares: hypot's care for overflow costs a tenth of the helper's time)
		for (final double[] s : others) {
			final double dx = x - s[0], dy = y - s[1];
			if (dx * dx + dy * dy < m2) return true;
		}
		return false;
	}

	/** The reach: scanning inwards from the background annulus, the first ring off the background by more than s. */
	static double reach(final PooledProfile p, final double radiusCap, final List<Finding> findings) {
		final double inner = innerBackgroundRadius(radiusCap);
		int last = -1;
		for (int k = 0; k < p.radius().length; k++)
			if (p.radius()[k] < inner && p.count()[k] > 0) last = k;
		for (int k = last; k >= 0; k--) {
			if (p.count()[k] == 0 || !(Math.abs(p.height()[k]) > p.noise())) continue;
			if (k == last) {
				if (findings != null) findings.add(new Finding.NotBackToBackground(inner));
				return p.radius()[k];
			}
			int j = k + 1;
			while (j < last && p.count()[j] == 0)
				j++;
			final double a = Math.abs(p.height()[k]), b = Math.abs(p.height()[j]);
			return p.radius()[k] + (p.radius()[j] - p.radius()[k]) * (a - p.noise()) / (a - b);
		}
		return 0;
	}

	/** The pooled profile at radius {@code r}, linearly interpolated; 0 beyond the reach. */
	static double height(final PooledProfile p, final double r, final double reach) {
		if (r > reach) return 0;
		int below = -1, above = -1;
		for (int k = 0; k < p.radius().length; k++) {
			if (p.count()[k] == 0) continue;
			if (p.radius()[k] <= r) below = k;
			else {
				above = k;
				break;
			}
		}
		if (below < 0) return above < 0 ? 0 : p.height()[above];
		if (above < 0) return p.height()[below];
		return p.height()[below] + (p.height()[above] - p.height()[below]) * (r - p.radius()[below]) / (p
			.radius()[above] - p.radius()[below]);
	}

	static double innerBackgroundRadius(final double radiusCap) {
		return radiusCap * (1 - BACKGROUND_ANNULUS_PERCENT / 100.0);
	}
}
