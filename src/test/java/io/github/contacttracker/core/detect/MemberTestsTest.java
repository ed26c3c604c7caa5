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
package io.github.contacttracker.core.detect;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

class MemberTestsTest {

	private static final int W = 140, H = 140;
	private static final double RADIUS = 7, BLUR = 1.7, NOISE = 3;

	/**
	 * Touching particles sit one diameter apart, so with the true diameter given about half of their fitted centres
	 * lie just nearer than that, and each is tested against its neighbours: those whose light reaches its pixels by
	 * the profile's radius. One at the end of that reach lights none of them; its column of the least squares was 0,
	 * the system singular, the verdict NaN, and a NaN removed the particle (on a simulated monolayer at contact with
	 * the true diameter given: 59 real particles removed, and every spot flagged). Such a neighbour is left out of
	 * the solve: the particle is kept, and a third member on the two's contact, where no particle is, is not.
	 */
	@Test
	void aNeighbourWhoseLightDoesNotReachLeavesATouchingParticleKept() {
		final double d = 2 * RADIUS, ax = 60.3, ay = 70.2;
		final List<Scenes.Truth> pair = List.of(new Scenes.Truth(ax, ay, 100, RADIUS), new Scenes.Truth(ax + d - 0.02,
			ay + 0.01, 100, RADIUS));
		final double[] clean = Scenes.noisy(Scenes.render(W, H, (x, y) -> 30, pair, Scenes.blurredDisc(1, BLUR /
			RADIUS), 2), NOISE, 0, 255, 7);
		// the profile as the rounds measure it, out to 13 px (1.5 r_out), at the true centres
		final EmpiricalProfile profile = Scenes.measured(Plane.of(TestImages.bytes(clean, W, H)), pair, 13);
		// a third particle on the far side, just within the reach by which a neighbour counts: its light ends before
		// the first particle's pixels
		final double far = profile.informationRadius(ProfileMatch.MATCHED_INFORMATION) + profile.radius() - 0.05;
		final List<Scenes.Truth> truth = new ArrayList<>(pair);
		truth.add(new Scenes.Truth(ax - far, ay, 100, RADIUS));
		final Plane plane = Plane.of(TestImages.bytes(Scenes.noisy(Scenes.render(W, H, (x, y) -> 30, truth, Scenes
			.blurredDisc(1, BLUR / RADIUS), 2), NOISE, 0, 255, 8), W, H));
		final int n = truth.size();
		final Estimate[] members = new Estimate[n + 1];
		for (int k = 0; k < n; k++)
			members[k] = new Estimate(truth.get(k).x(), truth.get(k).y(), 0, 0, 0, null, Double.NaN, Double.NaN, 1, 1);
		// a faint member on the pair's contact, as a seed between them is fitted
		members[n] = new Estimate(ax + d / 2, ay, 0, 0, 0, null, Double.NaN, Double.NaN, 0.05, 1);
		final EmpiricalProfile[] of = new EmpiricalProfile[n + 1];
		java.util.Arrays.fill(of, profile);
		final double[] significance = { 300, 310, 320, 1 }; // (tested weakest first: the contact's member first)
		final float[] data = BandPass.pixels(plane);
		final boolean[] keep = { true, true, true, true };
		MemberTests.overlapTest(data, W, H, members, of, keep, significance, d, NOISE);
		assertFalse(keep[n], "the member on the contact is kept");
		// the next round, that member gone: the pair is tested, the far particle among the first's neighbours
		MemberTests.overlapTest(data, W, H, members, of, keep, significance, d, NOISE);
		assertTrue(keep[0] && keep[1] && keep[2], "the particles kept: " + keep[0] + ", " + keep[1] + ", " + keep[2]);
	}
}
