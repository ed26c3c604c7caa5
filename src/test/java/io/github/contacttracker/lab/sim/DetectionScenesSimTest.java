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

import net.imglib2.img.array.ArrayImg;
import net.imglib2.type.numeric.RealType;

/** The detection study's scenes are what they say they are: checked on their truth and their pixels. */
class DetectionScenesSimTest {

	@Test
	void blurredDiscHasAFlatTopAndHalfItsHeightAtItsEdge() {
		final BlurredDisc disc = new BlurredDisc(6, 1.5, 100);
		assertEquals(100, disc.value(0), 0.05);
		// a straight edge blurred by a Gaussian is at half height on the edge; a disc's curved edge a little below
		assertEquals(45, disc.value(6), 1.5);
		assertTrue(disc.value(6 + 4.5) < 0.2, "3 sigma outside: " + disc.value(10.5));
	}

	@Test
	void pairSweepGoesFromTwoDiametersToHalfOne() {
		final DetectionScene s = DetectionScenes.pairSweep(40, 1);
		final double d = s.scene().type().diameterPx();
		assertEquals(12, d, 1e-9);
		for (int t = 0; t < 40; t++) {
			final List<double[]> c = s.truth().get(t);
			final double sep = Math.hypot(c.get(0)[0] - c.get(1)[0], c.get(0)[1] - c.get(1)[1]) / d;
			assertEquals(s.labels()[t], sep, 1e-9);
		}
		assertEquals(2.0, s.labels()[0], 1e-12);
		assertEquals(0.5, s.labels()[39], 1e-12);
		assertEquals(">= 1 D", s.bands().get(0));
		assertEquals("0.5-0.75 D", s.bands().get(39));
	}

	@Test
	void dimSpotsLieOnAnOffsetOf500In16Bits() {
		final DetectionScene s = DetectionScenes.dim(1, 2);
		assertEquals(16, s.bitDepth());
		final double[] v = moments(s.frames().get(0));
		// offset 500 + 20 of background light; noise sqrt(2 * 20 + 16) = 7.5
		assertEquals(520, v[0], 2);
		assertTrue(v[1] > 7 && v[1] < 9, "noise " + v[1]);
		assertEquals(40, s.scene().particles().size());
		assertEquals(10, s.groups().stream().filter(DetectionScenes.TOUCHING::equals).count());
	}

	@Test
	void aThirdOfTheClippedBackgroundReadsZero() {
		final DetectionScene s = DetectionScenes.clipped(1, 3);
		final ArrayImg<?, ?> f = s.frames().get(0);
		long zeros = 0, all = 0;
		for (final Object p : f) {
			all++;
			if (((RealType<?>) p).getRealDouble() == 0) zeros++;
		}
		// the particles cover about a seventh of the frame; of the rest about 35% reads 0
		assertTrue(zeros > 0.25 * all && zeros < 0.4 * all, zeros + " of " + all + " pixels read 0");
	}

	/** Area fraction 0.7, no two discs overlapping, and almost every disc within 1 px of touching another. */
	@Test
	void denseMonolayerIsPackedWithoutOverlaps() {
		final DetectionScene s = DetectionScenes.denseBidisperse(1, 4);
		final List<Scene.Particle> ps = s.scene().particles();
		final List<double[]> c = s.truth().get(0);
		double area = 0;
		int alone = 0;
		for (int i = 0; i < ps.size(); i++) {
			area += Math.PI / 4 * s.diameter(i) * s.diameter(i);
			double gap = Double.POSITIVE_INFINITY;
			for (int j = 0; j < ps.size(); j++) {
				if (j == i) continue;
				final double g = Math.hypot(c.get(i)[0] - c.get(j)[0], c.get(i)[1] - c.get(j)[1]) - 0.5 * (s.diameter(i) + s
					.diameter(j));
				assertTrue(g > -0.011, "discs " + i + " and " + j + " overlap by " + -g + " px");
				gap = Math.min(gap, g);
			}
			if (gap > 1) alone++;
		}
		assertEquals(0.7, area / (512 * 512), 0.005);
		assertTrue(alone < 0.02 * ps.size(), alone + " of " + ps.size() + " discs more than 1 px from any other");
	}

	/**
	 * The confocal packing of many sizes: spheres at area fraction 0.72 that never overlap, almost every one within
	 * 1 px of touching another; each shows as a disc 0.9 of its diameter across, the discs' diameters spread evenly
	 * from 7 to 13.3 px (each third of that range holds about a third of them), so that neighbours show a dark line
	 * apart.
	 */
	@Test
	void polydispersePackingIsPackedWithoutOverlapsOverItsRangeOfSizes() {
		final DetectionScene s = DetectionScenes.densePolydisperse(1, 4);
		final List<Scene.Particle> ps = s.scene().particles();
		final List<double[]> c = s.truth().get(0);
		double area = 0, smallest = Double.POSITIVE_INFINITY, largest = 0;
		final int[] thirds = new int[3];
		int alone = 0;
		final double from = DetectionScenes.POLY_SMALLEST, to = from * DetectionScenes.POLY_RANGE;
		for (int i = 0; i < ps.size(); i++) {
			final double disc = s.diameter(i), sphere = disc / DetectionScenes.POLY_SECTION;
			area += Math.PI / 4 * sphere * sphere;
			smallest = Math.min(smallest, disc);
			largest = Math.max(largest, disc);
			thirds[Math.min(2, (int) (3 * (disc - from) / (to - from)))]++;
			double gap = Double.POSITIVE_INFINITY;
			for (int j = 0; j < ps.size(); j++) {
				if (j == i) continue;
				final double g = Math.hypot(c.get(i)[0] - c.get(j)[0], c.get(i)[1] - c.get(j)[1]) - 0.5 * (sphere + s
					.diameter(j) / DetectionScenes.POLY_SECTION);
				assertTrue(g > -0.011, "spheres " + i + " and " + j + " overlap by " + -g + " px");
				gap = Math.min(gap, g);
			}
			if (gap > 1) alone++;
		}
		assertEquals(0.72, area / (256 * 256), 0.01);
		assertTrue(alone < 0.02 * ps.size(), alone + " of " + ps.size() + " spheres more than 1 px from any other");
		assertTrue(smallest >= from && smallest < from + 0.2, "smallest disc " + smallest);
		assertTrue(largest <= to && largest > to - 0.2, "largest disc " + largest);
		for (final int n : thirds)
			assertTrue(n > 0.25 * ps.size() && n < 0.42 * ps.size(), java.util.Arrays.toString(thirds));
	}

	private static double[] moments(final ArrayImg<?, ?> f) {
		final double[] v = new double[(int) (f.dimension(0) * f.dimension(1))];
		int i = 0;
		for (final Object p : f)
			v[i++] = ((RealType<?>) p).getRealDouble();
		java.util.Arrays.sort(v);
		// the median and the half-width of the middle 68% (robust to the spots)
		return new double[] { v[v.length / 2], 0.5 * (v[(int) (0.84 * v.length)] - v[(int) (0.16 * v.length)]) };
	}
}
