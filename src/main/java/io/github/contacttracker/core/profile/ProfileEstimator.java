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
package io.github.contacttracker.core.profile;

import io.github.contacttracker.core.TrackerParameters;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.CensoredNormal;
import io.github.contacttracker.core.math.SymmetricSolver;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Estimates a particle's radial profile from frames whose particle centres are (approximately) known: every
 * pixel within {@code radius} of a particle is modelled as background plus the sum of the profiles of all
 * particles reaching it, {@code I(x) = B + sum_k P(|x - c_k|)}, and the profile's spline coefficients and
 * {@code B} are found by linear least squares. Overlaps are modelled, not avoided, so the profile can be
 * measured even where no particle has an undistorted side (long-range profiles at contact).
 * <p>
 * A light penalty on the coefficients' second differences keeps sparsely sampled knots (near r = 0) stable.
 * Pixels near spots flagged as merged or degenerate are left out, since their centres do not describe them, and
 * near spots cut by the border ({@code AT_BORDER}), whose amplitudes, scales and centres the visible part leaves
 * loose (on a crop of a movie they can make the profile change by up to its height from round to round);
 * so are clipped pixels and, given the previous estimate, those near a clip level ({@link Censoring}); where the
 * floor is linked, the pixels near it enter instead, linearised about the previous estimate's model.
 * <p>
 * An estimator made {@link #ProfileEstimator(double, int, Linearisation) from the linearisation} of an earlier estimate takes
 * one chord step of the same least squares instead: it accumulates only the gradient {@code A^T (b - A x)} at the
 * earlier solution {@code x} (a pass linear in the particles that reach a pixel, not quadratic) and solves with the
 * earlier normal matrix. Its fixed point is the exact least-squares solution, and where the centres moved little
 * since the earlier estimate (the profile rounds of a movie) one step lands within a small fraction of that change.
 * Not thread-safe.
 */
public final class ProfileEstimator {

	/** Knot spacing of the profile spline (px). */
	public static final double SPACING = 1.0;
	/** Weight of the smoothness penalty, relative to the mean diagonal of the normal matrix. */
	static final double SMOOTHNESS = 1e-4;

	private final double radius;
	/** Coefficients of one profile. */
	private final int count;
	/** Profiles measured at once, one per kind of particle: coefficients {@code kind * count ...}, then B. */
	private final int kinds;
	/** Index of the background's first coefficient. */
	private final int bIndex;
	/** The normal matrix's lower triangle; null for a chord step, which accumulates only its diagonal. */
	private final double[][] ata;
	/** A chord step's: the normal matrix's diagonal (the penalty's scale), and a row's sums per coefficient. */
	private final double[] diagonal, rowSum;
	/** The earlier estimate a chord step starts from, or null: a full estimate. */
	private final Linearisation from;
	/** A full estimate's {@code A^T b}; a chord step's {@code A^T (b - A x)} at the earlier solution. */
	private final double[] atb;
	private int samples;
	private int profileSamples;
	/** Per kind (with more than one), the pixel values added within reach of a particle of that kind. */
	private final int[] kindSamples;
	/**
	 * The pixels of the background alone (within reach of no particle) of integer frames: how many read the floor, how
	 * many lie above it, their sum and sum of squares, and the floor ({@link #heldBackground}).
	 */
	private long backgroundAtFloor, backgroundAbove;
	private double backgroundSum, backgroundSquares, floor = Double.NaN;
	/** The frames' pixel noise, the largest given (0: none given, and no background is held). */
	private double noise;

	/** @param radius the profile's reach (px): {@link TrackerParameters#profileReach()} */
	public ProfileEstimator(final double radius) {
		this(radius, 1);
	}

	/**
	 * @param radius the profile's reach (px)
	 * @param kinds how many profiles to measure at once, one per kind of particle (all sharing the background)
	 */
	public ProfileEstimator(final double radius, final int kinds) {
		this(radius, kinds, null);
	}

	/**
	 * @param radius the profile's reach (px)
	 * @param kinds how many profiles to measure at once
	 * @param from an earlier estimate of the same radius and kinds to take a chord step from, or null
	 */
	public ProfileEstimator(final double radius, final int kinds, final Linearisation from) {
		if (!(radius > 3 * SPACING)) throw new IllegalArgumentException("profile radius must exceed " + 3 * SPACING +
			" px, not " + radius);
		if (kinds < 1) throw new IllegalArgumentException("at least one kind of particle, not " + kinds);
		this.count = (int) Math.round(radius / SPACING) - 1;
		this.radius = (count + 1) * SPACING;
		this.kinds = kinds;
		this.bIndex = kinds * count;
		if (from != null && from.solution.length != bIndex + 3) throw new IllegalArgumentException(
			"the earlier estimate has another radius or number of kinds");
		this.from = from;
		ata = from == null ? new double[bIndex + 3][bIndex + 3] : null;
		diagonal = from == null ? null : new double[bIndex + 3];
		rowSum = from == null ? null : new double[bIndex + 3];
		atb = new double[bIndex + 3];
		kindSamples = new int[kinds];
	}

	/**
	 * Adds a frame with its spots (positions in the frame's coordinates). Spots flagged merged, degenerate, at the
	 * border or not converged are masked out. Each spot's fitted amplitude and radial scale are used where known (divided by
	 * their means {@code amplitudeNorm} and {@code scaleNorm}, which fix the profile's own height and size).
	 */
	public <T extends RealType<T>> void add(final RandomAccessibleInterval<T> frame, final List<Localization> spots,
		final double amplitudeNorm, final double scaleNorm)
	{
		add(frame, spots, amplitudeNorm, scaleNorm, null, 0);
	}

	/**
	 * As {@link #add(RandomAccessibleInterval, List, double, double)}, the spots fitted with {@code previous}: where
	 * its model comes near a clip level of the frame (of noise {@code noise}), pixels are left out, or linked at the
	 * floor (see {@link Censoring}; a background clipped there linked with {@code previous}' floor noise); with
	 * {@code previous} null only the clipped pixels are left out.
	 */
	public <T extends RealType<T>> void add(final RandomAccessibleInterval<T> frame, final List<Localization> spots,
		final double amplitudeNorm, final double scaleNorm, final EmpiricalProfile previous, final double noise)
	{
		add(frame, spots, new int[spots.size()], new double[] { amplitudeNorm }, new double[] { scaleNorm },
			previous == null ? null : new EmpiricalProfile[] { previous }, noise);
	}

	/**
	 * As {@link #add(RandomAccessibleInterval, List, double, double, EmpiricalProfile, double)}, spot {@code k} of
	 * kind {@code kind[k]} (0-based), each kind with its own norms and previous profile.
	 */
	public <T extends RealType<T>> void add(final RandomAccessibleInterval<T> frame, final List<Localization> spots,
		final int[] kind, final double[] amplitudeNorms, final double[] scaleNorms, final EmpiricalProfile[] previous,
		final double noise)
	{
		final Plane plane = Plane.of(frame);
		final int n = spots.size();
		final double[] cx = new double[n], cy = new double[n], amp = new double[n], scale = new double[n];
		final boolean[] masked = new boolean[n];
		for (int k = 0; k < n; k++) {
			final Localization s = spots.get(k);
			cx[k] = s.x() - plane.minX();
			cy[k] = s.y() - plane.minY();
			amp[k] = Double.isFinite(s.amplitude()) ? s.amplitude() / amplitudeNorms[kind[k]] : 1;
			scale[k] = Double.isFinite(s.scale()) && s.scale() > 0 ? s.scale() / scaleNorms[kind[k]] : 1;
			masked[k] = !usable(s);
		}
		add(plane, cx, cy, amp, scale, masked, kind, previous == null ? null : new Previous(previous, Censoring.of(
			plane, noise).withFloorNoise(previous[0].floorNoise()), amplitudeNorms, scaleNorms));
	}

	/**
	 * The previous estimate's model, which chooses the pixels left out near the clip levels: its profiles (one per
	 * kind), the rule, and per kind the norms that turn the spots' amplitudes and scales given to {@code add} back
	 * into those fitted with it.
	 */
	public record Previous(EmpiricalProfile[] profiles, Censoring censoring, double[] amplitudeNorms,
		double[] scaleNorms)
	{
		/** One kind. */
		public Previous(final EmpiricalProfile profile, final Censoring censoring, final double amplitudeNorm,
			final double scaleNorm)
		{
			this(new EmpiricalProfile[] { profile }, censoring, new double[] { amplitudeNorm }, new double[] {
				scaleNorm });
		}
	}

	/**
	 * @return whether the pixels within reach of a spot enter the profile: not a suspected merge nor a degenerate
	 *         first pass (its centre does not describe them), nor a particle cut by the border (its amplitude, scale
	 *         and centre are loose), nor a fit that did not converge (its centre, amplitude and scale may be anywhere:
	 *         two members on one particle, say; taken in, a single such fit can swing the profile, and with it every
	 *         centre, from one round to the next)
	 */
	public static boolean usable(final Localization spot) {
		return !spot.has(Flag.MERGED) && !spot.has(Flag.DEGENERATE) && !spot.has(Flag.AT_BORDER) && !spot.has(
			Flag.NOT_CONVERGED);
	}

	/**
	 * @return {mean amplitude, geometric mean scale} of the spots' fitted values (1 where none is known), over
	 *         the {@link #usable} spots
	 */
	public static double[] norms(final List<Localization> spots) {
		final double[][] n = norms(spots, new int[spots.size()], 1);
		return new double[] { n[0][0], n[1][0] };
	}

	/**
	 * @return per kind ({@code kind[k]} of spot {@code k}, 0-based, below {@code kinds}): {mean amplitudes, geometric
	 *         mean scales}, as {@link #norms(List)} over the spots of that kind
	 */
	public static double[][] norms(final List<Localization> spots, final int[] kind, final int kinds) {
		final double[] a = new double[kinds], s = new double[kinds];
		final int[] n = new int[kinds];
		for (int k = 0; k < spots.size(); k++) {
			final Localization l = spots.get(k);
			if (!usable(l) || !Double.isFinite(l.amplitude()) || !(l.scale() > 0)) continue;
			a[kind[k]] += l.amplitude();
			s[kind[k]] += Math.log(l.scale());
			n[kind[k]]++;
		}
		final double[][] out = new double[2][kinds];
		for (int c = 0; c < kinds; c++) {
			final boolean none = n[c] == 0 || !(a[c] > 0);
			out[0][c] = none ? 1 : a[c] / n[c];
			out[1][c] = none ? 1 : Math.exp(s[c] / n[c]);
		}
		return out;
	}

	/** Adds a plane with centres in its local coordinates, particles alike; pixels near masked centres are skipped. */
	void add(final Plane plane, final double[] cx, final double[] cy, final boolean[] masked) {
		final double[] ones = new double[cx.length];
		java.util.Arrays.fill(ones, 1);
		add(plane, cx, cy, ones, ones, masked);
	}

	/** As {@link #add(Plane, double[], double[], double[], double[], boolean[], Previous)} without a previous model. */
	void add(final Plane plane, final double[] cx, final double[] cy, final double[] amp, final double[] scale,
		final boolean[] masked)
	{
		add(plane, cx, cy, amp, scale, masked, null);
	}

	/**
	 * Adds a plane with centres in its local coordinates, each particle drawn as {@code amp_k P(r / scale_k)};
	 * pixels near masked centres, and clipped pixels (saturated, or at 0 where a dark ring falls below it), are
	 * skipped, and so are those where the {@code previous} model (if not null) comes near a clip level; where that
	 * model's rule links the floor, the pixels at and near it are kept, each pixel's row of the design matrix times
	 * the link's slope {@code s} at the previous model {@code m0}, its value replaced by {@code v - E(m0) + s m0}.
	 */
	public void add(final Plane plane, final double[] cx, final double[] cy, final double[] amp, final double[] scale,
		final boolean[] masked, final Previous previous)
	{
		add(plane, cx, cy, amp, scale, masked, new int[cx.length], previous);
	}

	/**
	 * As {@link #add(Plane, double[], double[], double[], double[], boolean[], Previous)}, particle {@code k} of kind
	 * {@code kind[k]} (0-based, below the estimator's number of kinds) drawn with its kind's profile.
	 */
	public void add(final Plane plane, final double[] cx, final double[] cy, final double[] amp, final double[] scale,
		final boolean[] masked, final int[] kind, final Previous previous)
	{
		final int n = cx.length, w = plane.width(), h = plane.height();
		final double saturation = plane.saturation(), floor = plane.floor();
		// the background's pixels at the floor are counted (an integer frame's: a float one has none)
		final boolean countsFloor = floor > Double.NEGATIVE_INFINITY && (Double.isNaN(this.floor) || this.floor == floor);
		if (countsFloor) this.floor = floor;
		if (previous != null) noise = Math.max(noise, previous.censoring().noise());
		final int[] near = new int[n], spanFrom = new int[n], spanTo = new int[n];
		final int[] idx = new int[4 * n + 3];
		final double[] val = new double[4 * n + 3];
		final double[] linkAt = new double[2]; // the link's mean and slope at a pixel (Censoring#link)
		final double mx = 0.5 * (w - 1), my = 0.5 * (h - 1);
		// The previous model decides which pixels are too near a clip level. Where a pixel is within reach of one
		// particle alone whose whole range of light keeps the model usable (or of none, and the background is), the
		// decision is known without evaluating it.
		final int[] inReach = new int[n];
		final double[] inReachR = new double[n];
		final boolean backgroundUsable = previous == null || previous.censoring().usable(previous.profiles()[0]
			.background());
		// Where the floor is linked (Censoring#mean), the pixels near it enter linearised about the previous model m0:
		// v - E(m0) + s m0 = s m, s the link's slope at m0. Known not to come near it likewise: a pixel of the
		// background alone, or of one particle whose whole range of light stays above the link. Where neither the band
		// nor the link is settled so, the model is evaluated once for both.
		final boolean linked = previous != null && previous.censoring().linked();
		final double linkTop = linked ? previous.censoring().linkTop() : Double.NEGATIVE_INFINITY;
		final boolean backgroundSettled = backgroundUsable && (!linked || previous.profiles()[0].background() >=
			linkTop);
		final boolean[] aloneSettled = new boolean[n];
		if (previous != null) for (int k = 0; k < n; k++) {
			final EmpiricalProfile pk = previous.profiles()[kind[k]];
			final double a = previous.amplitudeNorms()[kind[k]] * amp[k], b = pk.background(), lo = b + pk.leastLight(a);
			aloneSettled[k] = previous.censoring().usableBetween(lo, b + pk.greatestLight(a)) && lo >= linkTop;
		}
		final boolean[] reachedKind = new boolean[kinds];
		final double[] values = new double[w]; // each row read once (Plane.read), not pixel by pixel
		// Per row, the particles whose reach covers each pixel, in the order of the particles (so the sums are added in
		// the same order as when every particle of the row was tested at every pixel, which is slower in a dense
		// field): each particle's chord of the row, widened by a pixel, marked on the pixels it covers; the exact test
		// stays per pixel.
		final int[] first = new int[w + 1], at = new int[w];
		int[] covering = new int[4 * w];
		for (int y = 0; y < h; y++) {
			final double yd = y;
			plane.read(0, w - 1, y, y, values, 0);
			java.util.Arrays.fill(first, 0);
			int nn = 0;
			for (int k = 0; k < n; k++) {
				final double reach = radius * scale[k], dy = y - cy[k];
				if (!(Math.abs(dy) < reach)) continue;
				final double half = Math.sqrt(reach * reach - dy * dy);
				final int a = (int) Math.max(0, Math.floor(cx[k] - half) - 1), b = (int) Math.min(w - 1, Math.ceil(cx[k] +
					half) + 1);
				if (a > b) continue;
				near[nn] = k;
				spanFrom[nn] = a;
				spanTo[nn++] = b;
				for (int x = a; x <= b; x++)
					first[x + 1]++;
			}
			for (int x = 0; x < w; x++)
				first[x + 1] += first[x];
			if (covering.length < first[w]) covering = new int[2 * first[w]];
			System.arraycopy(first, 0, at, 0, w);
			for (int q = 0; q < nn; q++)
				for (int x = spanFrom[q]; x <= spanTo[q]; x++)
					covering[at[x]++] = near[q];
			// (x counted as a double too, exactly: RowRuns#row says why)
			double xd = -1;
			for (int x = 0; x < w; x++) {
				xd++;
				final double v = values[x];
				if (v >= saturation || v <= floor && !countsFloor) continue;
				int len = 0, reached = 0;
				boolean skip = false;
				if (kinds > 1) java.util.Arrays.fill(reachedKind, false);
				for (int q = first[x]; q < first[x + 1] && !skip; q++) {
					final int k = covering[q];
					final double dx = xd - cx[k], dy = yd - cy[k], d2 = dx * dx + dy * dy, reach = radius * scale[k];
					if (d2 >= reach * reach) continue;
					if (masked[k]) {
						skip = true;
						break;
					}
					final double r = Math.sqrt(d2), u = r / (SPACING * scale[k]);
					inReach[reached] = k;
					inReachR[reached++] = r;
					final int i = (int) u;
					// the four cubic B-spline weights of knots i-1..i+2 (EmpiricalProfile.bspline at u - j)
					final double f = u - i, g = 1 - f, f3 = f * f * f, g3 = g * g * g;
					final double a = amp[k];
					final int off = kind[k] * count;
					if (kinds > 1) reachedKind[kind[k]] = true;
					len = term(idx, val, len, i - 1, a * g3 / 6, off);
					len = term(idx, val, len, i, a * (2.0 / 3 - f * f + 0.5 * f3), off);
					len = term(idx, val, len, i + 1, a * (2.0 / 3 - g * g + 0.5 * g3), off);
					len = term(idx, val, len, i + 2, a * f3 / 6, off);
				}
				if (skip) continue;
				if (reached == 0 && countsFloor) {
					if (v <= floor) backgroundAtFloor++;
					else {
						backgroundAbove++;
						backgroundSum += v;
						backgroundSquares += v * v;
					}
				}
				// (NaN where the previous model need not be evaluated: no previous one, or band and link settled above)
				final boolean settled = previous == null || (reached == 0 ? backgroundSettled : reached == 1 &&
					aloneSettled[inReach[0]]);
				final double m0 = settled ? Double.NaN : model(previous, reached, inReach, inReachR, amp, scale, kind);
				if (v <= floor && !linked || !settled && !previous.censoring().usable(m0)) continue;
				if (kinds > 1) for (int c = 0; c < kinds; c++)
					if (reachedKind[c]) kindSamples[c]++;
				// (one pass for every pixel, of the background alone or of one particle or more: a separate copy for the
				// simpler pixels would not be faster)
				// the background plane B + bx u + by v, about the frame's centre (u, v in hundreds of px)
				idx[len] = bIndex;
				val[len++] = 1;
				idx[len] = bIndex + 1;
				val[len++] = (xd - mx) / RAMP_UNIT;
				idx[len] = bIndex + 2;
				val[len++] = (yd - my) / RAMP_UNIT;
				samples++;
				if (len > 3) profileSamples++;
				double target = v;
				if (m0 < linkTop) { // (false for NaN)
					previous.censoring().link(m0, linkAt);
					target = v - linkAt[0] + linkAt[1] * m0;
					for (int a = 0; a < len; a++)
						val[a] *= linkAt[1];
				}
				if (from != null) {
					gradient(idx, val, len, target);
					continue;
				}
				// The outer product, lower triangle only (by index: mirrored in estimate()), each unordered pair of
				// terms once; two terms on one coefficient (the mirror at r = 0, two particles) add twice.
				for (int a = 0; a < len; a++) {
					final int ia = idx[a];
					final double va = val[a];
					final double[] row = ata[ia];
					atb[ia] += va * target;
					row[ia] += va * va;
					for (int b = 0; b < a; b++) {
						final int ib = idx[b];
						final double pv = va * val[b];
						if (ib < ia) row[ib] += pv;
						else if (ib > ia) ata[ib][ia] += pv;
						else row[ia] += 2 * pv;
					}
				}
			}
		}
	}

	/**
	 * A chord step's pass over one pixel of value {@code v} whose row of the design matrix is the {@code len} terms
	 * {@code idx, val}: its residual at the earlier solution times its row into {@code atb}, and its row's squares
	 * (terms on one coefficient summed first, as in the outer product) into the diagonal.
	 */
	private void gradient(final int[] idx, final double[] val, final int len, final double v) {
		final double[] x = from.solution;
		double model = 0;
		for (int a = 0; a < len; a++) {
			model += val[a] * x[idx[a]];
			rowSum[idx[a]] += val[a];
		}
		final double r = v - model;
		for (int a = 0; a < len; a++) {
			final int ia = idx[a];
			atb[ia] += val[a] * r;
			final double sum = rowSum[ia];
			if (sum != 0) {
				diagonal[ia] += sum * sum;
				rowSum[ia] = 0;
			}
		}
	}

	/** @return the {@code previous} model at a pixel within reach of the {@code reached} particles {@code inReach} */
	private static double model(final Previous previous, final int reached, final int[] inReach,
		final double[] inReachR, final double[] amp, final double[] scale, final int[] kind)
	{
		double model = previous.profiles()[0].background();
		for (int q = 0; q < reached; q++) {
			final int k = inReach[q], c = kind[k];
			model += previous.amplitudeNorms()[c] * amp[k] * previous.profiles()[c].lookup(inReachR[q] / (previous
				.scaleNorms()[c] * scale[k]));
		}
		return model;
	}

	/**
	 * Appends knot {@code j}'s term {@code value} (if it has a coefficient and is not zero) of the profile whose
	 * coefficients start at {@code offset}; returns the length.
	 */
	private int term(final int[] idx, final double[] val, final int len, final int j, final double value,
		final int offset)
	{
		final int c = EmpiricalProfile.coefficientIndex(j, count);
		if (c < 0 || value == 0) return len;
		idx[len] = c + offset;
		val[len] = value;
		return len + 1;
	}

	/** Unit of the background plane's coordinates (px): keeps its columns of the size of the others. */
	static final double RAMP_UNIT = 100;

	/** Adds what {@code other} (of the same radius) has accumulated, so frames can be measured in parallel. */
	public void merge(final ProfileEstimator other) {
		if (other.count != count || other.kinds != kinds || other.from != from) throw new IllegalArgumentException(
			"profile radii, kinds or earlier estimates differ");
		for (int i = 0; i < atb.length; i++) {
			atb[i] += other.atb[i];
			if (from != null) diagonal[i] += other.diagonal[i];
			else for (int j = 0; j < atb.length; j++)
				ata[i][j] += other.ata[i][j];
		}
		samples += other.samples;
		profileSamples += other.profileSamples;
		if (!Double.isNaN(other.floor) && (Double.isNaN(floor) || floor == other.floor)) {
			floor = other.floor;
			backgroundAtFloor += other.backgroundAtFloor;
			backgroundAbove += other.backgroundAbove;
			backgroundSum += other.backgroundSum;
			backgroundSquares += other.backgroundSquares;
		}
		noise = Math.max(noise, other.noise);
		for (int c = 0; c < kinds; c++)
			kindSamples[c] += other.kindSamples[c];
	}

	/**
	 * @return the profile (of the first kind)
	 * @throws IllegalStateException when the data cannot determine it
	 */
	public EmpiricalProfile estimate() {
		return estimateAll()[0];
	}

	/**
	 * @return the profile of each kind, all with the same background
	 * @throws IllegalStateException when the data cannot determine them (naming the kind, if one has too few pixels)
	 */
	public EmpiricalProfile[] estimateAll() {
		return solve().profiles();
	}

	/**
	 * The earlier estimate a chord step starts from: its solution (every kind's coefficients, then the background
	 * plane) and the penalised normal matrix it was solved with (a chord step's: that of the full estimate it goes
	 * back to).
	 */
	public static final class Linearisation {
		private final double[][] normal;
		private final double[] solution;

		private Linearisation(final double[][] normal, final double[] solution) {
			this.normal = normal;
			this.solution = solution;
		}

		/**
		 * @return how far the profiles moved from {@code earlier}'s (same radius and kinds): the largest change of a
		 *         profile coefficient over the largest coefficient (the background plane left out)
		 */
		public double change(final Linearisation earlier) {
			if (earlier.solution.length != solution.length) throw new IllegalArgumentException(
				"another radius or number of kinds");
			double change = 0, size = 0;
			for (int i = 0; i < solution.length - 3; i++) {
				change = Math.max(change, Math.abs(solution[i] - earlier.solution[i]));
				size = Math.max(size, Math.abs(solution[i]));
			}
			return size > 0 ? change / size : change;
		}
	}

	/** The profile of each kind, and the linearisation a later chord step starts from. */
	public record Solution(EmpiricalProfile[] profiles, Linearisation linearisation) {}

	/**
	 * @return as {@link #estimateAll()}, with this estimate's linearisation
	 * @throws IllegalStateException when the data cannot determine the profiles
	 */
	public Solution solve() {
		final int m = bIndex + 3;
		final double[] clippedNormal = clippedBackground();
		final double held = clippedNormal == null ? Double.NaN : clippedNormal[0];
		// the weight of the penalty on each kind's second differences: the kind's diagonal and the background's
		final double[] lambda = new double[kinds];
		for (int c = 0; c < kinds; c++) {
			double trace = 0;
			for (int i = c * count; i < (c + 1) * count; i++)
				trace += diagonalAt(i);
			trace += diagonalAt(bIndex);
			lambda[c] = SMOOTHNESS * trace / (count + 1);
		}
		final double[][] normal;
		final double[] x;
		if (from == null) {
			normal = new double[m][m];
			for (int i = 0; i < m; i++)
				for (int j = 0; j <= i; j++)
					normal[i][j] = normal[j][i] = ata[i][j];
			// A background without a ramp (one frame: no pixel off its centre row) leaves the plane's slopes free
			for (int i = bIndex + 1; i < m; i++)
				if (normal[i][i] == 0) normal[i][i] = 1;
			for (int c = 0; c < kinds; c++)
				addPenalty(normal, c * count, lambda[c]);
			x = held(normal, atb.clone(), held, 0);
		}
		else { // x + N^-1 (A^T (b - A x) - penalty x), N the earlier normal matrix
			normal = from.normal;
			final double[][] penalty = new double[m][m];
			for (int c = 0; c < kinds; c++)
				addPenalty(penalty, c * count, lambda[c]);
			final double[] g = atb.clone();
			for (int i = 0; i < m; i++)
				for (int j = 0; j < m; j++)
					g[i] -= penalty[i][j] * from.solution[j];
			x = held(normal, g, held, from.solution[bIndex]);
			if (x != null) for (int i = 0; i < m; i++)
				x[i] += from.solution[i];
		}
		// pixels of the background alone determine no profile: the smoothness penalty would make one up
		if (x == null || samples < 4 * (count + 1) || profileSamples < 4 * count)
			throw new IllegalStateException("too few pixels (" + samples + ", " + profileSamples + " within reach of a " +
				"usable particle) to estimate the particles' profile");
		// (one kind: its pixels are those within reach of a particle, checked above)
		if (kinds > 1) for (int c = 0; c < kinds; c++)
			if (kindSamples[c] < 4 * count) throw new IllegalStateException("too few pixels (" + kindSamples[c] +
				") within reach of a usable particle of kind " + (c + 1) + " to estimate its profile");
		final EmpiricalProfile[] out = new EmpiricalProfile[kinds];
		for (int c = 0; c < kinds; c++) {
			final double[] coefficients = new double[count];
			System.arraycopy(x, c * count, coefficients, 0, count);
			out[c] = new EmpiricalProfile(SPACING, coefficients, x[bIndex], samples, clippedNormal == null ? Double.NaN
				: clippedNormal[1]);
		}
		return new Solution(out, new Linearisation(normal, x));
	}

	/**
	 * A clipped background is held only where the normal it is taken for spreads at most this many times the frames'
	 * pixel noise, as a flat background does (the clipped normal's spread was 0.55 times the frame's noise estimate
	 * on a simulated clipped scene, 1.3 times on a public confocal stack), and not a background of structure (the dark
	 * walls between a foam's bubbles: 50 times).
	 */
	static final double NOISE_LIKE = 2;

	/**
	 * The background of a frame clipped at the floor (more than {@link Censoring#CLIPPED_BACKGROUND} of the background's
	 * pixels at it): the mean of the normal whose values below
	 * the floor were read as the floor ({@link CensoredNormal}), from the pixels of the background alone. A value read
	 * as the floor of an integer frame stands for every true value below half a level above it (the pixels are
	 * rounded), and one above it for its own. Where the background is clipped and banded, no pixel a fit may use
	 * shows it (they lie {@link Censoring clear of the floor}), and the profile's outer knots and the background would trade
	 * places freely: measured from the pixels above the floor alone, the background came out 2 grey levels high on
	 * discs on a background of 2 clipped at 0 (noise 4), each profile's tail as much too low, and touching particles,
	 * whose tails add up between them, pulled 0.03 px towards each other. The profile is measured about this
	 * background, held, and the normal's standard deviation is the noise the fit links the floor with
	 * ({@link EmpiricalProfile#floorNoise}).
	 *
	 * @return {mean, standard deviation} of that normal, or null where the background is not clipped or spreads more
	 *         than noise does
	 */
	private double[] clippedBackground() {
		final long all = backgroundAtFloor + backgroundAbove;
		if (Double.isNaN(floor) || !(noise > 0) || !(backgroundAtFloor > Censoring.CLIPPED_BACKGROUND * all))
			return null;
		final double[] normal = CensoredNormal.estimate(floor + 0.5, backgroundAtFloor, backgroundAbove, backgroundSum,
			backgroundSquares);
		return normal == null || !(normal[1] <= NOISE_LIKE * noise) ? null : normal;
	}

	/**
	 * @return the solution of {@code normal x = rhs} with the background's level held at {@code level} where it is a
	 *         number ({@code rhs} then changed), its solution being the change from {@code from} (0 for a full estimate)
	 */
	private double[] held(final double[][] normal, final double[] rhs, final double level, final double from) {
		if (Double.isNaN(level)) return SymmetricSolver.solve(normal, rhs);
		final int m = rhs.length;
		final double step = level - from;
		final double[][] a = new double[m][];
		for (int i = 0; i < m; i++) {
			a[i] = normal[i].clone();
			rhs[i] -= normal[i][bIndex] * step;
			a[i][bIndex] = 0;
		}
		java.util.Arrays.fill(a[bIndex], 0);
		a[bIndex][bIndex] = 1;
		rhs[bIndex] = step;
		return SymmetricSolver.solve(a, rhs);
	}

	private double diagonalAt(final int i) {
		return from == null ? ata[i][i] : diagonal[i];
	}

	/**
	 * Adds to {@code a} the penalty of weight {@code lambda} on the second differences {@code d_j = c_{j-1} - 2 c_j +
	 * c_{j+1}}, {@code j = 0..count}, of the profile whose coefficients start at {@code off}, with {@code c_-1 = c_1}
	 * and {@code c_count = 0} (beyond the last coefficient).
	 */
	private void addPenalty(final double[][] a, final int off, final double lambda) {
		for (int j = 0; j <= count; j++) {
			final int[] ci = { EmpiricalProfile.coefficientIndex(j - 1, count), EmpiricalProfile.coefficientIndex(j,
				count), EmpiricalProfile.coefficientIndex(j + 1, count) };
			final double[] cw = { 1, -2, 1 };
			for (int p = 0; p < 3; p++)
				for (int q = 0; q < 3; q++)
					if (ci[p] >= 0 && ci[q] >= 0) a[off + ci[p]][off + ci[q]] += lambda * cw[p] * cw[q];
		}
	}
}
