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
package io.github.contacttracker.core.track;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * Two kinds of particle of unlike shape (in focus: a small bright core in a dark ring; out of focus: a broad core),
 * touching in unlike pairs, as on the paper authors' real movie: the {@code fit} method tells the kinds apart, fits
 * each with its own measured profile, and so finds the centres nearer the truth than with one profile for all.
 */
class KindsTrackingTest {

	static final RadialProfile IN_FOCUS = new GaussianBesselProfile(120, 0.30, 10);
	static final RadialProfile OUT_OF_FOCUS = new GaussianBesselProfile(80, 0.12, 14);
	static final double BACKGROUND = 60, THRESHOLD = 100, R_OUT = 25, APART = 18, SPACING = 100;
	static final int FRAMES = 8, GRID = 4, SIZE = (int) (SPACING * GRID + 20);

	/** A true particle: centre and kind (1 in focus, the smaller core; 2 out of focus). */
	record Truth(int frame, double x, double y, int kind) {}

	@Test
	void unlikeKindsAreToldApartAndFittedEachWithItsProfile() {
		final List<Truth> truth = new ArrayList<>();
		final List<RandomAccessibleInterval<UnsignedByteType>> frames = movie(truth, 5);
		final TrackerParameters params = TrackerParameters.of(THRESHOLD, R_OUT).withMethod(Method.FIT);
		final List<Localization> kinds = StackTracker.spots(new StackTracker(params).track(frames, false));
		final List<Localization> alike = StackTracker.spots(new StackTracker(params.withKinds(1)).track(frames, false));

		int right = 0, matched = 0;
		for (final Truth t : truth) {
			final Localization s = nearest(kinds, t);
			if (s == null) continue;
			matched++;
			if (s.kind() == t.kind()) right++;
		}
		assertTrue(matched >= 0.98 * truth.size(), "particles found: " + matched + " of " + truth.size());
		assertTrue(right >= 0.98 * matched, "kinds right: " + right + " of " + matched);
		for (final Localization s : alike)
			assertEquals(0, s.kind(), "one kind: none told apart");

		final double withKinds = rms(kinds, truth), withOne = rms(alike, truth);
		// measured: 0.034 px with a profile per kind, 0.43 px with one for both (its shape fits neither kind)
		assertTrue(withKinds < 0.05 && withKinds < 0.2 * withOne, "centres with a profile per kind: rms " + withKinds +
			" px, with one profile: " + withOne + " px");
	}

	/** @return the spot of the truth's frame within 3 px of it, or null */
	private static Localization nearest(final List<Localization> spots, final Truth t) {
		Localization best = null;
		double d = 3;
		for (final Localization s : spots)
			if (s.frame() == t.frame() && Math.hypot(s.x() - t.x(), s.y() - t.y()) < d) {
				d = Math.hypot(s.x() - t.x(), s.y() - t.y());
				best = s;
			}
		return best;
	}

	/** @return the rms distance of the true centres from their spots (px) */
	private static double rms(final List<Localization> spots, final List<Truth> truth) {
		double sum = 0;
		int n = 0;
		for (final Truth t : truth) {
			final Localization s = nearest(spots, t);
			if (s == null) continue;
			sum += Math.pow(s.x() - t.x(), 2) + Math.pow(s.y() - t.y(), 2);
			n++;
		}
		return Math.sqrt(sum / n);
	}

	/** Frames of unlike pairs on a grid, {@value #APART} px apart at random angles, 8-bit with Gaussian noise. */
	static List<RandomAccessibleInterval<UnsignedByteType>> movie(final List<Truth> truth, final long seed) {
		final SplittableRandom random = new SplittableRandom(seed);
		final ImageSimulator inFocus = new ImageSimulator(IN_FOCUS), outOfFocus = new ImageSimulator(OUT_OF_FOCUS);
		final List<RandomAccessibleInterval<UnsignedByteType>> frames = new ArrayList<>();
		for (int t = 0; t < FRAMES; t++) {
			final NoiseFreeImage image = NoiseFreeImage.uniform(SIZE, SIZE, BACKGROUND);
			for (int i = 0; i < GRID; i++)
				for (int j = 0; j < GRID; j++) {
					final double cx = 10 + SPACING * (i + 0.5) + random.nextDouble(-5, 5), cy = 10 + SPACING * (j + 0.5) +
						random.nextDouble(-5, 5), a = random.nextDouble(2 * Math.PI);
					final double ax = cx - 0.5 * APART * Math.cos(a), ay = cy - 0.5 * APART * Math.sin(a);
					final double bx = cx + 0.5 * APART * Math.cos(a), by = cy + 0.5 * APART * Math.sin(a);
					inFocus.addParticle(image, ax, ay);
					outOfFocus.addParticle(image, bx, by);
					truth.add(new Truth(t, ax, ay, 1));
					truth.add(new Truth(t, bx, by, 2));
				}
			frames.add(Quantiser.toUnsignedBytes(image, NoiseModel.gaussian(3), random).image());
		}
		return frames;
	}
}
