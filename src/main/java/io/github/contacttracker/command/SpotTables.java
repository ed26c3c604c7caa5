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

import java.util.ArrayList;
import java.util.List;
import java.util.StringJoiner;

import ij.measure.ResultsTable;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.settings.SettingValues;

/**
 * The ImageJ results tables of Contact Tracker. The spots table has the columns of the command line's CSV
 * ({@link SpotColumn}) with the same values, one row per spot, the row index being the spot's ID; positions are in
 * calibrated units. Its columns are ordered for a reader ({@link #DISPLAY_ORDER}: position, its error and the
 * flags first), with the 1-based {@link #SLICE} beside the 0-based {@code FRAME}; the CSV keeps TrackMate's key
 * order, which TrackMate's importer expects.
 * <p>
 * The same content can be written into ImageJ's system results table ({@link #toSystemTable}), which a macro
 * reads with {@code nResults} and {@code getResult}.
 */
public final class SpotTables {

	/** Title of the spots table, followed by {@code ": "} and the image's title: one table per image. */
	public static final String SPOTS_TITLE = "Contact Tracker spots";
	/**
	 * The frame counted from 1, beside TrackMate's 0-based {@code FRAME}: what ImageJ's slider shows (1/30 for
	 * {@code FRAME} 0).
	 */
	public static final String SLICE = "SLICE";
	/** The readable flags column: the warning flags' names, "-" for none (the 0/1 columns stay for macros). */
	public static final String FLAGS = "FLAGS";
	/** Title of the pair-distance table. */
	public static final String PAIRS_TITLE = "Contact Tracker pairs";

	/** Decimal places shown for non-integer values (the stored values are full doubles). */
	static final int DECIMALS = 4;

	/**
	 * The spots table's columns, left to right: what a user reads first (which spot, where, how big and bright,
	 * how precisely), then the readable {@link #FLAGS} column (after {@link #FLAGS_AFTER}), then the 0/1 flags and
	 * the rest. Every {@link SpotColumn} appears once.
	 */
	public static final List<SpotColumn> DISPLAY_ORDER = List.of(SpotColumn.ID, SpotColumn.FRAME,
		SpotColumn.POSITION_X, SpotColumn.POSITION_Y, SpotColumn.RADIUS, SpotColumn.QUALITY, SpotColumn.SIGMA_X,
		SpotColumn.SIGMA_Y, SpotColumn.FLAG_FELL_BACK, SpotColumn.FLAG_DEGENERATE, SpotColumn.FLAG_AT_BORDER,
		SpotColumn.FLAG_MERGED, SpotColumn.FLAG_NOT_CONVERGED, SpotColumn.FLAG_UNMODELLED_NEIGHBOUR,
		SpotColumn.FLAG_SECOND_PASS, SpotColumn.KIND, SpotColumn.POSITION_T,
		SpotColumn.ACTIVE_RADIUS, SpotColumn.FIRST_PASS_X, SpotColumn.FIRST_PASS_Y, SpotColumn.ACTIVE_AREA,
		SpotColumn.SECOND_AREA, SpotColumn.ITERATIONS, SpotColumn.POSITION_Z, SpotColumn.VISIBILITY);
	/** The column the readable {@link #FLAGS} column follows. */
	public static final SpotColumn FLAGS_AFTER = SpotColumn.SIGMA_Y;

	/** Columns of the pair table, in order. */
	public static final String PAIR_FRAME = "FRAME", PAIR_ID_A = "SPOT_A", PAIR_ID_B = "SPOT_B",
		PAIR_DISTANCE = "DISTANCE", PAIR_FIRST_PASS_DISTANCE = "FIRST_PASS_DISTANCE", PAIR_FLAGGED = "FLAGGED";
	private static final String[] PAIR_COLUMNS = { PAIR_FRAME, PAIR_ID_A, PAIR_ID_B, PAIR_DISTANCE,
		PAIR_FIRST_PASS_DISTANCE, PAIR_FLAGGED };
	private static final List<String> PAIR_INTEGERS = List.of(PAIR_FRAME, PAIR_ID_A, PAIR_ID_B, PAIR_FLAGGED);

	/**
	 * Contact Tracker's last run: its spots table, what Pair Potential reads when ImageJ's Results table, where the
	 * run put the spots too, has since been given something else (the Profile's suggestion); and the image's field
	 * of view, the real size the spots were found in. One run, held like ImageJ's own Results table, for the
	 * session.
	 *
	 * @param spots the spots table
	 * @param image the image's title
	 * @param field the image's field of view, in the spots' units
	 */
	public record LastRun(ResultsTable spots, String image, FieldOfView field) {}

	private static volatile LastRun lastRun;

	private SpotTables() {}

	/** Forgets the last run (a session that tracked nothing yet). */
	static void forgetLastRun() {
		lastRun = null;
	}

	/** @return Contact Tracker's last run in this session, or null */
	public static LastRun lastRun() {
		return lastRun;
	}

