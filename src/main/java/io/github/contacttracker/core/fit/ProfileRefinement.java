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
package io.github.contacttracker.core.fit;

import java.util.Arrays;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileEstimator;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.radial.Refinement;
import io.github.contacttracker.core.radial.SecondPass;

/**
 * The profile methods, {@code deblend} and {@code fit}: iterative centres first; then the particles' radial profile
 * (given, or measured on this frame: again and again around the refined centres, until they settle); then the centres
 * refined with it by {@link Deblender} or {@link GroupFit}. If the frame's profile cannot be measured the
 * iterative centres are kept, flagged {@code FELL_BACK}.
 */
public final class ProfileRefinement implements Refinement {

	/** The {@code deblend} method. */
	public static final Refinement DEBLEND = new ProfileRefinement(true);
	/** The {@code fit} method. */
	public static final Refinement FIT = new ProfileRefinement(false);

	/**
	 * What {@link Deblender} and {@link GroupFit} return: every particle's estimate (unchanged where not refined)
	 * and the iterations needed, negative if the limit was reached.
	 */
	record Refined(Estimate[] estimates, int iterations) {}

	/**
	 * At most this many rounds of profile and centres on the sample frames (here and in the stack tracker), which
	 * stop when every fitted centre has {@link GroupFit#settled settled}.
	 */
	public static final int PROFILE_ROUNDS = 30;

	private final boolean deblend;

	private ProfileRefinement(final boolean deblend) {
		this.deblend = deblend;
	}

