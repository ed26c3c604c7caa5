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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Plane;
import net.imglib2.img.array.ArrayImgs;

/** The pooling of the profile helper where no particle has background around it, and where the pooled image ends. */
class PooledProfileTest {

	/**
	 * A frame smaller than a particle's background annulus, with a diameter of 0 (the masks start at 0 and may narrow
	 * to 0): the helper refuses in one line at once. It used to narrow a mask of 0 for ever (a 104x32 frame found by
	 * the fuzz never answered).
	 */
	@Test
	void noBackgroundWithAZeroMaskIsRefusedNotNarrowedForEver() {
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(new byte[64], 8, 8));
		final List<double[]> centres = List.of(new double[] { 4, 4 });
		final double[][] spots = { { 4, 4 } };
		assertTimeoutPreemptively(Duration.ofSeconds(10), () -> assertThrows(InvalidInputException.class,
			() -> PooledProfile.poolNarrowing(plane, centres, spots, 0, 20, 0, null)));
	}

	/** @return a profile sampled every 0.5 px out to 30 px, noise 1 */
	private static PooledProfile sampled(final java.util.function.DoubleUnaryOperator height) {
		final int n = 61;
		final double[] r = new double[n], h = new double[n];
		final int[] count = new int[n];
		for (int k = 0; k < n; k++) {
			r[k] = 0.5 * k;
			h[k] = height.applyAsDouble(r[k]);
			count[k] = 10;
		}
		return new PooledProfile(r, h, count, 0, 1, List.of());
	}

	/**
	 * A blurred disc (radius 6, blur 1.5 px, 120 noise sigmas high) has its rim at half height, not where its light
	 * meets the noise; a Gaussian spot, no wider than its blur, keeps its reach; a bright-field particle, the outer edge
	 * of its dark ring.
	 */
	@Test
	void theRimIsAPlateausHalfHeightElseWhereTheImageEnds() {
		final PooledProfile disc = sampled(r -> 120 / (1 + Math.exp((r - 6) * 1.702 / 1.5)));
		final double discReach = PooledProfile.reach(disc, 30, null);
		assertEquals(6, PooledProfile.rim(disc, discReach), 0.05);
		assertTrue(discReach > 8, "the light meets the noise more than 2 px beyond the rim: " + discReach);

		final PooledProfile gaussian = sampled(r -> 120 * Math.exp(-r * r / (2 * 1.5 * 1.5)));
		final double gaussianReach = PooledProfile.reach(gaussian, 30, null);
		assertEquals(gaussianReach, PooledProfile.rim(gaussian, gaussianReach), 1e-12);

		final PooledProfile ringed = sampled(r -> r < 4 ? 100 : r < 10 ? -40 : 0);
		final double ringedReach = PooledProfile.reach(ringed, 30, null);
		assertEquals(PooledProfile.imageEdge(ringed, ringedReach), PooledProfile.rim(ringed, ringedReach), 1e-12);
		assertEquals(10, PooledProfile.rim(ringed, ringedReach), 0.5);
	}
}
