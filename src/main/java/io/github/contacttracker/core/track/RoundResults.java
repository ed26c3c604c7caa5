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
package io.github.contacttracker.core.track;

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.detect.ModelSelection;
import io.github.contacttracker.core.fit.GroupFit;
import io.github.contacttracker.core.fit.Rounds;
import io.github.contacttracker.core.profile.ProfileEstimator;

/**
 * What the rounds of profile and centres on a movie's sample frames say of each spot ({@link ProfileRounds}): how far
 * it moved from one round to the next, whether it still moves, whether it may teach the next profile, and the flags
 * that follow.
 */
final class RoundResults {

	private RoundResults() {}

	/**
	 * The particles kept out of the profile in the rounds that refit the same particles
	 * ({@link ProfileRounds#SETTLED_MEMBERS}): one whose fit did not settle in one of those rounds
	 * ({@link ProfileEstimator#usable}: a member that cannot find its place, such as one seeded between the particles
	 * of a packed patch), or that the fit would have removed as a bump of noise (its significance below
	 * {@link ModelSelection#SIGNIFICANCE}), stays out of the profiles of the later rounds (such bumps, kept in, lowered
	 * the profile's typical amplitude on dim compressed footage, and the last pass found half as many spots again).
	 * Which fits settle changes from round to round; each change takes a particle's pixels into the profile or out of
	 * it, and in a packed field moves every centre near it by more than its tolerance, so the rounds would never
	 * settle (two of four simulated dense monolayers: the median move stalled at 2 to 10 tolerances, every spot
	 * flagged; kept out, the rounds settle and only the spots still moving are flagged). A frame whose particles
	 * changed in number (one refitted off the frame) starts afresh.
	 */
	static final class Unsettled {
		private final List<boolean[]> out = new ArrayList<>();

		/** @return {@code round}, each spot kept out so far (this round's included) flagged {@code NOT_CONVERGED} */
		List<FrameResult> keptOut(final List<FrameResult> round) {
			final List<FrameResult> marked = new ArrayList<>(round.size());
			for (int i = 0; i < round.size(); i++) {
				final List<Localization> spots = round.get(i).spots();
				if (i == out.size()) out.add(null);
				if (out.get(i) == null || out.get(i).length != spots.size()) out.set(i, new boolean[spots.size()]);
				final boolean[] kept = out.get(i);
				final List<Localization> copy = new ArrayList<>(spots.size());
				for (int k = 0; k < spots.size(); k++) {
					final Localization l = spots.get(k);
					kept[k] |= !ProfileEstimator.usable(l) || l.quality() < ModelSelection.SIGNIFICANCE;
					copy.add(kept[k] ? l.withFlags(l.flags() | Flag.NOT_CONVERGED.bit()) : l);
				}
				marked.add(round.get(i).withSpots(copy));
			}
			return marked;
		}
	}

	/** @return the results' spots that may teach a profile ({@link ProfileEstimator#usable}) */
	static int usable(final List<FrameResult> results) {
		int usable = 0;
		for (final FrameResult r : results)
			for (final Localization l : r.spots())
				if (ProfileEstimator.usable(l)) usable++;
		return usable;
	}

	/** @return the share of the results' spots that may teach a profile ({@link #usable}; 0 for none) */
	static double usableShare(final List<FrameResult> results) {
		int all = 0;
		for (final FrameResult r : results)
			all += r.spots().size();
		return all == 0 ? 0 : usable(results) / (double) all;
	}

	/** @return per frame of {@code round}, the spots {@code rounds} saw still moving */
	static List<List<Localization>> stillMoving(final List<FrameResult> round, final Rounds rounds) {
		final List<List<Localization>> out = new ArrayList<>(round.size());
		int i = 0;
		for (final FrameResult r : round) {
			final List<Localization> moving = new ArrayList<>();
			for (final Localization l : r.spots())
				if (rounds.stillMoving(i++)) moving.add(l);
			out.add(moving);
		}
		return out;
	}

