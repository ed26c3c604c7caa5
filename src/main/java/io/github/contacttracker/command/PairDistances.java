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
package io.github.contacttracker.command;

import io.github.contacttracker.core.InvalidInputException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;

/**
 * Centre distances between spots of the same frame closer than a cutoff: the quantity pair-potential studies
 * histogram. Distances are in calibrated units ({@code sqrt((dx pixelWidth)^2 + (dy pixelHeight)^2)}).
 */
public final class PairDistances {

	/**
	 * One pair of spots of one frame.
	 *
	 * @param frame the frame (0-based)
	 * @param idA the first spot's ID (its row in the spots table; {@code idA < idB})
	 * @param idB the second spot's ID
	 * @param distance distance of the final centres (calibrated units)
	 * @param firstPassDistance distance of the first-pass centres (calibrated units), for comparison
	 * @param flagged whether either spot carries a warning flag
	 */
	public record Pair(int frame, int idA, int idB, double distance, double firstPassDistance, boolean flagged) {}

	private PairDistances() {}

	/**
	 * @param spots the spots, their list positions being their IDs (any frame order)
	 * @param cal the calibration
	 * @param cutoff pairs closer than this (calibrated units; strictly) are listed
	 * @return the pairs, by frame, then {@code idA}, then {@code idB}
	 * @throws IllegalArgumentException when the cutoff is not a positive number
	 */
	public static List<Pair> within(final List<Localization> spots, final Calibration cal, final double cutoff) {
		if (!(cutoff > 0) || !Double.isFinite(cutoff))
			throw new InvalidInputException("pair_cutoff must be a positive distance, not " + cutoff);
		final double pw = cal.pixelWidth(), ph = cal.pixelHeight();
		// sweep along x: spots of one frame sorted by calibrated x, compare only while dx < cutoff
		final Integer[] order = new Integer[spots.size()];
		for (int i = 0; i < order.length; i++)
			order[i] = i;
		Arrays.sort(order, Comparator.<Integer> comparingInt(i -> spots.get(i).frame()).thenComparingDouble(i -> spots
			.get(i).x()));
		final List<Pair> pairs = new ArrayList<>();
		for (int a = 0; a < order.length; a++) {
			final Localization p = spots.get(order[a]);
			for (int b = a + 1; b < order.length; b++) {
				final Localization q = spots.get(order[b]);
				if (q.frame() != p.frame() || (q.x() - p.x()) * pw >= cutoff) break;
				final double d = Math.hypot((q.x() - p.x()) * pw, (q.y() - p.y()) * ph);
				if (d >= cutoff) continue;
				final int i = Math.min(order[a], order[b]), j = Math.max(order[a], order[b]);
				final Localization s = spots.get(i), t = spots.get(j);
				pairs.add(new Pair(p.frame(), i, j, d, Math.hypot((t.firstX() - s.firstX()) * pw, (t.firstY() - s
					.firstY()) * ph), p.isFlagged() || q.isFlagged()));
			}
		}
		pairs.sort(Comparator.comparingInt(Pair::frame).thenComparingInt(Pair::idA).thenComparingInt(Pair::idB));
		return pairs;
	}
}
