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
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;

/**
 * Accuracy of the methods beyond the paper at contact, on short noisy stacks, against the truth and the
 * Cramer-Rao bound. (The full protocol with 200 images per separation is {@code contact-tracker accuracy}.)
 */
class MethodAccuracyTest {

	private static DistanceError run(final ParticleType type, final Scenario scenario, final Method m,
		final int frames)
	{
		final DistanceStudy study = new DistanceStudy(type, scenario, 2);
		final SimulatedStack<?> stack = study.simulate(1.0, frames, 99);
		return study.measure(stack, study.track(stack, m), m);
	}

	@Test
	void fitReachesTheBoundWithoutBiasAtContact() {
		final ParticleType type = PaperParticles.silica553();
		final DistanceStudy study = new DistanceStudy(type, Scenario.PAIR, 2);
		final SimulatedStack<?> stack = study.simulate(1.0, 60, 99);
		final double crb = CramerRao.distanceBound(type, stack.truth().get(0), Scenario.PAIR.measuredPair(), stack
			.width(), stack.height()) * type.pixelSizeNm();
		final DistanceError fit = study.measure(stack, study.track(stack, Method.FIT), Method.FIT);
		assertEquals(0, fit.failures());
		// Standard error of a mean of 60 is ~0.2 nm: 1 nm is a 5-sigma margin.
		assertTrue(Math.abs(fit.meanErrorNm()) <= 1.0, "fit bias " + fit.meanErrorNm() + " nm");
		assertTrue(fit.stdNm() <= 1.5 * crb, "fit spread " + fit.stdNm() + " nm vs bound " + crb + " nm");
		// The reported per-spot errors agree with the observed spread.
		final double ratio = fit.meanSigmaNm() / fit.stdNm();
		assertTrue(ratio > 1 / 1.5 && ratio < 1.5, "reported/observed " + ratio);
	}

	@Test
	void everyMethodKeepsEveryParticleAndReportsHonestErrors() {
		for (final Method m : Method.values()) {
			final DistanceError e = run(PaperParticles.silica553(), Scenario.TRIPLE, m, 40);
			assertEquals(0, e.failures(), m + " lost a particle");
			final double ratio = e.meanSigmaNm() / e.stdNm();
			assertTrue(ratio > 1 / 1.5 && ratio < 1.5, m + ": reported/observed " + ratio);
		}
	}

	@Test
	void deblendRemovesTheContactBias() {
		final DistanceError first = run(PaperParticles.silica553(), Scenario.PAIR, Method.FIRST, 40);
		final DistanceError deblend = run(PaperParticles.silica553(), Scenario.PAIR, Method.DEBLEND, 40);
		assertTrue(first.meanErrorNm() < -5, "first-pass bias " + first.meanErrorNm());
		assertTrue(Math.abs(deblend.meanErrorNm()) < 2, "deblend bias " + deblend.meanErrorNm());
	}

	@Test
	void longRangeProfileAtContactGetsAResult() {
		// The paper's method has no undistorted area left here and falls back; the fit still measures.
		final ParticleType type = PaperParticles.silica206();
		final DistanceError paper = run(type, Scenario.PAIR, Method.PAPER, 12);
		assertEquals(12, paper.fallbacks());
		final DistanceError fit = run(type, Scenario.PAIR, Method.FIT, 12);
		assertEquals(0, fit.failures());
		assertEquals(0, fit.fallbacks());
		assertTrue(Math.abs(fit.meanErrorNm()) <= 5, "fit bias " + fit.meanErrorNm() + " nm");
	}

	@Test
	void iterativeSettlesAndReportsItsPasses() {
		final DistanceStudy study = new DistanceStudy(PaperParticles.silica553(), Scenario.PAIR, 1);
		final SimulatedStack<?> stack = study.simulate(1.0, 5, 3);
		final List<FrameResult> r = study.track(stack, Method.ITERATIVE);
		for (final FrameResult f : r)
			for (final Localization s : f.spots()) {
				assertTrue(s.iterations() >= 3, "passes " + s.iterations());
				assertTrue(s.iterations() < 100);
				assertTrue(!s.isFlagged(), s.flagSet().toString());
			}
	}
}
