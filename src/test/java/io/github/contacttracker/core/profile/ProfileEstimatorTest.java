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
package io.github.contacttracker.core.profile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.DoubleUnaryOperator;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.DoublePlane;

class ProfileEstimatorTest {

	/** Overlapping particles (no undistorted side): the joint model still recovers the profile. */
	@Test
	void recoversProfileFromOverlappingParticles() {
		final DoubleUnaryOperator profile = r -> 100 * Math.exp(-r * r / 50) - 20 * Math.exp(-(r - 12) * (r - 12) / 8);
		final int w = 120, h = 90;
		final double[][] c = { { 45.3, 44.8 }, { 63.1, 46.2 }, { 54.0, 30.4 } };
		final double[] img = TestImages.render(w, h, 30, profile, c);
		final ProfileEstimator est = new ProfileEstimator(30);
		est.add(new DoublePlane(img, w, h), new double[] { c[0][0], c[1][0], c[2][0] }, new double[] { c[0][1], c[1][1],
			c[2][1] }, new boolean[3]);
		final EmpiricalProfile p = est.estimate();
		assertEquals(30, p.background(), 0.05);
		assertNearTruth(profile, p);
		assertEquals(0, p.value(p.radius() + 1), 0);
	}

	/**
	 * A chord step from an estimate around centres 0.6 px off (the profile rounds' earlier centres) lands on the exact
	 * estimate around the true centres to within a small fraction of the gap between the two, and a second step from
	 * it closer still: the steps converge to the exact least squares.
	 */
	@Test
	void aChordStepLandsOnTheExactEstimate() {
		final DoubleUnaryOperator profile = r -> 100 * Math.exp(-r * r / 50) - 20 * Math.exp(-(r - 12) * (r - 12) / 8);
		final int w = 120, h = 90;
		final double[] cx = { 45.3, 63.1, 54.0 }, cy = { 44.8, 46.2, 30.4 };
		final DoublePlane plane = new DoublePlane(TestImages.render(w, h, 30, profile, new double[] { cx[0], cy[0] },
			new double[] { cx[1], cy[1] }, new double[] { cx[2], cy[2] }), w, h);
		final double[] amp = { 1.1, 0.9, 1 }, scale = { 1, 1.05, 0.97 };
		final double[] offX = cx.clone(), offY = cy.clone();
		for (int k = 0; k < 3; k++) {
			offX[k] += 0.6 * Math.cos(2 * k);
			offY[k] += 0.6 * Math.sin(2 * k);
		}
		final ProfileEstimator off = new ProfileEstimator(30, 1, null);
		off.add(plane, offX, offY, amp, scale, new boolean[3], null);
		final ProfileEstimator.Solution earlier = off.solve();
		final ProfileEstimator exact = new ProfileEstimator(30, 1, null);
		exact.add(plane, cx, cy, amp, scale, new boolean[3], null);
		final EmpiricalProfile truth = exact.estimate();
		final ProfileEstimator chord = new ProfileEstimator(30, 1, earlier.linearisation());
		chord.add(plane, cx, cy, amp, scale, new boolean[3], null);
		final ProfileEstimator.Solution step = chord.solve();
		final ProfileEstimator again = new ProfileEstimator(30, 1, step.linearisation());
		again.add(plane, cx, cy, amp, scale, new boolean[3], null);
		final double gap = largestDifference(earlier.profiles()[0], truth);
		final double first = largestDifference(step.profiles()[0], truth);
		final double second = largestDifference(again.estimate(), truth);
		assertTrue(gap > 0.4, "the centres' offset moves the profile: " + gap);
		assertTrue(first < 0.1 * gap, "one step: " + first + " of a gap of " + gap);
		assertTrue(second < 0.2 * first, "two steps: " + second + " after " + first);
		assertEquals(truth.background(), again.estimate().background(), 1e-3 * Math.abs(truth.background() - earlier
			.profiles()[0].background()) + 1e-9);
	}

	private static double largestDifference(final EmpiricalProfile a, final EmpiricalProfile b) {
		double d = 0;
		for (double r = 0; r < a.radius(); r += 0.25)
			d = Math.max(d, Math.abs(a.value(r) - b.value(r)));
		return d;
	}

	/**
	 * A fit that did not converge (two members put on one particle, a centre far off, a wild amplitude) does not
	 * describe its pixels: like a merge, it is left out of the profile, which the other particles then give right.
	 * Taken in, it pulls the profile several times further off than the tolerance below.
	 */
	@Test
	void aFitThatDidNotConvergeIsLeftOutOfTheProfile() {
		final DoubleUnaryOperator profile = r -> 100 * Math.exp(-r * r / 50) - 20 * Math.exp(-(r - 12) * (r - 12) / 8);
		final int w = 160, h = 90;
		final double[][] c = { { 35.3, 44.8 }, { 80.1, 46.2 }, { 125.0, 40.4 } };
		final net.imglib2.img.Img<net.imglib2.type.numeric.real.DoubleType> frame = net.imglib2.img.array.ArrayImgs
			.doubles(TestImages.render(w, h, 30, profile, c), w, h);
		final java.util.List<Localization> spots = java.util.List.of(spot(c[0][0], c[0][1], 1, 0), spot(c[1][0],
			c[1][1], 1, 0), spot(c[2][0] + 4, c[2][1] - 3, 2.5, Flag.NOT_CONVERGED.bit()));
		final ProfileEstimator est = new ProfileEstimator(30);
		est.add(frame, spots, 1, 1);
		final EmpiricalProfile p = est.estimate();
		assertNearTruth(profile, p);
	}

