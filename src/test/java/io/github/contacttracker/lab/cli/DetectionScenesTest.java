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
package io.github.contacttracker.lab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.lab.eval.DetectionStudy;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.lab.sim.DetectionScenes;

/**
 * Detection as a new user meets it, on the detection study's scenes, small and few: what the tracker meets today,
 * held so that it does not get worse. What it does not meet yet is in the documentation's report of the study.
 */
class DetectionScenesTest {

	private static DetectionStudy study(final DetectionScene scene) {
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, new NewUserTracker(2).track(scene));
		return study;
	}

	/**
	 * A blurred pair swept from 2 D to 0.5 D in 10 frames. At 1 D and more apart (7 frames) both particles are found
	 * in every frame, no spot is false, at least 9 in 10 spots are unflagged, and their centres are within 0.05 px of
	 * the truth (the study's 3 movies of 40 frames: 0.002 px) with a spread within twice the bound (there: 1.06).
	 */
	@Test
	void pairSweepApartIsFoundAndCentred() {
		final DetectionStudy study = study(DetectionScenes.pairSweep(10, 21));
		final DetectionStudy.Row apart = study.bands().get(0);
		assertEquals(">= 1 D", apart.band());
		assertEquals(14, apart.particles());
		assertEquals(1.0, apart.recall(), "recall");
		assertEquals(0, apart.falseSpots(), "false spots");
		assertEquals(0, apart.duplicates(), "duplicates");
		assertTrue(apart.unflaggedShare() >= 0.9, "unflagged " + apart.unflaggedShare() + ", mostly " + apart
			.mainFlag());
		assertTrue(apart.worstBias() < 0.05, "bias " + apart.worstBias() + " px");
		assertTrue(apart.spreadOverBound() < 2, "spread / CRB " + apart.spreadOverBound());
	}
}