	/**
	 * @return {@code found}, each spot within {@code near} px of one of the frame's {@code moving} spots flagged
	 *         {@code NOT_CONVERGED} where the frame holds as many spots as the rounds' ({@code rounds}): a frame found
	 *         otherwise holds other particles than those whose moves the rounds saw (a member the first rounds added
	 *         between the two of a pair, which the final profile does without), and its own fit judges it
	 */
	static List<FrameResult> carried(final List<FrameResult> rounds, final List<List<Localization>> moving,
		final List<FrameResult> found, final double near)
	{
		final List<FrameResult> out = new ArrayList<>(found.size());
		for (int i = 0; i < found.size(); i++) {
			if (found.get(i).spots().size() != rounds.get(i).spots().size()) {
				out.add(found.get(i));
				continue;
			}
			final List<Localization> spots = new ArrayList<>(found.get(i).spots().size());
			for (final Localization l : found.get(i).spots()) {
				boolean flag = false;
				for (final Localization m : moving.get(i))
					flag |= Math.hypot(m.x() - l.x(), m.y() - l.y()) < near;
				spots.add(flag ? l.withFlags(l.flags() | Flag.NOT_CONVERGED.bit()) : l);
			}
			out.add(found.get(i).withSpots(spots));
		}
		return out;
	}

	/** @return the results, the spots {@code rounds} saw still moving flagged {@code NOT_CONVERGED} */
	static List<FrameResult> stillMovingFlagged(final List<FrameResult> results, final Rounds rounds) {
		final List<FrameResult> out = new ArrayList<>(results.size());
		int i = 0;
		for (final FrameResult r : results) {
			final List<Localization> spots = new ArrayList<>(r.spots().size());
			for (final Localization l : r.spots())
				spots.add(rounds.stillMoving(i++) ? l.withFlags(l.flags() | Flag.NOT_CONVERGED.bit()) : l);
			out.add(r.withSpots(spots));
		}
		return out;
	}

	/** @return the results, every spot flagged {@code NOT_CONVERGED} unless the profile rounds {@code settled} */
	static List<FrameResult> flagged(final List<FrameResult> results, final boolean settled) {
		if (settled) return results;
		final List<FrameResult> out = new ArrayList<>(results.size());
		for (final FrameResult r : results) {
			final List<Localization> spots = new ArrayList<>(r.spots().size());
			for (final Localization l : r.spots())
				spots.add(l.withFlags(l.flags() | Flag.NOT_CONVERGED.bit()));
			out.add(r.withSpots(spots));
		}
		return out;
	}

	/**
	 * The moves of the spots between two results of the same frames, in frame order, each in units of its
	 * {@link GroupFit#settled tolerance}; NaN for a spot whose centre is not the fit's own. A spot's partner before is
	 * the one at its place in the list where the frame's spots are the same in number and that one lies within its
	 * particle's size; otherwise (a detection by the image added or removed particles as the profile changed, as many
	 * as it added or not) the nearest spot before, and a spot with none within its particle's size (a particle
	 * added) has NaN: the others' moves say whether the frame settled.
	 */
	static double[] moves(final List<FrameResult> before, final List<FrameResult> after) {
		int n = 0;
		for (final FrameResult r : after)
			n += r.spots().size();
		final double[] moves = new double[n];
		int i = 0;
		for (int t = 0; t < before.size(); t++) {
			final List<Localization> a = before.get(t).spots(), b = after.get(t).spots();
			final boolean same = a.size() == b.size();
			for (int k = 0; k < b.size(); k++, i++) {
				final Localization now = b.get(k), then = same && near(a.get(k), now) ? a.get(k) : nearest(a, now);
				moves[i] = fitted(now) && then != null ? Math.hypot(then.x() - now.x(), then.y() - now.y()) / GroupFit
					.settled(now.settlingSigmaX(), now.settlingSigmaY()) : Double.NaN;
			}
		}
		return moves;
	}

	/** @return whether {@code then} lies within {@code now}'s radius (at least a pixel) of it */
	static boolean near(final Localization then, final Localization now) {
		return Math.hypot(then.x() - now.x(), then.y() - now.y()) < Math.max(1, now.radius());
	}

	/** @return the spot of {@code spots} nearest to {@code l} within {@code l}'s radius, or null */
	static Localization nearest(final List<Localization> spots, final Localization l) {
		Localization best = null;
		double d = Math.max(1, l.radius());
		for (final Localization s : spots) {
			final double e = Math.hypot(s.x() - l.x(), s.y() - l.y());
			if (e < d) {
				d = e;
				best = s;
			}
		}
		return best;
	}

	/**
	 * Whether a spot's centre is the fit's own: not one kept from the first pass because the fit could not be made
	 * ({@code FELL_BACK}), nor a particle left out of the model; only those take part in the profile's fixed point
	 * (the spot in the newer result: the older may be the iterative pass's).
	 */
	static boolean fitted(final Localization l) {
		return !l.has(Flag.FELL_BACK) && !l.has(Flag.MERGED) && !l.has(Flag.DEGENERATE);
	}
}