	@Override
	public Outcome refine(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final EmpiricalProfile given, final double noise)
	{
		final Outcome iterative = SecondPass.iterate(ps, params);
		Estimate[] e = iterative.estimates();
		if (ps.length == 0) return iterative;
		// measured here: alternated with the centres until these stop moving (see the stack tracker)
		// pixels near the clip levels, chosen by the model (see Censoring), at the frame's noise
		final Censoring censoring = Censoring.of(plane, noise);
		final int rounds = given == null ? PROFILE_ROUNDS : 1;
		EmpiricalProfile profile = given;
		final int clear = Flag.SECOND_PASS.bit() | Flag.FELL_BACK.bit() | Flag.NOT_CONVERGED.bit();
		boolean settled = given != null;
		final Rounds settling = new Rounds();
		for (int round = 0; round < rounds; round++) {
			if (given == null) {
				profile = measure(plane, ps, e, params.rOut(), round == 0 ? null : profile, censoring);
				if (profile == null) {
					final Estimate[] kept = e.clone();
					for (int k = 0; k < kept.length; k++)
						kept[k] = kept[k].withFlags(kept[k].flags() | Flag.FELL_BACK.bit());
					return new Outcome(kept, iterative.discs());
				}
			}
			// the iterative pass's flags do not describe the refined centres (a group that cannot be fitted sets its own)
			final Estimate[] start = e.clone();
			for (int k = 0; k < start.length; k++)
				start[k] = start[k].withFlags(start[k].flags() & ~clear);
			final Refined r;
			if (deblend) {
				double disc = profile.activeRadius(params.threshold());
				if (disc < 3) disc = medianEquivalentRadius(ps);
				r = Deblender.refine(plane, ps, start, profile, disc);
			}
			else r = GroupFit.refine(plane, ps, start, profile, 2 * params.rOut(), params.rOut(), censoring);
			final Estimate[] next = r.estimates();
			for (int k = 0; k < next.length; k++) {
				next[k] = new Estimate(next[k].x(), next[k].y(), next[k].flags(), next[k].secondArea(), Math.abs(r
					.iterations()),
					next[k].solve(), next[k].sigmaX(), next[k].sigmaY(), next[k].amplitude(), next[k].scale());
			}
			final double[] moves = new double[next.length];
			for (int k = 0; k < next.length; k++)
				moves[k] = ps[k].reliable() && !next[k].has(Flag.FELL_BACK) && !e[k].has(Flag.FELL_BACK) ? next[k]
					.distanceTo(e[k]) / GroupFit.settled(next[k].sigmaX(), next[k].sigmaY()) : Double.NaN;
			e = next;
			// (the first round's moves are from the iterative centres; a verdict needs a round on a measured profile)
			final Rounds.Verdict verdict = round == 0 ? Rounds.Verdict.GOING_ON : settling.next(moves);
			if (verdict == Rounds.Verdict.GOING_ON) continue;
			if (verdict == Rounds.Verdict.CYCLING) for (int k = 0; k < e.length; k++)
				if (settling.stillMoving(k)) e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED.bit());
			settled = true;
			break;
		}
		// profile and centres still moving at the last round: no fixed point, the centres can be off by that much
		if (!settled) for (int k = 0; k < e.length; k++)
			e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED.bit());
		flagUnmodelledNeighbours(ps, e, params.rOut());
		return new Outcome(e, iterative.discs());
	}

	/**
	 * The profile on this frame around centres {@code e}, unreliable particles masked; null if too few pixels. The
	 * profile {@code e} was fitted with, if any, chooses the pixels left out near clip levels.
	 */
	private static EmpiricalProfile measure(final Plane plane, final Particle[] ps, final Estimate[] e,
		final double rOut, final EmpiricalProfile fittedWith, final Censoring censoring)
	{
		final ProfileEstimator estimator = ProfileEstimator.forROut(rOut);
		final int n = ps.length;
		final double[] cx = new double[n], cy = new double[n], amp = new double[n], scale = new double[n];
		final boolean[] masked = new boolean[n];
		double ampSum = 0, logScaleSum = 0;
		int fitted = 0;
		for (int k = 0; k < n; k++) {
			cx[k] = e[k].x();
			cy[k] = e[k].y();
			masked[k] = !ps[k].reliable();
			final boolean known = Double.isFinite(e[k].amplitude()) && e[k].scale() > 0;
			amp[k] = known ? e[k].amplitude() : 1;
			scale[k] = known ? e[k].scale() : 1;
			if (known && !masked[k]) {
				ampSum += amp[k];
				logScaleSum += Math.log(scale[k]);
				fitted++;
			}
		}
		// the profile's own height and size: the particles' mean amplitude and (geometric) mean scale
		final double ampNorm = fitted > 0 && ampSum > 0 ? ampSum / fitted : 1;
		final double scaleNorm = fitted > 0 ? Math.exp(logScaleSum / fitted) : 1;
		for (int k = 0; k < n; k++) {
			amp[k] /= ampNorm;
			scale[k] /= scaleNorm;
		}
		estimator.add(plane, cx, cy, amp, scale, masked, fittedWith == null ? null : new ProfileEstimator.Previous(
			fittedWith, censoring, ampNorm, scaleNorm));
		try {
			return estimator.estimate();
		}
		catch (final IllegalStateException ex) {
			return null;
		}
	}

	/**
	 * Flags every refined spot that an unmodelled particle's light reaches: a suspected merge or a first pass
	 * without a centre is left out of the model (its centre is meaningless), so its light is fitted as if it were
	 * the neighbour's and pulls that centre by an amount nothing measures. Reach: as for a group
	 * ({@code 2 r_out}: a particle's light above the noise reaches {@code r_out}, and the fit reads pixels up to
	 * {@code r_out} from its particles), plus the unmodelled component's own equivalent radius (a merge spans two).
	 */
	static void flagUnmodelledNeighbours(final Particle[] ps, final Estimate[] e, final double rOut) {
		for (int q = 0; q < ps.length; q++) {
			if (ps[q].reliable()) continue;
			final double reach = 2 * rOut + Math.sqrt(ps[q].region.area() / Math.PI);
			for (int k = 0; k < ps.length; k++)
				if (k != q && ps[k].reliable() && Math.hypot(e[k].x() - ps[q].first.x(), e[k].y() - ps[q].first.y()) <
					reach) e[k] = e[k].withFlags(e[k].flags() | Flag.UNMODELLED_NEIGHBOUR.bit());
		}
	}

	private static double medianEquivalentRadius(final Particle[] ps) {
		final double[] r = new double[ps.length];
		for (int k = 0; k < ps.length; k++)
			r[k] = Math.sqrt(ps[k].region.area() / Math.PI);
		Arrays.sort(r);
		return r[r.length / 2];
	}
}
