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

import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * A simulated movie with its ground truth. Every frame shows the same configuration, displaced as a whole by
 * a random sub-pixel offset (uniform in [-0.5, 0.5) px along x and y) and with fresh noise, both drawn from
 * one generator seeded by the caller: equal seeds give identical stacks.
 *
 * @param <T> pixel type ({@code UnsignedByteType} or {@code UnsignedShortType})
 * @param frames the frames, in order
 * @param truth per frame, the true centres {@code {x, y}} (px, TrackMate convention), in particle index order
 * @param type the particles simulated
 * @param scenario the paper's geometry, or empty for {@link #benchmarkStack}'s layout
 * @param separationOverD the measured pairs' centre distance in diameters (1 = contact)
 * @param measuredPairs index pairs whose distance is the quantity of interest
 * @param width frame width (px)
 * @param height frame height (px)
 * @param clippedPixels pixels clipped to the pixel type's range, over all frames (0 for the presets)
 */
public record SimulatedStack<T extends RealType<T> & NativeType<T>>(List<ArrayImg<T, ?>> frames,
	List<List<double[]>> truth, ParticleType type, Optional<Scenario> scenario, double separationOverD,
	List<int[]> measuredPairs, int width, int height, long clippedPixels)
{

	/** Free border (px) between the outermost particle's visible reach and the image edge. */
	public static final double MARGIN_PX = 8;
	/** Size of {@link #benchmarkStack} frames (px, square). */
	public static final int BENCHMARK_SIZE = 512;

	/** Copies the lists (not the arrays in them). */
	public SimulatedStack {
		frames = List.copyOf(frames);
		truth = List.copyOf(truth);
		Objects.requireNonNull(type, "type");
		Objects.requireNonNull(scenario, "scenario");
		measuredPairs = List.copyOf(measuredPairs);
		if (frames.size() != truth.size())
			throw new IllegalArgumentException(frames.size() + " frames but truth for " + truth.size());
	}

	/**
	 * Simulates one of the paper's scenarios. The frame is just large enough for every particle's visible
	 * reach ({@code max(reach(0.5), rOut)}) plus {@link #MARGIN_PX} and the frame offsets; the configuration is
	 * centred in it.
	 *
	 * @param type the particles
	 * @param scenario the geometry
	 * @param separationOverD the measured pair's centre distance in diameters
	 * @param frameCount number of frames
	 * @param seed seed of the offsets and the noise
	 * @param bitDepth 8 or 16
	 * @return the stack (its pixel type follows {@code bitDepth})
	 */
	public static SimulatedStack<?> simulate(final ParticleType type, final Scenario scenario,
		final double separationOverD, final int frameCount, final long seed, final int bitDepth)
	{
		final List<double[]> centred = scenario.centres(separationOverD, type.diameterPx(), 0, 0);
		double minX = Double.POSITIVE_INFINITY, maxX = Double.NEGATIVE_INFINITY;
		double minY = Double.POSITIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
		for (final double[] c : centred) {
			minX = Math.min(minX, c[0]);
			maxX = Math.max(maxX, c[0]);
			minY = Math.min(minY, c[1]);
			maxY = Math.max(maxY, c[1]);
		}
		final double visibleReach = Math.max(type.profile().reach(PaperParticles.REACH_LEVEL), type.rOut());
		final double halfBorder = visibleReach + MARGIN_PX + 0.5; // 0.5: room for the frame offset
		final int width = (int) Math.ceil(maxX - minX + 2 * halfBorder) + 1;
		final int height = (int) Math.ceil(maxY - minY + 2 * halfBorder) + 1;
		final double shiftX = 0.5 * (width - 1) - 0.5 * (minX + maxX);
		final double shiftY = 0.5 * (height - 1) - 0.5 * (minY + maxY);
		final List<double[]> layout = translate(centred, shiftX, shiftY);
		return stack(type, layout, Optional.of(scenario), separationOverD, List.of(scenario.measuredPair()), width,
			height, frameCount, seed, bitDepth);
	}

	/**
	 * A {@value #BENCHMARK_SIZE} x {@value #BENCHMARK_SIZE} 8-bit stack of 12 particles for speed and
	 * robustness tests: four touching pairs (centre distance D; indices 0-1, 2-3, 4-5, 6-7) and four single
	 * particles (8-11). Row {@code k = 0..3} is centred at {@code y = 64 + 128 k}: its pair's midpoint at
	 * {@code x = 170}, horizontal (tilted pairs would bring discs of different rows together), its single
	 * particle at {@code x = 390}. With the 5.53 um-like preset ({@code R_out} = 61 px) every {@code R_out}
	 * disc lies inside the frame and discs of different groups do not overlap; with longer-range profiles
	 * (2.06 um-like) the faint tails reach into neighbouring rows and past the edges. Frames move and get
	 * noise as in {@link #simulate}.
	 *
	 * @param type the particles
	 * @param frameCount number of frames
	 * @param seed seed of the offsets and the noise
	 * @return the stack
	 */
	@SuppressWarnings("unchecked")
	public static SimulatedStack<UnsignedByteType> benchmarkStack(final ParticleType type, final int frameCount,
		final long seed)
	{
		final double d = type.diameterPx();
		final double[] pairAngleDegrees = { 0, 0, 0, 0 };
		final List<double[]> pairs = new ArrayList<>();
		final List<double[]> singles = new ArrayList<>();
		final List<int[]> pairIndices = new ArrayList<>();
		for (int row = 0; row < 4; row++) {
			final double y = 64 + 128 * row;
			final double angle = Math.toRadians(pairAngleDegrees[row]);
			final double hx = 0.5 * d * Math.cos(angle);
			final double hy = 0.5 * d * Math.sin(angle);
			pairIndices.add(new int[] { pairs.size(), pairs.size() + 1 });
			pairs.add(new double[] { 170 - hx, y - hy });
			pairs.add(new double[] { 170 + hx, y + hy });
			singles.add(new double[] { 390, y });
		}
		final List<double[]> layout = new ArrayList<>(pairs);
		layout.addAll(singles);
		return (SimulatedStack<UnsignedByteType>) stack(type, layout, Optional.empty(), 1, pairIndices,
			BENCHMARK_SIZE, BENCHMARK_SIZE, frameCount, seed, 8);
	}

	/**
	 * One frame of any layout. Builds a renderer each call (about a millisecond): to render many frames of
	 * one type, keep an {@link ImageSimulator} and call {@link Quantiser} directly.
	 *
	 * @param type the particles (profile and background)
	 * @param centres particle centres {@code {x, y}} (px)
	 * @param width frame width (px)
	 * @param height frame height (px)
	 * @param noise noise to add (e.g. {@code type.noise()})
	 * @param random noise source
	 * @param bitDepth 8 or 16
	 * @return the frame and its clipping counts
	 */
	public static QuantisedFrame<?> renderFrame(final ParticleType type, final List<double[]> centres,
		final int width, final int height, final NoiseModel noise, final RandomGenerator random, final int bitDepth)
	{
		final NoiseFreeImage exact = new ImageSimulator(type.profile()).render(centres, width, height,
			type.background());
		return Quantiser.quantise(exact, noise, random, bitDepth);
	}

	/**
	 * Writes the truth as CSV: header {@code frame,particle,x_px,y_px,x_um,y_um}, one line per particle and
	 * frame, frames and particles 0-based, micrometres from {@link ParticleType#pixelSizeNm()}.
	 *
	 * @param out where to write (flushed, not closed)
	 * @throws IOException when writing fails
	 */
	public void writeTruthCsv(final Writer out) throws IOException {
		final double micronsPerPixel = type.pixelSizeMicrons();
		out.write("frame,particle,x_px,y_px,x_um,y_um\n");
		for (int f = 0; f < truth.size(); f++) {
			final List<double[]> centres = truth.get(f);
			for (int p = 0; p < centres.size(); p++) {
				final double x = centres.get(p)[0];
				final double y = centres.get(p)[1];
				out.write(f + "," + p + "," + plain(x) + "," + plain(y) + "," + plain(x * micronsPerPixel) + ","
					+ plain(y * micronsPerPixel) + "\n");
			}
		}
		out.flush();
	}

	/** @return the number of frames */
	public int frameCount() {
		return frames.size();
	}

	private static SimulatedStack<?> stack(final ParticleType type, final List<double[]> layout,
		final Optional<Scenario> scenario, final double separationOverD, final List<int[]> measuredPairs,
		final int width, final int height, final int frameCount, final long seed, final int bitDepth)
	{
		if (frameCount < 1) throw new IllegalArgumentException("need at least one frame, not " + frameCount);
		if (bitDepth != 8 && bitDepth != 16)
			throw new IllegalArgumentException("bit depth must be 8 or 16, not " + bitDepth);
		final ImageSimulator simulator = new ImageSimulator(type.profile());
		final SplittableRandom random = new SplittableRandom(seed);
		final List<ArrayImg<?, ?>> frames = new ArrayList<>(frameCount);
		final List<List<double[]>> truth = new ArrayList<>(frameCount);
		long clipped = 0;
		for (int f = 0; f < frameCount; f++) {
			final List<double[]> centres = translate(layout, random.nextDouble(-0.5, 0.5), random.nextDouble(-0.5,
				0.5));
			final NoiseFreeImage exact = simulator.render(centres, width, height, type.background());
			final QuantisedFrame<?> frame = Quantiser.quantise(exact, type.noise(), random, bitDepth);
			frames.add(frame.image());
			truth.add(centres);
			clipped += frame.clippedPixels();
		}
		return typed(frames, truth, type, scenario, separationOverD, measuredPairs, width, height, clipped);
	}

	// all frames share the pixel type chosen by bitDepth, so the unchecked cast is safe
	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static SimulatedStack<?> typed(final List<ArrayImg<?, ?>> frames, final List<List<double[]>> truth,
		final ParticleType type, final Optional<Scenario> scenario, final double separationOverD,
		final List<int[]> measuredPairs, final int width, final int height, final long clipped)
	{
		return new SimulatedStack(frames, truth, type, scenario, separationOverD, measuredPairs, width, height,
			clipped);
	}

	private static List<double[]> translate(final List<double[]> centres, final double dx, final double dy) {
		final List<double[]> moved = new ArrayList<>(centres.size());
		for (final double[] c : centres)
			moved.add(new double[] { c[0] + dx, c[1] + dy });
		return List.copyOf(moved);
	}

	private static String plain(final double v) {
		return BigDecimal.valueOf(v).toPlainString();
	}
}
