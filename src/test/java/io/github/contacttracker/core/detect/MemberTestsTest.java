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

import static org.junit.jupiter.api.Assertions.assertEquals;
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

	/**
	 * The sum of squares a least-squares fit explains is that of the columns that add something: a column of 0s (a
	 * neighbour whose light does not reach) and a column equal to another's (a member on the very light of another)
	 * leave it as it is, where a plain solve finds the system singular; an independent column raises it.
	 */
	@Test
	void aColumnThatAddsNothingLeavesTheExplainedSumAsItIs() {
		final java.util.Random random = new java.util.Random(3);
		final int pixels = 50;
		final double[][] f = new double[pixels][4];
		final double[] y = new double[pixels];
		for (int i = 0; i < pixels; i++) {
			f[i][0] = 1;
			f[i][1] = random.nextGaussian();
			f[i][2] = 0; // a column of 0s
			f[i][3] = f[i][1]; // a column equal to another
			y[i] = 2 + 3 * f[i][1] + random.nextGaussian();
		}
		final double two = explained(f, y, new int[] { 0, 1 });
		assertEquals(two, explained(f, y, new int[] { 0, 1, 2 }), 1e-9 * two, "with a column of 0s");
		assertEquals(two, explained(f, y, new int[] { 0, 1, 3 }), 1e-9 * two, "with a column equal to another");
		// the explained sum of two columns, by the normal equations solved by hand (2 x 2)
		double n = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
		for (int i = 0; i < pixels; i++) {
			n++;
			sx += f[i][1];
			sxx += f[i][1] * f[i][1];
			sy += y[i];
			sxy += f[i][1] * y[i];
		}
		final double det = n * sxx - sx * sx;
		final double p0 = (sxx * sy - sx * sxy) / det, p1 = (n * sxy - sx * sy) / det;
		assertEquals(p0 * sy + p1 * sxy, two, 1e-9 * two, "two independent columns");
	}

	/** @return {@link MemberTests#explained} of columns {@code use} of {@code f} against {@code y} */
	private static double explained(final double[][] f, final double[] y, final int[] use) {
		final int np = use.length;
		final double[][] a = new double[np][np];
		final double[] b = new double[np];
		for (int i = 0; i < f.length; i++)
			for (int r = 0; r < np; r++) {
				b[r] += f[i][use[r]] * y[i];
				for (int c = 0; c < np; c++)
					a[r][c] += f[i][use[r]] * f[i][use[c]];
			}
		return MemberTests.explained(a, b, np);
	}
}
