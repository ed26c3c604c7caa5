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

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * A particle's match with its profile, judged on the frame and on its own light. In a packed field every particle's
 * disc holds its neighbours' light too, and the frame matches no single profile there; with the neighbours' fitted
 * light taken out, a particle matches its profile as one standing alone does, and a bump of noise still does not.
 */
class ProfileMatchTest {

	private static final int W = 120, H = 120;
	private static final double RADIUS = 7, BLUR = 1.7, NOISE = 3;

	@Test
	void aPackedParticleMatchesItsProfileOnItsOwnLight() {
		// a hexagonal patch of 19 discs of 14 px at contact, the middle one ringed by six neighbours
		final List<Scenes.Truth> truth = new ArrayList<>();
		final double s = 2 * RADIUS, cx = 60.3, cy = 60.2;
		for (int row = -2; row <= 2; row++)
			for (int col = -3; col <= 3; col++) {
				final double x = cx + s * (col + 0.5 * row), y = cy + s * Math.sqrt(0.75) * row;
				if (Math.hypot(x - cx, y - cy) < 2.05 * s) truth.add(new Scenes.Truth(x, y, 100, RADIUS));
			}
		final double[] pixels = Scenes.noisy(Scenes.render(W, H, (x, y) -> 30, truth, Scenes.blurredDisc(1, BLUR /
			RADIUS), 2), NOISE, 0, 255, 5);
		final Plane plane = Plane.of(TestImages.bytes(pixels, W, H));
		// the exact profile, measured at the true centres
		final EmpiricalProfile profile = Scenes.measured(plane, truth, 1.5 * s);
		final int n = truth.size();
		final double[] x = new double[n], y = new double[n];
		for (int k = 0; k < n; k++) {
			x[k] = truth.get(k).x();
			y[k] = truth.get(k).y();
		}
		// the fit's residuals: the frame less every particle's light
		final float[] data = BandPass.pixels(plane), residual = data.clone();
		final Estimate[] members = new Estimate[n];
		int middle = 0;
		for (int k = 0; k < n; k++) {
			members[k] = new Estimate(x[k], y[k], 0, 0, 0, null, Double.NaN, Double.NaN, 1, 1);
			DrawnModel.draw(residual, W, H, members[k], profile, -1);
			if (Math.hypot(x[k] - cx, y[k] - cy) < 1) middle = k;
		}
		final double onFrame = ProfileMatch.matched(data, W, H, x[middle], y[middle], profile, NOISE);
		final double own = ProfileMatch.matchedOwn(residual, W, H, members[middle], profile, NOISE);
		assertTrue(onFrame < ProfileMatch.MATCH, "on the frame, six neighbours' light spoils the match: " + onFrame);
		assertTrue(own > 0.95, "on its own light it matches: " + own);
		// a member on the gap between the middle particle and two of its neighbours, where no particle is: what is
		// left there once the particles' light is taken out is the noise
		final Estimate gap = new Estimate(cx + s / 2, cy + s / (2 * Math.sqrt(3)), 0, 0, 0, null, Double.NaN,
			Double.NaN, 0, 1);
		final double none = ProfileMatch.matchedOwn(residual, W, H, gap, profile, NOISE);
		assertTrue(none < ProfileMatch.MATCH, "a member on a gap matches nothing: " + none);
		assertTrue(truth.size() == 19, truth.size() + " particles");
	}
	/**
	 * At a peak signal to noise of 3 a particle's correlation with its profile is mostly noise: many fall below
	 * {@link ProfileMatch#MATCH}, and the shape verdict would remove real particles. Its pixels differ from the profile
	 * by no more than the noise makes them, and the verdict keeps them; a bright blob of another shape (two spots side
	 * by side, where the profile has one) differs from it by far more than the noise, and is not kept.
	 */
	@Test
	void aFaintParticleMatchesWithinTheNoiseAndABrightBlobOfAnotherShapeDoesNot() {
		final int w = 200, h = 200;
		final double noise = 3;
		final java.util.function.DoubleUnaryOperator spot = Scenes.blurredDisc(0, 1.2);
		final List<Scenes.Truth> faint = new ArrayList<>();
		for (int i = 0; i < 8; i++)
			for (int j = 0; j < 8; j++)
				faint.add(new Scenes.Truth(15.3 + 24 * i + 0.1 * j, 15.6 + 24 * j + 0.07 * i, 3 * noise, 1));
		// the profile, measured where the same spots are bright
		final List<Scenes.Truth> bright = new ArrayList<>();
		for (final Scenes.Truth t : faint)
			bright.add(new Scenes.Truth(t.x(), t.y(), 100 * noise, 1));
		final Plane clear = Plane.of(TestImages.floats(Scenes.noisy(Scenes.render(w, h, (x, y) -> 100, bright, spot, 6),
			noise, 0, 1e9, 3), w, h));
		final EmpiricalProfile profile = Scenes.measured(clear, bright, 6);
		final double typical = profile.lookup(0) - profile.background();
		int correlated = 0, kept = 0;
		for (long seed = 1; seed <= 4; seed++) {
			final float[] data = BandPass.pixels(Plane.of(TestImages.floats(Scenes.noisy(Scenes.render(w, h, (xx,
				yy) -> 100, faint, spot, 6), noise, 0, 1e9, 10 + seed), w, h)));
			for (final Scenes.Truth t : faint) {
				// the member fitted at its own place and amplitude, its light drawn: the residuals hold the rest
				final Estimate e = new Estimate(t.x(), t.y(), 0, 0, 0, null, Double.NaN, Double.NaN, t.amplitude() /
					typical, 1);
				final float[] residual = data.clone();
				DrawnModel.draw(residual, w, h, e, profile, -1);
				if (ProfileMatch.matchedOwn(residual, w, h, e, profile, noise) >= ProfileMatch.MATCH) correlated++;
				if (ProfileMatch.shapeOwn(residual, w, h, e, profile, noise) >= ProfileMatch.MATCH) kept++;
			}
		}
		final int all = 4 * faint.size();
		assertTrue(correlated < 0.9 * all, "the correlation alone keeps " + correlated + " of " + all);
		assertTrue(kept >= 0.97 * all, "the verdict keeps " + kept + " of " + all);
		// a bright blob of two spots 4 px apart, drawn as one particle of the profile at its middle
		final List<Scenes.Truth> two = List.of(new Scenes.Truth(99.5, 100.4, 30 * noise, 1), new Scenes.Truth(103.5,
			100.4, 30 * noise, 1));
		final float[] data = BandPass.pixels(Plane.of(TestImages.floats(Scenes.noisy(Scenes.render(w, h, (xx,
			yy) -> 100, two, spot, 6), noise, 0, 1e9, 99), w, h)));
		final Estimate middle = new Estimate(101.5, 100.4, 0, 0, 0, null, Double.NaN, Double.NaN, 30 * noise /
			typical, 1);
		final float[] residual = data.clone();
		DrawnModel.draw(residual, w, h, middle, profile, -1);
		final double shape = ProfileMatch.shapeOwn(residual, w, h, middle, profile, noise);
		assertTrue(shape < ProfileMatch.MATCH, "two spots drawn as one: " + shape);
	}
}
