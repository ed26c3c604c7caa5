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

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/**
 * The fit of a group too large to fit jointly ({@link GroupFit#MAX_JOINT}), member by member: sweeps over the
 * group in which each member is fitted alone by {@link GroupFit}'s least squares, its neighbours' light held at their
 * latest estimates. Its cost grows linearly with the group's size where a joint fit's grows with its cube, and a
 * member that cannot settle holds up only its own fit.
 */
final class MemberSweeps {

	/**
	 * A member fitted in turn whose centre ends further than this many equivalent radii of its active area from
	 * where the sweeps started is no fit.
	 */
	static final double MAX_SLIDE = 1;
	/**
	 * At most this many sweeps over a large group. With the background held, a member's amplitude and scale take up
	 * what its neighbours' light leaves, which couples the members more than a local plane of their own did: on a
	 * packed monolayer of 254 blurred discs, 10 sweeps left 224 of them still moving, 20 left 43 and 40 none. The
	 * sweeps stop as soon as no member moves, so the limit costs only where they would not settle.
	 */
	static final int MAX_SWEEPS = 40;
	/** A member fitted in turn takes at most this many iterations a sweep (the next sweep goes on from there). */
	static final int ITERATIONS_PER_SWEEP = 25;
	/** A member fitted in turn uses the pixels that hold this fraction of the information on its centre. */
	static final double INFORMATION = 0.95;

	private MemberSweeps() {}

