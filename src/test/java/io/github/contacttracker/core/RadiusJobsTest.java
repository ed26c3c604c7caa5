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
package io.github.contacttracker.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The four jobs {@code r_out} does in the core, each derived from it as its accessor says. */
class RadiusJobsTest {

	@Test
	void eachJobIsItsMultipleOfROut() {
		for (final double rOut : new double[] { 2.5, 8, 20.25 }) { // the fit method (the default) needs r_out > 2 px
			final TrackerParameters p = TrackerParameters.of(100, rOut);
			assertEquals(rOut, p.exclusionRadius(), "the paper's exclusion disc");
			assertEquals(rOut, p.aloneReach(), "merge detection's reach beyond the component");
			assertEquals(2 * rOut, p.groupingDistance(), "two images of reach r_out overlap below 2 r_out");
			assertEquals(1.5 * rOut, p.profileReach(), "the profile carries the tail beyond r_out");
		}
	}
}
