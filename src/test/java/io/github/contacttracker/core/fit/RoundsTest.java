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

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.fit.Rounds.Verdict;

/** The verdicts of the rounds of profile and centres, on sequences of moves shaped as real footage gives them. */
class RoundsTest {

	/** @return 101 moves (in tolerances) whose median is {@code median} and whose largest is {@code max} */
	private static double[] round(final double median, final double max) {
		final double[] m = new double[101];
		for (int i = 0; i < 50; i++) {
			m[i] = median / 2;
			m[51 + i] = max;
		}
		m[50] = median;
		return m;
	}

	private static Verdict[] verdicts(final double[]... rounds) {
		final Rounds r = new Rounds();
		final Verdict[] out = new Verdict[rounds.length];
		for (int i = 0; i < rounds.length; i++)
			out[i] = r.next(rounds[i]);
		return out;
	}

	/** A geometric approach to the fixed point (a tenfold shrink a round, as on a bright-field movie) settles. */
	@Test
	void aGeometricApproachSettles() {
		final Verdict[] v = verdicts(round(46, 320), round(3, 18), round(0.3, 1.2), round(0.03, 0.4));
		assertEquals(Verdict.GOING_ON, v[0]);
		assertEquals(Verdict.GOING_ON, v[1]);
		assertEquals(Verdict.GOING_ON, v[2]);
		assertEquals(Verdict.SETTLED, v[3]);
	}

	/** Medians of many standard errors that do not shrink (a dense field the model cannot describe): stalled. */
	@Test
	void roundsFarFromSettledThatDoNotShrinkStall() {
		final Verdict[] v = verdicts(round(68, 3300), round(113, 2000), round(78, 740), round(34, 1800), round(50,
			1400));
		assertEquals(Verdict.GOING_ON, v[0]);
		assertEquals(Verdict.GOING_ON, v[1]);
		assertEquals(Verdict.GOING_ON, v[2]);
		assertEquals(Verdict.STALLED, v[3], "three rounds without halving the median of 68 tolerances");
	}

	/** A plateau near the tolerance (the bulk settled, a few centres wandering) never counts as stalled. */
	@Test
	void aPlateauNearTheToleranceGoesOnUntilItCycles() {
		final Verdict[] v = verdicts(round(29, 3800), round(1.4, 2000), round(1.1, 390), round(0.7, 1560), round(0.8,
			560), round(1.0, 830), round(0.8, 360), round(1.6, 720), round(0.3, 1560));
		for (int i = 0; i < v.length - 1; i++)
			assertEquals(Verdict.GOING_ON, v[i], "round " + (i + 1));
		assertEquals(Verdict.CYCLING, v[v.length - 1]);
	}

	/** Slow rounds that still halve the median every few rounds are an approach, not a stall. */
	@Test
	void aSlowButShrinkingApproachGoesOn() {
		final Verdict[] v = verdicts(round(80, 500), round(70, 500), round(60, 500), round(39, 500), round(35, 500),
			round(30, 500), round(19, 500));
		for (int i = 0; i < v.length; i++)
			assertEquals(Verdict.GOING_ON, v[i], "round " + (i + 1));
	}
	/**
	 * When the rounds cycle, the centres that jump half a standard error or more (5 tolerances) are flagged; those a
	 * noisy profile moves by a fraction of that (faint particles: 1 to 4 tolerances, round after round) are not.
	 */
	@Test
	void cyclingFlagsTheCentresThatJumpHalfAnError() {
		final double[] faint = round(0.3, 3), jumping = round(0.3, 3);
		jumping[100] = 16;
		for (final double[][] rounds : new double[][][] { { round(0.3, 3), round(0.3, 3), faint }, { round(0.3, 16),
			round(0.3, 3), jumping } })
		{
			final Rounds r = new Rounds();
			Verdict v = null;
			for (final double[] m : rounds)
				v = r.next(m);
			assertEquals(Verdict.CYCLING, v);
			int flagged = 0;
			for (int i = 0; i < 101; i++)
				if (r.stillMoving(i)) flagged++;
			assertEquals(rounds[2] == jumping ? 1 : 0, flagged, "centres moving 3 tolerances" + (rounds[2] == jumping
				? ", one 16" : ""));
		}
	}

	/**
	 * Rounds that reach their limit with the centres as a whole settled (a median move of a tolerance or less: a
	 * confocal stack of polydisperse spheres, a tenth of its centres jumping two standard errors every round) end as
	 * cycling, the centres still jumping flagged; with the median above a tolerance, with no fixed point.
	 */
	@Test
	void atTheLimitTheBulkDecides() {
		for (final double last : new double[] { 0.7, 1.4 }) {
			final Rounds r = new Rounds();
			for (final double[] m : new double[][] { round(14, 180), round(4.7, 170), round(1.9, 200), round(1.2, 280),
				round(0.9, 190), round(last, 230) })
				assertEquals(Verdict.GOING_ON, r.next(m));
			assertEquals(last <= 1 ? Verdict.CYCLING : Verdict.GOING_ON, r.atLimit(), "median " + last);
			int flagged = 0;
			for (int i = 0; i < 101; i++)
				if (r.stillMoving(i)) flagged++;
			assertEquals(50, flagged, "the 50 centres that moved 230 tolerances");
		}
	}
}
