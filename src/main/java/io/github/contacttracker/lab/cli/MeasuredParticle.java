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

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import ij.ImagePlus;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.lab.eval.SceneStudy;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.TabulatedProfile;

/**
 * A simulated particle like a real movie's ({@code accuracy --scene ... --particle movie:PATH}): its radial profile,
 * background and noise as the profile helper measures them on the movie's first frame, with the threshold, r_out
 * and diameter it suggests; the paper's pixel size (84.7 nm), so the errors read in the same nanometres as the other
 * particles'. Scenes of it at contact show how accurate the methods are on particles that look like the real ones,
 * where the real movie has no ground truth.
 * <p>
 * A movie of several kinds of particle ({@code core.kind}) gives one particle per kind ({@link #kinds}): the
 * kinds found and each kind's profile measured as the tracker measures them ({@code fit}, kinds found
 * automatically, on the movie's first {@link #KIND_FRAMES} frames), with the movie's background, noise,
 * threshold, r_out and diameter (the kinds of a movie are taken as the same particles, in and out of focus).
 */
final class MeasuredParticle {

	/** The pixel size the simulated particle is given (nm): the paper's. */
	static final double PIXEL_NM = 84.7;
	/** The prefix of a particle key that names a movie. */
	static final String PREFIX = "movie:";

	/** The first frames of a movie its kinds and their profiles are measured on. */
	static final int KIND_FRAMES = 8;
	/** Step of the table a measured kind's profile is rendered from (px). */
	static final double TABLE_STEP_PX = 0.25;

	private MeasuredParticle() {}

	/**
	 * @return the particle of each kind found on {@code movie}'s first frames ({@code "like NAME kind K"}), or the one
	 *         particle of {@link #of} (named {@code "like NAME"}) when the movie shows one kind
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	static SceneStudy.Kinds kinds(final Path movie) throws java.io.IOException {
		final ParticleType whole = of(movie);
		final ImagePlusFrames frames = ImagePlusFrames.of(ImageFiles.open(movie), 1);
		final List<net.imglib2.RandomAccessibleInterval> all = (List) frames.frames();
		final int count = Math.min(KIND_FRAMES, all.size());
		final StackTracker tracker = new StackTracker(TrackerParameters.of(whole.threshold(), whole.rOut()).withMethod(
			Method.FIT));
		final StackTracker.ProfileStage stage = tracker.profileStage(count, t -> all.get(t), () -> false);
		final KindProfiles profiles = stage == null ? null : stage.profile();
		if (profiles == null || profiles.count() < 2) return new SceneStudy.Kinds(whole.name(), List.of(whole));
		final List<ParticleType> kinds = new ArrayList<>();
		for (int c = 0; c < profiles.count(); c++)
			kinds.add(new ParticleType(whole.name() + " kind " + (c + 1), whole.diameterMicrons(), PIXEL_NM, table(
				profiles.profile(c)), whole.background(), whole.threshold(), whole.rOut(), whole.noise()));
		return new SceneStudy.Kinds(whole.name(), kinds);
	}

	/** @return the measured profile as a table, 0 beyond its radius */
	static TabulatedProfile table(final EmpiricalProfile p) {
		final int n = (int) Math.ceil(p.radius() / TABLE_STEP_PX) + 1;
		final double[] radii = new double[n + 1], values = new double[n + 1];
		for (int i = 0; i <= n; i++) {
			radii[i] = i * TABLE_STEP_PX;
			values[i] = i < n ? p.value(radii[i]) : 0;
		}
		return new TabulatedProfile(radii, values);
	}

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
