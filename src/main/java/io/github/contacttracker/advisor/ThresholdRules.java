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
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.radial.ComponentShape;

/**
 * The helper's threshold rules: the contact rule's bridge (the brightest point between particles at contact, from
 * the pooled profile), and the rules that raise the threshold above it: clear of the background's texture (bright
 * spots of halos and rings that are no particle's core) and until the frame's active areas have the shape of one
 * particle each (these two read the frame at candidate thresholds).
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
}
