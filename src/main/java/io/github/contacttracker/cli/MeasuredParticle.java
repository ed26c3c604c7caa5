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
package io.github.contacttracker.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import ij.ImagePlus;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImagePlusFrames;
import io.github.contacttracker.sim.NoiseModel;
import io.github.contacttracker.sim.ParticleType;
import io.github.contacttracker.sim.TabulatedProfile;

/**
 * A simulated particle like a real movie's ({@code accuracy --scene ... --particle movie:PATH}): its radial profile,
 * background and noise as the profile helper measures them on the movie's first frame, with the threshold, r_out
 * and diameter it suggests; the paper's pixel size (84.7 nm), so the errors read in the same nanometres as the other
 * particles'. Scenes of it at contact show how accurate the methods are on particles that look like the real ones,
 * where the real movie has no ground truth.
 */
final class MeasuredParticle {

	/** The pixel size the simulated particle is given (nm): the paper's. */
	static final double PIXEL_NM = 84.7;
	/** The prefix of a particle key that names a movie. */
	static final String PREFIX = "movie:";

	private MeasuredParticle() {}

	/** @return the particle type measured on {@code movie}'s first frame */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	static ParticleType of(final Path movie) throws java.io.IOException {
		final ImagePlus imp = ImageFiles.open(movie);
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, 1);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse((net.imglib2.RandomAccessibleInterval) frames.frames()
			.get(0), 0, 0);
		final boolean integerData = imp.getBitDepth() != 32;
		// the rings measured (some may hold no pixel), from r = 0 with the innermost ring's level
		final List<double[]> points = new ArrayList<>();
		for (int k = 0; k < r.radius().length; k++)
			if (r.count()[k] > 0) {
				if (points.isEmpty()) points.add(new double[] { 0, r.level()[k] - r.background() });
				if (r.radius()[k] > points.get(points.size() - 1)[0]) points.add(new double[] { r.radius()[k], r.level()[k] -
					r.background() });
			}
		final double[] radii = new double[points.size()], values = new double[points.size()];
		for (int i = 0; i < radii.length; i++) {
			radii[i] = points.get(i)[0];
			values[i] = points.get(i)[1];
		}
		return new ParticleType("like " + movie.getFileName(), r.suggestedDiameter() * PIXEL_NM / 1000, PIXEL_NM,
			new TabulatedProfile(radii, values), r.background(), r.suggestedThreshold(integerData), r.suggestedROut(),
			NoiseModel.gaussian(r.noise()));
	}
}
