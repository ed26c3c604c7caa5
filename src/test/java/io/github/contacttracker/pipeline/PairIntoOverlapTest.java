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
package io.github.contacttracker.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * A tweezer pair pushed from two diameters apart into overlap, tracked as a new user does: no value given, the
 * profile helper measures the settings on the first frame, where the two stand apart. Blurred spheres have no dark
 * ring, and their light reaches past their rim by the blur: the diameter must be the rim's, not the light's, or two
 * particles closer than the light's reach are taken for one.
 */
class PairIntoOverlapTest {

	/** Disc diameter (px), the blur of its edge (px), and the movie's length. */
	private static final double D = 12, BLUR = 1.5;
	private static final int FRAMES = 40, W = 100, H = 80;

	/** @return the centres of frame {@code t}: 2 diameters apart in the first frame, half a diameter in the last */
	private static double[][] centres(final int t) {
		final double separation = D * (2 - 1.5 * t / (FRAMES - 1));
		return new double[][] { { 50.3 - separation / 2, 40.2 }, { 50.3 + separation / 2, 40.2 } };
	}

	/** 8-bit frames: peak 120 above a background of 37, pixel noise 3 (40 noise sigmas). */
	private static List<RandomAccessibleInterval<UnsignedByteType>> movie() {
		// a disc's edge blurred by a Gaussian of BLUR px is, to a few per cent, a logistic step of width BLUR / 1.702
		final ImageSimulator sim = new ImageSimulator(r -> 120 / (1 + Math.exp((r - D / 2) * 1.702 / BLUR)), 3);
		final SplittableRandom rnd = new SplittableRandom(11);
		final List<RandomAccessibleInterval<UnsignedByteType>> frames = new ArrayList<>();
		for (int t = 0; t < FRAMES; t++)
			frames.add(Quantiser.toUnsignedBytes(sim.render(List.of(centres(t)), W, H, 37), NoiseModel.gaussian(3), rnd)
				.image());
		return frames;
	}

	@Test
	void aBlurredPairIsTwoUnflaggedSpotsDownToHalfADiameterWithNoValueGiven() {
		final List<RandomAccessibleInterval<UnsignedByteType>> movie = movie();
		final MeasuredSettings.Result m = MeasuredSettings.of("pair.tif", movie::get, FRAMES, true, SettingValues
			.defaults(), Set.of(), FrontEnd.COMMAND_LINE);
		final double diameter = m.settings().get(TrackingSettings.DIAMETER);
		assertEquals(D, diameter, 0.05 * D, "the rim's diameter, not the light's reach: " + m.notice());
		final TrackingResult r = new TrackingPipeline(m.settings()).run(FrameSource.of(FRAMES, movie::get,
			Calibration.PIXELS, "pair.tif", null), false);
		for (int t = 0; t < FRAMES; t++) {
			final FrameResult f = r.frames().get(t);
			assertEquals(2, f.spots().size(), "frame " + t + ": " + f.spots());
			for (final double[] c : centres(t)) {
				Localization nearest = null;
				for (final Localization l : f.spots())
					if (nearest == null || Math.hypot(l.x() - c[0], l.y() - c[1]) < Math.hypot(nearest.x() - c[0], nearest
						.y() - c[1])) nearest = l;
				final double error = Math.hypot(nearest.x() - c[0], nearest.y() - c[1]);
				assertEquals(0, nearest.flags(), "frame " + t + ": " + nearest);
				assertTrue(error < 0.1, "frame " + t + " (" + c[0] + ", " + c[1] + "): " + error + " px off");
			}
		}
	}
}