	/** Pixel integration blurs the profile slightly: it is compared with the pixel-averaged truth, out to 20 px. */
	private static void assertNearTruth(final DoubleUnaryOperator profile, final EmpiricalProfile p) {
		for (double r = 0; r < 20; r += 0.7)
			assertEquals(pixelAverage(profile, r), p.value(r), 0.3, "at r = " + r);
	}

	/** @return the profile averaged over a pixel whose centre lies {@code r} from the particle's */
	private static double pixelAverage(final DoubleUnaryOperator profile, final double r) {
		double avg = 0;
		for (int i = 0; i < 8; i++)
			for (int j = 0; j < 8; j++)
				avg += profile.applyAsDouble(Math.hypot(r + (i + 0.5) / 8 - 0.5, (j + 0.5) / 8 - 0.5));
		return avg / 64;
	}

	private static Localization spot(final double x, final double y, final double amplitude, final int flags) {
		return new Localization(0, x, y, x, y, 150, 150, 1, 7, flags, 5, 0.01, 0.01, amplitude, 1, 0);
	}

	/**
	 * Discs on a background of 2 clipped at 0 (noise 4, 8-bit: a third of the background reads 0), measured as a movie's
	 * rounds measure them, the second pass leaving out the pixels whose model comes near the floor: the background is
	 * the clipped normal's mean, 2, not the 4 of the pixels above the floor, and the profile about it is the particles'
	 * light where the fit uses it (above 12, three noise deviations clear of the floor). Measured from the pixels above
	 * the floor alone, the background and the profile's outer knots traded places freely (here it came out -1.2; on the
	 * detection study's clipped scene 4, every profile value 2 too low): between touching particles, whose tails add
	 * up, the model then lacks that much light and pulls them together. The round after, the floor linked with the
	 * clipped normal's spread ({@code Censoring#mean}), measures the profile's tail too, down to the floor, out to
	 * 11 px.
	 */
	@Test
	void aBackgroundClippedAtTheFloorIsItsUnclippedMean() {
		final DoubleUnaryOperator profile = r -> 100 / (1 + Math.exp((r - 5) / 0.9));
		final int w = 200, h = 200;
		final java.util.List<Localization> spots = new java.util.ArrayList<>();
		for (int i = 0; i < 5; i++)
			for (int j = 0; j < 5; j++)
				spots.add(spot(20.3 + 39.7 * i, 19.6 + 40.1 * j, 1, 0));
		final double[] clean = TestImages.render(w, h, 2, profile, spots.stream().map(s -> new double[] { s.x(), s.y() })
			.toArray(double[][]::new));
		final java.util.SplittableRandom random = new java.util.SplittableRandom(7);
		final byte[] pixels = new byte[w * h];
		int atFloor = 0;
		for (int i = 0; i < pixels.length; i++) {
			final long v = Math.max(0, Math.min(255, Math.round(clean[i] + 4 * gaussian(random))));
			if (v == 0) atFloor++;
			pixels[i] = (byte) v;
		}
		assertTrue(atFloor > 0.25 * pixels.length, "a clipped background: " + atFloor);
		final net.imglib2.img.Img<net.imglib2.type.numeric.integer.UnsignedByteType> frame = net.imglib2.img.array.ArrayImgs
			.unsignedBytes(pixels, w, h);
		final ProfileEstimator first = new ProfileEstimator(12);
		first.add(frame, spots, 1, 1);
		final ProfileEstimator second = new ProfileEstimator(12);
		second.add(frame, spots, 1, 1, first.estimate(), 4);
		final EmpiricalProfile p = second.estimate();
		assertEquals(2, p.background(), 0.15, "background");
		for (double r = 0; r < 6.5; r += 0.5)
			assertEquals(pixelAverage(profile, r), p.value(r), 1, "at r = " + r);
		// the clipped normal's spread is the background's noise, which the next round links the floor with
		assertEquals(4, p.floorNoise(), 0.3, "floor noise");
		final ProfileEstimator third = new ProfileEstimator(12);
		third.add(frame, spots, 1, 1, p, 4);
		final EmpiricalProfile linked = third.estimate();
		assertEquals(2, linked.background(), 0.15, "background, linked");
		for (double r = 0; r < 11; r += 0.5)
			assertEquals(pixelAverage(profile, r), linked.value(r), 1, "linked, at r = " + r);
	}

	private static double gaussian(final java.util.SplittableRandom random) {
		return Math.sqrt(-2 * Math.log(1 - random.nextDouble())) * Math.cos(2 * Math.PI * random.nextDouble());
	}

	@Test
	void tooLittleDataIsRefused() {
		final ProfileEstimator est = new ProfileEstimator(30);
		assertThrows(IllegalStateException.class, est::estimate);
	}
}
