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
package io.github.contacttracker.core;

/**
 * Parameters of the localizer, immutable and validated on construction.
 *
 * @param threshold grey level: pixels with {@code I >= threshold} form the active areas
 * @param rOut radius (px) of a particle's effective disc: where its image has returned to background, plus 2 px.
 *        One measured length that does four jobs, each named by an accessor: {@link #exclusionRadius()} (the
 *        paper's second pass), {@link #aloneReach()} (merge detection), {@link #groupingDistance()} (the joint fit)
 *        and {@link #profileReach()} (the measured profile)
 * @param minArea components with fewer active pixels are noise and dropped (px)
 * @param connectivity pixel neighbourhood of the labelling
 * @param minSecondArea below this many pixels in the second active area the spot keeps its first-pass centre
 *        and is flagged {@link Flag#FELL_BACK}
 * @param method how centres are computed
 * @param diameter the particles' diameter (px): the smallest centre distance of two particles at contact; 0 when
 *        not known. Merge detection uses it: a component too small to hold two particles that far apart is one
 *        particle, whatever its gradient lines do (the component's shape, {@code core.radial.ComponentShape})
 * @param kinds kinds of particle the profile methods tell apart, each with its own measured profile: 0 found
 *        automatically (by size and brightness, {@code core.kind.Kinds}), 1 all alike, or that many
 * @param detection how the profile methods find the particles: by their image ({@link Detection#IMAGE}, given a
 *        diameter), by the threshold's components, or either, chosen per movie ({@link Detection#AUTO}); the paper's
 *        method and the first pass always use the threshold
 */
