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
package io.github.contacttracker.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import io.github.contacttracker.advisor.Finding;
import org.junit.jupiter.api.Test;

/** The profile helper's findings in words: the sentences users have read since the helper had warnings. */
class ProfileReportTest {

	@Test
	void everyFindingHasItsSentence() {
		final Map<Finding, String> expected = new LinkedHashMap<>();
		expected.put(new Finding.DiameterFromImage(30.0213, 15.0107), "the diameter (30.02 px) is estimated as twice " +
			"the radius where the particles' image returns to the background (15.01 px): give it if you know it");
		expected.put(new Finding.DiameterFromSpacing(34.0589, 10, 85, 42.9791), "the diameter (34.06 px) is estimated " +
			"as the 10-th percentile of the 85 spots' nearest-neighbour distances, closer than the particles' image " +
			"reaches (42.98 px across): give it if you know it");
		expected.put(new Finding.MergedAtPoint(), "the particle's active area looks merged with a neighbour's: pick an " +
			"isolated particle");
		expected.put(new Finding.NotRefined(), "could not refine the centre; the profile is taken around the point " +
			"given");
		expected.put(new Finding.NotIsolated(93.0844, 52.44), "no particle is isolated: the most isolated has a " +
			"neighbour at 93.08 px (1.780 diameters); the profile's outer part may show neighbours");
		expected.put(new Finding.NotBackToBackground(12.8), "the profile has not returned to the background by 12.80 " +
			"px: increase max_radius (r_out is a lower bound)");
		expected.put(new Finding.BackgroundTexture(61.4321, 10, 13.9789, 123.98), "at 61.43, 10 bright spots of the " +
			"background (halos, rings; up to 13.98 above it) would be taken for particles, whose cores rise at least " +
			"124.0 above it: the threshold is raised to the middle of that gap");
		expected.put(new Finding.RaisedUntilRound(154.8012, 67, 159), "at 154.8, 67 of the frame's 159 active areas " +
			"have the shape of no single particle (bright fringes between touching particles, or particles merged): the " +
			"threshold is raised until they are round");
		expected.put(new Finding.NotRound(3, 120, 131.456), "3 of the frame's 120 active areas have the shape of no " +
			"single particle up to 131.5 (half the cores' height): they will be flagged MERGED");
		expected.put(new Finding.ThresholdAboveCentre(), "the suggested threshold is above the particle's centre: at " +
			"contact no threshold separates two such particles (the profile is too long-ranged for the method)");
		expected.put(new Finding.ROutAboveDiameter(42.1634, 30), "r_out (42.16 px) is larger than the diameter (30 px): " +
			"at contact little undistorted active area is left for the paper's second pass (the paper needs r_out <= D; " +
			"the deblend and fit methods do not)");
		for (final Map.Entry<Finding, String> e : expected.entrySet())
			assertEquals(e.getValue(), ProfileReport.sentence(e.getKey()), e.getKey().toString());
		// a new kind of finding needs its sentence here too
		final Set<Class<?>> kinds = Arrays.stream(Finding.class.getPermittedSubclasses()).collect(Collectors.toSet());
		assertEquals(kinds, expected.keySet().stream().map(Object::getClass).collect(Collectors.toSet()));
	}
}
