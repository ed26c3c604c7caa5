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
