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

import java.util.Arrays;
import java.util.List;
import java.util.function.DoubleToIntFunction;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.radial.ComponentShape;

/**
 * The helper's threshold (steps 7-9 of {@link ProfileAnalysis}): the contact rule's bridge (the brightest point
 * between particles at contact, from the pooled profile), and the rules that raise the threshold above it: clear of
 * the background's texture (bright spots of halos and rings that are no particle's core) and until the frame's active
 * areas have the shape of one particle each (these two read the frame at candidate thresholds); and what a threshold
 * leaves of a particle, its active radius and the {@code min_area} that follows.
 */
final class ThresholdRules {

	/** Smallest ratio of peak heights that separates the background's texture from the particles' cores. */
	static final double TEXTURE_GAP_RATIO = 2;
	/** At most this share (percent) of the active areas may fail the outline tests at the suggested threshold. */
	static final int MAX_NOT_ROUND_PERCENT = 1;
	/** Grid step (px) of the bridge search. */
	static final double BRIDGE_STEP_PX = 0.5;

	private ThresholdRules() {}

	/**
	 * Components of the frame at a threshold, split by their peak height above the background at the largest gap
	 * (a ratio of at least {@value #TEXTURE_GAP_RATIO}) below half the highest peak: below it the background's
	 * texture (bright-field halos and rings, their sums between particles, an uneven background), above it the
	 * particles' cores. The texture is the sum of faint tails, an order of magnitude below the cores' peaks, so the
	 * heights fall in two groups with a wide gap between them; a threshold just above the sum of two profiles at
	 * contact but below that gap picks up texture spots.
	 * Components below {@code minArea} pixels are left out, as the tracker drops them.
	 *
	 * @return {@code {highest texture peak, lowest core peak, texture components}} above the background, or NaNs
	 *         when there is no such gap
	 */
	static double[] textureGap(final Plane plane, final double threshold, final double background, final int minArea) {
		final List<Region> regions = ComponentLabeling.label(plane, threshold, Connectivity.EIGHT);
		final DoubleList heights = new DoubleList();
		for (final Region r : regions) {
			if (r.area() < minArea) continue;
			double peak = Double.NEGATIVE_INFINITY;
			for (int k = 0; k < r.runCount(); k++)
				for (int x = r.runStart(k); x <= r.runEnd(k); x++)
					peak = Math.max(peak, plane.get(x, r.runY(k)));
			heights.add(peak - background);
		}
		final double[] hs = heights.toArray();
		Arrays.sort(hs);
		int cut = -1;
		double best = TEXTURE_GAP_RATIO;
		for (int i = 0; i + 1 < hs.length && hs[i] < hs[hs.length - 1] / 2; i++) {
			final double ratio = hs[i + 1] / Math.max(hs[i], 1e-9);
			if (ratio >= best) {
				best = ratio;
				cut = i;
			}
		}
		return cut < 0 ? new double[] { Double.NaN, Double.NaN, 0 } : new double[] { hs[cut], hs[cut + 1], cut + 1 };
	}

	/**
	 * The lowest threshold from {@code from} up to {@code ceiling} (in steps of {@code step}) at which at most
	 * {@value #MAX_NOT_ROUND_PERCENT}% of the frame's active areas (of at least {@code minArea} px at that threshold,
	 * away from the border) fail the outline tests of merge detection ({@link ComponentShape}: elongated, or with a
	 * bay).
	 *
	 * @return {@code {threshold, active areas that fail at the threshold from, active areas there}}; the threshold
	 *         is {@code from} when no step up to the ceiling does better
	 */
	static double[] roundFrom(final Plane plane, final double from, final double ceiling, final double step,
		final DoubleToIntFunction minArea)
	{
		final int[] first = notRound(plane, from, minArea.applyAsInt(from));
		for (double t = from; t <= ceiling; t += step) {
			final int[] n = t == from ? first : notRound(plane, t, minArea.applyAsInt(t));
			if (n[0] * 100 <= MAX_NOT_ROUND_PERCENT * n[1]) return new double[] { t, first[0], first[1] };
		}
		return new double[] { from, first[0], first[1] };
	}

	/** @return {@code {active areas that fail the outline tests, active areas}} at a threshold */
	private static int[] notRound(final Plane plane, final double threshold, final int minArea) {
		int bad = 0, all = 0;
		for (final Region r : ComponentLabeling.label(plane, threshold, Connectivity.EIGHT)) {
			if (r.area() < minArea || r.minX() == 0 || r.minY() == 0 || r.maxX() == plane
				.width() - 1 || r.maxY() == plane.height() - 1) continue;
			all++;
			if (ComponentShape.of(r).outlineMerged(false)) bad++;
		}
		return new int[] { bad, all };
	}

