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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.util.Intervals;
import net.imglib2.type.numeric.integer.UnsignedShortType;

class SimulatedStackTest {

	@TempDir
	Path dir;

	@Test
	void equalSeedsGiveEqualStacksAndOtherSeedsOtherStacks() {
		final ParticleType t = PaperParticles.silica553();
		final SimulatedStack<?> a = SimulatedStack.simulate(t, Scenario.PAIR, 1.1, 3, 42, 8);
		final SimulatedStack<?> b = SimulatedStack.simulate(t, Scenario.PAIR, 1.1, 3, 42, 8);
		assertTrue(mean(a.frames().get(0)) > t.background(), "wildcard frames pass to generic code");
		final SimulatedStack<?> c = SimulatedStack.simulate(t, Scenario.PAIR, 1.1, 3, 43, 8);
		for (int f = 0; f < 3; f++) {
			assertArrayEquals(QuantiserTest.pixels(a.frames().get(f)), QuantiserTest.pixels(b.frames().get(f)));
			assertArrayEquals(a.truth().get(f).get(1), b.truth().get(f).get(1), 0);
			assertFalse(java.util.Arrays.equals(QuantiserTest.pixels(a.frames().get(f)), QuantiserTest.pixels(c
				.frames().get(f))));
			assertTrue(a.truth().get(f).get(0)[0] != c.truth().get(f).get(0)[0]);
		}
		// frames differ from each other: offsets and noise are fresh
		assertFalse(java.util.Arrays.equals(QuantiserTest.pixels(a.frames().get(0)), QuantiserTest.pixels(a.frames()
			.get(1))));
	}

	@Test
	void framesFitTheParticlesAndTruthKeepsTheGeometry() {
		final ParticleType t = PaperParticles.silica553();
		final SimulatedStack<?> s = SimulatedStack.simulate(t, Scenario.TRIPLE, 1.5, 4, 7, 16);
		assertTrue(s.frames().get(0).firstElement() instanceof UnsignedShortType);
		assertEquals(Scenario.TRIPLE, s.scenario().orElseThrow());
		assertEquals(1.5, s.separationOverD(), 0);
		assertEquals(4, s.frameCount());
		assertEquals(0, s.clippedPixels());
		final double border = t.rOut() + SimulatedStack.MARGIN_PX;
		for (final List<double[]> centres : s.truth()) {
			assertEquals(3, centres.size());
			final double[] p0 = centres.get(0), p1 = centres.get(1), p2 = centres.get(2);
			assertEquals(1.5 * t.diameterPx(), Math.hypot(p1[0] - p0[0], p1[1] - p0[1]), 1e-9);
			assertEquals(Math.hypot(0.75, Math.sqrt(3) / 2) * t.diameterPx(), Math.hypot(p2[0] - p0[0], p2[1] - p0[1]),
				1e-9);
			for (final double[] p : centres)
				assertTrue(p[0] >= border && p[0] <= s.width() - 1 - border && p[1] >= border && p[1] <= s.height() - 1
					- border, "centre " + p[0] + "," + p[1] + " in " + s.width() + "x" + s.height());
		}
		assertEquals(s.width(), s.frames().get(0).dimension(0));
		assertEquals(s.height(), s.frames().get(0).dimension(1));
		// the offsets spread the configuration over a pixel
		final double x0 = s.truth().get(0).get(0)[0];
		assertTrue(s.truth().stream().anyMatch(c -> Math.abs(c.get(0)[0] - x0) > 0.05));
	}

	@Test
	void pixelsMatchTheExactRenderWithinTheNoise() {
		final ParticleType t = PaperParticles.silica206();
		final SimulatedStack<?> s = SimulatedStack.simulate(t, Scenario.PAIR, 1.3, 1, 5, 8);
		final NoiseFreeImage exact = new ImageSimulator(t.profile()).render(s.truth().get(0), s.width(), s.height(), t
			.background());
		final int[] pixels = QuantiserTest.pixels(s.frames().get(0));
		double worst = 0, sum = 0;
		for (int i = 0; i < pixels.length; i++) {
			worst = Math.max(worst, Math.abs(pixels[i] - exact.pixels()[i]));
			sum += pixels[i] - exact.pixels()[i];
		}
		assertTrue(worst <= 5.5, "noise amplitude 5 plus rounding, got " + worst);
		assertEquals(0, sum / pixels.length, 0.05);
		// the corners show the background: the frame leaves room around the rings
		assertEquals(t.background(), exact.get(0, 0), 0.5);
	}

