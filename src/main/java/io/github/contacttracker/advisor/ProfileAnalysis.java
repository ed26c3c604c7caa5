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

import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleToIntFunction;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.kind.KindFeatures;
import io.github.contacttracker.core.kind.Kinds;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.radial.ComponentShape;
import io.github.contacttracker.core.track.ContactTracker;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Suggests {@code threshold}, {@code r_out} (and, when not given, the diameter) from the radial intensity profile
 * of isolated particles, the way the paper reads them off its Fig. 2. One implementation for the Fiji helper and
 * the command line's {@code profile}. Built to hold on real movies: saturated cores, a background that drifts
 * across the frame, dense neighbours and compression (MJPEG) noise.
 * <ol>
 * <li>Particles: the frame's bright spots at half height between the frame's median and its brightest pixels
 * (a point given on a particle fainter than that: half its brightest pixel's height), localized by one
 * radial-symmetry pass; merged spots (by shape) and spots at the border are not profiled.</li>
 * <li>Diameter {@code D}: given, or the smaller of the 10th percentile of the spots' nearest-neighbour distances
 * (colloids at contact sit one diameter apart) and twice where the particles' own image ends (the outer edge of a
 * dark ring, else the reach), read off a profile taken to a provisional diameter and measured again at the
 * estimate; a warning says which.</li>
 * <li>Profiled particles: up to {@value #MAX_PARTICLES} spots with the largest distances to their nearest
 * neighbour; a point given, its particle alone when isolated (nearest neighbour and image edge at least twice
 * {@code r_out} away), else those spots, and said. Pixels within the reach of any other spot are masked (first
 * {@code D}, then the measured reach).</li>
 * <li>Local background: around each particle a plane fitted robustly to the outer {@value #BACKGROUND_ANNULUS_PERCENT}%
 * of {@code max_radius} ({@value #AUTO_RADIUS_DIAMETERS} diameters unless given): a background drifting across
 * the frame is removed with it.</li>
 * <li>Noise {@code s}: the robust (3.5-sigma clipped) standard deviation of the pixels of those annuli about their
 * planes. It
 * sees compression noise that is smooth within 8x8 blocks, which a pixel-difference estimator (Immerkaer) misses,
 * and is not moved by a neighbour's light in part of the annulus.</li>
 * <li>Profile {@code P(r)}: the interquartile mean, over all profiled particles, of the pixels' heights above their
 * local background in 1 px wide rings. It ignores the part of a ring a neighbour covers (up to a quarter), and
 * unlike a median it is not stuck on the integer steps of 8-bit data.</li>
 * <li>{@code r_out}: the radius beyond which {@code |P(r)| <= s} (the reach), plus {@value #R_OUT_MARGIN_PX}
 * px.</li>
 * <li>{@code threshold}: particles at contact add up. For two (centres {@code D} apart) and three (a touching
 * triangle) the summed profiles are evaluated on a 0.5 px grid at every point at least {@code D/2} from all
 * centres (outside every particle's own half): the brightest such point is the bridge their active areas must
 * not reach. The threshold is the bridge plus {@value #THRESHOLD_MARGIN_SIGMAS} {@code s}. On a saturated core
 * only the plateau is flat, and the rule does not look inside {@code D/2}.</li>
 * <li>Raised, when it must be, clear of the background's texture ({@link ThresholdRules#textureGap}) and until the
 * frame's active areas are round ({@link ThresholdRules#roundFrom}).</li>
 * <li>Kinds of particle ({@link #kinds}): the frame tracked at the suggested threshold and {@code r_out} (the
 * paper's method), each particle measured about its centre ({@link KindFeatures}) and the kinds found
 * automatically ({@link Kinds#find(java.util.Collection)}), as the tracker finds them.</li>
 * </ol>
 */
public final class ProfileAnalysis {

	/** Added to the reach for {@code r_out}: half the width of the gradient operator. */
	public static final double R_OUT_MARGIN_PX = 2;
	/** Noise margin of the threshold above the brightest point between particles at contact, in noise sigmas. */
	public static final double THRESHOLD_MARGIN_SIGMAS = 3;
	/** Default {@code max_radius}, in particle diameters. */
	public static final double AUTO_RADIUS_DIAMETERS = 2.5;
	/** The background is measured in this outer part of {@code max_radius} (percent). */
	public static final int BACKGROUND_ANNULUS_PERCENT = 20;
	/** At most this many particles are profiled together. */
	public static final int MAX_PARTICLES = 8;
	/** Percentile of the nearest-neighbour distances taken as the diameter when it is not given. */
	public static final double DIAMETER_PERCENTILE = 10;
	/** Fewest pixels accepted in the background annulus. */
	static final int MIN_BACKGROUND_PIXELS = 20;
	/** Values further than this many sigmas from the mean do not count in the noise. */
	static final double CLIP_SIGMAS = 3.5;
	/**
	 * The provisional diameter (to measure the profile on) is at most this many times the spots' median radius at
	 * half height: a Gaussian particle's image ends about 2.5 half-height radii out, a bright-field particle's further,
	 * its dark ring lying outside a narrow bright core; six leaves a margin above both.
	 */
	static final double PROVISIONAL_CORE_RADII = 6;
	/** Grid step (px) of the bridge search. */
	static final double BRIDGE_STEP_PX = 0.5;
	/** Significant digits of the numbers in the helper's messages and warnings ({@link Numbers#significant}). */
	public static final int SIGNIFICANT_DIGITS = 4;

	/**
	 * What the profile shows.
	 *
	 * @param x refined centre x of the particle at the point given, else of the first profiled particle (px,
	 *        TrackMate convention)
	 * @param y refined centre y (px)
	 * @param refined whether the particle was found by radial symmetry (else the point given is used)
	 * @param diameter the particle diameter (px), given or estimated
	 * @param diameterEstimated whether the diameter was estimated from the spots' distances
	 * @param particles how many particles the profile pools
	 * @param maxRadius radius measured out to (px)
	 * @param radius mean distance of each ring's pixels from the centre (px); ring {@code k} holds the pixels at
	 *        distances in {@code [k - 0.5, k + 0.5)}
	 * @param level each ring's grey level: the background plus the interquartile mean height of its pixels above
	 *        the local background (NaN for an empty ring)
	 * @param count pixels in each ring (over all profiled particles)
	 * @param background background grey level {@code I0} (mean of the local backgrounds at the centres)
	 * @param noise pixel-noise standard deviation {@code s} (robust, around the particles)
	 * @param peak brightest pixel of the (first) particle
	 * @param reach radius beyond which {@code |I(r) - I0| <= s} (px)
	 * @param rOut suggested {@code r_out}: {@code reach + 2} (px, not rounded)
	 * @param bridge brightest grey level between two or three such particles at contact
	 * @param atContact {@code bridge + 3 s}: the threshold that keeps two or three particles at contact apart
	 * @param threshold suggested threshold (not rounded): {@code atContact}, raised clear of the background's texture
	 *        and until every active area is round, when it must be
	 * @param activeRadius radius of the particle's active area at the suggested threshold (px; 0 when even the
	 *        centre is below it)
	 * @param centres the profiled particles' centres {@code {x, y}} (px)
	 * @param findings things the user should know (empty when all is well), in the order they were found; the front
	 *        ends put them into words ({@code report.ProfileReport})
	 * @param kinds the kinds of particle at the suggested threshold and {@code r_out}
	 */
	public record Result(double x, double y, boolean refined, double diameter, boolean diameterEstimated,
		int particles, double maxRadius, double[] radius, double[] level, int[] count, double background,
		double noise, double peak, double reach, double rOut, double bridge, double atContact, double threshold,
		double activeRadius,
		List<double[]> centres, List<Finding> findings, ParticleKinds kinds)
	{
		public Result {
			findings = List.copyOf(findings);
			centres = List.copyOf(centres);
		}

		/** @return {@link #threshold} rounded up to a whole grey level when the data are integers */
		public double suggestedThreshold(final boolean integerData) {
			return integerData ? Math.ceil(threshold - 1e-9) : threshold;
		}

		/** @return {@link #diameter} rounded to 0.01 px, as the helper prints it */
		public double suggestedDiameter() {
			return round2(diameter);
		}

		/** @return {@link #rOut} rounded up to whole pixels */
		public double suggestedROut() {
			return Math.ceil(rOut - 1e-9);
		}

		/**
		 * What the paper's second pass keeps of a particle at contact with one neighbour, at the suggested values:
		 * the part of its active disc (radius {@link #activeRadius}) farther than {@link #suggestedROut} from the
		 * neighbour's centre, {@link #diameter} away. {@code r_out} is where a particle's light returns to the
		 * background, which for a haloed particle lies beyond a diameter; the second pass then keeps less than half
		 * of the active area, and nothing once {@code r_out >= D + activeRadius}. Below
		 * {@link TrackerParameters#DEFAULT_MIN_SECOND_AREA} px the paper's method keeps the first pass there
		 * ({@code FELL_BACK}); the profile methods model the neighbours' light and need no undistorted area.
		 *
		 * @return that area (px, the discs' geometry)
		 */
		public double secondPassArea() {
			return discOutside(activeRadius, suggestedROut(), diameter);
		}

		/**
		 * @param threshold the threshold the movie is tracked at (given, or {@link #suggestedThreshold})
		 * @return the {@code min_area} for particles of this profile at that threshold ({@link ProfileAnalysis#minArea}):
		 *         the default unless they are so small that their active areas come near it
		 */
		public int suggestedMinArea(final double threshold) {
			return minArea(ProfileAnalysis.activeRadius(radius, level, count, threshold));
		}

		/**
		 * @return whether the particles are so small that {@link #suggestedMinArea} at {@code threshold} lies below
		 *         the default {@code min_area} (only then is it suggested)
		 */
		public boolean smallParticles(final double threshold) {
			return suggestedMinArea(threshold) < TrackerParameters.DEFAULT_MIN_AREA;
		}
	}

	/**
	 * The kinds of particle the helper found ({@link #kinds}): the frames tracked at the suggested threshold and
	 * {@code r_out}, their particles' kinds found automatically, as the tracker finds them.
	 *
	 * @param frames how many frames the kinds were found on (the frame profiled, and more when given)
	 * @param particles how many particles those frames hold at the suggested threshold
	 * @param kinds the kinds, numbered by size as in the {@code KIND} column, each with its particles in those
	 *        frames (empty when no particle has a bright core)
	 */
	public record ParticleKinds(int frames, int particles, List<Kinds.Kind> kinds) {

		public ParticleKinds {
			kinds = List.copyOf(kinds);
		}

		/** @return the particles of no kind ({@code KIND} 0: no bright core, e.g. cut by the border) */
		public int unclassified() {
			return particles - kinds.stream().mapToInt(Kinds.Kind::count).sum();
		}
	}

	/** The kinds of particle are found on at most this many frames ({@link #kindFrames}). */
	public static final int KIND_FRAMES = 5;

	private ProfileAnalysis() {}

	/**
	 * The frames of a movie to find the kinds of particle on: the frame profiled and the ones after it, then the
	 * ones before it when the movie ends first, {@value #KIND_FRAMES} in all at most. The rarest kind of a movie
	 * may have two particles in a frame: a kind needs {@value Kinds#MIN_MEMBERS}.
	 *
	 * @param frame the frame profiled, 0-based
	 * @param frameCount the movie's frames
	 * @return their 0-based indices, the frame profiled first, then in order
	 */
	public static List<Integer> kindFrames(final int frame, final int frameCount) {
		final List<Integer> frames = new ArrayList<>(List.of(frame));
		for (int t = frame + 1; t < frameCount && frames.size() < KIND_FRAMES; t++)
			frames.add(t);
		for (int t = frame - 1; t >= 0 && frames.size() < KIND_FRAMES; t--)
			frames.add(1, t);
		return frames;
	}

	/**
	 * The profile of the particle at a point (the Fiji helper: the user clicked it).
	 *
	 * @param frame a 2D frame
	 * @param px x of a point on the particle (px, in the frame's coordinates)
	 * @param py y of a point on the particle (px)
	 * @param diameter particle diameter (px): the centre distance at contact; 0 to estimate it from the frame
	 * @param maxRadius radius to measure out to (px); 0 for {@value #AUTO_RADIUS_DIAMETERS} diameters. It is
	 *        clipped to the farthest image corner.
	 * @return the profile and the suggestions; the kinds of particle are those of this frame
	 * @throws IllegalArgumentException with a one-line message: bad diameter or radius, point outside the frame,
	 *         no background ring inside the image, or no particle brighter than the noise at the point
	 */
	public static <T extends RealType<T>> Result analyse(final RandomAccessibleInterval<T> frame, final double px,
		final double py, final double diameter, final double maxRadius)
	{
		return run(frame, new double[] { px, py }, diameter, maxRadius, List.of(frame));
	}

	/**
	 * The profile of the particle at a point, and the kinds of particle found on several frames of the movie.
	 *
	 * @param kindFrames the frames to find the kinds of particle on (the frame profiled among them; see
	 *        {@link #kindFrames}), of the same size and pixel type
	 * @see #analyse(RandomAccessibleInterval, double, double, double, double)
	 */
	public static <T extends RealType<T>> Result analyse(final RandomAccessibleInterval<T> frame, final double px,
		final double py, final double diameter, final double maxRadius,
		final List<? extends RandomAccessibleInterval<T>> kindFrames)
	{
		return run(frame, new double[] { px, py }, diameter, maxRadius, kindFrames);
	}

	/**
	 * The profile of the frame's most isolated particles, found without help.
	 *
	 * @see #analyse(RandomAccessibleInterval, double, double, double, double)
	 */
	public static <T extends RealType<T>> Result analyse(final RandomAccessibleInterval<T> frame,
		final double diameter, final double maxRadius)
	{
		return run(frame, null, diameter, maxRadius, List.of(frame));
	}

	/**
	 * The profile of the frame's most isolated particles, and the kinds of particle found on several frames.
	 *
	 * @see #analyse(RandomAccessibleInterval, double, double, double, double, List)
	 */
	public static <T extends RealType<T>> Result analyse(final RandomAccessibleInterval<T> frame,
		final double diameter, final double maxRadius, final List<? extends RandomAccessibleInterval<T>> kindFrames)
	{
		return run(frame, null, diameter, maxRadius, kindFrames);
	}

	private static <T extends RealType<T>> Result run(final RandomAccessibleInterval<T> frame, final double[] point,
		final double diameterGiven, final double maxRadiusGiven,
		final List<? extends RandomAccessibleInterval<T>> kindFrames)
	{
		checkArguments(diameterGiven, maxRadiusGiven);
		final Plane plane = Plane.of(frame);
		final double[] at = point == null ? null : local(plane, point);
		final Spots spots = findSpots(plane, point, at, diameterGiven);
		final List<Finding> findings = new ArrayList<>();
		final Sized sized = sizeAndMeasure(plane, spots, at, diameterGiven, maxRadiusGiven, findings);
		final double diameter = sized.diameter();
		final Measured m = sized.measured();
		final PooledProfile pooled = m.pooled();
		final double[] centre = m.centres().get(0), subject = m.at() != null ? m.at() : centre;
		final double rOut = m.reach() + R_OUT_MARGIN_PX;
		final double[] level = levels(pooled);
		final Threshold t = threshold(plane, pooled, level, diameter, m.reach(), centre, findings);
		final double activeRadius = activeRadius(pooled.radius(), level, pooled.count(), t.threshold());
		if (activeRadius == 0) findings.add(new Finding.ThresholdAboveCentre());
		final List<double[]> inFrame = new ArrayList<>();
		for (final double[] c : m.centres())
			inFrame.add(new double[] { c[0] + plane.minX(), c[1] + plane.minY() });
		return new Result(subject[0] + plane.minX(), subject[1] + plane.minY(), m.refined(), diameter, sized
			.estimated(), m.centres().size(), m.radiusCap(), pooled.radius(), level, pooled.count(), pooled.background(), pooled
				.noise(), t.peak(), m.reach(), rOut, t.bridge(), t.atContact(), t.threshold(), activeRadius, inFrame,
			findings, kinds(kindFrames, t.threshold(), rOut, minArea(activeRadius)));
	}

	/**
	 * Step 10: the kinds of particle. Each frame is tracked at the suggested threshold and {@code r_out} (before
	 * rounding) by the paper's method (the nearer the true centres, the sharper the particles' profiles), each
	 * particle is measured about its centre out to {@code r_out} against its frame's background, and the kinds are
	 * found automatically among the particles of all the frames. A frame that cannot be tracked (NaN pixels, a plane
	 * that cannot be read) is left out: the kinds are a report, and the profile itself is measured.
	 */
	private static <T extends RealType<T>> ParticleKinds kinds(final List<? extends RandomAccessibleInterval<T>> frames,
		final double threshold, final double rOut, final int minArea)
	{
		final ContactTracker tracker = new ContactTracker(TrackerParameters.of(threshold, rOut).withMinArea(minArea)
			.withMethod(Method.PAPER));
		final List<KindFeatures> features = new ArrayList<>();
		int used = 0;
		for (final RandomAccessibleInterval<T> frame : frames) {
			final List<KindFeatures> own;
			try {
				final Plane plane = Plane.of(frame);
				own = Arrays.asList(KindFeatures.measure(plane, tracker.analyse(plane, 0, false).spots(), rOut));
			}
			catch (final InvalidInputException | UncheckedIOException e) {
				continue;
			}
			features.addAll(own);
			used++;
		}
		return new ParticleKinds(used, features.size(), Kinds.find(features).describe());
	}

	/** @throws InvalidInputException for a diameter or radius that is negative or not a number */
	private static void checkArguments(final double diameterGiven, final double maxRadiusGiven) {
		if (!(diameterGiven >= 0) || !Double.isFinite(diameterGiven))
			throw new InvalidInputException("diameter must be the particle diameter in pixels (> 0; 0 = estimate " +
				"it), not " + fmt(diameterGiven));
		if (!(maxRadiusGiven >= 0) || !Double.isFinite(maxRadiusGiven))
			throw new InvalidInputException("max_radius must be >= 0 pixels (0 = automatic), not " + fmt(
				maxRadiusGiven));
	}

	/**
	 * @return the point in the plane's own coordinates
	 * @throws InvalidInputException if it is outside the plane
	 */
	private static double[] local(final Plane plane, final double[] point) {
		final double lx = point[0] - plane.minX(), ly = point[1] - plane.minY();
		if (!(lx >= -0.5 && lx < plane.width() - 0.5 && ly >= -0.5 && ly < plane.height() - 0.5))
			throw new InvalidInputException("point (" + fmt(point[0]) + ", " + fmt(point[1]) + ") is outside the " +
				"image");
		return new double[] { lx, ly };
	}

	/**
	 * The frame's spots, in the plane's coordinates, with their nearest-neighbour distances.
	 *
	 * @param near how far from a point given its particle's brightest pixel is looked for (px)
	 */
	private record Spots(List<Localization> spots, double[][] xy, double[] nn, double near, double level) {}

	/**
	 * Step 1: the spots at half height between the frame's median and its brightest pixels (or the brightest pixel
	 * near the point given, when that lies below the frame's half height), by one radial-symmetry pass. The same
	 * spots with a point as without, wherever the particle at the point is among them: the frame's values, when the
	 * particle at a point gives them ({@link #measure}), are then those of the frame.
	 *
	 * @param point the point given, in the frame's coordinates ({@code null} if none)
	 * @param at the same point in the plane's coordinates
	 * @throws InvalidInputException if nothing is brighter than the noise
	 */
	private static Spots findSpots(final Plane plane, final double[] point, final double[] at,
		final double diameterGiven)
	{
		final double[] sample = sample(plane);
		final double median0 = Statistics.quantile(sample, 0.5);
		final double noise0 = Math.max(NoiseEstimate.sigma(plane), 1e-6);
		final double near = diameterGiven > 0 ? Math.max(2, diameterGiven / 4) : 5;
		final double frameTop = Statistics.quantile(sample, 1 - Math.max(1e-4, 20.0 / sample.length));
		// the frame's spots, as without a point, unless the particle at the point would not be among them
		final double own = point != null ? peak(plane, at[0], at[1], near) : frameTop;
		final double top = own >= median0 + 0.5 * (frameTop - median0) ? frameTop : own;
		if (!(top - median0 > THRESHOLD_MARGIN_SIGMAS * noise0)) {
			if (point != null) throw new InvalidInputException(String.format(Locale.ROOT, "no bright particle at " +
				"(%s, %s): the brightest pixel within %s px is %s, within %s noise sigmas (%s) of the background %s", fmt(
					point[0]), fmt(point[1]), fmt(near), fmt(top), fmt(THRESHOLD_MARGIN_SIGMAS), fmt(noise0), fmt(
						median0)));
			throw new InvalidInputException("no particle brighter than the noise in the frame");
		}
		final double level = median0 + 0.5 * (top - median0);
		final TrackerParameters find = new TrackerParameters(level, 10, 5, Connectivity.EIGHT,
			TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.FIRST);
		final List<Localization> spots = new ContactTracker(find).analyse(plane, 0, false).spots();
		final double[][] xy = new double[spots.size()][];
		for (int k = 0; k < xy.length; k++)
			xy[k] = new double[] { spots.get(k).x() - plane.minX(), spots.get(k).y() - plane.minY() };
		return new Spots(spots, xy, nearestNeighbourDistances(xy), near, level);
	}

	/** The diameter the profile was measured with, whether it was estimated, and the profile. */
	private record Sized(double diameter, boolean estimated, Measured measured) {}

	/**
	 * Step 2 and the profile (steps 3-6): the diameter given; or where the particles' own image ends, unless the
	 * spots sit closer than that. It is measured on a profile taken out to a provisional diameter: the spots'
	 * spacing, but no more than {@link #PROVISIONAL_CORE_RADII} times their half-height radius (isolated particles
	 * sit far apart: their spacing would take the profile far out, over the background's texture and every
	 * neighbour), and measured again at the estimate.
	 */
	private static Sized sizeAndMeasure(final Plane plane, final Spots s, final double[] at,
		final double diameterGiven, final double maxRadiusGiven, final List<Finding> findings)
	{
		if (diameterGiven != 0) {
			final Measured m = measure(plane, s, at, diameterGiven, maxRadiusGiven, false);
			findings.addAll(m.findings());
			return new Sized(diameterGiven, false, m);
		}
		double[] spacing = s.nn().clone();
		double fromSpots = spacing.length >= 2 ? Statistics.quantile(spacing.clone(), DIAMETER_PERCENTILE / 100) : Double.NaN;
		final double[] radii = new double[s.spots().size()];
		for (int k = 0; k < radii.length; k++)
			radii[k] = Math.sqrt(s.spots().get(k).activeArea() / Math.PI);
		final double fromCores = PROVISIONAL_CORE_RADII * Statistics.quantile(radii, 0.5);
		double provisional = Double.isFinite(fromSpots) ? Math.min(fromSpots, fromCores) : fromCores;
		Measured m = measure(plane, s, at, provisional, maxRadiusGiven, true);
		// Two particles of this profile closer than 'closest' would have been one spot where the spots were found; spots
		// that close are not both such particles (bright marks burned into the frame: a timestamp's digits 6 px apart
		// among particles 20-50 px across gave a diameter of 5.6 px and a threshold above every pixel). Their distances
		// are left out of the spacing, and the profile measured again. Not when no two spots are left: in a field with
		// no background between the particles (a lattice at contact) the profile holds the neighbours' light, and two
		// of it would never stay apart.
		if (fromSpots > 0 && !apart(m, fromSpots, s.level())) {
			final double closest = closestApart(m, fromSpots, s.level());
			final double[] kept = Arrays.stream(spacing).filter(d -> d >= closest).toArray();
			if (kept.length >= 2) {
				findings.add(new Finding.SpotsTooClose(spacing.length - kept.length, closest));
				spacing = kept;
				fromSpots = Statistics.quantile(kept.clone(), DIAMETER_PERCENTILE / 100);
				provisional = Math.min(fromSpots, fromCores);
				m = measure(plane, s, at, provisional, maxRadiusGiven, true);
			}
		}
		final double own = 2 * m.imageEdge();
		final boolean fromImage = !(fromSpots < own);
		final double diameter = fromImage ? own : fromSpots;
		if (Math.abs(diameter - provisional) > 0.01 * provisional) m = measure(plane, s, at, diameter, maxRadiusGiven,
			true);
		findings.add(fromImage ? new Finding.DiameterFromImage(diameter, own / 2) : new Finding.DiameterFromSpacing(
			diameter, DIAMETER_PERCENTILE, spacing.length, own));
		findings.addAll(m.findings());
		return new Sized(diameter, true, m);
	}

	/**
	 * @return whether two particles of {@code m}'s profile {@code distance} apart (and three in a triangle) stay apart
	 *         at {@code level}: the brightest point between them lies below it
	 */
	private static boolean apart(final Measured m, final double distance, final double level) {
		return m.pooled().background() + ThresholdRules.brightestBetween(m.pooled(), distance, m.reach()) < level;
	}

	/**
	 * @return the shortest distance (to {@value #BRIDGE_STEP_PX} px, above {@code from}, at which they are not) at
	 *         which particles of {@code m}'s profile stay {@link #apart} at {@code level}; beyond twice the profile's
	 *         reach if they never do within it
	 */
	private static double closestApart(final Measured m, final double from, final double level) {
		double lo = from, hi = 2 * m.reach() + 1;
		if (!apart(m, hi, level)) return hi;
		while (hi - lo > BRIDGE_STEP_PX) {
			final double mid = (lo + hi) / 2;
			if (apart(m, mid, level)) hi = mid;
			else lo = mid;
		}
		return hi;
	}

	/**
	 * The suggested threshold and what it was raised from.
	 *
	 * @param bridge the brightest grey level between particles at contact
	 * @param atContact {@code bridge} plus the noise margin
	 * @param threshold the suggestion (not rounded)
	 * @param peak the brightest pixel of the first particle
	 */
	private record Threshold(double bridge, double atContact, double threshold, double peak) {}

	/**
	 * Steps 7-9: the bridge between particles at contact plus the noise margin; raised clear of the background's
	 * texture (halos, rings, their sums between particles); and raised until every active area has the shape of one
	 * particle (bright fringes between touching particles in bright field are brighter than the sum of two
	 * profiles), up to half the cores' height.
	 */
	private static Threshold threshold(final Plane plane, final PooledProfile pooled, final double[] level,
		final double diameter, final double reach, final double[] centre, final List<Finding> findings)
	{
		final double bridge = pooled.background() + Math.max(0, ThresholdRules.brightestBetween(pooled, diameter,
			reach));
		final double atContact = bridge + THRESHOLD_MARGIN_SIGMAS * pooled.noise();
		// the active areas that count as particles at a threshold: as the tracker will keep them (small particles' are
		// smaller than the default min_area: counting only the larger ones would judge the merges alone)
		final DoubleToIntFunction minArea = th -> minArea(activeRadius(pooled.radius(), level, pooled.count(), th));
		final double[] gap = ThresholdRules.textureGap(plane, atContact, pooled.background(), minArea.applyAsInt(
			atContact));
		final double clear = Math.max(atContact, Double.isNaN(gap[0]) ? atContact : pooled.background() + (gap[0] +
			gap[1]) / 2);
		if (clear > atContact) findings.add(new Finding.BackgroundTexture(atContact, (int) gap[2], gap[0], gap[1]));
		final double peak = peak(plane, centre[0], centre[1], Math.max(2, diameter / 4));
		final double ceiling = pooled.background() + 0.5 * (peak - pooled.background());
		final double[] shaped = ThresholdRules.roundFrom(plane, clear, ceiling, Math.max(0.5, pooled.noise() / 2),
			minArea);
		final double threshold = shaped[0];
		if (threshold > clear) findings.add(new Finding.RaisedUntilRound(clear, (int) shaped[1], (int) shaped[2]));
		else if (shaped[1] > 0) findings.add(new Finding.NotRound((int) shaped[1], (int) shaped[2], ceiling));
		return new Threshold(bridge, atContact, threshold, peak);
	}

	/** @return each ring's grey level: the background plus its height (NaN for an empty ring) */
	private static double[] levels(final PooledProfile pooled) {
		final double[] level = new double[pooled.radius().length];
		for (int k = 0; k < level.length; k++)
			level[k] = pooled.count()[k] > 0 ? pooled.background() + pooled.height()[k] : Double.NaN;
		return level;
	}

	/**
	 * @param radius each ring's mean radius, {@code level} its grey level, {@code count} its pixels (as in {@link Result})
	 * @return where the profile falls below the threshold (px, interpolated; 0 when even the centre is below)
	 */
	private static double activeRadius(final double[] radius, final double[] level, final int[] count,
		final double threshold)
	{
		double activeRadius = 0;
		int previous = -1;
		for (int k = 0; k < level.length; k++) {
			if (count[k] == 0) continue;
			if (level[k] < threshold) {
				if (previous >= 0) activeRadius = radius[previous] + (radius[k] - radius[previous]) * (level[previous] -
					threshold) / (level[previous] - level[k]);
				break;
			}
			activeRadius = radius[k];
			previous = k;
		}
		return activeRadius;
	}

	/**
	 * The {@code min_area} for particles whose active areas at a threshold have radius {@code activeRadius}: half
	 * their area {@code pi r^2}, at most the default {@value TrackerParameters#DEFAULT_MIN_AREA} px (0: the default).
	 * The default was set for particles tens of pixels across; particles a few pixels across have active areas near
	 * it, and the default dropped many (in trackpy's bulk_water sample in-focus particles of 15-19 px, where the
	 * profile's active disc holds 28 px at the helper's threshold; 69 of 126 simulated spots 7.5 px across). A
	 * component of less than half a particle's area is noise or a fringe: the threshold lies 3 noise levels above the
	 * brightest point between two particles.
	 */
	public static int minArea(final double activeRadius) {
		if (!(activeRadius > 0)) return TrackerParameters.DEFAULT_MIN_AREA;
		return (int) Math.max(TrackerParameters.MIN_AREA_AT_LEAST, Math.min(TrackerParameters.DEFAULT_MIN_AREA, Math
			.floor(Math.PI * activeRadius * activeRadius / 2)));
	}

	/**
	 * The profile of the particles chosen for a diameter: their centres, how far out it is measured, the pooled
	 * profile, its reach and where the particles' own image ends
	 * ({@link PooledProfile#imageEdge(PooledProfile, double)}).
	 *
	 * @param at the centre of the particle at the point given (whether profiled or not), {@code null} without a point
	 */
	private record Measured(List<double[]> centres, double[] at, boolean refined, double radiusCap,
		PooledProfile pooled, double reach, double imageEdge, List<Finding> findings) {

		Measured withAt(final double[] point, final boolean pointRefined, final List<Finding> more) {
			final List<Finding> all = new ArrayList<>(more);
			all.addAll(findings);
			return new Measured(centres, point, pointRefined, radiusCap, pooled, reach, imageEdge, all);
		}
	}

	/**
	 * Steps 3-6: picks the particles (the one at {@code point}, else the most isolated), masks their neighbours and
	 * pools their profile, twice (the masks widened to the measured reach the second time).
	 * <p>
	 * A particle at a point is profiled alone only when it is isolated: its nearest neighbour, and the image's edge
	 * (beyond which a neighbour goes unseen), at least twice {@code r_out} away (the reach plus
	 * {@value #R_OUT_MARGIN_PX} px, measured on the frame's most isolated particles or on the particle alone,
	 * whichever is larger), so that no pixel holds the light of both and the neighbours' masks leave its own pixels.
	 * Closer, its profile never returns to the background between it and its neighbours: its own background, noise
	 * and reach would be the neighbours' halos (a reach of twice the true one, masks that swallow the particle
	 * itself), so the profile and the values are the frame's most isolated particles' instead (as without a point),
	 * and said ({@link Finding.FrameValuesAtPoint}).
	 *
	 * @param narrow whether the masks may narrow where they leave no background ({@link PooledProfile#poolNarrowing}):
	 *        for an
	 *        estimated diameter; a given one that leaves none is wrong for the image, and the front ends say so and
	 *        estimate it instead
	 */
	private static Measured measure(final Plane plane, final Spots s, final double[] point, final double diameter,
		final double maxRadiusGiven, final boolean narrow)
	{
		final List<Localization> spots = s.spots();
		final double[][] xy = s.xy();
		final double wanted = maxRadiusGiven > 0 ? maxRadiusGiven : AUTO_RADIUS_DIAMETERS * diameter;
		if (point == null) {
			final List<Finding> findings = new ArrayList<>();
			final List<Integer> chosen = mostIsolated(plane, s, diameter, wanted);
			if (chosen.isEmpty()) throw new InvalidInputException("no single particle away from the border found in " +
				"the frame: give a point on one");
			if (s.nn().length > 1 && s.nn()[chosen.get(0)] < 2 * diameter)
				findings.add(new Finding.NotIsolated(s.nn()[chosen.get(0)], diameter));
			return pooledTwice(plane, s, centresOf(xy, chosen), diameter, wanted, narrow, findings);
		}
		final List<Finding> findings = new ArrayList<>();
		int best = -1;
		for (int k = 0; k < xy.length; k++) {
			final double d = Math.hypot(xy[k][0] - point[0], xy[k][1] - point[1]);
			if (d <= Math.max(s.near(), diameter / 2) && (best < 0 || d < Math.hypot(xy[best][0] - point[0], xy[best][1] -
				point[1]))) best = k;
		}
		final double[] own;
		if (best >= 0) {
			own = xy[best];
			if (spots.get(best).has(Flag.MERGED) && outlineMerged(plane, s.level(), own)) findings.add(
				new Finding.MergedAtPoint());
		}
		else {
			own = point;
			findings.add(new Finding.NotRefined());
		}
		double neighbour = Double.POSITIVE_INFINITY;
		for (int k = 0; k < xy.length; k++)
			if (k != best) neighbour = Math.min(neighbour, Math.hypot(xy[k][0] - own[0], xy[k][1] - own[1]));
		// beyond the image's edge a neighbour goes unseen: the edge counts as one
		final double edge = Math.min(Math.min(own[0], plane.width() - 1 - own[0]), Math.min(own[1], plane.height() - 1 -
			own[1]));
		final boolean byEdge = edge < neighbour;
		neighbour = Math.min(neighbour, edge);
		final List<Integer> frame = mostIsolated(plane, s, diameter, wanted);
		Measured m = null;
		if (!frame.isEmpty()) {
			try {
				m = pooledTwice(plane, s, centresOf(xy, frame), diameter, wanted, narrow, new ArrayList<>());
			}
			catch (final InvalidInputException e) {
				m = null; // the frame's particles have no background: the particle is measured alone
			}
		}
		Measured alone = null;
		final List<Finding> ownFindings = new ArrayList<>();
		try {
			alone = pooledTwice(plane, s, List.of(own), diameter, wanted, narrow, ownFindings);
		}
		catch (final InvalidInputException e) {
			if (m == null) throw e;
		}
		// r_out as the frame gives it or as the particle alone does, whichever reaches further
		final double rOut = Math.max(m == null ? 0 : m.reach(), alone == null ? 0 : alone.reach()) + R_OUT_MARGIN_PX;
		if (m != null && (alone == null || neighbour < 2 * rOut)) {
			findings.add(new Finding.FrameValuesAtPoint(neighbour, byEdge, m.reach() + R_OUT_MARGIN_PX, alone == null
				? Double.NaN : alone.reach() + R_OUT_MARGIN_PX, m.centres().size()));
			return m.withAt(own, best >= 0, findings);
		}
		return alone.withAt(own, best >= 0, findings);
	}

	/**
	 * Whether the active area at {@code level} that holds the pixel nearest {@code at} has the outline of several
	 * particles ({@link ComponentShape#outlineMerged}: elongated, or with a bay). The spot finder also flags an
	 * area whose gradient lines miss one another, as a saturated core's flat top makes them: a particle larger or
	 * brighter than the rest, not merged, and no reason to send the user to another.
	 */
	private static boolean outlineMerged(final Plane plane, final double level, final double[] at) {
		final int x = (int) Math.round(at[0]), y = (int) Math.round(at[1]);
		for (final Region r : ComponentLabeling.label(plane, level, Connectivity.EIGHT))
			for (int k = 0; k < r.runCount(); k++)
				if (r.runY(k) == y && r.runStart(k) <= x && x <= r.runEnd(k)) return ComponentShape.of(r).outlineMerged(
					false);
		return false;
	}

	/**
	 * The spots to profile when no point is given: the ones with the largest distances to their nearest neighbours,
	 * none merged, degenerate or near the border, at most {@value #MAX_PARTICLES}, down to half the first one's
	 * distance (or {@code wanted}).
	 */
	private static List<Integer> mostIsolated(final Plane plane, final Spots s, final double diameter,
		final double wanted)
	{
		final int w = plane.width(), h = plane.height();
		final double[][] xy = s.xy();
		final double[] nn = s.nn();
		final Integer[] order = new Integer[xy.length];
		for (int k = 0; k < order.length; k++)
			order[k] = k;
		Arrays.sort(order, Comparator.comparingDouble(k -> -nn[k]));
		final List<Integer> chosen = new ArrayList<>();
		for (final int k : order) {
			final Localization spot = s.spots().get(k);
			if (spot.has(Flag.MERGED) || spot.has(Flag.AT_BORDER) || spot.has(Flag.DEGENERATE)) continue;
			if (xy[k][0] < diameter / 2 || xy[k][1] < diameter / 2 || xy[k][0] > w - 1 - diameter / 2 || xy[k][1] > h - 1 -
				diameter / 2) continue;
			if (!chosen.isEmpty() && nn[k] < Math.min(wanted, 0.5 * nn[chosen.get(0)])) break;
			chosen.add(k);
			if (chosen.size() == MAX_PARTICLES) break;
		}
		return chosen;
	}

	private static List<double[]> centresOf(final double[][] xy, final List<Integer> chosen) {
		final List<double[]> centres = new ArrayList<>();
		for (final int k : chosen)
			centres.add(xy[k]);
		return centres;
	}

	/**
	 * Pools the profile of {@code centres} (the first one's window sets how far out), masking the other spots within
	 * a diameter, then again within the measured reach plus the margin.
	 */
	private static Measured pooledTwice(final Plane plane, final Spots s, final List<double[]> centres,
		final double diameter, final double wanted, final boolean narrow,
		final List<Finding> findings)
	{
		final double radiusCap = Math.min(wanted, farthestCorner(centres.get(0)[0], centres.get(0)[1], plane.width(),
			plane.height()));
		final double narrowest = narrow ? diameter / 2 : Double.POSITIVE_INFINITY;
		PooledProfile pooled = PooledProfile.poolNarrowing(plane, centres, s.xy(), diameter, radiusCap, narrowest,
			null);
		double reach = PooledProfile.reach(pooled, radiusCap, null);
		pooled = PooledProfile.poolNarrowing(plane, centres, s.xy(), Math.max(diameter, reach + R_OUT_MARGIN_PX),
			radiusCap, narrowest, findings);
		reach = PooledProfile.reach(pooled, radiusCap, findings);
		return new Measured(pooled.centres(), null, true, radiusCap, pooled, reach, PooledProfile.imageEdge(pooled,
			reach), findings);
	}

	/**
	 * @return the area of the disc of radius {@code a} about the origin outside the disc of radius {@code r} whose
	 *         centre lies {@code d} away (the circles' lens formula)
	 */
	static double discOutside(final double a, final double r, final double d) {
		final double whole = Math.PI * a * a;
		if (!(a > 0)) return 0;
		if (d >= a + r) return whole;
		if (d <= r - a) return 0; // inside the other disc
		if (d <= a - r) return whole - Math.PI * r * r; // the other disc inside
		final double lens = a * a * Math.acos((d * d + a * a - r * r) / (2 * d * a)) + r * r * Math.acos((d * d + r * r -
			a * a) / (2 * d * r)) - 0.5 * Math.sqrt((-d + a + r) * (d + a - r) * (d - a + r) * (d + a + r));
		return Math.max(0, whole - lens);
	}

	/** Distance of each point to its nearest other point (infinite for a lone point). */
	static double[] nearestNeighbourDistances(final double[][] xy) {
		final double[] nn = new double[xy.length];
		Arrays.fill(nn, Double.POSITIVE_INFINITY);
		for (int i = 0; i < xy.length; i++)
			for (int j = i + 1; j < xy.length; j++) {
				final double d = Math.hypot(xy[i][0] - xy[j][0], xy[i][1] - xy[j][1]);
				nn[i] = Math.min(nn[i], d);
				nn[j] = Math.min(nn[j], d);
			}
		return nn;
	}

	/** Up to about a million pixels of the frame on a regular grid. */
	private static double[] sample(final Plane plane) {
		final long n = (long) plane.width() * plane.height();
		final int stride = (int) Math.max(1, Math.ceil(Math.sqrt(n / 1e6)));
		final DoubleList s = new DoubleList();
		for (int y = 0; y < plane.height(); y += stride)
			for (int x = 0; x < plane.width(); x += stride)
				s.add(plane.get(x, y));
		return s.toArray();
	}


	/**
	 * How much further below the frame's median its darkest pixel must lie than its brightest above it for the
	 * particles to be taken for dark ones when nobody said which. The background covers most of a frame, so the
	 * median is the background's level; bright particles reach further above it than their dark rings reach below,
	 * and dark particles the other way round. Twice as far leaves a margin: saturated cores and deep dark rings can
	 * bring bright particles' two reaches near each other, and such footage must not be taken for dark (manual.md
	 * gives the figures measured on real footage).
	 */
	public static final double DARK_RATIO = 2;

	/**
	 * @return whether the frame's darkest pixel lies more than {@link #DARK_RATIO} times as far below its median as
	 *         its brightest above it (the pixels as {@link #findSpots} samples them): particles darker than the
	 *         background, to be inverted first ({@code core.image.Inversion})
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public static boolean looksDark(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		final double[] v = sample(Plane.of((RandomAccessibleInterval) frame));
		final double median = Statistics.quantile(v, 0.5); // sorted by it
		return median - v[0] > DARK_RATIO * (v[v.length - 1] - median);
	}


	private static double peak(final Plane plane, final double cx, final double cy, final double within) {
		double peak = Double.NEGATIVE_INFINITY;
		final int x0 = (int) Math.max(0, Math.floor(cx - within)), x1 = (int) Math.min(plane.width() - 1, Math.ceil(cx +
			within));
		final int y0 = (int) Math.max(0, Math.floor(cy - within)), y1 = (int) Math.min(plane.height() - 1, Math.ceil(
			cy + within));
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				if (Math.hypot(x - cx, y - cy) <= within) peak = Math.max(peak, plane.get(x, y));
		return peak;
	}

	private static double farthestCorner(final double x, final double y, final int w, final int h) {
		final double dx = Math.max(x, w - 1 - x), dy = Math.max(y, h - 1 - y);
		return Math.hypot(dx, dy);
	}

	static double round2(final double v) {
		return Math.round(v * 100) / 100.0;
	}

	/** How the helper's error messages write a number: {@value #SIGNIFICANT_DIGITS} significant digits. */
	static String fmt(final double v) {
		return Numbers.significant(v, SIGNIFICANT_DIGITS);
	}
}
