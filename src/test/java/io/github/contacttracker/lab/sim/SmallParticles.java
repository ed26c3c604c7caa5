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

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * Particles a few pixels across, as much colloid footage shows them (trackpy's bulk_water sample: about 8 px): a
 * Gaussian spot of height 60 and standard deviation 1.35 px (diameter about 7.5 px, where its image meets the
 * background) on background 40 with noise of 2 grey levels, 8-bit. Each frame holds 40 scattered particles at least
 * 14 px apart, 10 px from the edges, and a pair at contact (6 px apart) away from them. At the threshold the helper
 * suggests their active areas hold about 20 px, and the default {@code min_area} of 20 px drops many.
 */
public final class SmallParticles {

	/** Frame width and height (px). */
	public static final int WIDTH = 200, HEIGHT = 160;

	private SmallParticles() {}

	/** @param frames the frames, 8-bit; {@code truth} each frame's true centres {x, y} (px) */
	public record Field(List<ArrayImg<UnsignedByteType, ?>> frames, List<List<double[]>> truth) {}

	/** @return {@code count} frames of such particles, the layout drawn anew in each from {@code seed} */
	public static Field simulate(final int count, final long seed) {
		final SplittableRandom rnd = new SplittableRandom(seed);
		final ImageSimulator sim = new ImageSimulator(r -> 60 * Math.exp(-r * r / (2 * 1.35 * 1.35)), 3);
		final List<ArrayImg<UnsignedByteType, ?>> frames = new ArrayList<>();
		final List<List<double[]>> truth = new ArrayList<>();
		for (int t = 0; t < count; t++) {
			final double a = rnd.nextDouble() * Math.PI;
			final double[] p = { 100 + rnd.nextDouble(), 80 + rnd.nextDouble() }, q = { p[0] + 6 * Math.cos(a), p[1] + 6 *
				Math.sin(a) };
			final List<double[]> c = new ArrayList<>(List.of(p, q));
			while (c.size() < 42) {
				final double[] n = { 10 + rnd.nextDouble() * (WIDTH - 20), 10 + rnd.nextDouble() * (HEIGHT - 20) };
				if (c.stream().allMatch(o -> Math.hypot(n[0] - o[0], n[1] - o[1]) > 14)) c.add(n);
			}
			truth.add(c);
			frames.add(Quantiser.toUnsignedBytes(sim.render(c, WIDTH, HEIGHT, 40), NoiseModel.gaussian(2), rnd).image());
		}
		return new Field(frames, truth);
	}
}
