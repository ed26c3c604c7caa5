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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;

class MisfitTest {

	/** A spot of significance {@code q} whose centre error is {@code times} what a described particle's would be. */
	private static Localization spot(final double q, final double times, final int flags) {
		final double sigma = times * 0.3 / Math.sqrt(q);
		return new Localization(0, 10, 10, 10, 10, 80, 80, q, 5, flags, 3, sigma, 0.9 * sigma, 1, 1, 1);
	}

	@Test
	void aSpotWhoseErrorItsSignificanceDoesNotExplainIsFlaggedMerged() {
		final List<Localization> spots = new ArrayList<>();
		for (int k = 0; k < 20; k++)
			spots.add(spot(50 + 40 * k, 0.8 + 0.02 * k, 0)); // dim to bright, all described
		spots.add(spot(400, 6, 0)); // two particles fitted as one
		spots.add(spot(400, 4, 0)); // a poor fit, within the mark
		spots.add(spot(400, 30, Flag.AT_BORDER.bit())); // flagged already: not in the typical product
		final List<FrameResult> sample = List.of(new FrameResult(spots, List.of(), List.of(), 1, 0, false));
		final Misfit m = Misfit.of(sample);
		assertEquals(0.3 * 1.0, m.typical(), 0.03, "the median of the unflagged spots' products");
		final List<Localization> out = m.flagged(sample).get(0).spots();
		for (int k = 0; k < 20; k++)
			assertFalse(out.get(k).has(Flag.MERGED), "spot " + k);
		assertTrue(out.get(20).has(Flag.MERGED));
		assertFalse(out.get(21).has(Flag.MERGED));
		assertTrue(out.get(22).has(Flag.MERGED) && out.get(22).has(Flag.AT_BORDER));
	}

	@Test
	void tooFewSpotsTestNone() {
		final List<Localization> few = new ArrayList<>();
		for (int k = 0; k < Misfit.MIN_SPOTS - 1; k++)
			few.add(spot(100, 1, 0));
		final Misfit m = Misfit.of(List.of(new FrameResult(few, List.of(), List.of(), 1, 0, false)));
		assertTrue(Double.isNaN(m.typical()));
		final List<FrameResult> odd = List.of(new FrameResult(List.of(spot(100, 50, 0)), List.of(), List.of(), 1, 0,
			false));
		assertFalse(m.flagged(odd).get(0).spots().get(0).has(Flag.MERGED), "no typical product: nothing flagged");
	}
}
