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
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class RadialProfileTest {

	@Test
	void gaussianReachIsTheAnalyticCrossing() {
		final double amplitude = 80;
		final double sigma = 4.5;
		final double level = 0.5;
		final double expected = sigma * Math.sqrt(2 * Math.log(amplitude / level));
		final RadialProfile lambda = r -> amplitude * Math.exp(-r * r / (2 * sigma * sigma));
		assertEquals(expected, lambda.reach(level), 1e-8);
		assertEquals(expected, GaussianBesselProfile.gaussian(amplitude, sigma).reach(level), 1e-8);
	}

	@Test
	void reachFindsTheOutermostCrossingOfASignChangingProfile() {
		// 10 - 4r down to -10 at r = 5, then back up to 0 at r = 10: |value| < 2 around r = 2.5 but for good
		// only beyond r = 9, where the dark ring has faded to -2
		final RadialProfile ring = r -> r <= 5 ? 10 - 4 * r : r <= 10 ? -10 + 2 * (r - 5) : 0;
		assertEquals(9, ring.reach(2), 1e-8);
		assertEquals(9.75, ring.reach(0.5), 1e-8);
	}

	@Test
	void gaussianBesselReachAgreesWithTheFullScan() {
		for (final GaussianBesselProfile p : new GaussianBesselProfile[] { new GaussianBesselProfile(120, 0.1, 18),
			new GaussianBesselProfile(100, 0.16, 40), new GaussianBesselProfile(-50, 0.3, 10) })
			for (final double level : new double[] { 0.5, 1e-3, 7 })
				assertEquals(RadialProfile.reachWithin(p, level, RadialProfile.REACH_SCAN_LIMIT), p.reach(level), 1e-9,
					p + " level " + level);
	}

	@Test
	void gaussianBesselValue() {
		final GaussianBesselProfile p = new GaussianBesselProfile(120, 0.1, 18);
		assertEquals(120, p.value(0), 1e-5);
		assertEquals(120 * 0.7651976865579666 * Math.exp(-100.0 / 648), p.value(10), 2e-5);
		assertEquals(0, p.value(24.04825557695773), 1e-5);
	}

	@Test
	void reachRejectsBadLevelsAndNonDecayingProfiles() {
		final RadialProfile flat = r -> 1;
		assertThrows(IllegalArgumentException.class, () -> flat.reach(0.5));
		assertThrows(IllegalArgumentException.class, () -> flat.reach(0));
		assertEquals(0, flat.reach(2), 0);
	}
}
