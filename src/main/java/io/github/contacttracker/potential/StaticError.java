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
import java.util.Arrays;
import java.util.List;

/**
 * The static localization error of a spots table, measured from the particles' own motion (Savin and Doyle,
 * Biophys. J. 88, 623, 2005): for a diffusing particle tracked with a position error of variance {@code sigma^2}
 * per axis, the mean squared displacement along one axis at lag {@code tau} frames is
 * {@code MSD(tau) = 2 D tau + 2 sigma^2}, so the intercept of a straight line through the first lags gives
 * {@code sigma}. No ground truth is needed: this is how accurate the positions are on real footage. With motion
 * during the exposure {@code t_E} the intercept is {@code 2 sigma^2 - (2/3) D t_E}, so where that blur is not
 * negligible the estimate is a lower bound.
 * <p>
 * Tracks are formed by linking mutual nearest neighbours in consecutive frames within {@code maxStep}; the
 * lags are counted in frames.
 */
public final class StaticError {

	/**
	 * @param tracks linked tracks with at least two positions
	 * @param steps one-frame displacements in them
	 * @param msdX mean squared displacement along x at lags 1..{@code msdX.length}
	 * @param msdY the same along y
	 * @param pairs the number of displacements averaged at each lag
	 * @param varianceX the static error's variance along x ({@code intercept / 2}; negative when the intercept is,
	 *        i.e. when the error is below what the data resolve)
	 * @param varianceY the same along y
	 * @param diffusionX the diffusion coefficient along x (slope / 2), in squared units per frame
	 * @param diffusionY the same along y
	 * @param varianceError the standard error of {@code varianceX} and {@code varianceY} (mean of the two), from
	 *        the spread of the estimate over {@value #GROUPS} groups of the tracks; NaN with fewer tracks
	 */
	public record Result(int tracks, int steps, double[] msdX, double[] msdY, long[] pairs, double varianceX,
		double varianceY, double diffusionX, double diffusionY, double varianceError)
	{

		/** @return the static error along x, {@code sqrt(varianceX)}, 0 when the variance is not positive */
		public double sigmaX() {
			return Math.sqrt(Math.max(0, varianceX));
		}

		/** @return the static error along y */
		public double sigmaY() {
			return Math.sqrt(Math.max(0, varianceY));
		}
	}

	private StaticError() {}

	/**
	 * @param spots the spots (flagged ones already left out, as {@link SpotSet} does)
	 * @param maxStep the largest displacement between consecutive frames that links two spots
	 * @param lags the number of lags the line is fitted to (at least 2)
	 * @return the estimate
	 * @throws IllegalArgumentException if {@code lags < 2}, {@code maxStep} is not positive, or no track is long
	 *         enough for {@code lags}
	 */
	public static Result estimate(final SpotSet spots, final double maxStep, final int lags) {
		if (lags < 2) throw new IllegalArgumentException("at least 2 lags are needed for a line, not " + lags);
		if (!(maxStep > 0)) throw new IllegalArgumentException("the largest step must be positive, not " + maxStep);
		final List<double[][]> tracks = tracks(spots, maxStep);
		final Result all = estimate(tracks, lags, Double.NaN);
		if (all.pairs()[lags - 1] == 0) throw new IllegalArgumentException("no track spans " + lags + " frames (" +
			tracks.size() + " tracks linked within " + maxStep + "): link farther (a larger step) or use fewer lags");
		if (tracks.size() < GROUPS) return all;
		// the tracks are independent: the estimate's spread over groups of them gives its standard error
		final double[] v = new double[GROUPS];
		for (int g = 0; g < GROUPS; g++) {
			final List<double[][]> part = new ArrayList<>();
			for (int i = g; i < tracks.size(); i += GROUPS)
				part.add(tracks.get(i));
			final Result r = estimate(part, lags, Double.NaN);
			v[g] = 0.5 * (r.varianceX() + r.varianceY());
		}
		double mean = 0, ss = 0;
		for (final double x : v)
			mean += x / GROUPS;
		for (final double x : v)
			ss += (x - mean) * (x - mean);
		final double error = Math.sqrt(ss / (GROUPS - 1) / GROUPS);
		return new Result(all.tracks(), all.steps(), all.msdX(), all.msdY(), all.pairs(), all.varianceX(), all
			.varianceY(), all.diffusionX(), all.diffusionY(), error);
	}

	/** The tracks are split into this many groups for the estimate's standard error. */
	public static final int GROUPS = 10;

