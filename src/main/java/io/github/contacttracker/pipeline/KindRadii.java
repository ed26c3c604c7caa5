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
package io.github.contacttracker.pipeline;

import java.util.Arrays;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.math.Statistics;

/**
 * The particles' radii ({@code RADIUS}) when their diameter was given: half of it for particles all of one kind;
 * with several kinds found ({@code KIND} 1, 2, ...), each kind its own. The diameter given (or measured by the
 * profile helper from the nearest neighbours' distances) is the contact distance of the most numerous kind; the
 * other kinds' radii are scaled from it by the ratio of the kinds' typical active-area radii (the median of each
 * kind's spots), which the threshold cuts alike for particles of one profile shape. Spots of no kind take the
 * most numerous kind's radius.
 */
public final class KindRadii {

	private KindRadii() {}

	/**
	 * @param spots the spots (their {@code radius} the active area's, their kinds as found)
	 * @param diameter the particle diameter given (px; above 0)
	 * @return the radius of each kind, indexed by kind (index 0: spots of no kind)
	 */
	public static double[] of(final List<Localization> spots, final double diameter) {
		int max = 0;
		for (final Localization s : spots)
			max = Math.max(max, s.kind());
		final double[] radius = new double[max + 1];
		Arrays.fill(radius, diameter / 2);
		if (max < 2) return radius;
		final int[] count = new int[max + 1];
		for (final Localization s : spots)
			count[s.kind()]++;
		int main = 1, kinds = 0;
		for (int k = 1; k <= max; k++) {
			if (count[k] > 0) kinds++;
			if (count[k] > count[main]) main = k;
		}
		if (kinds < 2) return radius;
		final double[] median = new double[max + 1];
		for (int k = 1; k <= max; k++)
			median[k] = count[k] == 0 ? Double.NaN : median(spots, k, count[k]);
		if (!(median[main] > 0)) return radius;
		for (int k = 1; k <= max; k++)
			if (median[k] > 0) radius[k] = diameter / 2 * median[k] / median[main];
		return radius;
	}

	/** @return the median active-area radius of the spots of one kind */
	private static double median(final List<Localization> spots, final int kind, final int count) {
		final double[] r = new double[count];
		int n = 0;
		for (final Localization s : spots)
			if (s.kind() == kind) r[n++] = s.radius();
		return Statistics.median(r, n);
	}
}
