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
package io.github.contacttracker.core.track;

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.detect.ImageDetection;
import io.github.contacttracker.core.detect.ModelSelection;
import io.github.contacttracker.core.fit.ProfileRefinement;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.radial.CentreUncertainty;
import io.github.contacttracker.core.radial.ComponentShape;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.radial.Refinement;
import io.github.contacttracker.core.radial.SecondPass;
import io.github.contacttracker.core.radial.Solve;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Localizes the particles of one 2D frame with the close-contact radial-symmetry method of Yucel and
 * Okumusoglu (J. Phys.: Condens. Matter 29, 465101, 2017):
 * <ol>
 * <li>active areas: pixels {@code >= threshold}, labelled into components; components smaller than
 * {@code min_area} are dropped as noise;</li>
 * <li>first pass: each particle's radial-symmetry centre on its whole active area;</li>
 * <li>effective discs of radius {@code r_out} around the first centres;</li>
 * <li>second pass: each particle's centre again on its active area minus the other particles' discs.</li>
 * </ol>
 * Stateless and thread-safe: one instance can serve many threads.
 */
public final class ContactTracker {


	private final TrackerParameters params;

	public ContactTracker(final TrackerParameters params) {
		if (params == null) throw new IllegalArgumentException("parameters must be given");
		this.params = params;
	}

	/** @return the parameters */
	public TrackerParameters parameters() {
		return params;
	}

	/**
	 * Localizes the particles of a 2D frame.
	 *
	 * @param frame the frame; positions are returned in its coordinates (its interval minimum included)
	 * @param frameIndex the frame index written into the spots
	 * @return the spots, in raster order of their active areas' first pixels
	 * @throws IllegalArgumentException if the frame is not 2D or holds NaN or infinite pixels
	 */
	public <T extends RealType<T>> List<Localization> track(final RandomAccessibleInterval<T> frame,
		final int frameIndex)
	{
		return analyse(Plane.of(frame), frameIndex, false).spots();
	}

	/**
	 * Localizes the particles of a 2D frame and keeps each spot's active and second active areas.
	 *
	 * @see #track(RandomAccessibleInterval, int)
	 */
	public <T extends RealType<T>> FrameResult analyse(final RandomAccessibleInterval<T> frame,
		final int frameIndex)
	{
		return analyse(Plane.of(frame), frameIndex, true);
	}

