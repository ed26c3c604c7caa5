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

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.image.DoublePlane;

class OtherContrastTest {

	/**
	 * @return a 160 x 160 frame on a background of 100 (noise 3) with a grid of particles of diameter 10 px, every
	 *         {@code darkEvery}-th of them dark (amplitude -80), the others bright (+80); {@code profile} their shape
	 */
	private static Scenes.Frame field(final int darkEvery, final java.util.function.DoubleUnaryOperator profile) {
		final List<Scenes.Truth> truth = new ArrayList<>();
		int i = 0;
		for (int gy = 0; gy < 5; gy++)
			for (int gx = 0; gx < 5; gx++, i++)
				truth.add(new Scenes.Truth(18.3 + 30.1 * gx, 17.6 + 30.4 * gy, darkEvery > 0 && i % darkEvery == 0 ? -80
					: 80, 1));
		final double[] clean = Scenes.render(160, 160, (x, y) -> 100, truth, profile, 12);
		return new Scenes.Frame(Scenes.noisy(clean, 3, 0, 255, 5), 160, 160, truth, 10);
	}

	/** @return the number of blobs of the other contrast counted with the bright particles of {@code f} tracked */
	private static int count(final Scenes.Frame f) {
		final double[] inverted = new double[f.pixels().length];
		for (int i = 0; i < inverted.length; i++)
			inverted[i] = 255 - f.pixels()[i];
		final List<double[]> bright = new ArrayList<>();
		for (final Scenes.Truth t : f.truth())
			if (t.amplitude() > 0) bright.add(new double[] { t.x() + 0.2, t.y() - 0.3 });
		final double[] x = new double[bright.size()], y = new double[bright.size()];
		for (int k = 0; k < x.length; k++) {
			x[k] = bright.get(k)[0];
			y[k] = bright.get(k)[1];
		}
		return OtherContrast.blobs(new DoublePlane(f.pixels(), 160, 160), new DoublePlane(inverted, 160, 160), x, y,
			f.diameter());
	}

	/** A field of bright and dark discs, the bright ones tracked: each dark one is counted, nothing else. */
	@Test
	void theDarkParticlesOfAMixedFieldAreCounted() {
		assertEquals(9, count(field(3, Scenes.blurredDisc(5, 1.2))), "every third of 25 dark");
	}

	/**
	 * A field of bright discs alone, and one of bright cores in dark rings (bright-field colloids, whose rings stand as
	 * high as a fifth of their cores in the inverted frame, within a diameter of them): nothing is counted.
	 */
	@Test
	void aFieldOfOneContrastCountsNothing() {
		assertEquals(0, count(field(0, Scenes.blurredDisc(5, 1.2))), "bright discs");
		assertEquals(0, count(field(0, r -> Scenes.ringed(3, 1.5).applyAsDouble(r))), "bright cores in dark rings");
	}

	/**
	 * A monolayer of bright discs packed edge to edge on a dark background (a triangular lattice, shaken), every
	 * seventh of them missing: those gaps, a particle wide, stand out of the inverted frame against the bright
	 * particles around them as dark particles would; they only read the background, and nothing is counted.
	 */
	@Test
	void theGapsOfAPackedMonolayerAreNotParticles() {
		final java.util.Random shake = new java.util.Random(17);
		final List<Scenes.Truth> truth = new ArrayList<>();
		int k = 0;
		for (int row = 0; row < 20; row++)
			for (int col = 0; col < 19; col++, k++)
				if (k % 7 != 6) truth.add(new Scenes.Truth(6 + SPACING * (col + 0.5 * (row % 2)) + shake.nextGaussian() * 0.4,
					6 + SPACING * Math.sqrt(0.75) * row + shake.nextGaussian() * 0.4, 150, 1));
		final double[] clean = Scenes.render(210, 210, (px, py) -> 15, truth, Scenes.blurredDisc(4.5, 2), 12);
		final double[] pixels = Scenes.noisy(clean, 3, 0, 255, 23);
		final double[] inverted = new double[pixels.length];
		for (int i = 0; i < inverted.length; i++)
			inverted[i] = 255 - pixels[i];
		final double[] x = new double[truth.size()], y = new double[truth.size()];
		for (int j = 0; j < x.length; j++) {
			x[j] = truth.get(j).x();
			y[j] = truth.get(j).y();
		}
		assertEquals(0, OtherContrast.blobs(new DoublePlane(pixels, 210, 210), new DoublePlane(inverted, 210, 210), x, y,
			SPACING - 0.5), truth.size() + " bright discs packed");
	}

	/** The packed monolayer's spacing (px): a diameter and half a pixel. */
	private static final double SPACING = 11;

	/** Nothing tracked: nothing to compare with, nothing counted. */
	@Test
	void nothingTrackedCountsNothing() {
		final Scenes.Frame f = field(1, Scenes.blurredDisc(5, 1.2));
		assertEquals(0, OtherContrast.blobs(new DoublePlane(f.pixels(), 160, 160), new DoublePlane(f.pixels(), 160, 160),
			new double[0], new double[0], 10));
	}
}
