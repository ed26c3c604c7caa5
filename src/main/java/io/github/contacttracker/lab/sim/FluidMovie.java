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
import java.util.stream.IntStream;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * A movie of a 2D colloidal fluid with a known pair potential: {@link MonteCarloFluid} configurations rendered as
 * 8-bit frames with {@link ImageSimulator} and the particle type's noise. The frame is the Monte Carlo box
 * itself (pixel {@code (i, j)} centred at {@code (i, j)}, the box covering {@code [-0.5, size - 0.5)}), and
 * particles are drawn with their periodic images, so the frame is a window onto an unbounded fluid: particles
 * cut by the border look as they would in a real field of view, and have neighbours beyond it.
 *
 * @param frames the frames
 * @param truth per frame, the true centres {@code {x, y}} (px) of the particles whose centre lies in the frame
 * @param type the particles
 * @param interaction the true pair potential
 * @param width frame width (px)
 * @param height frame height (px)
 * @param clippedPixels pixels clipped to 0..255 over all frames (overlapping bright cores can saturate)
 */
public record FluidMovie(List<ArrayImg<UnsignedByteType, ?>> frames, List<List<double[]>> truth, ParticleType type,
	PairInteraction interaction, int width, int height, long clippedPixels)
{

	/** Copies the lists. */
	public FluidMovie {
		frames = List.copyOf(frames);
		truth = List.copyOf(truth);
	}

	/**
	 * @param type the particles (profile, background, noise)
	 * @param interaction the pair potential, in pixels
	 * @param particles number of particles in the frame
	 * @param width frame width (px)
	 * @param height frame height (px)
	 * @param frameCount frames
	 * @param sweepsBetween Monte Carlo sweeps between frames
	 * @param seed seed of the configurations and the noise
	 * @return the movie (frames rendered in parallel; the result does not depend on the number of threads)
	 */
	public static FluidMovie simulate(final ParticleType type, final PairInteraction interaction, final int particles,
		final int width, final int height, final int frameCount, final int sweepsBetween, final long seed)
	{
		final SplittableRandom random = new SplittableRandom(seed);
		final List<List<double[]>> configs = new MonteCarloFluid(interaction, particles, width, height).sample(
			frameCount, sweepsBetween, random.nextLong());
		final long[] noiseSeeds = new long[frameCount];
		for (int f = 0; f < frameCount; f++)
			noiseSeeds[f] = random.nextLong();
		final ImageSimulator simulator = new ImageSimulator(type.profile());
		final double reach = simulator.cutoffRadius() + 1;
		final List<List<double[]>> truth = new ArrayList<>(frameCount);
		for (final List<double[]> c : configs) {
			final List<double[]> shifted = new ArrayList<>(c.size());
			for (final double[] p : c)
				shifted.add(new double[] { p[0] - 0.5, p[1] - 0.5 });
			truth.add(List.copyOf(shifted));
		}
		@SuppressWarnings("unchecked")
		final QuantisedFrame<UnsignedByteType>[] rendered = new QuantisedFrame[frameCount];
		IntStream.range(0, frameCount).parallel().forEach(f -> {
			final NoiseFreeImage exact = NoiseFreeImage.uniform(width, height, type.background());
			for (final double[] p : truth.get(f))
				for (int kx = -1; kx <= 1; kx++)
					for (int ky = -1; ky <= 1; ky++) {
						final double x = p[0] + kx * width, y = p[1] + ky * height;
						// only the copies whose light reaches the frame
						if (x > -reach && x < width + reach && y > -reach && y < height + reach)
							simulator.addParticle(exact, x, y);
					}
			rendered[f] = Quantiser.toUnsignedBytes(exact, type.noise(), new SplittableRandom(noiseSeeds[f]));
		});
		final List<ArrayImg<UnsignedByteType, ?>> frames = new ArrayList<>(frameCount);
		long clipped = 0;
		for (final QuantisedFrame<UnsignedByteType> q : rendered) {
			frames.add(q.image());
			clipped += q.clippedPixels();
		}
		return new FluidMovie(frames, truth, type, interaction, width, height, clipped);
	}
}
