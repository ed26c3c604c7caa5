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

import io.github.contacttracker.core.InvalidInputException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;

/**
 * The spots that enter a pair analysis, grouped by frame, and how many were left out and why. Built from a
 * spots table's columns (TrackMate's keys {@code POSITION_X}, {@code POSITION_Y}, {@code FRAME}, and our
 * {@code FLAG_...} columns when present), or directly from positions.
 */
public final class SpotSet {

	/** Column keys read from a spots table. */
	public static final String X = "POSITION_X", Y = "POSITION_Y", FRAME = "FRAME", FLAG_PREFIX = "FLAG_";

	/** @return whether {@link #fromColumns} reads the column {@code key} (positions, frame, flags) */
	public static boolean reads(final String key) {
		return key.equals(X) || key.equals(Y) || key.equals(FRAME) || key.startsWith(FLAG_PREFIX);
	}

	/**
	 * Which spots to use.
	 *
	 * @param startFrame spots of earlier frames are left out (e.g. while the sample settles)
	 * @param dropFlagged leave out spots with a warning flag (every {@code FLAG_} column but
	 *          {@code FLAG_SECOND_PASS}, which marks the normal case): their centres are unreliable (fallback to
	 *          the biased first pass, merged particles, cut by the border, ...)
	 */
	public record Selection(int startFrame, boolean dropFlagged) {

		/** All frames, flagged spots left out. */
		public static final Selection DEFAULT = new Selection(0, true);

		/** @throws IllegalArgumentException for a negative start frame */
		public Selection {
			if (startFrame < 0) throw new InvalidInputException("the start frame must be 0 or more, not " + startFrame);
		}
	}

	/** The column of the flag that marks a spot cut by the image's border. */
	public static final String BORDER_FLAG = FLAG_PREFIX + Flag.AT_BORDER.name();

	/** The deepest a band of spots cut by the border may reach into the field, as a fraction of its smaller side. */
	public static final double DEEPEST_BORDER = 0.25;

	private final List<Integer> frameNumbers;
	private final List<double[][]> frames;
	private final int rows, flaggedLeftOut, earlyLeftOut, nearBorderLeftOut;
	private final List<String> flagColumns;
	/** Spots left out for a warning flag: {@code {x, y, 1 when flagged at the border else 0}} each. */
	private final List<double[]> flagged;

	private SpotSet(final TreeMap<Integer, List<double[]>> byFrame, final int rows, final int flaggedLeftOut,
		final int earlyLeftOut, final List<String> flagColumns, final List<double[]> flagged, final int nearBorderLeftOut)
	{
		this.flagged = List.copyOf(flagged);
		this.nearBorderLeftOut = nearBorderLeftOut;
		this.frameNumbers = List.copyOf(byFrame.keySet());
		final List<double[][]> f = new ArrayList<>();
		for (final List<double[]> spots : byFrame.values()) {
			final double[][] xy = new double[2][spots.size()];
			for (int i = 0; i < spots.size(); i++) {
				xy[0][i] = spots.get(i)[0];
				xy[1][i] = spots.get(i)[1];
			}
			f.add(xy);
		}
		this.frames = Collections.unmodifiableList(f);
		this.rows = rows;
		this.flaggedLeftOut = flaggedLeftOut;
		this.earlyLeftOut = earlyLeftOut;
		this.flagColumns = List.copyOf(flagColumns);
	}

	/**
	 * @param positions per frame (frame numbers 0, 1, ...), the spots' {@code {x, y}}
	 * @param scale the positions are multiplied by it
	 * @return every spot, none left out
	 */
	public static SpotSet ofPositions(final List<List<double[]>> positions, final double scale) {
		final TreeMap<Integer, List<double[]>> byFrame = new TreeMap<>();
		int n = 0;
		for (int f = 0; f < positions.size(); f++) {
			final List<double[]> scaled = new ArrayList<>();
			for (final double[] p : positions.get(f))
				scaled.add(new double[] { p[0] * scale, p[1] * scale });
			byFrame.put(f, scaled);
			n += positions.get(f).size();
		}
		return new SpotSet(byFrame, n, 0, 0, List.of(), List.of(), 0);
	}