	private static Result estimate(final List<double[][]> tracks, final int lags, final double error) {
		final double[] sx = new double[lags], sy = new double[lags];
		final long[] pairs = new long[lags];
		int steps = 0;
		for (final double[][] t : tracks) {
			final double[] x = t[0], y = t[1];
			steps += x.length - 1;
			for (int lag = 1; lag <= lags && lag < x.length; lag++)
				for (int i = 0; i + lag < x.length; i++) {
					final double dx = x[i + lag] - x[i], dy = y[i + lag] - y[i];
					sx[lag - 1] += dx * dx;
					sy[lag - 1] += dy * dy;
					pairs[lag - 1]++;
				}
		}
		for (int k = 0; k < lags; k++) {
			sx[k] /= pairs[k];
			sy[k] /= pairs[k];
		}
		final double[] lineX = line(sx), lineY = line(sy);
		return new Result(tracks.size(), steps, sx, sy, pairs, lineX[0] / 2, lineY[0] / 2, lineX[1] / 2, lineY[1] / 2,
			error);
	}

	/** @return {intercept, slope} of the least-squares line through {@code (k + 1, msd[k])} */
	private static double[] line(final double[] msd) {
		final int n = msd.length;
		double st = 0, sm = 0, stt = 0, stm = 0;
		for (int k = 0; k < n; k++) {
			final double t = k + 1;
			st += t;
			sm += msd[k];
			stt += t * t;
			stm += t * msd[k];
		}
		final double slope = (n * stm - st * sm) / (n * stt - st * st);
		return new double[] { (sm - slope * st) / n, slope };
	}

	/**
	 * @return the tracks, each {x[], y[]} over consecutive frames: a spot is linked to the nearest spot of the next
	 *         frame if that one's nearest in this frame is it (mutual nearest neighbours) and they lie within
	 *         {@code maxStep}
	 */
	static List<double[][]> tracks(final SpotSet spots, final double maxStep) {
		final List<Integer> numbers = spots.frameNumbers();
		final List<double[][]> frames = spots.frames();
		final List<double[][]> done = new ArrayList<>();
		// open tracks: per spot of the current frame, its positions so far
		List<double[]> openX = new ArrayList<>(), openY = new ArrayList<>();
		List<Integer> openLength = new ArrayList<>();
		for (int f = 0; f < frames.size(); f++) {
			final double[][] cur = frames.get(f);
			final int n = cur[0].length;
			final List<double[]> nextX = new ArrayList<>(n), nextY = new ArrayList<>(n);
			final List<Integer> nextLength = new ArrayList<>(n);
			final int[] from = f > 0 && numbers.get(f) == numbers.get(f - 1) + 1 ? links(frames.get(f - 1), cur, maxStep)
				: null;
			final boolean[] continued = new boolean[openX.size()];
			for (int j = 0; j < n; j++) {
				final int i = from == null ? -1 : from[j];
				double[] tx, ty;
				int len;
				if (i >= 0) {
					continued[i] = true;
					tx = openX.get(i);
					ty = openY.get(i);
					len = openLength.get(i);
					if (len == tx.length) {
						tx = Arrays.copyOf(tx, 2 * len);
						ty = Arrays.copyOf(ty, 2 * len);
					}
				}
				else {
					tx = new double[8];
					ty = new double[8];
					len = 0;
				}
				tx[len] = cur[0][j];
				ty[len] = cur[1][j];
				nextX.add(tx);
				nextY.add(ty);
				nextLength.add(len + 1);
			}
			for (int i = 0; i < continued.length; i++)
				if (!continued[i]) close(openX.get(i), openY.get(i), openLength.get(i), done);
			openX = nextX;
			openY = nextY;
			openLength = nextLength;
		}
		for (int i = 0; i < openX.size(); i++)
			close(openX.get(i), openY.get(i), openLength.get(i), done);
		return done;
	}

	private static void close(final double[] x, final double[] y, final int length, final List<double[][]> done) {
		if (length >= 2) done.add(new double[][] { Arrays.copyOf(x, length), Arrays.copyOf(y, length) });
	}

	/** @return per spot of {@code b}, the spot of {@code a} it is linked to, or -1 */
	private static int[] links(final double[][] a, final double[][] b, final double maxStep) {
		final int[] nearestInA = nearest(b, a), nearestInB = nearest(a, b);
		final int[] from = new int[b[0].length];
		for (int j = 0; j < from.length; j++) {
			final int i = nearestInA[j];
			from[j] = i >= 0 && nearestInB[i] == j && Math.hypot(a[0][i] - b[0][j], a[1][i] - b[1][j]) <= maxStep ? i
				: -1;
		}
		return from;
	}

	/** @return per spot of {@code p}, the index of the nearest spot of {@code q} (-1 if q is empty) */
	private static int[] nearest(final double[][] p, final double[][] q) {
		final int[] out = new int[p[0].length];
		for (int i = 0; i < out.length; i++) {
			double best = Double.POSITIVE_INFINITY;
			out[i] = -1;
			for (int j = 0; j < q[0].length; j++) {
				final double d = (p[0][i] - q[0][j]) * (p[0][i] - q[0][j]) + (p[1][i] - q[1][j]) * (p[1][i] - q[1][j]);
				if (d < best) {
					best = d;
					out[i] = j;
				}
			}
		}
		return out;
	}
}
