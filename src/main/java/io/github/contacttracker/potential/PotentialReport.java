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
package io.github.contacttracker.potential;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The human-readable summary of a pair analysis, shared by the command line and Fiji. */
public final class PotentialReport {

	private PotentialReport() {}

	/**
	 * @param spots the spots selected
	 * @param r the result
	 * @param unit the spots' unit ("" when unknown)
	 * @return lines: spots used and left out, the field of view (given or inferred, and shrunk from the border),
	 *         pairs, the zero of U
	 */
	public static List<String> lines(final SpotSet spots, final PairCorrelation.Result r, final String unit) {
		final List<String> out = new ArrayList<>();
		out.add(String.format(Locale.ROOT, "%d spots in %d frames used (of %d rows; left out: %d flagged%s, %d " +
			"before the start frame%s)", r.spots(), r.frames(), spots.rows(), spots.flaggedLeftOut(), spots
				.flagColumns().isEmpty() ? "" : " by " + String.join("/", spots.flagColumns()), spots.earlyLeftOut(), r
					.borderReach() > 0 ? ", " + r.nearBorderLeftOut() + " as near the border as flagged ones" : ""));
		final String u = unit.isEmpty() ? "" : " " + unit;
		final FieldOfView f = r.field();
		out.add(String.format(Locale.ROOT, "field of view %s x %s%s, %s%s", PairCorrelation.num(f.width()),
			PairCorrelation.num(f.height()), u, f.inferred()
				? "INFERRED from the spots (their bounding box): give the width and height if you know them"
				: "as given", r.borderReach() > 0 ? String.format(Locale.ROOT, "; less %s%s on every side, where spots " +
					"cut by the border were left out", PairCorrelation.num(r.borderReach()), u) : Double.isNaN(r.borderReach())
						? "; NOT shrunk for the spots left out at the border: some lie too deep inside it to mark its edge " +
							"(tracked within a selection? give its size)" : ""));
		out.add(String.format(Locale.ROOT, "%d pairs closer than %s%s (%s pairs of the same frame in all)", r.pairs(),
			PairCorrelation.num(r.bins().get(r.bins().size() - 1).rHigh()), u, PairCorrelation.num(r.framePairs())));
		if (!Double.isNaN(r.zeroFrom()))
			out.add(String.format(Locale.ROOT, "U = 0 on average over r in [%s, %s]%s (shifted by %+.4f kT)",
				PairCorrelation.num(r.zeroFrom()), PairCorrelation.num(r.zeroTo()), u, -r.uZero()));
		else out.add("U = -ln g (no zero range set)");
		return out;
	}

	/**
	 * @param spots the spots used
	 * @param f the field of view
	 * @return a warning when the spots spread beyond a given field, or null
	 */
	public static String fieldWarning(final SpotSet spots, final FieldOfView f) {
		if (f.inferred() || spots.size() == 0) return null;
		final double[] x = spots.allX(), y = spots.allY();
		double x0 = Double.POSITIVE_INFINITY, x1 = Double.NEGATIVE_INFINITY, y0 = x0, y1 = x1;
		for (int i = 0; i < x.length; i++) {
			x0 = Math.min(x0, x[i]);
			x1 = Math.max(x1, x[i]);
			y0 = Math.min(y0, y[i]);
			y1 = Math.max(y1, y[i]);
		}
		if (x1 - x0 <= f.width() && y1 - y0 <= f.height()) return null;
		return String.format(Locale.ROOT, "the spots spread over %s x %s, more than the field of view given (%s x %s): " +
			"check --width/--height (same units as the spots)", PairCorrelation.num(x1 - x0), PairCorrelation.num(y1 -
				y0), PairCorrelation.num(f.width()), PairCorrelation.num(f.height()));
	}
}
