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
package io.github.contacttracker.lab.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.lab.sim.FluidMovie;
import io.github.contacttracker.lab.sim.PaperParticles;

/**
 * U(r) end to end, images to U(r), on small simulated movies of a fluid with a known potential (hard core + 2 kT
 * attraction): the default method finds no pair inside the hard core and U within its error bars of the truth;
 * the first pass of the long-range 2.06 um-like particles puts touching pairs inside the hard core (the spurious
 * attraction at contact).
 */
class PotentialStudyTest {

	@Test
	void defaultMethodRecoversThePotentialFromImages() {
		// the demo's fluid in a smaller frame (384 x 384 px, 6 particles, 30 frames), bins of 0.05 D, to stay fast
		final PotentialStudy demo = PotentialStudy.demo(PaperParticles.silica553(), 30);
		final PotentialStudy study = new PotentialStudy(demo.type(), demo.interaction(), 6, 384, 30, demo
			.sweepsBetween(), demo.seed(), 0.05, 2.5, 2);
		final FluidMovie movie = study.simulate();
		assertEquals(0, movie.clippedPixels());
		final List<Localization> spots = study.track(movie, Method.DEFAULT, 0);
		final PairCorrelation.Result fit = study.measure(spots), truth = study.measureTruthOf(movie, spots);
		final PotentialStudy.Comparison c = study.compare(fit, 1, 2);
		assertEquals(0, c.pairsInsideCore());
		assertEquals(20, c.bins());
		assertTrue(c.chi2PerBin() < 2 && c.maxAbsZ() < 4, c.toString());
		// the same configurations (the true centres of the particles kept, spots cut by the border left out as the analysis
		// does): the tracked U follows the one from the true centres far within the error bars
		for (int i = 0; i < fit.bins().size(); i++) {
			final PairCorrelation.Bin b = fit.bins().get(i);
			if (b.rLow() < 1 || b.r() > 2 || b.pairs() < 10) continue;
			assertEquals(truth.u(i), fit.u(i), 0.5 * b.uError(), "r/D = " + b.r());
		}
	}

	@Test
	void firstPassPutsTouchingPairsInsideTheHardCore() {
		final PotentialStudy study = PotentialStudy.demo(PaperParticles.silica206(), 30);
		final FluidMovie movie = study.simulate();
		final PotentialStudy.Comparison truth = study.compare(study.measureTruth(movie), 1, 2);
		final PotentialStudy.Comparison first = study.compare(study.measure(study.track(movie, Method.FIRST, 0)), 1, 2);
		assertEquals(0, truth.pairsInsideCore());
		assertTrue(first.pairsInsideCore() >= 10, first.toString());
	}
}
