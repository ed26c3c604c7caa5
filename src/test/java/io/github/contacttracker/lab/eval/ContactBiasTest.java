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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import net.imglib2.img.array.ArrayImgs;

/** Bias of the measured distance at contact, on noise-free images of the 5.53 um-like profile. */
class ContactBiasTest {

	private static final ParticleType TYPE = PaperParticles.silica553();
	private static final ImageSimulator SIMULATOR = new ImageSimulator(TYPE.profile());

	/** Mean distance error (px) of the measured pair over sub-pixel offsets; also checks every particle is found. */
	private static double meanDistanceError(final Scenario scenario, final Method method, final int offsets) {
		final SplittableRandom rnd = new SplittableRandom(5);
		final TrackerParameters p = TrackerParameters.of(TYPE.threshold(), TYPE.rOut()).withMethod(method);
		double sum = 0;
		for (int i = 0; i < offsets; i++) {
			final List<double[]> c = scenario.centres(1.0, TYPE.diameterPx(), 120 + rnd.nextDouble() - 0.5, 130 + rnd
				.nextDouble() - 0.5);
			final NoiseFreeImage img = SIMULATOR.render(c, 240, 230, TYPE.background());
			final List<Localization> spots = new ContactTracker(p).track(ArrayImgs.doubles(img.pixels(), 240, 230), 0);
			assertEquals(c.size(), spots.size(), "every particle found");
			final Localization a = nearest(spots, c.get(0)), b = nearest(spots, c.get(1));
			for (final Localization s : spots) {
				assertTrue(!s.isFlagged(), "no warning flags at contact: " + s.flagSet());
				if (method == Method.PAPER) assertTrue(s.has(Flag.SECOND_PASS));
			}
			sum += Math.hypot(a.x() - b.x(), a.y() - b.y()) - Math.hypot(c.get(0)[0] - c.get(1)[0], c.get(0)[1] - c
				.get(1)[1]);
		}
		return sum / offsets;
	}

	private static Localization nearest(final List<Localization> spots, final double[] p) {
		Localization best = null;
		for (final Localization s : spots)
			if (best == null || Math.hypot(s.x() - p[0], s.y() - p[1]) < Math.hypot(best.x() - p[0], best.y() - p[1]))
				best = s;
		return best;
	}

	@Test
	void secondPassCutsThePairBiasAtLeastThreeFold() {
		final double first = meanDistanceError(Scenario.PAIR, Method.FIRST, 8);
		final double paper = meanDistanceError(Scenario.PAIR, Method.PAPER, 8);
		// The first pass sees each particle pulled towards its neighbour: the distance comes out short.
		assertTrue(first < -0.05, "first-pass bias " + first + " px");
		assertTrue(3 * Math.abs(paper) <= Math.abs(first), "paper " + paper + " px vs first " + first + " px");
	}

	@Test
	void threeParticlesInContact() {
		final double first = meanDistanceError(Scenario.TRIPLE, Method.FIRST, 8);
		final double paper = meanDistanceError(Scenario.TRIPLE, Method.PAPER, 8);
		assertTrue(first < -0.05, "first-pass bias " + first + " px");
		assertTrue(3 * Math.abs(paper) <= Math.abs(first), "paper " + paper + " px vs first " + first + " px");
		assertTrue(Math.abs(paper) * TYPE.pixelSizeNm() < 5, "paper's bias " + paper * TYPE.pixelSizeNm() + " nm");
	}
}
