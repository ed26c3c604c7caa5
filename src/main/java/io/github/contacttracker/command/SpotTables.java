package io.github.contacttracker.command;

import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;

/**
 * The ImageJ results tables of Contact Tracker. The spots table has exactly the columns of the command line's
 * CSV ({@link SpotColumn}, TrackMate's keys first, then ours), one row per spot, the row index being the spot's
 * ID; positions are in calibrated units.
 */
public final class SpotTables {

	/** Title of the spots table. */
	public static final String SPOTS_TITLE = "Contact Tracker spots";
	/** Title of the pair-distance table. */
	public static final String PAIRS_TITLE = "Contact Tracker pairs";

	/** Decimal places shown for non-integer columns (the stored values are full doubles). */
	static final int DECIMALS = 4;

	/** Columns of the pair table, in order. */
	public static final String PAIR_FRAME = "FRAME", PAIR_ID_A = "SPOT_A", PAIR_ID_B = "SPOT_B",
		PAIR_DISTANCE = "DISTANCE", PAIR_FIRST_PASS_DISTANCE = "FIRST_PASS_DISTANCE", PAIR_FLAGGED = "FLAGGED";
	private static final String[] PAIR_COLUMNS = { PAIR_FRAME, PAIR_ID_A, PAIR_ID_B, PAIR_DISTANCE,
		PAIR_FIRST_PASS_DISTANCE, PAIR_FLAGGED };

	private SpotTables() {}

	/** @return the spots table: one row per spot, IDs 0, 1, ... in list order */
	public static TitledResultsTable spots(final List<Localization> spots, final Calibration cal) {
		final TitledResultsTable rt = new TitledResultsTable(SPOTS_TITLE);
		rt.showRowNumbers(false);
		rt.setNaNEmptyCells(false);
		final SpotColumn[] columns = SpotColumn.values();
		for (int id = 0; id < spots.size(); id++) {
			rt.incrementCounter();
			for (final SpotColumn c : columns)
				rt.addValue(c.key(), c.value(spots.get(id), id, cal));
		}
		if (spots.isEmpty()) // an empty table still has its columns
			for (final SpotColumn c : columns)
				rt.getFreeColumn(c.key());
		for (final SpotColumn c : columns)
			decimals(rt, c.key(), c.isInteger() ? 0 : DECIMALS);
		return rt;
	}

	/** @return the pair table: frame, the two spot IDs, the distances (calibrated units) and a flag column */
	public static TitledResultsTable pairs(final List<PairDistances.Pair> pairs) {
		final TitledResultsTable rt = new TitledResultsTable(PAIRS_TITLE);
		rt.showRowNumbers(false);
		if (pairs.isEmpty())
			for (final String c : PAIR_COLUMNS)
				rt.getFreeColumn(c);
		for (final PairDistances.Pair p : pairs) {
			rt.incrementCounter();
			rt.addValue(PAIR_FRAME, p.frame());
			rt.addValue(PAIR_ID_A, p.idA());
			rt.addValue(PAIR_ID_B, p.idB());
			rt.addValue(PAIR_DISTANCE, p.distance());
			rt.addValue(PAIR_FIRST_PASS_DISTANCE, p.firstPassDistance());
			rt.addValue(PAIR_FLAGGED, p.flagged() ? 1 : 0);
		}
		for (final String c : new String[] { PAIR_FRAME, PAIR_ID_A, PAIR_ID_B, PAIR_FLAGGED })
			decimals(rt, c, 0);
		decimals(rt, PAIR_DISTANCE, DECIMALS);
		decimals(rt, PAIR_FIRST_PASS_DISTANCE, DECIMALS);
		return rt;
	}

	private static void decimals(final TitledResultsTable rt, final String column, final int places) {
		final int index = rt.getColumnIndex(column);
		if (index >= 0) rt.setDecimalPlaces(index, places);
	}
}