	/**
	 * @param spots tracked spots of any frames, in pixels
	 * @param selection which spots to use (a spot is flagged when it has a warning flag, {@link Flag#isWarning()})
	 * @param firstPass use the first-pass centres instead of the final ones (to show the first pass's bias)
	 * @param scale the positions are multiplied by it (e.g. {@code 1 / diameter} for distances in diameters)
	 * @return the spots
	 */
	public static SpotSet ofLocalizations(final List<Localization> spots, final Selection selection,
		final boolean firstPass, final double scale)
	{
		final TreeMap<Integer, List<double[]>> byFrame = new TreeMap<>();
		final List<double[]> leftOut = new ArrayList<>();
		int flagged = 0, early = 0;
		for (final Localization s : spots) {
			if (s.frame() < selection.startFrame()) {
				early++;
				continue;
			}
			final double x = (firstPass ? s.firstX() : s.x()) * scale, y = (firstPass ? s.firstY() : s.y()) * scale;
			if (selection.dropFlagged() && s.isFlagged()) {
				flagged++;
				leftOut.add(new double[] { x, y, s.has(Flag.AT_BORDER) ? 1 : 0 });
				continue;
			}
			byFrame.computeIfAbsent(s.frame(), k -> new ArrayList<>()).add(new double[] { x, y });
		}
		final List<String> flagColumns = new ArrayList<>();
		if (selection.dropFlagged()) for (final Flag f : Flag.values())
			if (f.isWarning()) flagColumns.add(FLAG_PREFIX + f.name());
		return new SpotSet(byFrame, spots.size(), flagged, early, flagColumns, leftOut, 0);
	}

	/**
	 * @param columns a spots table, by column key (all arrays of one length; NaN for an empty cell)
	 * @param selection which spots to use
	 * @return the spots
	 * @throws IllegalArgumentException naming the column (and row, 1-based) of a missing column or bad value
	 */
	public static SpotSet fromColumns(final Map<String, double[]> columns, final Selection selection) {
		final double[] x = column(columns, X), y = column(columns, Y), frame = column(columns, FRAME);
		final int rows = x.length;
		final List<String> flagKeys = new ArrayList<>();
		for (final String key : columns.keySet())
			if (key.startsWith(FLAG_PREFIX) && isWarning(key.substring(FLAG_PREFIX.length()))) flagKeys.add(key);
		Collections.sort(flagKeys);
		final TreeMap<Integer, List<double[]>> byFrame = new TreeMap<>();
		final List<double[]> leftOut = new ArrayList<>();
		final double[] border = columns.get(BORDER_FLAG);
		int flagged = 0, early = 0;
		for (int i = 0; i < rows; i++) {
			final double f = frame[i];
			if (!(f >= 0) || f != Math.rint(f) || f > Integer.MAX_VALUE)
				throw new InvalidInputException(String.format(Locale.ROOT,
					"row %d: %s must be a whole number 0 or more, not %s", i + 1, FRAME, text(f)));
			if (!Double.isFinite(x[i]) || !Double.isFinite(y[i]))
				throw new InvalidInputException(String.format(Locale.ROOT, "row %d: %s and %s must be numbers, not %s " +
					"and %s", i + 1, X, Y, text(x[i]), text(y[i])));
			if (f < selection.startFrame()) {
				early++;
				continue;
			}
			if (selection.dropFlagged() && isFlagged(columns, flagKeys, i)) {
				flagged++;
				leftOut.add(new double[] { x[i], y[i], border != null && Double.isFinite(border[i]) && border[i] != 0 ? 1
					: 0 });
				continue;
			}
			byFrame.computeIfAbsent((int) f, k -> new ArrayList<>()).add(new double[] { x[i], y[i] });
		}
		return new SpotSet(byFrame, rows, flagged, early, selection.dropFlagged() ? flagKeys : List.of(), leftOut, 0);
	}

	private static double[] column(final Map<String, double[]> columns, final String key) {
		final double[] c = columns.get(key);
		if (c == null) throw new InvalidInputException("missing column " + key);
		return c;
	}

	/** A flag column counts as a warning unless it is one of our flags that is not a warning. */
	private static boolean isWarning(final String flagName) {
		for (final Flag f : Flag.values())
			if (f.name().equals(flagName)) return f.isWarning();
		return true; // an unknown flag: safer to treat as a warning
	}

	private static boolean isFlagged(final Map<String, double[]> columns, final List<String> flagKeys, final int row) {
		for (final String key : flagKeys) {
			final double v = columns.get(key)[row];
			if (Double.isFinite(v) && v != 0) return true;
		}
		return false;
	}

	private static String text(final double v) {
		return Double.isNaN(v) ? "empty" : Double.toString(v);
	}

	/** @return the frame numbers that have at least one spot, ascending */
	public List<Integer> frameNumbers() {
		return frameNumbers;
	}

	/** @return per frame (in {@link #frameNumbers()} order) the arrays {@code {x[], y[]}} of its spots */
	public List<double[][]> frames() {
		return frames;
	}

	/** @return the number of spots used */
	public int size() {
		int n = 0;
		for (final double[][] f : frames)
			n += f[0].length;
		return n;
	}

	/** @return the number of rows the table had */
	public int rows() {
		return rows;
	}

	/** @return spots left out for a warning flag */
	public int flaggedLeftOut() {
		return flaggedLeftOut;
	}

	/** @return spots left out for being before the start frame */
	public int earlyLeftOut() {
		return earlyLeftOut;
	}

	/** @return the flag columns that counted as warnings (empty when flagged spots were kept) */
	public List<String> flagColumns() {
		return flagColumns;
	}

