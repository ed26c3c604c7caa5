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
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * The 2D pair distribution g(r) and the pair potential U(r)/kT = -ln g(r) from spots, counting only pairs of the
 * same frame.
 * <p>
 * For each bin {@code [r, r + w)} the pairs closer than {@code rMax} are counted, and compared with the number
 * an ideal gas of the same particles would give: per frame with {@code n} spots, {@code n (n - 1) / 2} pairs,
 * each at a distance distributed as for two independent uniform points of the same field of view
 * ({@link FieldOfView#pairFractionWithin}: exact for a rectangle, so shells that leave the field need no
 * further correction). {@code g = pairs / expected}. When spots cut by the image's border were left out, the
 * field shrinks to where the spots kept are uniform ({@link SpotSet#awayFromBorder}): area and counts alike.
 * <p>
 * Error bars are counting statistics: a bin's count is taken as Poisson, so the standard error of {@code U/kT}
 * is {@code 1 / sqrt(pairs)} (and of g, {@code g / sqrt(pairs)}). Pairs are not independent (one particle is in
 * many pairs, and successive frames are correlated when the sampling is faster than the particles move), so
 * these are lower bounds; frames far enough apart in time make them honest.
 * <p>
 * U(r) from g(r) is the potential of mean force, which equals the pair potential only when the particles are
 * dilute (no third particle nearby): at higher densities, neighbours add structure.
 */
public final class PairCorrelation {

	/**
	 * One distance bin.
	 *
	 * @param rLow lower edge (inclusive)
	 * @param rHigh upper edge (exclusive)
	 * @param pairs pairs of spots of the same frame at a distance in the bin
	 * @param expected pairs an ideal gas of the same particles in the same field would give
	 */
	public record Bin(double rLow, double rHigh, long pairs, double expected) {

		/** @return the bin centre */
		public double r() {
			return 0.5 * (rLow + rHigh);
		}

		/** @return g(r): pairs over the ideal-gas expectation */
		public double g() {
			return pairs / expected;
		}

		/** @return the standard error of g (Poisson), {@code g / sqrt(pairs)}; NaN for an empty bin */
		public double gError() {
			return pairs > 0 ? g() / Math.sqrt(pairs) : Double.NaN;
		}

		/** @return {@code -ln g} without any zero shift; NaN for an empty bin (U is unbounded there) */
		public double rawU() {
			return pairs > 0 ? -Math.log(g()) : Double.NaN;
		}

		/** @return the standard error of U/kT, {@code 1 / sqrt(pairs)}; NaN for an empty bin */
		public double uError() {
			return pairs > 0 ? 1 / Math.sqrt(pairs) : Double.NaN;
		}
	}

	/**
	 * The result.
	 *
	 * @param bins the bins, from r = 0 up
	 * @param field the field of view used for the ideal-gas reference
	 * @param frames frames with at least one spot
	 * @param spots spots used
	 * @param framePairs all pairs of spots of the same frame, at any distance ({@code sum n (n - 1) / 2})
	 * @param uZero the constant subtracted from {@code -ln g} to give U (0 unless a zero range was set)
	 * @param zeroFrom lower end of the zero range (NaN when none)
	 * @param zeroTo upper end of the zero range (NaN when none)
	 * @param borderReach how far the field was shrunk on every side because spots at its border were left out
	 * @param nearBorderLeftOut spots left out for lying within that reach, though not flagged themselves
	 */
	public record Result(List<Bin> bins, FieldOfView field, int frames, int spots, double framePairs, double uZero,
		double zeroFrom, double zeroTo, double borderReach, int nearBorderLeftOut)
	{

		/** Copies the bins. */
		public Result {
			bins = List.copyOf(bins);
		}

		/** @return U(r)/kT of bin {@code i}, {@code -ln g - uZero}; NaN for an empty bin */
		public double u(final int i) {
			return bins.get(i).rawU() - uZero;
		}

		/** @return the pairs counted in all bins */
		public long pairs() {
			long n = 0;
			for (final Bin b : bins)
				n += b.pairs();
			return n;
		}

		/**
		 * Sets the zero of U over a range of r (e.g. where the particles no longer interact): subtracts
		 * {@code -ln(sum pairs / sum expected)} over the bins whose centres lie in {@code [from, to]}, so that
		 * U averages to 0 there. g is left as measured. The shift's own error (about
		 * {@code 1 / sqrt(pairs in the range)}) moves all of U together and is not in the per-bin errors.
		 *
		 * @param from lower end of the range
		 * @param to upper end of the range
		 * @return the result with U shifted
		 * @throws IllegalArgumentException when no bin centre lies in the range, or its bins hold no pair
		 */
		public Result withZero(final double from, final double to) {
			if (!(from <= to)) throw new InvalidInputException("the zero range must run from low to high, not " +
				from + " to " + to);
			long pairs = 0;
			double expected = 0;
			int inRange = 0;
			for (final Bin b : bins)
				if (b.r() >= from && b.r() <= to) {
					pairs += b.pairs();
					expected += b.expected();
					inRange++;
				}
			if (inRange == 0)
				throw new InvalidInputException(String.format(Locale.ROOT,
					"the zero range %s to %s holds no bin centre (bins end at %s)", num(from), num(to), num(bins.get(bins
						.size() - 1).rHigh())));
			if (pairs == 0)
				throw new InvalidInputException(String.format(Locale.ROOT,
					"no pair in the zero range %s to %s: U cannot be set to 0 there", num(from), num(to)));
			return new Result(bins, field, frames, spots, framePairs, -Math.log(pairs / expected), from, to, borderReach,
				nearBorderLeftOut);
		}
	}

	private PairCorrelation() {}

	/**
	 * @param all the spots, by frame
	 * @param found the field of view they were found in
	 * @param binWidth bin width, in the spots' units
	 * @param rMax the largest distance: bins cover {@code [0, k binWidth)} with {@code k = floor(rMax / binWidth)}
	 * @return g(r) and U(r), without a zero shift, of the spots away from the border when some at the border were
	 *         left out ({@link SpotSet#awayFromBorder})
	 * @throws IllegalArgumentException for bad bins, {@code rMax} beyond the field's smaller side, or no frame
	 *         with two spots
	 */
	public static Result compute(final SpotSet all, final FieldOfView found, final double binWidth,
		final double rMax)
	{
		final SpotSet.AwayFromBorder away = all.awayFromBorder(found);
		final SpotSet spots = away.spots();
		final FieldOfView field = away.field();
		final int count = bins(field, binWidth, rMax);
		final long[] pairs = new long[count];
		double framePairs = 0;
		for (final double[][] frame : spots.frames()) {
			final int n = frame[0].length;
			framePairs += 0.5 * n * (n - 1.0);
			final long[] own = framePairs(frame[0], frame[1], binWidth, count);
			for (int k = 0; k < count; k++)
				pairs[k] += own[k];
		}
		return fromCounts(pairs, framePairs, spots.frames().size(), spots.size(), field, binWidth, away.reach(), spots
			.nearBorderLeftOut());
	}

	/**
	 * @return the number of bins of width {@code binWidth} up to {@code rMax}: {@code floor(rMax / binWidth)}
	 * @throws IllegalArgumentException for bad bins, or {@code rMax} beyond the field's smaller side
	 */
	public static int bins(final FieldOfView field, final double binWidth, final double rMax) {
		if (!(binWidth > 0) || !Double.isFinite(binWidth))
			throw new InvalidInputException("the bin width must be a positive number, not " + binWidth);
		if (!(rMax >= binWidth) || !Double.isFinite(rMax))
			throw new InvalidInputException("r_max must be at least one bin width (" + num(binWidth) + "), not " +
				num(rMax));
		final int count = (int) Math.floor(rMax / binWidth + 1e-9);
		if (count > 1_000_000) throw new InvalidInputException("more than a million bins: use a wider bin");
		final double top = count * binWidth;
		if (top > field.maxDistance() * (1 + 1e-12))
			throw new InvalidInputException(String.format(Locale.ROOT, "r_max %s exceeds the smaller side of the " +
				"field of view (%s x %s%s): the edge correction holds only up to %s", num(top), num(field.width()), num(
					field.height()), field.inferred() ? ", inferred from the spots" : "", num(field.maxDistance())));
		return count;
	}

	/**
	 * One frame's pair counts, what a distributed front end counts frame by frame and sums.
	 *
	 * @param x the frame's spots' x
	 * @param y their y
	 * @param count the number of bins ({@link #bins})
	 * @return the pairs closer than {@code count * binWidth}, per bin of distance
	 */
	public static long[] framePairs(final double[] x, final double[] y, final double binWidth, final int count) {
		final long[] pairs = new long[count];
		final double top = count * binWidth, rMax2 = top * top;
		final int n = x.length;
		// sorted by x, a spot needs comparing only with the following ones closer than top along x
		final Integer[] order = new Integer[n];
		for (int i = 0; i < n; i++)
			order[i] = i;
		Arrays.sort(order, Comparator.comparingDouble(i -> x[i]));
		final double[] sx = new double[n], sy = new double[n];
		for (int i = 0; i < n; i++) {
			sx[i] = x[order[i]];
			sy[i] = y[order[i]];
		}
		for (int a = 0; a < n; a++)
			for (int b = a + 1; b < n; b++) {
				final double dx = sx[b] - sx[a];
				if (dx >= top) break;
				final double dy = sy[b] - sy[a], d2 = dx * dx + dy * dy;
				if (d2 >= rMax2) continue;
				final int k = (int) (Math.sqrt(d2) / binWidth);
				if (k < count) pairs[k]++; // k == count only by rounding at the very edge
			}
		return pairs;
	}

	/**
	 * @param pairs the pairs per bin, summed over the frames
	 * @param framePairs the pairs of spots summed over the frames, {@code sum n (n - 1) / 2}
	 * @param frames the frames with spots
	 * @param spots the spots
	 * @return g(r) and U(r), without a zero shift
	 * @throws IllegalArgumentException when no frame has two spots
	 */
	public static Result fromCounts(final long[] pairs, final double framePairs, final int frames, final int spots,
		final FieldOfView field, final double binWidth)
	{
		return fromCounts(pairs, framePairs, frames, spots, field, binWidth, 0, 0);
	}

	/**
	 * As {@link #fromCounts(long[], double, int, int, FieldOfView, double)}, for spots counted within a field
	 * shrunk from the border ({@link SpotSet#awayFromBorder}).
	 *
	 * @param borderReach how far the field was shrunk on every side (0: not; NaN: not, the flagged spots lay too
	 *          deep)
	 * @param nearBorderLeftOut spots left out for lying within that reach, though not flagged themselves
	 */
	public static Result fromCounts(final long[] pairs, final double framePairs, final int frames, final int spots,
		final FieldOfView field, final double binWidth, final double borderReach, final int nearBorderLeftOut)
	{
		if (framePairs == 0)
			throw new InvalidInputException("no frame has two spots: there is no pair to count");
		final int count = pairs.length;
		final List<Bin> bins = new ArrayList<>(count);
		double below = 0;
		for (int k = 0; k < count; k++) {
			final double lo = k * binWidth, hi = (k + 1) * binWidth;
			final double within = field.pairFractionWithin(Math.min(hi, field.maxDistance()));
			bins.add(new Bin(lo, hi, pairs[k], framePairs * (within - below)));
			below = within;
		}
		return new Result(bins, field, frames, spots, framePairs, 0, Double.NaN, Double.NaN, borderReach,
			nearBorderLeftOut);
	}

	/** @return {@code v} with at most 6 significant digits and no trailing zeros, for messages */
	static String num(final double v) {
		final String s = String.format(Locale.ROOT, "%.6g", v);
		if (s.contains("e") || !s.contains(".")) return s;
		return s.replaceAll("0+$", "").replaceAll("\\.$", "");
	}
}
