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
package io.github.contacttracker.lab.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PaperParticlesTest {

	@Test
	void silica553IsShortRange() {
		final ParticleType t = PaperParticles.silica553();
		assertEquals(65.29, t.diameterPx(), 0.005);
		assertEquals(Math.ceil(t.profile().reach(0.5) + 2), t.rOut(), 0);
		assertTrue(t.rOut() <= t.diameterPx(), "rOut " + t.rOut() + " <= D " + t.diameterPx());
		assertEquals(60, t.background(), 0);
		assertEquals(85, t.threshold(), 0);
		// At contact the bridge between two particles stays below threshold (no merged active areas).
		assertTrue(t.background() + 2 * t.profile().value(t.diameterPx() / 2) + 5 < t.threshold());
		assertEquals(NoiseModel.uniform(5), t.noise());
		assertEquals(180, t.background() + t.profile().value(0), 1e-5);
	}

	@Test
	void silica206IsLongRange() {
		final ParticleType t = PaperParticles.silica206();
		assertEquals(55.68, t.diameterPx(), 0.005);
		assertEquals(Math.ceil(t.profile().reach(0.5) + 2), t.rOut(), 0);
		assertTrue(t.rOut() > t.diameterPx(), "rOut " + t.rOut() + " > D " + t.diameterPx());
		assertEquals(140, t.threshold(), 0);
		// Three overlapping rings stay below threshold: no spurious component between particles.
		double ring = 0;
		for (double r = t.diameterPx() / 2; r < t.rOut(); r += 0.1)
			ring = Math.max(ring, t.profile().value(r));
		assertTrue(t.background() + 3 * ring + 5 < t.threshold(), "ring " + ring);
		assertEquals(NoiseModel.uniform(5), t.noise());
	}

	@Test
	void presetsStayWithin8Bit() {
		for (final ParticleType t : new ParticleType[] { PaperParticles.silica553(), PaperParticles.silica206() }) {
			double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
			for (double r = 0; r < t.rOut(); r += 0.05) {
				min = Math.min(min, t.profile().value(r));
				max = Math.max(max, t.profile().value(r));
			}
			final double amplitude = ((NoiseModel.Uniform) t.noise()).amplitude();
			assertTrue(t.background() + min - amplitude >= 0 && t.background() + max + amplitude <= 255, t.name()
				+ ": " + min + ".." + max);
		}
	}
}