	/**
	 * @return the spots left out because they lie as close to the border as spots flagged there, though not
	 *         flagged themselves ({@link #awayFromBorder})
	 */
	public int nearBorderLeftOut() {
		return nearBorderLeftOut;
	}

	/**
	 * The field of view inferred from every spot with a position, used or left out for a flag (so that spots left
	 * out at the border still mark where the field ends), as {@link FieldOfView#inferred(double[], double[])}.
	 *
	 * @return the inferred field
	 * @throws IllegalArgumentException for fewer than 2 such spots, or all on one line
	 */
	public FieldOfView inferredField() {
		final double[] x = allX(), y = allY();
		final double[] ax = Arrays.copyOf(x, x.length + flagged.size()), ay = Arrays.copyOf(y, y.length + flagged
			.size());
		for (int i = 0; i < flagged.size(); i++) {
			ax[x.length + i] = flagged.get(i)[0];
			ay[y.length + i] = flagged.get(i)[1];
		}
		return FieldOfView.inferred(ax, ay);
	}

	/**
	 * The spots and field that describe one uniform population when spots flagged at the image's border were left
	 * out. Left out, those spots thin the particles near the edge: the counts lose them, and unless the field
	 * shrinks with them an ideal gas would give g below 1 at the reference's scale and above 1 after U's zero is
	 * set. The border's reach is the deepest such spot's distance to the field's edge; every spot closer to the
	 * edge than that is left out too, and the field shrinks by it on every side, so that the spots kept are as
	 * dense at the new edge as in the middle.
	 *
	 * @param field the field the spots were found in
	 * @return this set and {@code field} when no spot was left out at the border, or when one lies deeper in the
	 *         field than a border band can ({@link #DEEPEST_BORDER} of its smaller side: the reach is NaN then); else
	 *         the spots and field inside the border's reach
	 * @throws IllegalArgumentException when the border's reach leaves no field
	 */
	public AwayFromBorder awayFromBorder(final FieldOfView field) {
		double deepest = Double.NEGATIVE_INFINITY;
		for (final double[] s : flagged)
			if (s[2] != 0) deepest = Math.max(deepest, field.depth(s[0], s[1]));
		final double reach = borderReach(field, deepest);
		if (!(reach > 0)) return new AwayFromBorder(this, field, reach);
		final FieldOfView inner = field.inset(reach);
		final TreeMap<Integer, List<double[]>> byFrame = new TreeMap<>();
		int near = 0;
		for (int k = 0; k < frames.size(); k++) {
			final double[][] f = frames.get(k);
			final List<double[]> kept = new ArrayList<>();
			for (int i = 0; i < f[0].length; i++)
				if (inner.depth(f[0][i], f[1][i]) >= 0) kept.add(new double[] { f[0][i], f[1][i] });
				else near++;
			if (!kept.isEmpty()) byFrame.put(frameNumbers.get(k), kept);
		}
		return new AwayFromBorder(new SpotSet(byFrame, rows, flaggedLeftOut, earlyLeftOut, flagColumns, flagged,
			nearBorderLeftOut + near), inner, reach);
	}

	/**
	 * The rule of {@link #awayFromBorder}, for a front end that gathers the spots in parts.
	 *
	 * @param field the field the spots were found in
	 * @param deepest the largest {@link FieldOfView#depth} of a spot left out for being cut by the border;
	 *          negative infinity when there is none
	 * @return how far to shrink the field on every side: 0 when no spot was left out at the border, NaN when one
	 *         lies too deep in the field to mark its border ({@link #DEEPEST_BORDER} of its smaller side: a
	 *         selection's border, or a table of other origin)
	 */
	public static double borderReach(final FieldOfView field, final double deepest) {
		if (deepest == Double.NEGATIVE_INFINITY) return 0;
		if (deepest > DEEPEST_BORDER * field.maxDistance()) return Double.NaN;
		return Math.max(0, deepest);
	}

	/**
	 * @return the spots left out for a warning flag, each {@code {x, y, 1 when flagged at the border else 0}}
	 */
	public List<double[]> flaggedPositions() {
		return flagged;
	}

	/**
	 * Spots and the field they are uniform in, when spots at the border were left out.
	 *
	 * @param spots the spots kept
	 * @param field the field they fill
	 * @param reach how far the field was shrunk on every side (0 when no spot was left out at the border, NaN
	 *          when such spots lay too deep in the field to mark its border)
	 */
	public record AwayFromBorder(SpotSet spots, FieldOfView field, double reach) {}

	/** @return x of every spot used, frame after frame */
	public double[] allX() {
		return all(0);
	}

	/** @return y of every spot used, frame after frame */
	public double[] allY() {
		return all(1);
	}

	private double[] all(final int axis) {
		final double[] out = new double[size()];
		int k = 0;
		for (final double[][] f : frames)
			for (final double v : f[axis])
				out[k++] = v;
		return out;
	}
}