public record TrackerParameters(double threshold, double rOut, int minArea, Connectivity connectivity,
	int minSecondArea, Method method, double diameter, int kinds, Detection detection)
{
	/**
	 * How far out the particles' profile is measured and modelled, as a multiple of {@code r_out}: {@code r_out}
	 * marks where the light falls below the noise, but the faint tail beyond still tilts a neighbour's gradients at
	 * the nanometre level, so the model must carry it.
	 */
	public static final double PROFILE_REACH_FACTOR = 1.5;

	/** Default {@code min_area} (px). */
	public static final int DEFAULT_MIN_AREA = 20;
	/** Default {@code min_second_area} (px). */
	public static final int DEFAULT_MIN_SECOND_AREA = 50;

	// The limits of the parameters, stated here only: the settings descriptor (settings.TrackingSettings), and
	// through it every front end, takes them from these constants (compile-time constants, so that the Fiji
	// command's @Parameter annotations can name them too).

	/** What a valid threshold is, for messages. */
	public static final String THRESHOLD_ALLOWED = "a finite grey level";
	/** {@code r_out} must be above this (px). */
	public static final double R_OUT_ABOVE = 0;
	/** What a valid {@code r_out} is, for messages. */
	public static final String R_OUT_ALLOWED = "a positive number of pixels";
	/**
	 * The measured profile's reach ({@link #profileReach()}) must exceed this (px): the profile is sampled every
	 * pixel from its centre, and fewer than three samples describe no particle ({@code core.profile.ProfileEstimator}).
	 */
	public static final double PROFILE_REACH_ABOVE = 3;
	/** {@code r_out} must be above this (px) for the methods that measure the profile. */
	public static final double PROFILE_R_OUT_ABOVE = PROFILE_REACH_ABOVE / PROFILE_REACH_FACTOR;
	/** Smallest {@code min_area} (px): one pixel. */
	public static final int MIN_AREA_AT_LEAST = 1;
	/** What a valid {@code min_area} is, for messages. */
	public static final String MIN_AREA_ALLOWED = "at least " + MIN_AREA_AT_LEAST + " pixel";
	/** Smallest {@code min_second_area} (px). */
	public static final int MIN_SECOND_AREA_AT_LEAST = 3;
	/** What a valid {@code min_second_area} is, for messages. */
	public static final String MIN_SECOND_AREA_ALLOWED = "at least " + MIN_SECOND_AREA_AT_LEAST + " pixels";
	/** Smallest diameter (px); the smallest, 0, means not known. */
	public static final double DIAMETER_AT_LEAST = 0;
	/** Most kinds of particle (the profile methods measure a profile per kind). */
	public static final int KINDS_AT_MOST = 4;
	/** What a valid number of kinds is, for messages. */
	public static final String KINDS_ALLOWED = "0 (found automatically), 1 (all alike) or up to " + KINDS_AT_MOST;

	/** @throws IllegalArgumentException with a one-line message naming the bad parameter */
	public TrackerParameters {
		if (!Double.isFinite(threshold))
			throw new InvalidInputException("threshold must be " + THRESHOLD_ALLOWED + ", not " + threshold);
		if (!(rOut > R_OUT_ABOVE) || !Double.isFinite(rOut))
			throw new InvalidInputException("r_out must be " + R_OUT_ALLOWED + ", not " + rOut);
		if (minArea < MIN_AREA_AT_LEAST)
			throw new InvalidInputException("min_area must be " + MIN_AREA_ALLOWED + ", not " + minArea);
		if (minSecondArea < MIN_SECOND_AREA_AT_LEAST)
			throw new InvalidInputException("min_second_area must be " + MIN_SECOND_AREA_ALLOWED + ", not " +
				minSecondArea);
		if (connectivity == null) throw new InvalidInputException("connectivity must be given (4 or 8)");
		if (method == null) throw new InvalidInputException("method must be given");
		if (method.needsProfile() && !(rOut > PROFILE_R_OUT_ABOVE)) throw new InvalidInputException("r_out must exceed " +
			PROFILE_R_OUT_ABOVE + " px for the " + method.key() + " method, not " + rOut + ": it measures the particles' " +
			"profile out to 1.5 r_out, which needs more than " + PROFILE_REACH_ABOVE + " px; particles this small are " +
			"tracked with the paper method");
		if (!(diameter >= DIAMETER_AT_LEAST) || !Double.isFinite(diameter))
			throw new InvalidInputException("diameter must be >= 0 pixels (0 = not given), not " + diameter);
		if (kinds < 0 || kinds > KINDS_AT_MOST) throw new InvalidInputException("kinds must be " + KINDS_ALLOWED +
			", not " + kinds);
		if (detection == null) throw new InvalidInputException("detection must be given (auto, image or threshold)");
	}

	/** Parameters with the {@link Detection#DEFAULT default detection}. */
	public TrackerParameters(final double threshold, final double rOut, final int minArea,
		final Connectivity connectivity, final int minSecondArea, final Method method, final double diameter,
		final int kinds)
	{
		this(threshold, rOut, minArea, connectivity, minSecondArea, method, diameter, kinds, Detection.DEFAULT);
	}

	/**
	 * @return whether this frame's particles are found by their image: a profile method (or the iterative pass that
	 *         starts it), {@link Detection#IMAGE}, and a diameter to set the filter's scale
	 */
	public boolean detectsByImage() {
		return detection == Detection.IMAGE && diameter > 0 && (method.needsProfile() || method == Method.ITERATIVE);
	}

	/**
	 * @return whether a movie's detection is still to be chosen from its sample frames ({@link Detection#AUTO}, a
	 *         profile method and a diameter; see {@code core.detect.DetectionChoice})
	 */
	public boolean choosesDetection() {
		return detection == Detection.AUTO && diameter > 0 && method.needsProfile();
	}

	/**
	 * @return the radius (px) of the disc around a neighbour's first-pass centre that the paper's second pass leaves
	 *         out of a spot's active area: inside it the neighbour's light, not the spot's, sets the gradients
	 *         ({@code r_out})
	 */
	public double exclusionRadius() {
		return rOut;
	}

	/**
	 * @return how far (px) beyond a component's equivalent radius no other particle's first-pass centre may lie for
	 *         merge detection to call it alone: a particle's image reaches {@code r_out} from its centre, so only
	 *         then do the component's gradient lines owe nothing to a neighbour, and their failing to meet in one
	 *         point means several particles ({@code r_out})
	 */
	public double aloneReach() {
		return rOut;
	}

	/**
	 * @return the centre distance (px) below which the profile methods fit particles together, and up to which a
	 *         particle left out of the model is said to disturb a neighbour: each image reaches {@code r_out}, so two
	 *         closer than twice that share pixels ({@code 2 r_out})
	 */
	public double groupingDistance() {
		return 2 * rOut;
	}

	/** @return how far (px) from its centre a particle's profile is measured and modelled ({@code 1.5 r_out}) */
	public double profileReach() {
		return PROFILE_REACH_FACTOR * rOut;
	}

	/** Parameters without a diameter (not known). */
	public TrackerParameters(final double threshold, final double rOut, final int minArea,
		final Connectivity connectivity, final int minSecondArea, final Method method)
	{
		this(threshold, rOut, minArea, connectivity, minSecondArea, method, 0);
	}

	/** Parameters whose kinds of particle are found automatically. */
	public TrackerParameters(final double threshold, final double rOut, final int minArea,
		final Connectivity connectivity, final int minSecondArea, final Method method, final double diameter)
	{
		this(threshold, rOut, minArea, connectivity, minSecondArea, method, diameter, 0);
	}

	/** @return parameters with the given threshold and r_out and defaults for the rest */
	public static TrackerParameters of(final double threshold, final double rOut) {
		return new TrackerParameters(threshold, rOut, DEFAULT_MIN_AREA, Connectivity.EIGHT, DEFAULT_MIN_SECOND_AREA,
			Method.DEFAULT);
	}

	public TrackerParameters withMinArea(final int a) {
		return new TrackerParameters(threshold, rOut, a, connectivity, minSecondArea, method, diameter, kinds, detection);
	}

	public TrackerParameters withMinSecondArea(final int a) {
		return new TrackerParameters(threshold, rOut, minArea, connectivity, a, method, diameter, kinds, detection);
	}

	public TrackerParameters withDiameter(final double d) {
		return new TrackerParameters(threshold, rOut, minArea, connectivity, minSecondArea, method, d, kinds, detection);
	}

	public TrackerParameters withMethod(final Method m) {
		return new TrackerParameters(threshold, rOut, minArea, connectivity, minSecondArea, m, diameter, kinds, detection);
	}

	public TrackerParameters withDetection(final Detection d) {
		return new TrackerParameters(threshold, rOut, minArea, connectivity, minSecondArea, method, diameter, kinds, d);
	}

	/** @param k kinds of particle: 0 found automatically, 1 all alike, or that many */
	public TrackerParameters withKinds(final int k) {
		return new TrackerParameters(threshold, rOut, minArea, connectivity, minSecondArea, method, diameter, k, detection);
	}
}
