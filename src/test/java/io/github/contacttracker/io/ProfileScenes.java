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
package io.github.contacttracker.io;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import ij.ImagePlus;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.SimulatedStack;
import io.github.contacttracker.lab.sim.SmallParticles;
import net.imglib2.img.array.ArrayImg;

/**
 * Small 8-bit movies for the "Measure from the image" buttons (Fiji's dialog, TrackMate's panel): particles the
 * profile helper can measure, or none.
 */
public final class ProfileScenes {

	/** Small particles, defined here: D = 20 px, a dark ring near 16 px, background 40, Gaussian noise sigma 3. */
	public static final ParticleType SMALL = new ParticleType("small", 2.0, 100, new GaussianBesselProfile(120, 0.15,
		5), 40, 100, 16, NoiseModel.gaussian(3));
	/** Frame size (px). */
	public static final int SIZE = 200;

	private ProfileScenes() {}

	/**
	 * @param frames how many frames
	 * @param cal the calibration to set
	 * @return a time series; every frame holds three isolated particles and a pair at contact (so that the
	 *         diameter can be estimated), each frame at other sub-pixel positions and with its own noise
	 */
	public static ImagePlus particles(final String title, final int frames, final Calibration cal) {
		final SplittableRandom rnd = new SplittableRandom(20261202L);
		final double d = SMALL.diameterPx();
		final List<ArrayImg<?, ?>> images = new ArrayList<>();
		for (int t = 0; t < frames; t++) {
			final List<double[]> c = new ArrayList<>();
			for (final double[] at : new double[][] { { 2, 2 }, { 8, 2 }, { 2, 8 } })
				c.add(new double[] { at[0] * d + rnd.nextDouble(), at[1] * d + rnd.nextDouble() });
			final double px = 6.5 * d + rnd.nextDouble(), py = 6.5 * d + rnd.nextDouble();
			c.add(new double[] { px - d / 2, py });
			c.add(new double[] { px + d / 2, py });
			images.add(SimulatedStack.renderFrame(SMALL, c, SIZE, SIZE, SMALL.noise(), rnd, 8).image());
		}
		return TimeSeries.of(title, images, cal);
	}

	/**
	 * @return one frame of particles a few pixels across ({@link SmallParticles}): their active areas come near the
	 *         default {@code min_area}, and the buttons lower it
	 */
	public static ImagePlus tiny(final String title) {
		return TimeSeries.of(title, SmallParticles.simulate(1, 11).frames(), Calibration.PIXELS);
	}

	/**
	 * @return one frame of flat background: nothing to measure (on noise alone the helper finds spots of noise and
	 *         suggests values, with warnings)
	 */
	public static ImagePlus empty(final String title) {
		return TimeSeries.of(title, List.of(SimulatedStack.renderFrame(SMALL, List.of(), SIZE, SIZE, NoiseModel
			.none(), new SplittableRandom(3), 8).image()), Calibration.PIXELS);
	}
}
