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
package io.github.contacttracker.trackmate;

import io.github.contacttracker.settings.TrackMateSettings;
import java.util.HashMap;
import java.util.Map;

import io.github.contacttracker.core.TrackerParameters;
import net.imglib2.Cursor;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.type.numeric.real.FloatType;
import io.github.contacttracker.settings.SettingsOf;

/** Small deterministic test frames: Gaussian particles on a flat background, rendered in pixel units. */
final class TestImages {

	static final double BACKGROUND = 20;
	static final double AMPLITUDE = 200;
	static final double SIGMA = 3.5;
	static final int WIDTH = 64;
	static final int HEIGHT = 56;

	/** Particle centres (x, y) in pixels of frame 0: a close pair and a lone particle. */
	static final double[][] CENTRES = { { 20.3, 22.7 }, { 34.9, 25.3 }, { 48.2, 40.8 } };

	/** Parameters that find the three particles (the pair's discs reach each other: second pass). */
	static TrackerParameters params() {
		// The paper's method, so the close pair exercises the second pass the assertions look for.
		return TrackerParameters.of(80, 10).withMinArea(10).withMinSecondArea(10).withMethod(io.github.contacttracker.core.Method.PAPER);
	}

	static Map<String, Object> settings(final int channel) {
		return new HashMap<>(SettingsOf.map(params(), channel));
	}

	private TestImages() {}

	/** @return an image of {@code dims} (X, Y first), each XY plane filled by {@link #renderPlane}. */
	static ArrayImg<FloatType, FloatArray> image(final long... dims) {
		final ArrayImg<FloatType, FloatArray> img = ArrayImgs.floats(dims);
		final long planes = img.size() / (dims[0] * dims[1]);
		final float[] data = img.update(null).getCurrentStorageArray();
		for (int p = 0; p < planes; p++)
			renderPlane(data, p * (int) (dims[0] * dims[1]), (int) dims[0], (int) dims[1], p);
		return img;
	}

	/**
	 * Renders plane number {@code p}: the particles of {@link #CENTRES} shifted by {@code (1.7 p, 0.9 p)}; odd
	 * planes are dimmer (amplitude x 0.8) so that planes differ in more than position.
	 */
	static void renderPlane(final float[] data, final int offset, final int w, final int h, final int p) {
		final double amp = p % 2 == 0 ? AMPLITUDE : 0.8 * AMPLITUDE;
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				double v = BACKGROUND;
				for (final double[] c : CENTRES) {
					final double ddx = x - c[0] - 1.7 * p, ddy = y - c[1] - 0.9 * p;
					v += amp * Math.exp(-(ddx * ddx + ddy * ddy) / (2 * SIGMA * SIGMA));
				}
				data[offset + y * w + x] = (float) v;
			}
	}

	/** Sets every pixel to the background: an empty plane. */
	static void blank(final Cursor<FloatType> c) {
		while (c.hasNext())
			c.next().setReal(BACKGROUND);
	}
}
