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

import ij.measure.ResultsTable;
import io.github.contacttracker.potential.PairCorrelation;

/** The table of values the pair-potential command shows. */
final class PotentialColumns {

	private PotentialColumns() {}

	/** @return the table of values: R, PAIRS, G, U_KT, U_KT_ERR (as the CSV; empty cells for empty bins) */
	static TitledResultsTable table(final PairCorrelation.Result r, final String title) {
		final TitledResultsTable rt = new TitledResultsTable(title);
		rt.showRowNumbers(false);
		fill(rt, r);
		return rt;
	}

	/**
	 * Replaces the content of {@code rt} (e.g. ImageJ's Results table, which macros read) with the values.
	 *
	 * @return {@code rt}
	 */
	static ResultsTable fill(final ResultsTable rt, final PairCorrelation.Result r) {
		rt.reset();
		rt.setNaNEmptyCells(true);
		for (int i = 0; i < r.bins().size(); i++) {
			final PairCorrelation.Bin b = r.bins().get(i);
			rt.incrementCounter();
			rt.addValue("R", b.r());
			rt.addValue("PAIRS", b.pairs());
			rt.addValue("G", b.g());
			rt.addValue("U_KT", r.u(i));
			rt.addValue("U_KT_ERR", b.uError());
		}
		rt.setDecimalPlaces(rt.getColumnIndex("PAIRS"), 0);
		for (final String c : new String[] { "R", "G", "U_KT", "U_KT_ERR" })
			rt.setDecimalPlaces(rt.getColumnIndex(c), 4);
		return rt;
	}
}
