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
package io.github.contacttracker.potential;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.lab.sim.HardCoreAttraction;
import io.github.contacttracker.lab.sim.MonteCarloFluid;

/**
 * The estimator on Monte Carlo positions of a dilute fluid with a known potential (no images): the measured U(r)
 * agrees with the true U(r) within its error bars, and no pair is found inside the hard core.
 */
class PotentialFromMonteCarloTest {

	@Test
	void recoversAHardCoreWithAttractionWithinTheErrorBars() {
		final HardCoreAttraction truth = new HardCoreAttraction(10, 2, 1); // D = 10, 2 kT well decaying over 0.1 D
		// 60 particles in 400 x 400: area fraction 0.03, dilute enough that -ln g(r) (the potential of mean force)
		// equals U(r) within the error bars; at 0.06 and 0.12 the neighbours' structure shows (measured: chi2 per
		// bin 1.5 and 6)
		final List<List<double[]>> configs = new MonteCarloFluid(truth, 60, 400, 400).sample(2000, 8, 21);
		final PairCorrelation.Result r = PairCorrelation.compute(SpotSet.ofPositions(configs, 1), FieldOfView.of(400,
			400), 0.5, 40).withZero(25, 40);
		double chi2 = 0;
		int n = 0;
		for (int i = 0; i < r.bins().size(); i++) {
			final PairCorrelation.Bin b = r.bins().get(i);
			if (b.rHigh() <= 10) {
				assertEquals(0, b.pairs(), "pairs inside the hard core at r = " + b.r());
				continue;
			}
			if (b.rLow() < 10 || b.r() > 20) continue;
			assertTrue(b.pairs() > 40, "too few pairs for the test at r = " + b.r() + ": " + b.pairs());
			final double z = (r.u(i) - truth.energyKt(b.r())) / b.uError();
			assertTrue(Math.abs(z) < 4, String.format("r = %.3f: U = %.3f +- %.3f, true %.3f", b.r(), r.u(i), b.uError(),
				truth.energyKt(b.r())));
			chi2 += z * z;
			n++;
		}
		assertEquals(20, n);
		assertTrue(chi2 / n < 2, "chi2 per bin " + chi2 / n);
		// at contact the well is resolved: U within 0.15 kT of the truth at the bin centre (-1.56 kT)
		assertEquals(truth.energyKt(r.bins().get(20).r()), r.u(20), 0.15);
	}
}
