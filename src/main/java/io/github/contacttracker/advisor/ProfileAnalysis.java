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

import static io.github.contacttracker.advisor.HelperFormat.fmt;
import static io.github.contacttracker.advisor.HelperFormat.round2;

import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindFeatures;
import io.github.contacttracker.core.kind.Kinds;
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
 * (the same with a point as without; a particle at the point fainter than that is added, found at half its own
 * height), localized by one radial-symmetry pass; merged spots (by shape) and spots at the border are not profiled.</li>
 * <li>Diameter {@code D}: given, or the smaller of the 10th percentile of the spots' nearest-neighbour distances
 * (colloids at contact sit one diameter apart) and twice where the particles' own image ends (the outer edge of a
 * dark ring, else the reach), read off a profile taken to a provisional diameter and measured again at the
 * estimate; a warning says which.</li>
 * <li>Profiled particles: up to {@value ProfiledParticles#MAX_PARTICLES} spots with the largest distances to their
 * nearest neighbour; a point given, its particle alone when isolated (nearest neighbour and image edge at least twice
 * {@code r_out} away), else those spots, and said. Pixels within the reach of any other spot are masked (first
 * {@code D}, then the measured reach).</li>
 * <li>Local background: around each particle a plane fitted robustly to the outer
 * {@value PooledProfile#BACKGROUND_ANNULUS_PERCENT}% of {@code max_radius} ({@value Margins#AUTO_RADIUS_DIAMETERS}
 * diameters unless given): a background drifting across the frame is removed with it.</li>
 * <li>Noise {@code s}: the robust (3.5-sigma clipped) standard deviation of the pixels of those annuli about their
 * planes. It
 * sees compression noise that is smooth within 8x8 blocks, which a pixel-difference estimator (Immerkaer) misses,
 * and is not moved by a neighbour's light in part of the annulus.</li>
 * <li>Profile {@code P(r)}: the interquartile mean, over all profiled particles, of the pixels' heights above their
 * local background in 1 px wide rings. It ignores the part of a ring a neighbour covers (up to a quarter), and
 * unlike a median it is not stuck on the integer steps of 8-bit data.</li>
 * <li>{@code r_out}: the radius beyond which {@code |P(r)| <= s} (the reach), plus {@value Margins#R_OUT_MARGIN_PX}
 * px.</li>
 * <li>{@code threshold}: particles at contact add up. For two (centres {@code D} apart) and three (a touching
 * triangle) the summed profiles are evaluated on a 0.5 px grid at every point at least {@code D/2} from all
 * centres (outside every particle's own half): the brightest such point is the bridge their active areas must
 * not reach. The threshold is the bridge plus {@value Margins#THRESHOLD_MARGIN_SIGMAS} {@code s}. On a saturated core
 * only the plateau is flat, and the rule does not look inside {@code D/2}.</li>
 * <li>Raised, when it must be, clear of the background's texture ({@link ThresholdRules#textureGap}) and until the
 * frame's active areas are round ({@link ThresholdRules#roundFrom}).</li>
 * <li>Kinds of particle ({@link #kinds}): the frame tracked at the suggested threshold and {@code r_out} (the
 * paper's method), each particle measured about its centre ({@link KindFeatures}) and the kinds found
 * automatically ({@link Kinds#find(java.util.Collection)}), as the tracker finds them.</li>
 * </ol>
 * The steps have their own classes: the spots {@link FrameSpots}, the diameter {@link DiameterEstimate}, the
 * particles profiled {@link ProfiledParticles}, their background {@link BackgroundPlane} and pooled profile
 * {@link PooledProfile}, the threshold {@link ThresholdRules}; this class joins them. Whether a frame's particles are
 * dark, before any of it, is {@link Contrast}'s.
 */
public final class ProfileAnalysis {

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

		/**
		 * @return {@link #threshold} rounded up to a whole grey level when the data are integers, else to the helper's
		 *         significant digits ({@link HelperFormat#rounded}: a change of at most 0.05%, far below the noise)
		 */
		public double suggestedThreshold(final boolean integerData) {
			return integerData ? Math.ceil(threshold - 1e-9) : HelperFormat.rounded(threshold);
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
			return ThresholdRules.minArea(ThresholdRules.activeRadius(radius, level, count, threshold));
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
	 * @param maxRadius radius to measure out to (px); 0 for {@value Margins#AUTO_RADIUS_DIAMETERS} diameters. It is
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

	/** @return the radius of the profile's innermost ring that holds pixels (px); NaN if none does */
	private static double innermost(final PooledProfile pooled) {
		for (int k = 0; k < pooled.count().length; k++)
			if (pooled.count()[k] > 0) return pooled.radius()[k];
		return Double.NaN;
	}

	private static <T extends RealType<T>> Result run(final RandomAccessibleInterval<T> frame, final double[] point,
		final double diameterGiven, final double maxRadiusGiven,
		final List<? extends RandomAccessibleInterval<T>> kindFrames)
	{
		checkArguments(diameterGiven, maxRadiusGiven);
		final Plane plane = Plane.of(frame);
		// a particle wider than the frame cannot be profiled, and the helper's work grows as the diameter squared
		if (diameterGiven > Math.max(plane.width(), plane.height()))
			throw new InvalidInputException("diameter " + fmt(diameterGiven) + " px is wider than the frame (" + plane
				.width() + " x " + plane.height() + " px): give the particle diameter in pixels, or 0 to estimate it");
		final double[] at = point == null ? null : local(plane, point);
		final FrameSpots spots = FrameSpots.find(plane, point, at, diameterGiven);
		final List<Finding> findings = new ArrayList<>();
		final DiameterEstimate sized = DiameterEstimate.sizeAndMeasure(plane, spots, at, diameterGiven,
			maxRadiusGiven, findings);
		final double diameter = sized.diameter();
		final ProfiledParticles m = sized.measured();
		final PooledProfile pooled = m.pooled();
		final double[] centre = m.centres().get(0), subject = m.at() != null ? m.at() : centre;
		// a profile that starts beyond the particle's radius measured the space around something else (its pixels
		// masked by neighbours nearer than the particle is wide: a tweezer's bead, its texture and the dust around
		// it found as particles of their own), and its r_out and threshold would be made up
		// (a pixel's width of margin: the rings of a particle a few pixels across start near a pixel out)
		final double innermost = innermost(pooled);
		if (!(innermost <= diameter / 2 + 1)) throw new InvalidInputException(String.format(Locale.ROOT, "the profile " +
			"around (%.1f, %.1f) holds no pixel within the particle's radius (%.1f px) of its centre, its first at " +
			"%.1f px: the spots found there lie closer than a particle is wide; give a point on a particle%s",
			subject[0] + plane.minX(), subject[1] + plane.minY(), diameter / 2, innermost, diameterGiven > 0 ? ""
				: ", or its diameter"));
		final double rOut = m.reach() + Margins.R_OUT_MARGIN_PX;
		final double[] level = ThresholdRules.levels(pooled);
		final ThresholdRules.Threshold t = ThresholdRules.threshold(plane, pooled, level, diameter, m.reach(), centre, findings);
		final double activeRadius = ThresholdRules.activeRadius(pooled.radius(), level, pooled.count(), t.threshold());
		if (activeRadius == 0) findings.add(new Finding.ThresholdAboveCentre());
		final List<double[]> inFrame = new ArrayList<>();
		for (final double[] c : m.centres())
			inFrame.add(new double[] { c[0] + plane.minX(), c[1] + plane.minY() });
		return new Result(subject[0] + plane.minX(), subject[1] + plane.minY(), m.refined(), diameter, sized
			.estimated(), m.centres().size(), m.radiusCap(), pooled.radius(), level, pooled.count(), pooled.background(), pooled
				.noise(), t.peak(), m.reach(), rOut, t.bridge(), t.atContact(), t.threshold(), activeRadius, inFrame,
			findings, kinds(kindFrames, t.threshold(), rOut, ThresholdRules.minArea(activeRadius)));
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
}
