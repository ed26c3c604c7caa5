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

import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;

class CramerRaoTest {

	/**
	 * Two particles far apart: the distance bound is sqrt(2) times one centre's bound, which for a symmetric
	 * particle is 1 / sqrt(sum (dI/dx)^2 / s^2) (amplitude and background decouple from x by symmetry).
	 */
	@Test
	void farApartPairEqualsTwoIndependentCentres() {
		final ParticleType type = PaperParticles.silica553();
		final int w = 420, h = 160;
		final double[] a = { 80.3, 80.1 }, b = { 340.6, 79.8 };
		final double bound = CramerRao.distanceBound(type, List.of(a, b), new int[] { 0, 1 }, w, h);
		final ImageSimulator sim = new ImageSimulator(type.profile());
		final NoiseFreeImage plus = NoiseFreeImage.uniform(w, h, 0), minus = NoiseFreeImage.uniform(w, h, 0);
		sim.addParticle(plus, a[0] + 1e-3, a[1]);
		sim.addParticle(minus, a[0] - 1e-3, a[1]);
		double info = 0;
		for (int i = 0; i < w * h; i++) {
			final double d = (plus.pixels()[i] - minus.pixels()[i]) / 2e-3;
			info += d * d;
		}
		final double s2 = type.noise().sigma() * type.noise().sigma() + 1.0 / 12;
		final double single = 1 / Math.sqrt(info / s2);
		assertEquals(Math.sqrt(2) * single, bound, 0.01 * bound);
	}
}