	/**
	 * @param imageTitle the image's title, in the table's: one table (and window) per image
	 * @param width the image's width in pixels
	 * @param height its height
	 * @param settings the settings the spots were found with, which the table carries
	 * @return the spots table: one row per spot, IDs 0, 1, ... in list order; also {@link #lastRun()} from now on
	 */
	public static TitledResultsTable spots(final List<Localization> spots, final Calibration cal,
		final String imageTitle, final int width, final int height, final SettingValues settings)
	{
		final TitledResultsTable rt = new TitledResultsTable(spotsTitle(imageTitle), settings);
		rt.showRowNumbers(false);
		fillSpots(rt, spots, cal);
		lastRun = new LastRun(rt, imageTitle, FieldOfView.ofImage(width, height, cal.pixelWidth(), cal.pixelHeight()));
		return rt;
	}

	/** @return the title of the spots table of an image */
	public static String spotsTitle(final String imageTitle) {
		return imageTitle == null || imageTitle.isEmpty() ? SPOTS_TITLE : SPOTS_TITLE + ": " + imageTitle;
	}

	/** @return the warning flags of a spot in words, "; "-separated, or "-" */
	public static String flagWords(final Localization s) {
		final StringJoiner j = new StringJoiner("; ");
		for (final Flag f : s.flagSet())
			if (f.isWarning()) j.add(f.description());
		return j.length() == 0 ? "-" : j.toString();
	}

	/** @return the pair table: frame, the two spot IDs, the distances (calibrated units) and a flag column */
	public static TitledResultsTable pairs(final List<PairDistances.Pair> pairs, final String imageTitle) {
		final TitledResultsTable rt = new TitledResultsTable(imageTitle == null || imageTitle.isEmpty() ? PAIRS_TITLE :
			PAIRS_TITLE + ": " + imageTitle);
		rt.showRowNumbers(false);
		fillPairs(rt, pairs);
		return rt;
	}

	/**
	 * Replaces the content of ImageJ's system results table (the one a macro's {@code nResults} and
	 * {@code getResult} read, and <i>Analyze Particles</i> fills) with the spots table's.
	 *
	 * @return the system table
	 */
	public static ResultsTable spotsToSystemTable(final List<Localization> spots, final Calibration cal) {
		// the same object is kept, so that an open "Results" window goes on showing it
		final ResultsTable system = ResultsTable.getResultsTable();
		system.reset();
		fillSpots(system, spots, cal);
		return system;
	}

	/** Like {@link #spotsToSystemTable}, with the pair table's content. */
	public static ResultsTable pairsToSystemTable(final List<PairDistances.Pair> pairs) {
		final ResultsTable system = ResultsTable.getResultsTable();
		system.reset();
		fillPairs(system, pairs);
		return system;
	}

	private static void fillSpots(final ResultsTable rt, final List<Localization> spots, final Calibration cal) {
		rt.setNaNEmptyCells(false);
		for (int id = 0; id < spots.size(); id++) {
			rt.incrementCounter();
			for (final SpotColumn c : DISPLAY_ORDER) {
				rt.addValue(c.key(), c.value(spots.get(id), id, cal));
				if (c == SpotColumn.FRAME) rt.addValue(SLICE, spots.get(id).frame() + 1);
				if (c == FLAGS_AFTER) rt.addValue(FLAGS, flagWords(spots.get(id)));
			}
		}
		final List<String> keys = new ArrayList<>(), integers = new ArrayList<>();
		for (final SpotColumn c : DISPLAY_ORDER) {
			keys.add(c.key());
			if (c == SpotColumn.FRAME) {
				keys.add(SLICE);
				integers.add(SLICE);
			}
			if (c == FLAGS_AFTER) keys.add(FLAGS);
			if (c.isInteger()) integers.add(c.key());
		}
		format(rt, keys, integers, spots.isEmpty());
	}

	private static void fillPairs(final ResultsTable rt, final List<PairDistances.Pair> pairs) {
		for (final PairDistances.Pair p : pairs) {
			rt.incrementCounter();
			rt.addValue(PAIR_FRAME, p.frame());
			rt.addValue(PAIR_ID_A, p.idA());
			rt.addValue(PAIR_ID_B, p.idB());
			rt.addValue(PAIR_DISTANCE, p.distance());
			rt.addValue(PAIR_FIRST_PASS_DISTANCE, p.firstPassDistance());
			rt.addValue(PAIR_FLAGGED, p.flagged() ? 1 : 0);
		}
		format(rt, List.of(PAIR_COLUMNS), PAIR_INTEGERS, pairs.isEmpty());
	}

	/**
	 * Integer columns without decimals; the others in ImageJ's automatic format: {@link #DECIMALS} places, none
	 * for whole values (a QUALITY of 1 reads 1, not 1.0000).
	 */
	private static void format(final ResultsTable rt, final List<String> keys, final List<String> integers,
		final boolean empty)
	{
		if (empty) // an empty table still has its columns
			for (final String key : keys)
				rt.getFreeColumn(key);
		rt.setPrecision(DECIMALS);
		for (final String key : keys) {
			final int index = rt.getColumnIndex(key);
			if (index >= 0) rt.setDecimalPlaces(index, integers.contains(key) ? 0 : ResultsTable.AUTO_FORMAT);
		}
	}
}
