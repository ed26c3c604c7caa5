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
package io.github.contacttracker.lab.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class ImageSimulatorTest {

	/** Sum over pixels of (image - background) against 2 pi int P(r) r dr, known in closed form. */
	@Test
	void pixelIntegrationConservesTheIntegratedIntensity() {
		// Weber: int_0^inf J0(k r) exp(-r^2 / (2 s^2)) r dr = s^2 exp(-k^2 s^2 / 2)
		final double a = 120, k = 0.1, s = 18;
		final double expected = 2 * Math.PI * a * s * s * Math.exp(-k * k * s * s / 2);
		final ImageSimulator simulator = new ImageSimulator(new GaussianBesselProfile(a, k, s));
		final int size = 2 * (int) Math.ceil(simulator.cutoffRadius()) + 5;
		final double background = 60;
		final NoiseFreeImage image = simulator.render(List.<double[]> of(new double[] { size / 2 + 0.31, size / 2
			- 0.27 }), size, size, background);
		double sum = 0;
		for (final double v : image.pixels())
			sum += v - background;
		assertEquals(expected, sum, 0.005 * expected);

		final double gaussianExpected = 2 * Math.PI * 50 * 2.5 * 2.5;
		final ImageSimulator gaussian = new ImageSimulator(GaussianBesselProfile.gaussian(50, 2.5));
		final NoiseFreeImage spot = gaussian.render(List.<double[]> of(new double[] { 20.4, 19.55 }), 40, 40, 0);
		double spotSum = 0;
		for (final double v : spot.pixels())
			spotSum += v;
		assertEquals(gaussianExpected, spotSum, 0.005 * gaussianExpected);
	}

	@Test
	void centroidOfAnIsolatedSpotIsTheTrueCentre() {
		final double trueX = 20.37, trueY = 21.81, background = 30;
		final ImageSimulator simulator = new ImageSimulator(GaussianBesselProfile.gaussian(100, 3));
		final NoiseFreeImage image = simulator.render(List.<double[]> of(new double[] { trueX, trueY }), 44, 46,
			background);
		double mass = 0, mx = 0, my = 0;
		for (int y = 0; y < image.height(); y++)
			for (int x = 0; x < image.width(); x++) {
				final double w = image.get(x, y) - background;
				mass += w;
				mx += w * x;
				my += w * y;
			}
		assertEquals(trueX, mx / mass, 1e-3);
		assertEquals(trueY, my / mass, 1e-3);
	}

	@Test
	void singleSubPointSamplesPixelCentres() {
		final GaussianBesselProfile profile = new GaussianBesselProfile(120, 0.1, 18);
		final ImageSimulator pointSampler = new ImageSimulator(profile, 1);
		final NoiseFreeImage image = pointSampler.render(List.<double[]> of(new double[] { 40.25, 38.6 }), 80, 80,
			10);
		for (final int[] p : new int[][] { { 40, 38 }, { 50, 31 }, { 13, 60 }, { 70, 70 } }) {
			final double r = Math.hypot(p[0] - 40.25, p[1] - 38.6);
			assertEquals(10 + profile.value(r), image.get(p[0], p[1]), 2e-5, "pixel " + p[0] + "," + p[1]);
		}
	}

	@Test
	void pixelValueIsTheAverageOverThePixelArea() {
		// a cone 10 (1 - r / 8) integrated over a pixel differs from its centre value at the apex
		final RadialProfile cone = r -> Math.max(0, 10 * (1 - r / 8));
		final NoiseFreeImage image = new ImageSimulator(cone, 5).render(List.<double[]> of(new double[] { 10, 10 }), 21,
			21, 0);
		// 5 x 5 sub-points: the mean of the cone over them, not its apex value 10
		double meanR = 0;
		for (int i = 0; i < 5; i++)
			for (int j = 0; j < 5; j++)
				meanR += Math.hypot((i + 0.5) / 5 - 0.5, (j + 0.5) / 5 - 0.5) / 25;
		assertEquals(10 * (1 - meanR / 8), image.get(10, 10), 1e-4);
		// and close to the true pixel average, E[r] = (sqrt(2) + ln(1 + sqrt(2))) / 6 over a unit square
		final double exactMeanR = (Math.sqrt(2) + Math.log(1 + Math.sqrt(2))) / 6;
		assertEquals(10 * (1 - exactMeanR / 8), image.get(10, 10), 0.01);
	}

	@Test
	void particlesAddLinearlyAndMayLieOutsideTheImage() {
		final ImageSimulator simulator = new ImageSimulator(new GaussianBesselProfile(120, 0.1, 18));
		final double[] a = { 30.2, 40.7 }, b = { 75.9, 44.1 }, outside = { -30, 40 };
		final NoiseFreeImage both = simulator.render(List.of(a, b, outside), 100, 80, 60);
		final NoiseFreeImage onlyA = simulator.render(List.<double[]> of(a), 100, 80, 0);
		final NoiseFreeImage onlyB = simulator.render(List.<double[]> of(b), 100, 80, 0);
		final NoiseFreeImage onlyOutside = simulator.render(List.<double[]> of(outside), 100, 80, 0);
		for (int i = 0; i < both.pixels().length; i += 37)
			assertEquals(60 + onlyA.pixels()[i] + onlyB.pixels()[i] + onlyOutside.pixels()[i], both.pixels()[i],
				1e-9);
		assertTrue(Math.abs(onlyOutside.get(0, 40)) > 1e-3, "the outside particle's tail reaches in");
	}
}
