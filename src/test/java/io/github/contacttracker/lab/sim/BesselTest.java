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

import org.junit.jupiter.api.Test;

class BesselTest {

	@Test
	void matchesTabulatedValues() {
		assertEquals(1.0, Bessel.j0(0), 1e-7);
		assertEquals(0.7651976865579666, Bessel.j0(1), 1e-7);
		assertEquals(0.0, Bessel.j0(2.404825557695773), 1e-7);
		assertEquals(-0.1775967713143383, Bessel.j0(5), 1e-7);
		assertEquals(-0.2459357644513483, Bessel.j0(10), 1e-7);
		assertEquals(0.1670246643405831, Bessel.j0(20), 1e-7);
	}

	@Test
	void isEven() {
		assertEquals(Bessel.j0(3.7), Bessel.j0(-3.7), 0);
		assertEquals(Bessel.j0(1.2), Bessel.j0(-1.2), 0);
	}

	/** Against Bessel's integral (1/pi) int_0^pi cos(x sin t) dt, whose trapezoid rule converges geometrically. */
	@Test
	void matchesIntegralRepresentationFrom0To40() {
		double worst = 0;
		for (double x = 0; x <= 40; x += 0.0137) {
			final int n = 400;
			double sum = 0.5 * (1 + Math.cos(x * Math.sin(Math.PI)));
			for (int i = 1; i < n; i++)
				sum += Math.cos(x * Math.sin(Math.PI * i / n));
			final double reference = sum / n;
			worst = Math.max(worst, Math.abs(Bessel.j0(x) - reference));
		}
		assertEquals(0, worst, 1e-7);
	}
}