	/**
	 * The brightest height above background, at points at least {@code D/2} from every centre, of two particles
	 * at contact and of three in a touching triangle (0 where nothing reaches).
	 */
	static double brightestBetween(final PooledProfile p, final double diameter, final double reach) {
		final double[][][] configurations = { { { 0, 0 }, { diameter, 0 } }, { { 0, 0 }, { diameter, 0 }, { diameter /
			2, diameter * Math.sqrt(3) / 2 } } };
		double best = Double.NEGATIVE_INFINITY;
		final double half2 = diameter * diameter / 4;
		for (final double[][] conf : configurations) {
			final double x0 = -reach, x1 = diameter + reach, y0 = -reach, y1 = diameter + reach;
			for (double y = y0; y <= y1; y += BRIDGE_STEP_PX)
				for (double x = x0; x <= x1; x += BRIDGE_STEP_PX) {
					boolean outside = true;
					double sum = 0;
					for (final double[] c : conf) {
						final double d2 = (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]);
						if (d2 < half2) {
							outside = false;
							break;
						}
						sum += PooledProfile.height(p, Math.sqrt(d2), reach);
					}
					if (outside) best = Math.max(best, sum);
				}
		}
		return best;
	}

	/**
	 * The suggested threshold and what it was raised from.
	 *
	 * @param bridge the brightest grey level between particles at contact
	 * @param atContact {@code bridge} plus the noise margin
	 * @param threshold the suggestion (not rounded)
	 * @param peak the brightest pixel of the first particle
	 */
	record Threshold(double bridge, double atContact, double threshold, double peak) {}

	/**
	 * Steps 7-9: the bridge between particles at contact plus the noise margin; raised clear of the background's
	 * texture (halos, rings, their sums between particles); and raised until every active area has the shape of one
	 * particle (bright fringes between touching particles in bright field are brighter than the sum of two
	 * profiles), up to half the cores' height.
	 */
	static Threshold threshold(final Plane plane, final PooledProfile pooled, final double[] level,
		final double diameter, final double reach, final double[] centre, final List<Finding> findings)
	{
		final double bridge = pooled.background() + Math.max(0, ThresholdRules.brightestBetween(pooled, diameter,
			reach));
		final double atContact = bridge + Margins.THRESHOLD_MARGIN_SIGMAS * pooled.noise();
		// the active areas that count as particles at a threshold: as the tracker will keep them (small particles' are
		// smaller than the default min_area: counting only the larger ones would judge the merges alone)
		final DoubleToIntFunction minArea = th -> minArea(activeRadius(pooled.radius(), level, pooled.count(), th));
		final double[] gap = ThresholdRules.textureGap(plane, atContact, pooled.background(), minArea.applyAsInt(
			atContact));
		final double clear = Math.max(atContact, Double.isNaN(gap[0]) ? atContact : pooled.background() + (gap[0] +
			gap[1]) / 2);
		if (clear > atContact) findings.add(new Finding.BackgroundTexture(atContact, (int) gap[2], gap[0], gap[1]));
		final double peak = FrameSpots.peak(plane, centre[0], centre[1], Math.max(2, diameter / 4));
		final double ceiling = pooled.background() + 0.5 * (peak - pooled.background());
		final double[] shaped = ThresholdRules.roundFrom(plane, clear, ceiling, Math.max(0.5, pooled.noise() / 2),
			minArea);
		final double threshold = shaped[0];
		if (threshold > clear) findings.add(new Finding.RaisedUntilRound(clear, (int) shaped[1], (int) shaped[2]));
		else if (shaped[1] > 0) findings.add(new Finding.NotRound((int) shaped[1], (int) shaped[2], ceiling));
		return new Threshold(bridge, atContact, threshold, peak);
	}

	/** @return each ring's grey level: the background plus its height (NaN for an empty ring) */
	static double[] levels(final PooledProfile pooled) {
		final double[] level = new double[pooled.radius().length];
		for (int k = 0; k < level.length; k++)
			level[k] = pooled.count()[k] > 0 ? pooled.background() + pooled.height()[k] : Double.NaN;
		return level;
	}

	/**
	 * @param radius each ring's mean radius, {@code level} its grey level, {@code count} its pixels (as in {@link Result})
	 * @return where the profile falls below the threshold (px, interpolated; 0 when even the centre is below)
	 */
	static double activeRadius(final double[] radius, final double[] level, final int[] count,
		final double threshold)
	{
		double activeRadius = 0;
		int previous = -1;
		for (int k = 0; k < level.length; k++) {
			if (count[k] == 0) continue;
			if (level[k] < threshold) {
				if (previous >= 0) activeRadius = radius[previous] + (radius[k] - radius[previous]) * (level[previous] -
					threshold) / (level[previous] - level[k]);
				break;
			}
			activeRadius = radius[k];
			previous = k;
		}
		return activeRadius;
	}

	/**
	 * The {@code min_area} for particles whose active areas at a threshold have radius {@code activeRadius}: half
	 * their area {@code pi r^2}, at most the default {@value TrackerParameters#DEFAULT_MIN_AREA} px (0: the default).
	 * The default was set for particles tens of pixels across; particles a few pixels across have active areas near
	 * it, and the default dropped many (in trackpy's bulk_water sample in-focus particles of 15-19 px, where the
	 * profile's active disc holds 28 px at the helper's threshold; 69 of 126 simulated spots 7.5 px across). A
	 * component of less than half a particle's area is noise or a fringe: the threshold lies 3 noise levels above the
	 * brightest point between two particles.
	 */
	static int minArea(final double activeRadius) {
		if (!(activeRadius > 0)) return TrackerParameters.DEFAULT_MIN_AREA;
		return (int) Math.max(TrackerParameters.MIN_AREA_AT_LEAST, Math.min(TrackerParameters.DEFAULT_MIN_AREA, Math
			.floor(Math.PI * activeRadius * activeRadius / 2)));
	}
}
