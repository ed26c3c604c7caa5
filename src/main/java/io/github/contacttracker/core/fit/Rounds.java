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

import io.github.contacttracker.core.math.Statistics;

/**
 * When the rounds of profile and centres (see {@link ProfileRefinement}) may stop, judged from each round's moves of
 * the fitted centres, in units of their {@link GroupFit#settled tolerance}.
 * <ul>
 * <li>{@link Verdict#SETTLED}: no centre moved more than its tolerance: the fixed point of profile and centres.
 * <li>{@link Verdict#CYCLING}: the centres as a whole have settled (the median move is below half the tolerance: the
 * profile, which moves them all together, has stopped moving), and the largest move has not shrunk over two rounds
 * (by a tenth: {@link #STILL}).
 * What still moves then are single centres going back and forth between two fits (a centre whose model fits two
 * nearby minima about equally, such as a particle with a neighbour's light on one side, can jump many standard
 * errors every other round while the median move stays at a small fraction of one), which more rounds do not mend.
 * The rounds stop, and only the centres that moved by half their standard error or more in the last round are
 * flagged ({@link #stillMoving}). A geometric approach to the fixed point (every simulation) never
 * stalls over two rounds, so it always ends {@code SETTLED}.
 * <li>{@link Verdict#STALLED}: the centres as a whole are far from settled (the median move above
 * {@value #STALL_MEDIAN} tolerances, a whole standard error) and it has not come below half its value of
 * {@value #STALL_ROUNDS} or more rounds before (the last round that halved it, or the first). An approach to the fixed
 * point shrinks the median move several times each round; one that stays at a standard error and more round after round is no approach (a profile that
 * cannot describe the particles, such as a field too dense or too blurred for the model, moves the centres anew
 * every round), and the rounds, each a refit of every sample frame, would run to their limit for nothing. The
 * rounds stop as at their limit: no fixed point, every centre flagged.
 * <li>{@link Verdict#GOING_ON}: none of these.
 * </ul>
 * Rounds that reach their limit still going on end as {@link #atLimit} says: cycling where the centres as a whole
 * have settled, else with no fixed point.
 */
public final class Rounds {

	/** What a round's moves say. */
	public enum Verdict {
		/** more rounds needed */
		GOING_ON,
		/** every centre settled */
		SETTLED,
		/** the centres as a whole settled, a few still go back and forth: stop, flag those */
		CYCLING,
		/** the centres as a whole far from settled, and not approaching it: stop, flag all */
		STALLED
	}

	/** The median move (in tolerances) below which the centres as a whole count as settled. */
	static final double BULK = 0.5;

	/**
	 * The largest move has not shrunk over two rounds when it is at least this share of the one two rounds before: a
	 * centre that goes back and forth between two fits, refitted from the same start each round, repeats its moves
	 * to the last digits, and those can shrink by a few parts in a thousand each time without ever settling (a
	 * simulated pair at 0.8 diameters: 1.5999, 1.5976, 1.5999, 1.5975 tolerances, round after round, to the limit).
	 */
	static final double STILL = 0.9;

	/** The median move (in tolerances) above which rounds that do not shrink it count as stalled. */
	static final double STALL_MEDIAN = 10;

	/** How many rounds in a row may leave the median move above half its last anchor before they count as stalled. */
	static final int STALL_ROUNDS = 3;

	private double maxPrevious = Double.POSITIVE_INFINITY, maxBefore = Double.POSITIVE_INFINITY;
	/** the median move of the latest round that halved the one before (the first round's), and the rounds since */
	private double anchorMedian = Double.POSITIVE_INFINITY;
	private int sinceShrunk;
	/** the latest round's median move (infinite before a round had one) */
	private double lastMedian = Double.POSITIVE_INFINITY;
	private double[] last = new double[0];

	/**
	 * Takes the moves of a round.
	 *
	 * @param moves each fitted centre's move since the previous round, in units of its tolerance (centres not fitted:
	 *        NaN); kept, for {@link #stillMoving}
	 * @return the verdict
	 */
	public Verdict next(final double[] moves) {
		last = moves.clone();
		double max = 0;
		for (final double m : moves)
			if (m > max) max = m; // NaN: not fitted
		final double twoBack = maxBefore;
		maxBefore = maxPrevious;
		maxPrevious = max;
		if (max <= 1) return Verdict.SETTLED;
		final double median = Statistics.median(moves.clone());
		lastMedian = median;
		if (median < anchorMedian / 2) {
			anchorMedian = median;
			sinceShrunk = 0;
		}
		else sinceShrunk++;
		if (max >= STILL * twoBack && median <= BULK) return Verdict.CYCLING;
		return median > STALL_MEDIAN && sinceShrunk >= STALL_ROUNDS ? Verdict.STALLED : Verdict.GOING_ON;
	}

	/**
	 * The median move (in tolerances: a tenth of the centres' standard errors) at or below which rounds that reach their
	 * limit count as {@link Verdict#CYCLING}.
	 */
	static final double LIMIT_BULK = 1;

	/**
	 * The verdict of rounds that reached their limit still {@link Verdict#GOING_ON}. Where the latest median move is
	 * at most {@value #LIMIT_BULK} tolerance, the centres as a whole, and so the profile that moves them together, are
	 * at their fixed point to a tenth of their errors, and what still moves are single centres, as when the rounds
	 * cycle: {@link Verdict#CYCLING}, those centres flagged ({@link #stillMoving}). A field whose particles the one
	 * profile describes only roughly (a confocal stack of polydisperse spheres: the median move down from 14 to 0.5-0.9
	 * tolerances over the rounds, a tenth of the centres jumping 2 standard errors every round, the largest move never
	 * shrinking for two rounds at a median below half a tolerance) otherwise ends with every spot flagged, those that
	 * no longer move with them. Else {@link Verdict#GOING_ON}: no fixed point.
	 */
	public Verdict atLimit() {
		return lastMedian <= LIMIT_BULK ? Verdict.CYCLING : Verdict.GOING_ON;
	}

	/**
	 * A centre that still moves when the rounds stop on {@link Verdict#CYCLING} is flagged where its latest move is at
	 * least this many tolerances: half its standard error (or 0.005 px, the larger). A centre going back and forth
	 * between two fits jumps that far and more; one that a profile measured on faint particles, noisy itself, moves by
	 * a fraction of that each round rests as well on the data as its error says, and a flag would discard it for
	 * nothing (a field of dim spots at a signal to noise of 3 to 5: one spot in ten).
	 */
	static final double FLAGGED = 5;

	/** @return whether centre {@code i} moved by {@link #FLAGGED} tolerances or more in the latest round */
	public boolean stillMoving(final int i) {
		return last[i] >= FLAGGED;
	}
}