	/** The whole pipeline on a plane; regions are kept only when asked for. */
	public FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions) {
		return analyse(plane, frameIndex, keepRegions, null);
	}

	/** The first pass with shape flags: the particles every refinement starts from (package-private for tests). */
	static Particle[] particles(final Plane plane, final TrackerParameters params) {
		final int[] discarded = new int[1];
		return withShapeFlags(firstPasses(plane, params, discarded), NoiseEstimate.sigma(plane), params, discarded);
	}

	/**
	 * Labels the active areas and runs the first pass on each; components below {@code min_area}, or without any
	 * gradient line (a flat plateau: nothing to localize), are counted in {@code discarded[0]}.
	 */
	private static List<Particle> firstPasses(final Plane plane, final TrackerParameters params,
		final int[] discarded)
	{
		final List<Particle> found = new ArrayList<>();
		for (final Region r : ComponentLabeling.label(plane, params.threshold(), params.connectivity())) {
			final Particle p = r.area() >= params.minArea() ? Particle.firstPass(plane, r, params.threshold()) : null;
			if (p != null) found.add(p);
			else discarded[0]++;
		}
		return found;
	}

	/**
	 * The whole pipeline on a plane, with the profile of each kind of particle measured beforehand (null: the profile
	 * methods measure their own on this frame).
	 */
	FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions,
		final KindProfiles profile)
	{
		return analyse(plane, frameIndex, keepRegions, profile, null);
	}

	/**
	 * As {@link #analyse(Plane, int, boolean, KindProfiles)}; where the image detects and the profiles are given,
	 * {@code particles} (an earlier result's spots, in the frame's coordinates; null: none) are refitted, none added
	 * or removed, instead of found again ({@link ModelSelection#refit}).
	 */
	FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions,
		final KindProfiles profile, final List<Localization> particles)
	{
		checkReach(plane, params);
		final int[] discarded = new int[1];
		final double noise = NoiseEstimate.sigma(plane);
		final Particle[] ps;
		final Refinement.Outcome outcome;
		double[] significance = null;
		final Refinement refinement = refinement(params.method());
		if (params.detectsByImage()) {
			if (refinement instanceof ProfileRefinement profiled) {
				final ModelSelection.Result r = particles != null && profile != null ? refit(plane, profiled, profile,
					noise, particles) : ModelSelection.track(plane, params, profiled, profile, noise, () -> withShapeFlags(
						firstPasses(plane, params, new int[1]), noise, params, new int[1]));
				ps = r.particles();
				outcome = r.outcome();
				significance = r.significance();
				discarded[0] = r.removed();
			}
			else {
				ps = ImageDetection.particles(plane, params.diameter(), noise);
				outcome = refinement.refine(plane, ps, params, null, noise);
			}
		}
		else {
			ps = withShapeFlags(firstPasses(plane, params, discarded), noise, params, discarded);
			outcome = refinement instanceof ProfileRefinement profiled ? profiled.refine(plane, ps, params, profile,
				noise) : refinement.refine(plane, ps, params, null, noise);
		}
		final int[] kinds = outcome.kinds();
		final Estimate[] est = outcome.estimates();
		final List<Localization> spots = new ArrayList<>(ps.length);
		final List<Region> active = new ArrayList<>(), second = new ArrayList<>();
		final int dx = (int) plane.minX(), dy = (int) plane.minY();
		for (int k = 0; k < ps.length; k++) {
			final Particle p = ps[k];
			final Estimate e = est[k];
			double sx = e.reportedX(), sy = e.reportedY();
			if (Double.isNaN(sx) && e.solve() != null) {
				final Solve c = e.solve();
				final double[] cov = CentreUncertainty.covariancePerUnitNoise(c.field(), c.used(), e.x() - c.originX(),
					e.y() - c.originY(), c.matrix());
				sx = noise * Math.sqrt(cov[0]);
				sy = noise * Math.sqrt(cov[1]);
			}
			final double quality = significance != null ? significance(significance[k]) : quality(p.quality(), p.region()
				.area(), noise);
			spots.add(new Localization(frameIndex, e.x() + dx, e.y() + dy, p.first().x() + dx, p.first().y() + dy,
				p.region().area(), e.secondArea(), quality, Math.sqrt(p.region().area() / Math.PI), e.flags(),
				e.iterations(), sx, sy, e.amplitude(), e.scale(), kinds == null ? 0 : kinds[k], e.sigmaX(), e.sigmaY()));
			if (keepRegions) {
				active.add(p.region().translate(dx, dy));
				second.add(SecondPass.secondRegion(p.region(), k, outcome.discs(), params.exclusionRadius()).translate(dx, dy));
			}
		}
		return new FrameResult(spots, active, second, noise, discarded[0], profile == null && params.method()
			.needsProfile());
	}

	/**
	 * @return the {@code particles} (spots in the frame's coordinates; those without a finite centre left out)
	 *         refitted
	 */
	private ModelSelection.Result refit(final Plane plane, final ProfileRefinement refinement, final KindProfiles profile,
		final double noise, final List<Localization> particles)
	{
		final double[] x = new double[particles.size()], y = new double[particles.size()];
		int n = 0;
		for (final Localization l : particles)
			if (Double.isFinite(l.x()) && Double.isFinite(l.y())) {
				x[n] = l.x() - plane.minX();
				y[n++] = l.y() - plane.minY();
			}
		return ModelSelection.refit(plane, params, refinement, profile, noise, java.util.Arrays.copyOf(x, n), java.util
			.Arrays.copyOf(y, n));
	}

	/**
	 * Refuses an {@code r_out} or a diameter more than twice the frame's diagonal: no particle's image in the frame
	 * reaches so far, and the profile's and the filter's arrays, sized by them, would not fit in memory.
	 *
	 * @throws InvalidInputException in one line naming the value and the frame's size
	 */
	static void checkReach(final Plane plane, final TrackerParameters params) {
		final double most = 2 * Math.hypot(plane.width(), plane.height());
		if (params.rOut() > most) throw new InvalidInputException(String.format(java.util.Locale.ROOT,
			"r_out %s px reaches beyond twice the frame's diagonal (%d x %d px): give the reach of one particle's image",
			io.github.contacttracker.core.Numbers.fmt(params.rOut()), plane.width(), plane.height()));
		if (params.diameter() > most) throw new InvalidInputException(String.format(java.util.Locale.ROOT,
			"diameter %s px is larger than twice the frame's diagonal (%d x %d px): give the particles' diameter",
			io.github.contacttracker.core.Numbers.fmt(params.diameter()), plane.width(), plane.height()));
	}

	/** The significance at and above which a spot's {@code QUALITY} is 1: certainly a particle, not noise. */
	static final double FULL_SIGNIFICANCE = 50;

	/**
	 * A spot's {@code QUALITY}: how clearly its active area stands out of the noise, in [0, 1]. The significance is
	 * the summed intensity above the threshold in units of its noise, {@code z = sum(v - T) / (sigma sqrt(A))};
	 * the quality is {@code min(1, z / FULL_SIGNIFICANCE)}. Real particles all reach 1, so TrackMate's automatic
	 * (Otsu) quality threshold, which splits any two groups of values, keeps them all and cuts only weaker
	 * components; the summed intensity alone split particles of two brightnesses (two focus planes).
	 *
	 * @param excess the summed intensity above the threshold over the active area
	 * @param area the active area (pixels)
	 * @param noise the frame's noise (grey levels; 0 for a noiseless image: every spot is certain)
	 */
	static double quality(final double excess, final int area, final double noise) {
		if (!(noise > 0)) return 1;
		return Math.min(1, excess / (noise * Math.sqrt(area)) / FULL_SIGNIFICANCE);
	}

	/**
	 * A spot's {@code QUALITY} when found by its image: its significance ({@link ModelSelection}), how much its light
	 * lowers the residuals in noise units, which ranks particles above noise without a ceiling; 0 where it was not
	 * measured (a spot the fit did not draw).
	 */
	static double significance(final double z) {
		return Double.isNaN(z) ? 0 : Math.min(z, Double.MAX_VALUE);
	}

	/** Fewest round active areas in a frame for their sizes to tell what a merge must hold. */
	static final int MIN_ROUND_FOR_SIZES = 5;

	/**
	 * Flags particles at the border and components whose shape is that of several particles merged
	 * ({@link ComponentShape}: elongated, or with a bay as deep as a waist between two lobes). Size does not make a
	 * merge: particles in and out of focus differ in size, not in shape. But a merge holds two particles' active
	 * areas: a component of the wrong outline (elongated, or with a bay) smaller than twice the frame's small round
	 * ones (their 10th percentile, given {@value #MIN_ROUND_FOR_SIZES} or more) is no particle at all. In bright field such components are the
	 * bright fringes between touching particles; they are dropped and counted in {@code discarded[0]}, as the
	 * noise blobs below {@code min_area} are.
	 */
	private static Particle[] withShapeFlags(final List<Particle> particles, final double noise,
		final TrackerParameters params, final int[] discarded)
	{
		final Particle[] ps = new Particle[particles.size()];
		final boolean[] merged = new boolean[ps.length];
		final double[] roundAreas = new double[ps.length];
		int round = 0;
		for (int k = 0; k < ps.length; k++) {
			final Particle p = particles.get(k);
			merged[k] = p.shape().merged(p.atBorder(), noise, alone(particles, k, params.aloneReach()), params.diameter());
			if (!merged[k] && !p.atBorder()) roundAreas[round++] = p.region().area();
		}
		final double smallestMerge = round >= MIN_ROUND_FOR_SIZES ? 2 * Statistics.quantile(roundAreas, round, 0.1)
			: 0;
		int n = 0;
		for (int k = 0; k < ps.length; k++) {
			final Particle p = particles.get(k);
			// (by outline only: a particle flagged for its gradient lines has the shape of one)
			if (merged[k] && p.region().area() < smallestMerge && p.shape().outlineMerged(p.atBorder())) {
				discarded[0]++;
				continue;
			}
			ps[n++] = p.withShapeFlags((p.atBorder() ? Flag.AT_BORDER.bit() : 0) | (merged[k] ? Flag.MERGED.bit() : 0));
		}
		return java.util.Arrays.copyOf(ps, n);
	}

	/**
	 * @return whether no other particle's image (reaching {@code r_out} from its first-pass centre) reaches particle
	 *         {@code k}'s active area: only then do its gradient lines owe nothing to a neighbour's light, so that
	 *         their failing to meet in one point means several particles
	 */
	private static boolean alone(final List<Particle> particles, final int k, final double beyond) {
		final Particle p = particles.get(k);
		final double reach = beyond + Math.sqrt(p.region().area() / Math.PI);
		for (int q = 0; q < particles.size(); q++)
			if (q != k && Math.hypot(particles.get(q).first().x() - p.first().x(), particles.get(q).first().y() - p
				.first().y()) < reach) return false;
		return true;
	}

	/** @return the strategy that computes the method's centres from the first pass */
	private static Refinement refinement(final Method method) {
		switch (method) {
			case FIRST: return Refinement.FIRST_PASS;
			case PAPER: return SecondPass.PAPER;
			case ITERATIVE: return SecondPass.ITERATIVE;
			case DEBLEND: return ProfileRefinement.DEBLEND;
			case FIT: return ProfileRefinement.FIT;
			default: throw new AssertionError(method);
		}
	}
}