	/**
	 * A group too large to fit jointly (at the profile helper's r_out a dense field is one group of a hundred
	 * particles or more: a joint fit of 400 parameters costs minutes per frame, and one member that cannot settle
	 * holds all of them): each member fitted alone, its neighbours' light held at their latest estimates, in
	 * sweeps over the group (block coordinate descent on the same least squares, the background held at the
	 * profile's: see {@link GroupFit.Budget}). A member is fitted on the pixels holding {@value #INFORMATION} of the
	 * information on its
	 * centre ({@link EmpiricalProfile#informationRadius}), which in a dense field lie well within r_out, chosen in
	 * the first sweep and kept ({@link GroupFit.Kept}), to its own tolerance (in the first sweep, whose neighbours
	 * all move after it, that of its first J^T J: the centre's own error is not known before) and for at most
	 * {@value #ITERATIONS_PER_SWEEP} iterations a sweep; it is fitted again only when a neighbour whose window overlaps
	 * its own moved by more than {@link GroupFit#settled that neighbour's tolerance} after the member's latest fit, or
	 * when its own iterations ran out. The sweeps stop when no member is to be fitted again, at most {@code maxSweeps}
	 * ({@value #MAX_SWEEPS}); a member that would be fitted again then, or that the last sweep's fit still moved, is
	 * flagged {@code NOT_CONVERGED}, one that cannot be fitted or slides off its particle {@code FELL_BACK}. The cost
	 * is linear in the group's size and bounded. A member's standard errors are those of its own fit, without its
	 * covariance with the neighbours. Members, not blocks of them, are the unit: a member that cannot settle (its
	 * model wrong for it, its particle cut by the edge) holds up a joint fit of its block, not its neighbours' own.
	 *
	 * @return the largest iteration count of a member's fit in the last sweep
	 */
	static int fitInTurn(final Plane plane, final Particle[] particles, final Estimate[] e, final int[] group,
		final EmpiricalProfile[] profile, final double window, final Censoring censoring, final int maxSweeps)
	{
		final int n = group.length;
		final boolean[] failed = new boolean[n], active = new boolean[n], unfinished = new boolean[n];
		java.util.Arrays.fill(active, true);
		// when each member was last fitted and last moved (by more than its tolerance, or its iterations ran out),
		// counted in fits: a member is fitted again only when a neighbour moved after its own latest fit (block
		// Gauss-Seidel: a move before it, it has seen)
		final long[] fittedAt = new long[n], movedAt = new long[n];
		final int[] solves = new int[n]; // each member's iterations over the sweeps: the solves behind its centre
		long clock = 0;
		final Estimate[] start = new Estimate[n];
		for (int q = 0; q < n; q++)
			start[q] = e[group[q]];
		// each member's window: where its kind's profile holds the information on its centre
		final java.util.Map<EmpiricalProfile, Double> information = new java.util.IdentityHashMap<>();
		final double[] memberWindow = new double[n];
		for (int q = 0; q < n; q++)
			memberWindow[q] = Math.min(window, information.computeIfAbsent(profile[group[q]], pk -> pk
				.informationRadius(INFORMATION)));
		// (the particles near a member looked up in a grid where the frame holds many; a scan of a few is cheaper)
		final Nearby nearby = e.length >= Nearby.WORTH ? new Nearby(e, profile, plane.width(), plane.height()) : null;
		final int[] memberOf = new int[e.length]; // each particle's place in the group (-1: not a member)
		java.util.Arrays.fill(memberOf, -1);
		for (int q = 0; q < n; q++)
			memberOf[group[q]] = q;
		final GroupFit.Kept[] kept = new GroupFit.Kept[n];
		for (int q = 0; q < n; q++) {
			kept[q] = new GroupFit.Kept();
			kept[q].nearby = nearby; // (null: every particle scanned)
		}
		final NormalEquations passes = new NormalEquations(censoring); // (its work arrays serve every member's fits)
		int most = 0;
		boolean any = true;
		long sweepStart = 0;
		for (int sweep = 1; sweep <= maxSweeps && any; sweep++) {
			most = 0;
			sweepStart = clock;
			for (int q = 0; q < n; q++) {
				if (!active[q]) continue;
				final int k = group[q];
				final Estimate before = e[k];
				// the first sweep chooses the member's pixels (as a joint fit does), the later ones keep them and its
				// window, with the neighbours' light at their latest estimates
				final GroupFit.Budget budget = new GroupFit.Budget(ITERATIONS_PER_SWEEP, sweep == 1 ? GroupFit.OWN_ERROR
					: settled(before), GroupFit.MAX_SELECTIONS, true);
				final int it = GroupFit.fitGroup(plane, particles, e, new int[] { k }, profile, memberWindow[q],
					censoring, budget, kept[q], passes);
				solves[q] += Math.abs(it);
				// a centre that slid away from its particle (onto a neighbour, or off into the background): no fit
				failed[q] = it == 0 || e[k].distanceTo(start[q]) > MAX_SLIDE * Math.sqrt(particles[k].region().area() /
					Math.PI);
				if (failed[q]) e[k] = start[q].withFlags(e[k].flags());
				if (nearby != null) nearby.moved(k, e[k]);
				// a member that failed is back at its start: it moved if that is not where its neighbours last saw it
				// (counted as unfinished, one sliding off every sweep would hold its group for all of them)
				unfinished[q] = it < 0 && !failed[q];
				fittedAt[q] = ++clock;
				if (unfinished[q] || e[k].distanceTo(before) > settled(e[k])) movedAt[q] = clock;
				most = Math.max(most, Math.abs(it));
			}
			// fitted again: a member whose iterations ran out, and one that a neighbour's move after its own fit reaches:
			// the pixels of a member's fit lie within its window, and a neighbour's move changes its light where the
			// profile's slope lies, within the neighbour's own window. Beyond that window the neighbour's move changes
			// its light by far less than the noise, so refitting there would cost fits without moving a centre.
			// (the neighbours looked up in the grid: every member within the widest of their windows)
			double widest = 0;
			for (int j = 0; nearby != null && j < n; j++)
				widest = Math.max(widest, memberWindow[j] * GroupFit.scaleOf(e[group[j]]));
			any = false;
			for (int q = 0; q < n; q++) {
				active[q] = unfinished[q];
				if (active[q]) {
					any = true;
					continue;
				}
				final Estimate eq = e[group[q]];
				final double own = memberWindow[q] * GroupFit.scaleOf(eq);
				final int[] near = nearby == null ? null : nearby.nearInAnyOrder(eq.x(), eq.x(), eq.y(), eq.y(), own +
					widest + 1);
				for (int i = 0, m = near == null ? n : near.length; i < m; i++) {
					final int j = near == null ? i : memberOf[near[i]];
					if (j < 0 || j == q || movedAt[j] <= fittedAt[q]) continue;
					final Estimate ej = e[group[j]];
					final double reach = own + memberWindow[j] * GroupFit.scaleOf(ej);
					if (ej.closerThan(eq, reach)) {
						active[q] = true;
						break;
					}
				}
				any |= active[q];
			}
		}
		Coupling.widen(e, group, profile, kept, memberWindow, nearby, memberOf);
		for (int q = 0; q < n; q++) {
			final int k = group[q];
			e[k] = e[k].withIterations(solves[q]);
			if (failed[q]) e[k] = e[k].withFlags(e[k].flags() | Flag.FELL_BACK.bit());
			// out of sweeps: one that would be fitted again, or that the last sweep's fit still moved
			else if (any && (active[q] || movedAt[q] > sweepStart)) e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED
				.bit());
		}
		return most;
	}

	/** @return the move below which this estimate's centre counts as settled ({@link GroupFit#settled}) */
	private static double settled(final Estimate e) {
		return GroupFit.settled(e.sigmaX(), e.sigmaY());
	}
}
