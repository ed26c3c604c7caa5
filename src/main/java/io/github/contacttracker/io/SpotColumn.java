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
package io.github.contacttracker.io;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;

/**
 * The columns of every spot table we write (CSV, ImageJ results table, TrackMate XML features), in order:
 * TrackMate's own keys first, then ours. One definition serves all outputs so they cannot drift apart. The short
 * names head TrackMate's spot table, as its own do ("Mean ch1", "Circ."): words a person reads, with the unit in
 * the name only where TrackMate's dimension gives none (pixel counts); lengths and positions take TrackMate's
 * dimensions, so its table shows the image's unit under them.
 */
public enum SpotColumn {
	ID("ID", "Spot ID", "ID", Dimension.NONE, true),
	FRAME("FRAME", "Frame", "Frame", Dimension.NONE, true),
	POSITION_X("POSITION_X", "X", "X", Dimension.POSITION, false),
	POSITION_Y("POSITION_Y", "Y", "Y", Dimension.POSITION, false),
	POSITION_Z("POSITION_Z", "Z", "Z", Dimension.POSITION, false),
	POSITION_T("POSITION_T", "T", "T", Dimension.TIME, false),
	RADIUS("RADIUS", "Radius", "R", Dimension.LENGTH, false),
	QUALITY("QUALITY", "Quality", "Quality", Dimension.QUALITY, false),
	VISIBILITY("VISIBILITY", "Visibility", "Visibility", Dimension.NONE, true),
	FIRST_PASS_X("FIRST_PASS_X", "First-pass X", "1st-pass X", Dimension.POSITION, false),
	FIRST_PASS_Y("FIRST_PASS_Y", "First-pass Y", "1st-pass Y", Dimension.POSITION, false),
	// "SE", not "dX": TrackMate's table shows short names, and dX reads as a displacement
	SIGMA_X("SIGMA_X", "Standard error of X", "SE X", Dimension.LENGTH, false),
	SIGMA_Y("SIGMA_Y", "Standard error of Y", "SE Y", Dimension.LENGTH, false),
	ACTIVE_AREA("ACTIVE_AREA", "Active area (pixels)", "Area (px)", Dimension.NONE, true),
	ACTIVE_RADIUS("ACTIVE_RADIUS", "Active-area radius", "Area radius", Dimension.LENGTH, false),
	SECOND_AREA("SECOND_AREA", "Second-pass active area (pixels)", "2nd area (px)", Dimension.NONE, true),
	ITERATIONS("ITERATIONS", "Number of solves", "Solves", Dimension.NONE, true),
	FLAG_SECOND_PASS("FLAG_SECOND_PASS", "Second pass applied", "2nd pass", Dimension.NONE, true),
	FLAG_FELL_BACK("FLAG_FELL_BACK", "Fell back to first pass", "Fell back", Dimension.NONE, true),
	FLAG_DEGENERATE("FLAG_DEGENERATE", "Degenerate (near-singular) system", "Degenerate", Dimension.NONE, true),
	FLAG_AT_BORDER("FLAG_AT_BORDER", "Touches border", "At border", Dimension.NONE, true),
	FLAG_MERGED("FLAG_MERGED", "Suspected merge", "Merged", Dimension.NONE, true),
	FLAG_NOT_CONVERGED("FLAG_NOT_CONVERGED", "Not converged", "Not converged", Dimension.NONE, true),
	FLAG_UNMODELLED_NEIGHBOUR("FLAG_UNMODELLED_NEIGHBOUR", "Neighbour not modelled", "Unmodelled nbr.", Dimension.NONE, true),
	// last, so that the columns before keep their places in files written before kinds
	KIND("KIND", "Particle kind", "Kind", Dimension.NONE, true);

	/** TrackMate's feature dimensions, as written in its XML declarations. */
	public enum Dimension {
		NONE, POSITION, LENGTH, TIME, QUALITY
	}

	private final String key;
	private final String title;
	private final String shortName;
	private final Dimension dimension;
	private final boolean integer;

