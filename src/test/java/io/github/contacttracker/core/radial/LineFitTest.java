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
package io.github.contacttracker.core.radial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

class LineFitTest {

	@Test
	void recoversPointFromLinesThroughIt() {
		final double cx = 37.123456, cy = -12.654321;
		final Random rnd = new Random(3);
		final LineFit fit = new LineFit(30, -10);
		for (int i = 0; i < 50; i++) {
			final double angle = rnd.nextDouble() * 2 * Math.PI, dist = 1 + 20 * rnd.nextDouble();
			final double px = cx + dist * Math.cos(angle), py = cy + dist * Math.sin(angle);
			// Gradient along the line towards the centre (either sign), any magnitude.
			final double mag = 0.1 + 100 * rnd.nextDouble() * (rnd.nextBoolean() ? 1 : -1);
			fit.addPaperWeighted(px, py, mag * (cx - px), mag * (cy - py));
		}
		final LineFit.Solution s = fit.solve();
		assertTrue(s.ok());
		assertEquals(cx, s.x(), 1e-9);
		assertEquals(cy, s.y(), 1e-9);
		assertEquals(50, s.lines());
	}

	@Test
	void verticalAndHorizontalLinesNeedNoSlope() {
		// gx = 0 lines: the slope form would divide by zero here.
		final LineFit fit = new LineFit(0, 0);
		fit.addPaperWeighted(5, 0, 0, 3); // vertical line x = 5
		fit.addPaperWeighted(5, 9, 0, -2);
		fit.addPaperWeighted(0, 7, 4, 0); // horizontal line y = 7
		final LineFit.Solution s = fit.solve();
		assertTrue(s.ok());
		assertEquals(5, s.x(), 1e-12);
		assertEquals(7, s.y(), 1e-12);
	}

	@Test
	void parallelLinesAreReportedDegenerate() {
		final LineFit fit = new LineFit(0, 0);
		for (int i = 0; i < 20; i++)
			fit.addPaperWeighted(i, 2 * i, 1, 0.5);
		final LineFit.Solution s = fit.solve();
		assertFalse(s.ok());
		assertEquals(LineFit.Status.DEGENERATE, s.status());
		assertTrue(Double.isNaN(s.x()));
	}

	@Test
	void tooFewLinesAreDegenerate() {
		final LineFit fit = new LineFit(0, 0);
		fit.addPaperWeighted(1, 1, 1, 1);
		fit.addPaperWeighted(3, 3, 0, 0); // zero gradient: ignored
		final LineFit.Solution s = fit.solve();
		assertEquals(1, s.lines());
		assertFalse(s.ok());
	}
}
