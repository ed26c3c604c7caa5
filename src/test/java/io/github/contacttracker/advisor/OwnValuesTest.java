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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.SplittableRandom;

import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.report.ProfileReport;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import org.junit.jupiter.api.Test;

/**
 * The helper's values never raise the helper's own warnings. {@code r_out} is where a particle's light returns to
 * the background, which for a haloed bright-field particle lies beyond a diameter: a warning against {@code r_out > D}
 * would speak against the helper's own suggestion. On real-like simulated frames no warning speaks of r_out, the
 * threshold or the particle profiled, and what r_out means for the paper's second pass at contact is the discs'
 * geometry, checked here by counting points.
 */
class OwnValuesTest {

	/** Three real-like frames: long halos and clusters, dense saturated cores stored as JPEG, small isolated ones. */
	static List<RandomAccessibleInterval<UnsignedByteType>> frames() throws IOException {
		final int w = 480, h = 480;
		final SplittableRandom rnd = new SplittableRandom(3);
		final List<double[]> dense = ProfileSuggestionTest.scattered(40, w, h, 20, 40, rnd);
		final NoiseFreeImage exact = new ImageSimulator(ProfileSuggestionTest.BRIGHT_FIELD, 3).render(dense, w, h, 0);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				exact.pixels()[y * w + x] += 132 + 8.0 * (x + y) / (w + h);
		final byte[] noisy = ((ByteArray) Quantiser.toUnsignedBytes(exact, NoiseModel.gaussian(4), rnd).image().update(
			null)).getCurrentStorageArray();
		final List<double[]> isolated = ProfileSuggestionTest.scattered(5, 320, 320, 40, 90, rnd);
		return List.of(ProfileAtParticleTest.frame(1), ArrayImgs.unsignedBytes(ProfileSuggestionTest.jpeg(noisy, w, h,
			0.5f), w, h), RealFootageFailuresTest.frame(320, 320, RealFootageFailuresTest.SMALL, isolated, (x, y) -> 100, 2,
				10));
	}

	@Test
	void theHelpersValuesRaiseNoneOfItsWarnings() throws IOException {
		int beyondDiameter = 0;
		for (final RandomAccessibleInterval<UnsignedByteType> frame : frames()) {
			final ProfileAnalysis.Result r = ProfileAnalysis.analyse(frame, 0, 0);
			final List<String> warnings = ProfileReport.warnings(r);
			assertEquals(List.of(), warnings.stream().filter(s -> s.contains("r_out")).toList(), "r_out");
			for (final Finding f : r.findings())
				assertTrue(!(f instanceof Finding.ThresholdAboveCentre || f instanceof Finding.NotBackToBackground ||
					f instanceof Finding.MergedAtPoint), f.toString());
			assertTrue(r.activeRadius() > 0, "the suggested threshold leaves an active area");
			if (r.suggestedROut() > r.diameter()) beyondDiameter++;
			// what the paper's second pass keeps at contact, by the geometry: the active pixels farther than r_out
			// from a neighbour's centre one diameter away
			final double a = r.activeRadius(), rOut = r.suggestedROut(), d = r.diameter();
			int kept = 0, all = 0;
			for (double y = -a; y <= a; y += 0.01)
				for (double x = -a; x <= a; x += 0.01)
					if (x * x + y * y <= a * a) {
						all++;
						if ((x - d) * (x - d) + y * y > rOut * rOut) kept++;
					}
			assertEquals(Math.PI * a * a * kept / all, r.secondPassArea(), 0.01 * Math.PI * a * a + 0.1, "second area");
			assertEquals(r.secondPassArea() < TrackerParameters.DEFAULT_MIN_SECOND_AREA, ProfileReport.lines(r, true)
				.stream().anyMatch(l -> l.contains("--method paper keeps the first pass")), "said when the paper's " +
					"second pass falls back");
		}
		assertTrue(beyondDiameter > 0, "a frame whose r_out lies beyond the diameter");
	}
}