	SpotColumn(final String key, final String title, final String shortName, final Dimension dimension,
		final boolean integer)
	{
		this.key = key;
		this.title = title;
		this.shortName = shortName;
		this.dimension = dimension;
		this.integer = integer;
	}

	/** @return the column header / TrackMate feature key */
	public String key() {
		return key;
	}

	/** @return the long name (TrackMate's feature name) */
	public String title() {
		return title;
	}

	/** @return TrackMate's short feature name */
	public String shortName() {
		return shortName;
	}

	/** @return the physical dimension, which decides the unit */
	public Dimension dimension() {
		return dimension;
	}

	/** @return whether the values are integers */
	public boolean isInteger() {
		return integer;
	}

	/** @return whether this is one of TrackMate's own spot keys rather than a feature we declare */
	public boolean isTrackMateKey() {
		return ordinal() <= VISIBILITY.ordinal();
	}

	/** @return the unit of this column under {@code cal} ("" for dimensionless) */
	public String unit(final Calibration cal) {
		switch (dimension) {
			case POSITION: case LENGTH: return cal.unit();
			case TIME: return cal.timeUnit();
			default: return "";
		}
	}

	/**
	 * @param spot the spot, in pixel units
	 * @param id its unique ID
	 * @param cal the image's calibration
	 * @return this column's value for {@code spot}, in calibrated units
	 */
	public double value(final Localization spot, final int id, final Calibration cal) {
		switch (this) {
			case ID: return id;
			case FRAME: return spot.frame();
			case POSITION_X: return spot.x() * cal.pixelWidth();
			case POSITION_Y: return spot.y() * cal.pixelHeight();
			case POSITION_Z: return 0;
			case POSITION_T: return spot.frame() * cal.frameInterval();
			case RADIUS: return spot.radius() * Math.sqrt(cal.pixelWidth() * cal.pixelHeight());
			case ACTIVE_RADIUS: return Math.sqrt(spot.activeArea() / Math.PI) * Math.sqrt(cal.pixelWidth() * cal
				.pixelHeight());
			case QUALITY: return spot.quality();
			case VISIBILITY: return 1;
			case FIRST_PASS_X: return spot.firstX() * cal.pixelWidth();
			case FIRST_PASS_Y: return spot.firstY() * cal.pixelHeight();
			case SIGMA_X: return spot.sigmaX() * cal.pixelWidth();
			case SIGMA_Y: return spot.sigmaY() * cal.pixelHeight();
			case ACTIVE_AREA: return spot.activeArea();
			case SECOND_AREA: return spot.secondArea();
			case ITERATIONS: return spot.iterations();
			case FLAG_SECOND_PASS: return flag(spot, Flag.SECOND_PASS);
			case FLAG_FELL_BACK: return flag(spot, Flag.FELL_BACK);
			case FLAG_DEGENERATE: return flag(spot, Flag.DEGENERATE);
			case FLAG_AT_BORDER: return flag(spot, Flag.AT_BORDER);
			case FLAG_MERGED: return flag(spot, Flag.MERGED);
			case FLAG_NOT_CONVERGED: return flag(spot, Flag.NOT_CONVERGED);
			case FLAG_UNMODELLED_NEIGHBOUR: return flag(spot, Flag.UNMODELLED_NEIGHBOUR);
			case KIND: return spot.kind();
			default: throw new AssertionError(this);
		}
	}

	private static double flag(final Localization spot, final Flag f) {
		return spot.has(f) ? 1 : 0;
	}

	/**
	 * Appends the value as text: integers without a decimal point, others as {@link Double#toString(double)} (NaN
	 * as "NaN"). Appending to one builder, not making a string per cell, halves the CSV's writing time.
	 */
	public void appendTo(final StringBuilder out, final Localization spot, final int id, final Calibration cal) {
		final double v = value(spot, id, cal);
		if (integer) out.append((long) v);
		else out.append(v);
	}

	/** @return the value as text, as {@link #appendTo} writes it */
	public String format(final Localization spot, final int id, final Calibration cal) {
		final StringBuilder out = new StringBuilder(24);
		appendTo(out, spot, id, cal);
		return out.toString();
	}
}
