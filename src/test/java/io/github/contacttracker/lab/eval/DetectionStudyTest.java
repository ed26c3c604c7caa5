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
package io.github.contacttracker.lab.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.lab.sim.DetectionScenes;

/** The detection study's judging, on spots made from the truth: what it counts must follow from what it is given. */
class DetectionStudyTest {

	private static Localization spot(final double x, final double y, final int flags) {
		return spot(x, y, flags, 0.01);
	}

	/** @param sigma the standard error the spot reports on x and y (NaN: none) */
	private static Localization spot(final double x, final double y, final int flags, final double sigma) {
		return new Localization(0, x, y, x, y, 100, 100, 1, 6, flags, 1, sigma, sigma, Double.NaN, Double.NaN, 0);
	}

	private static DetectionStudy.Tracked tracked(final List<List<Localization>> spots) {
		return new DetectionStudy.Tracked(spots, "test", 12, 0, "");
	}

	@Test
	void exactSpotsAreAllFoundUnbiasedAndUnflagged() {
		final DetectionScene scene = DetectionScenes.pairSweep(4, 5);
		final List<List<Localization>> spots = new ArrayList<>();
		for (final List<double[]> t : scene.truth()) {
			final List<Localization> f = new ArrayList<>();
			for (final double[] c : t)
				f.add(spot(c[0] + 0.01, c[1], 0));
			spots.add(f);
		}
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, tracked(spots));
		final DetectionStudy.Row all = study.total();
		assertEquals(8, all.particles());
		assertEquals(1.0, all.recall());
		assertEquals(0, all.falseSpots());
		assertEquals(1.0, all.unflaggedShare());
		assertEquals(0.01, all.biasX(), 1e-9);
		assertEquals(0, all.biasY(), 1e-9);
		assertEquals(0, all.spread(), 1e-9);
		assertEquals(Math.sqrt(0.5), all.errorOverReported(), 1e-9); // 0.01 px off along x, at a reported 0.01
		assertTrue(all.bound() > 0.005 && all.bound() < 0.05, "bound " + all.bound());
		assertEquals(4, study.labels().size());
		assertTrue(Double.isNaN(DetectionStudy.failsAt(study.labels())));
	}

	/**
	 * Spots off their particles by 0.03 px along x and 0.04 along y, each reporting 0.01 px on both: the reported error
	 * is 0.01 px, and the errors are 3 and 4 times it, so that error / σ is the root of (9 + 16) / 2. A spot that
	 * reports no error (NaN) counts in the bias and spread but not in these two.
	 */
	@Test
	void theReportedErrorsAreComparedWithTheErrors() {
		final DetectionScene scene = DetectionScenes.pairSweep(2, 5);
		final List<List<Localization>> spots = new ArrayList<>();
		for (final List<double[]> t : scene.truth())
			spots.add(List.of(spot(t.get(0)[0] + 0.03, t.get(0)[1] + 0.04, 0), spot(t.get(1)[0] + 0.03, t.get(1)[1] +
				0.04, 0, Double.NaN)));
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, tracked(spots));
		final DetectionStudy.Row all = study.total();
		assertEquals(4, all.measured());
		assertEquals(0.01, all.reported(), 1e-12);
		assertEquals(Math.sqrt((9 + 16) / 2.0), all.errorOverReported(), 1e-9);
		final List<List<Localization>> none = new ArrayList<>();
		for (final List<double[]> t : scene.truth())
			none.add(List.of(spot(t.get(0)[0], t.get(0)[1], 0, Double.NaN), spot(t.get(1)[0], t.get(1)[1], 0,
				Double.NaN)));
		final DetectionStudy without = new DetectionStudy();
		without.add(scene, tracked(none));
		assertTrue(Double.isNaN(without.total().reported()) && Double.isNaN(without.total().errorOverReported()));
	}

	/**
	 * One spot between the particles of the closest pair (a merge), flagged, and two far from any particle, one of
	 * them flagged: one particle found of two there, two false spots, one of them unflagged, and the band's unflagged
	 * share counts the flagged spots.
	 */
	@Test
	void aMergeAndAFalseSpotAreCounted() {
		final DetectionScene scene = DetectionScenes.pairSweep(2, 6);
		final List<double[]> far = scene.truth().get(0), near = scene.truth().get(1);
		final List<List<Localization>> spots = List.of(List.of(spot(far.get(0)[0], far.get(0)[1], 0), spot(far.get(1)[0],
			far.get(1)[1], 0)), List.of(spot(0.5 * (near.get(0)[0] + near.get(1)[0]) + 0.1, 0.5 * (near.get(0)[1] + near
				.get(1)[1]), Flag.MERGED.bit()), spot(15, 15, 0), spot(15, 40, Flag.NOT_CONVERGED.bit())));
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, tracked(spots));
		final List<DetectionStudy.Row> bands = study.bands();
		assertEquals(">= 1 D", bands.get(0).band());
		assertEquals(1.0, bands.get(0).recall());
		final DetectionStudy.Row close = bands.get(1);
		assertEquals("0.5-0.75 D", close.band());
		// at 0.5 D the pair's midpoint lies a quarter diameter from each particle: the merged spot finds one of them
		assertEquals(0.5, close.recall());
		assertEquals(2, close.falseSpots());
		assertEquals(1, close.falseUnflagged());
		assertEquals(1 / 3.0, close.unflaggedShare(), 1e-12);
		assertEquals(0.5, DetectionStudy.failsAt(study.labels()), 1e-9);
	}
}
