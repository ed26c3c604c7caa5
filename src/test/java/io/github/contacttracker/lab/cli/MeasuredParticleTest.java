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

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.cli.ContactTrackerLab;

/** A particle measured on a movie is the particle the movie shows: checked on a simulated movie of a known one. */
class MeasuredParticleTest {

	@TempDir
	Path dir;

	/**
	 * Two 2.06 um-like particles three diameters apart: the measured type has the truth's background, noise and central
	 * height, and the pixel size the scenes are rendered at.
	 */
	@Test
	void aSimulatedMovieGivesBackItsParticle() throws Exception {
		final Path tif = dir.resolve("pair.tif");
		final java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
		assertEquals(0, ContactTrackerLab.run(new String[] { "simulate", "--scenario", "pair", "--separation", "3",
			"--particle", "2.06", "--frames", "2", "--seed", "5", "--out", tif.toString(), "--truth", dir.resolve(
				"truth.csv").toString() }, new java.io.PrintStream(new java.io.ByteArrayOutputStream()),
			new java.io.PrintStream(err)), err.toString());
		final ParticleType truth = PaperParticles.silica206(), measured = MeasuredParticle.of(tif);
		assertEquals(MeasuredParticle.PIXEL_NM, measured.pixelSizeNm());
		assertEquals(truth.background(), measured.background(), 1.0, "background");
		assertEquals(truth.noise().sigma(), measured.noise().sigma(), 0.15 * truth.noise().sigma(), "noise sigma");
		assertEquals(truth.profile().value(0), measured.profile().value(0), 0.05 * truth.profile().value(0),
			"central height above the background");
	}
}
