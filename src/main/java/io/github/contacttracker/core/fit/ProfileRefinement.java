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

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindFeatures;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.kind.Kinds;
import io.github.contacttracker.core.math.Statistics;
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
		return refine(plane, ps, params, given == null ? null : KindProfiles.one(given), noise);
	}

	/**
	 * As {@link #refine(Plane, Particle[], TrackerParameters, EmpiricalProfile, double)} with the profile of each kind
	 * of particle measured beforehand (over a stack), or {@code null}: then the kinds are told apart on this frame
	 * (unless {@link TrackerParameters#kinds()} is 1) and each kind's profile measured on it. Each particle is drawn
	 * with its kind's profile; the outcome holds the kinds.
	 */
	public Outcome refine(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final KindProfiles given, final double noise)
	{
		return fit(plane, ps, params, given, noise).outcome();
	}

	/**
	 * The outcome of a refinement and the profiles it drew the particles with (those given, or measured on the
	 * frame; {@code null} when none could be measured and the iterative centres were kept).
	 */
	public record Fitted(Outcome outcome, KindProfiles profiles) {}

	/**
	 * As {@link #refine(Plane, Particle[], TrackerParameters, KindProfiles, double)}, with the profiles used: a
	 * detection that adds or removes particles after the fit refits with them.
	 */
	public Fitted fit(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final KindProfiles given, final double noise)
	{
		return fit(plane, ps, params, given, noise, true);
	}

	/**
	 * @param iterate whether the fit starts from the iterative second passes (else from the first passes: particles
	 *        seeded by the image, each on its own pixels, start where their seeds put them)
	 */
	public Fitted fit(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final KindProfiles given, final double noise, final boolean iterate)
	{
		return fit(plane, ps, params, given, noise, iterate, null);
	}

	/**
	 * As {@link #fit(Plane, Particle[], TrackerParameters, KindProfiles, double, boolean)} from the first pass, each
	 * particle's fit started from {@code warm[k]} where given (its centre, amplitude and scale): a refit of particles
	 * an earlier fit with the same profiles found, most of whose members it leaves where they were. Started from
	 * their first passes, every member of a packed field moved, and moved its neighbours, for ten sweeps and more (a
	 * simulated bidisperse monolayer of 1,560 particles: 19,500 member fits a refit; warm, 8,000 to 10,000), and the
	 * members that had not settled in one fit's sweeps started over in the next (warm, they go on where they stopped:
	 * on the detection study's bidisperse monolayer, 442 spots flagged in 15,780 instead of 956, most NOT_CONVERGED).
	 *
	 * @param warm each particle's start (null, or null entries: its first pass); its flags are the first pass's
	 */
	public Fitted fit(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final KindProfiles given, final double noise, final Estimate[] warm)
	{
		return fit(plane, ps, params, given, noise, false, warm);
	}

	private Fitted fit(final Plane plane, final Particle[] ps, final TrackerParameters params,
		final KindProfiles given, final double noise, final boolean iterate, final Estimate[] warm)
	{
		final Outcome iterative = iterate ? SecondPass.iterate(ps, params) : Refinement.FIRST_PASS.refine(plane, ps,
			params, null, noise);
		Estimate[] e = iterative.estimates();
		if (warm != null) {
			e = e.clone();
			for (int k = 0; k < e.length; k++)
				if (warm[k] != null) e[k] = warm[k].withFlags(e[k].flags());
		}
		if (ps.length == 0) return new Fitted(iterative, given);
		// each particle's kind, among the movie's kinds or this frame's
		final Kinds kinds;
		final int[] kind;
		if (given != null || params.kinds() == 1) {
			kinds = given == null ? null : given.kinds();
			kind = KindProfiles.kindsOf(kinds, plane, ps, e, params.rOut());
		}
		else { // this frame's own kinds: its particles measured once, to find the kinds and to place each
			final KindFeatures[] f = KindFeatures.measure(plane, ps, e, params.rOut());
			final List<KindFeatures> sample = new ArrayList<>();
			for (int k = 0; k < ps.length; k++)
				if (!Flag.DEGENERATE.isSet(ps[k].first().flags())) sample.add(f[k]); // merges too: a kind may be all merged
			kinds = KindProfiles.tellApart(sample, params.kinds());
			kind = KindProfiles.kindsOf(kinds, f);
		}
		// measured here: alternated with the centres until these stop moving (see the stack tracker)
		// pixels near the clip levels, chosen by the model or linked to it (see Censoring), at the frame's noise, or
		// at a clipped background's own as the profile measures it
		final Censoring censoring = Censoring.of(plane, noise);
		final int rounds = given == null ? PROFILE_ROUNDS : 1;
		KindProfiles profiles = given;
		final int clear = Flag.SECOND_PASS.bit() | Flag.FELL_BACK.bit() | Flag.NOT_CONVERGED.bit();
		boolean settled = given != null;
		final Rounds settling = new Rounds();
		for (int round = 0; round < rounds; round++) {
			if (given == null) {
				profiles = measure(plane, ps, e, params.profileReach(), kinds, kind, round == 0 ? null : profiles,
					censoring);
				if (profiles == null) {
					final Estimate[] kept = e.clone();
					for (int k = 0; k < kept.length; k++)
						kept[k] = kept[k].withFlags(kept[k].flags() | Flag.FELL_BACK.bit());
					return new Fitted(new Outcome(kept, iterative.discs(), kind), null);
				}
			}
			final EmpiricalProfile[] of = profiles.byParticle(kind);
			// the iterative pass's flags do not describe the refined centres (a group that cannot be fitted sets its own)
			final Estimate[] start = e.clone();
			for (int k = 0; k < start.length; k++) // (the border: the first pass's, the cut decided again below)
				start[k] = start[k].withFlags(start[k].flags() & ~clear & ~Flag.AT_BORDER.bit() | ps[k].first().flags() &
					Flag.AT_BORDER.bit());
			final Refined r;
			if (deblend) {
				double disc = profiles.main().activeRadius(params.threshold());
				if (disc < 3) disc = medianEquivalentRadius(ps);
				r = Deblender.refine(plane, ps, start, of, disc);
			}
			else r = GroupFit.refine(plane, ps, start, of, params.groupingDistance(), params.rOut(),
				censoring.withFloorNoise(profiles.main().floorNoise()));
			final Estimate[] next = r.estimates();
			for (int k = 0; k < next.length; k++) {
				// (a group's fit: its own iterations; the deblender's: the frame's)
				if (deblend) next[k] = next[k].withIterations(Math.abs(r.iterations()));
			}
			// (each round: the next profile leaves out the pixels of particles cut by the edge)
			flagCutByTheBorder(plane, next, of);
			final double[] moves = new double[next.length];
			for (int k = 0; k < next.length; k++)
				moves[k] = ps[k].reliable() && !next[k].has(Flag.FELL_BACK) && !e[k].has(Flag.FELL_BACK) ? next[k]
					.distanceTo(e[k]) / GroupFit.settled(next[k].sigmaX(), next[k].sigmaY()) : Double.NaN;
			e = next;
			// (the first round's moves are from the iterative centres; a verdict needs a round on a measured profile)
			Rounds.Verdict verdict = round == 0 ? Rounds.Verdict.GOING_ON : settling.next(moves);
			if (verdict == Rounds.Verdict.GOING_ON && round > 0 && round == rounds - 1) verdict = settling.atLimit();
			if (verdict == Rounds.Verdict.GOING_ON) continue;
			if (verdict == Rounds.Verdict.STALLED) break; // (no fixed point: flagged below)
			if (verdict == Rounds.Verdict.CYCLING) for (int k = 0; k < e.length; k++)
				if (settling.stillMoving(k)) e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED.bit());
			settled = true;
			break;
		}
		// profile and centres still moving at the last round, or stalled: no fixed point, the centres can be off by that
		// much
		if (!settled) for (int k = 0; k < e.length; k++)
			e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED.bit());
		flagUnmodelledNeighbours(ps, e, params.groupingDistance());
		return new Fitted(new Outcome(e, iterative.discs(), kind), profiles);
	}

	/**
	 * The profile of each kind on this frame around centres {@code e}, unreliable particles masked; null if too few
	 * pixels. The profiles {@code e} was fitted with, if any, choose the pixels left out near clip levels.
	 */
	private static KindProfiles measure(final Plane plane, final Particle[] ps, final Estimate[] e,
		final double reach, final Kinds kinds, final int[] kind, final KindProfiles fittedWith,
		final Censoring censoring)
	{
		final int count = kinds == null ? 1 : kinds.count();
		final ProfileEstimator estimator = new ProfileEstimator(reach, count);
		final int n = ps.length;
		final double[] cx = new double[n], cy = new double[n], amp = new double[n], scale = new double[n];
		final boolean[] masked = new boolean[n];
		final int[] at = new int[n];
		// per kind, the profile's own height and size: its particles' mean amplitude and (geometric) mean scale
		final double[] ampSum = new double[count], logScaleSum = new double[count];
		final int[] fitted = new int[count];
		for (int k = 0; k < n; k++) {
			cx[k] = e[k].x();
			cy[k] = e[k].y();
			masked[k] = !ps[k].reliable() || e[k].has(Flag.AT_BORDER);
			at[k] = KindProfiles.position(kinds, kind[k]);
			final boolean known = Double.isFinite(e[k].amplitude()) && e[k].scale() > 0;
			amp[k] = known ? e[k].amplitude() : 1;
			scale[k] = known ? e[k].scale() : 1;
			if (known && !masked[k]) {
				ampSum[at[k]] += amp[k];
				logScaleSum[at[k]] += Math.log(scale[k]);
				fitted[at[k]]++;
			}
		}
		final double[] ampNorm = new double[count], scaleNorm = new double[count];
		for (int c = 0; c < count; c++) {
			ampNorm[c] = fitted[c] > 0 && ampSum[c] > 0 ? ampSum[c] / fitted[c] : 1;
			scaleNorm[c] = fitted[c] > 0 ? Math.exp(logScaleSum[c] / fitted[c]) : 1;
		}
		for (int k = 0; k < n; k++) {
			amp[k] /= ampNorm[at[k]];
			scale[k] /= scaleNorm[at[k]];
		}
		ProfileEstimator.Previous previous = null;
		if (fittedWith != null) {
			final EmpiricalProfile[] before = new EmpiricalProfile[count];
			for (int c = 0; c < count; c++)
				before[c] = fittedWith.profile(c);
			previous = new ProfileEstimator.Previous(before, censoring.withFloorNoise(before[0].floorNoise()), ampNorm,
				scaleNorm);
		}
		estimator.add(plane, cx, cy, amp, scale, masked, at, previous);
		try {
			final EmpiricalProfile[] measured = estimator.estimateAll();
			return kinds == null ? KindProfiles.one(measured[0]) : KindProfiles.of(kinds, measured);
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
	static void flagUnmodelledNeighbours(final Particle[] ps, final Estimate[] e, final double grouping) {
		for (int q = 0; q < ps.length; q++) {
			if (ps[q].reliable()) continue;
			final double reach = grouping + Math.sqrt(ps[q].region().area() / Math.PI);
			for (int k = 0; k < ps.length; k++)
				if (k != q && ps[k].reliable() && Math.hypot(e[k].x() - ps[q].first().x(), e[k].y() - ps[q].first()
					.y()) < reach) e[k] = e[k].withFlags(e[k].flags() | Flag.UNMODELLED_NEIGHBOUR.bit());
		}
	}

	/**
	 * A refined centre whose frame cuts off this share of the information on it (or more;
	 * {@link EmpiricalProfile#informationOutside}) counts as cut by the edge. The fitted profile is symmetric: the
	 * part cut off no longer balances the part left, so a model error the image would average out on all sides pulls
	 * the centre towards the frame, and the pull grows with the share cut. Crops of real footage keep a centre within
	 * its reported error of the uncut frame's up to about a tenth cut (methods.md, "Particles at the border");
	 * half of that is the limit.
	 * The first pass flags only an active area touching the edge, a far deeper cut.
	 */
	public static final double CUT_INFORMATION = 0.05;

	/**
	 * Flags {@code AT_BORDER} every refined centre (in the plane's local coordinates, particle {@code k} drawn with
	 * {@code profile[k]}) whose frame cuts off {@link #CUT_INFORMATION} of the information on it.
	 */
	static void flagCutByTheBorder(final Plane plane, final Estimate[] e, final EmpiricalProfile[] profile) {
		// a centre farther from every edge than the radius that holds 99% of its information cannot lose 5% to them:
		// the share is summed only nearer the edges, not for every centre of a dense field
		final java.util.Map<EmpiricalProfile, Double> safe = new java.util.IdentityHashMap<>();
		for (int k = 0; k < e.length; k++) {
			final double scale = e[k].scale() > 0 && Double.isFinite(e[k].scale()) ? e[k].scale() : 1;
			final double x = e[k].x(), y = e[k].y();
			final double inside = Math.min(Math.min(x + 0.5, plane.width() - 0.5 - x), Math.min(y + 0.5, plane
				.height() - 0.5 - y));
			if (inside >= scale * safe.computeIfAbsent(profile[k], p -> p.informationRadius(SAFE_INFORMATION))) continue;
			if (profile[k].cutOff(x, y, scale, plane.width(), plane.height(), CUT_INFORMATION)) e[k] =
				e[k].withFlags(e[k].flags() | Flag.AT_BORDER.bit());
		}
	}

	/** See {@link #flagCutByTheBorder}. */
	private static final double SAFE_INFORMATION = 0.99;

	private static double medianEquivalentRadius(final Particle[] ps) {
		final double[] r = new double[ps.length];
		for (int k = 0; k < ps.length; k++)
			r[k] = Math.sqrt(ps[k].region().area() / Math.PI);
		return Statistics.median(r);
	}
}
