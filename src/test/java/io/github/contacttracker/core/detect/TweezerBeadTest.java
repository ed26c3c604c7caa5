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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.ContactTracker;

/**
 * An optical tweezer's small field of view: one bead a third of the frame across, dark inside a bright rim, among the
 * background's faint bumps (uneven illumination, dust), as a public tweezer stack shows it (one bead 62 px across in
 * 184 x 181 px). The tracker sees it inverted ({@code --particles dark}): a bright core in a dark ring.
 */
class TweezerBeadTest {

	private static final double X = 92.3, Y = 88.6;

	/** A bright core of radius 25 px in a dark ring at 31 px, blurred: the inverted bead, 60 above, 95 below. */
	private static double bead(final double r) {
		final double core = 0.5 * Scenes.erfc((r - 25) / (Math.sqrt(2) * 2));
		final double ring = Math.exp(-(r - 31) * (r - 31) / (2 * 2.5 * 2.5));
		return 60 * core - 95 * ring;
	}

	/**
	 * @return the frame: the bead on a background of 120 with bumps 2 to 5 grey levels high, sixteen of them, most
	 *         near the frame's edges, and the little noise of a smooth video (0.5 grey levels), 8 bits
	 */
	private static double[] frame(final long seed) {
		final int w = 184, h = 181;
		final Random r = new Random(seed);
		final int bumps = 16;
		final double[] bx = new double[bumps], by = new double[bumps], ba = new double[bumps];
		for (int i = 0; i < bumps; i++) {
			// around the bead, out to the frame's edges
			do {
				bx[i] = r.nextDouble() * w;
				by[i] = r.nextDouble() * h;
			}
			while (Math.hypot(bx[i] - X, by[i] - Y) < 55);
			ba[i] = 2 + 3 * r.nextDouble();
		}
		final double[] img = Scenes.render(w, h, (x, y) -> {
			double v = 120;
			for (int i = 0; i < bumps; i++)
				v += ba[i] * Math.exp(-((x - bx[i]) * (x - bx[i]) + (y - by[i]) * (y - by[i])) / (2 * 8 * 8));
			return v;
		}, List.of(new Scenes.Truth(X, Y, 1, 1)), TweezerBeadTest::bead, 45);
		return Scenes.noisy(img, 0.5, 0, 255, seed);
	}

	/**
	 * Band-passed at the bead's scale, the bumps stand 15 to 40 times lower than the bead, far above the noise: the
	 * frame's own profile, measured on every seed, was no profile of the bead (the bumps' reach, cut by the edge,
	 * masked its pixels), and each bump was fitted as a particle: 12 spots. Measured on the bead alone, which stands
	 * apart, the profile is the bead's, and the bumps are no particles of it.
	 */
	@Test
	void theBeadIsOneSpotAtItsCentreAmongTheBackgroundsBumps() {
		for (final long seed : new long[] { 3, 4, 5 }) {
			final double[] img = frame(seed);
			final TrackerParameters p = TrackerParameters.of(140, 40).withDiameter(60).withDetection(Detection.IMAGE);
			final List<Localization> spots = new ContactTracker(p).track(TestImages.bytes(img, 184, 181), 0);
			assertEquals(1, spots.size(), "seed " + seed + ": one spot, not the bumps: " + spots);
			final Localization l = spots.get(0);
			assertEquals(0, l.flags(), "seed " + seed + ": unflagged: " + l);
			final double error = Math.hypot(l.x() - X, l.y() - Y);
			assertTrue(error < 0.05, "seed " + seed + ": within 0.05 px of the bead's centre, not " + error);
		}
	}
}