	@Test
	void truthCsvHasOneLinePerParticleAndFrame() throws IOException {
		final ParticleType t = PaperParticles.silica553();
		final SimulatedStack<?> s = SimulatedStack.simulate(t, Scenario.PAIR, 1, 2, 9, 8);
		final StringWriter out = new StringWriter();
		s.writeTruthCsv(out);
		final String[] lines = out.toString().split("\n");
		assertEquals(5, lines.length);
		assertEquals("frame,particle,x_px,y_px,x_um,y_um", lines[0]);
		final String[] row = lines[4].split(",");
		assertEquals("1", row[0]);
		assertEquals("1", row[1]);
		final double[] truth = s.truth().get(1).get(1);
		assertEquals(truth[0], Double.parseDouble(row[2]), 0);
		assertEquals(truth[1], Double.parseDouble(row[3]), 0);
		assertEquals(truth[0] * 0.0847, Double.parseDouble(row[4]), 1e-12);
		assertEquals(truth[1] * 0.0847, Double.parseDouble(row[5]), 1e-12);
	}

	@Test
	void benchmarkStackHasFourTouchingPairsAndFourSingles() {
		final ParticleType t = PaperParticles.silica553();
		final SimulatedStack<UnsignedByteType> s = SimulatedStack.benchmarkStack(t, 2, 3);
		assertEquals(512, s.width());
		assertEquals(512, s.height());
		assertEquals(512, s.frames().get(1).dimension(0));
		assertTrue(s.scenario().isEmpty());
		assertEquals(4, s.measuredPairs().size());
		final List<double[]> c = s.truth().get(1);
		assertEquals(12, c.size());
		for (final int[] pair : s.measuredPairs())
			assertEquals(t.diameterPx(), Math.hypot(c.get(pair[0])[0] - c.get(pair[1])[0], c.get(pair[0])[1] - c.get(
				pair[1])[1]), 1e-9);
		// with the 5.53 um-like preset every rOut disc lies inside the frame and discs of different groups
		// (a pair, or a single particle) do not overlap
		for (final double[] p : c)
			assertTrue(p[0] - t.rOut() >= 0 && p[0] + t.rOut() <= 511 && p[1] - t.rOut() >= 0 && p[1] + t.rOut() <= 511);
		for (int i = 0; i < 12; i++)
			for (int j = i + 1; j < 12; j++) {
				final boolean samePair = j < 8 && i / 2 == j / 2;
				final double distance = Math.hypot(c.get(i)[0] - c.get(j)[0], c.get(i)[1] - c.get(j)[1]);
				if (!samePair) assertTrue(distance > 2 * t.rOut(), i + "-" + j + ": " + distance);
			}
		// a generic consumer accepts the frames as they are
		assertEquals(t.background(), mean(s.frames().get(0)), 5);
	}

	/** A stand-in for the tracker's generic entry points. */
	private static <T extends RealType<T>> double mean(final RandomAccessibleInterval<T> image) {
		double sum = 0;
		for (final T v : image)
			sum += v.getRealDouble();
		return sum / Intervals.numElements(image);
	}

	@Test
	void renderFrameDrawsAnyLayout() {
		final ParticleType t = PaperParticles.silica553();
		final QuantisedFrame<?> frame = SimulatedStack.renderFrame(t, List.<double[]> of(new double[] { 40, 30 }), 80,
			60, NoiseModel.none(), new SplittableRandom(1), 8);
		final int[] pixels = QuantiserTest.pixels(frame.image());
		assertEquals(180, pixels[30 * 80 + 40], 1);
		assertEquals(0, frame.clippedPixels());
	}
}
