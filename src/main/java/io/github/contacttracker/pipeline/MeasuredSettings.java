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
package io.github.contacttracker.pipeline;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.IntFunction;

import io.github.contacttracker.advisor.Finding;
import io.github.contacttracker.advisor.HelperFormat;
import io.github.contacttracker.advisor.Margins;
import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.detect.ImageDetection;
import io.github.contacttracker.core.detect.ParticleScale;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;

/**
 * The settings of a run with what the user did not give measured from the movie's first frame by the profile
 * helper, as {@code profile} suggests it: the threshold and r_out (an error if they cannot be measured), the
 * diameter (merge detection and RADIUS use it; without it the movie is still tracked), and for particles so small
 * that their active areas come near the default {@code min_area} a smaller one. The command line's
 * {@code track} and the Spark job both use it, so that they track a movie with the same settings.
 */
public final class MeasuredSettings {

	private MeasuredSettings() {}

	/**
	 * @param settings the settings to use
	 * @param notice what was measured, with the options that override it, in one line; empty when nothing was
	 * @param profiled how many particles the helper pooled the profile of (0 where it did not measure)
	 */
	public record Result(SettingValues settings, String notice, int profiled) {

		/** A result the helper did not measure. */
		public Result(final SettingValues settings, final String notice) {
			this(settings, notice, 0);
		}
	}

	/**
	 * @param name the movie's file name, for messages
	 * @param first the movie's first frame
	 * @param integerData whether the pixels are integers (the threshold is then suggested as a whole number)
	 * @param settings the settings given (the others at their defaults)
	 * @param given the settings the user gave. Of these the threshold, r_out, the particles and {@code min_area}
	 *        count: when neither the particles (bright or dark) nor the threshold was given, the particles are taken
	 *        for dark ones where the frame looks so ({@link Contrast#looksDark}); when {@code min_area} was not,
	 *        it is lowered for small particles ({@link ProfileAnalysis.Result#suggestedMinArea}); the notice says so
	 * @throws InvalidInputException when the threshold or r_out is missing and cannot be measured
	 */
	public static Result of(final String name, final RandomAccessibleInterval<?> first, final boolean integerData,
		final SettingValues settings, final Set<Setting<?>> given, final FrontEnd words)
	{
		return of(name, first, 1, true, integerData, settings, given, words);
	}

	/**
	 * As {@link #of(String, RandomAccessibleInterval, boolean, SettingValues, Set)}, where the user gave at most a
	 * diameter and the particles' contrast besides the method and detection: what the front ends that measure on
	 * one frame ({@code profile}, the "Measure from the image" buttons) suggest where the helper's own threshold lies
	 * outside that frame.
	 *
	 * @param chosen the settings to measure with: the method and detection chosen, the rest as it comes
	 * @param diameter the diameter given (px), 0 for none (measured)
	 * @param particles the contrast given ({@link TrackingSettings#DARK} or the default), null for none (measured)
	 */
	public static Result of(final String name, final RandomAccessibleInterval<?> frame, final boolean integerData,
		final SettingValues chosen, final double diameter, final String particles, final FrontEnd words)
	{
		SettingValues v = chosen;
		final Set<Setting<?>> given = new HashSet<>();
		if (diameter > 0) {
			v = v.with(TrackingSettings.DIAMETER, diameter);
			given.add(TrackingSettings.DIAMETER);
		}
		if (particles != null) {
			v = v.withText(TrackingSettings.PARTICLES, particles);
			given.add(TrackingSettings.PARTICLES);
		}
		return of(name, frame, integerData, v, given, words);
	}

	/**
	 * As {@link #of(String, RandomAccessibleInterval, boolean, SettingValues, Set)}, on a movie of {@code count}
	 * frames, measured on the frame {@link HelperFrames} chooses (the first, unless it is blank, looks the other
	 * contrast's, or sizes a lone blob unlike the others), which the notice names.
	 *
	 * @param frame supplies frame {@code t} (0-based) of the movie
	 */
	public static Result of(final String name, final IntFunction<? extends RandomAccessibleInterval<?>> frame,
		final int count, final boolean integerData, final SettingValues settings, final Set<Setting<?>> given,
		final FrontEnd words)
	{
		return HelperFrames.of(name, frame, count, integerData, settings, given, words);
	}

	/** @return whether the particles' contrast is judged from the frame ({@link Contrast#looksDark}): nobody said it */
	static boolean contrastJudged(final SettingValues settings, final Set<Setting<?>> given) {
		return !given.contains(TrackingSettings.THRESHOLD) && !given.contains(TrackingSettings.PARTICLES) && !settings
			.dark();
	}

	/**
	 * @param number the frame's number in the movie, counted from 1, for the notice
	 * @param fallBack whether a frame the helper cannot measure on falls back to detection by the image (where that
	 *        may be chosen); without, it is refused
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	static Result of(final String name, final RandomAccessibleInterval<?> first, final int number,
		final boolean fallBack, final boolean integerData, final SettingValues settings, final Set<Setting<?>> given,
		final FrontEnd words)
	{
		final boolean thresholdGiven = given.contains(TrackingSettings.THRESHOLD), rOutGiven = given.contains(
			TrackingSettings.R_OUT), particlesGiven = given.contains(TrackingSettings.PARTICLES);
		final boolean diameter = settings.diameter() > 0;
		if (thresholdGiven && rOutGiven && diameter) return new Result(settings, "");
		SettingValues v = settings;
		final Said said = new Said();
		if (contrastJudged(settings, given) && Contrast.looksDark(
			(RandomAccessibleInterval) first, settings.diameter()))
		{
			v = v.withText(TrackingSettings.PARTICLES, TrackingSettings.DARK);
			said.add(TrackingSettings.PARTICLES, TrackingSettings.DARK);
		}
		final RandomAccessibleInterval seen = v.dark() ? Inversion.of((RandomAccessibleInterval) first) : first;
		ProfileAnalysis.Result r;
		try {
			r = ProfileAnalysis.analyse(seen, v.diameter(), 0);
		}
		catch (final InvalidInputException e) {
			if (!fallBack) throw e;
			final Seen frame = new Seen(seen);
			final boolean otherContrast = autoSeesOtherContrast(v, frame, particlesGiven);
			if (imageCanTake(v) && !(auto(v) && (thresholdGiven && rOutGiven || otherContrast))) return byImage(name,
				number, frame, v, thresholdGiven, rOutGiven, said, false, e, words);
			if (thresholdGiven && rOutGiven) return new Result(settings, "contact-tracker: " + name + ": the diameter " +
				"could not be measured (" + InvalidInputException.oneLine(e.getMessage()) + "); tracked without it (give " +
				words.name(TrackingSettings.DIAMETER) + ")");
			final List<String> missing = new ArrayList<>();
			if (!thresholdGiven) missing.add(words.name(TrackingSettings.THRESHOLD));
			if (!rOutGiven) missing.add(words.name(TrackingSettings.R_OUT));
			throw new InvalidInputException("cannot measure " + String.join(" and ", missing) + " on the first frame of " +
				name + ": " + e.getMessage() + (otherContrast && !v.dark() ? "; the inverted frame shows stronger blobs: if " +
					"the particles are darker than the background, give " + words.value(TrackingSettings.PARTICLES,
						TrackingSettings.DARK) : "") + byImageHint(frame, v, words) + "; or give them (" + words.measuresOne() +
				" measures one particle)", e);
		}
		boolean blobs = false; // the helper measured at the frame's blobs' diameter (atTheBlobs)
		if (!thresholdGiven) {
			final double[] range = ImagePlusFrames.range(seen, 0);
			final Seen frame = new Seen(seen);
			final double own = r.suggestedThreshold(integerData);
			// auto refuses a frame whose helper's threshold lies above every pixel where its other contrast's blobs stand
			// out more (see below): judged once, for the helper at the blobs' diameter and for the fall-back
			final boolean otherContrast = own > range[1] && autoSeesOtherContrast(settings, frame, particlesGiven);
			// (not where the helper measured the particles' rim, whose diameter stands)
			if (!diameter && !within(own, range) && !measuredRim(r) && !otherContrast) {
				final ProfileAnalysis.Result again = atTheBlobs(frame, range, integerData);
				if (again != null) {
					r = again;
					blobs = true;
				}
			}
			v = v.with(TrackingSettings.THRESHOLD, r.suggestedThreshold(integerData));
			said.add(TrackingSettings.THRESHOLD, optionValue(v.get(TrackingSettings.THRESHOLD)));
			// outside the frame's range. Above every pixel: what the helper took for particles' cores are not (e.g. the
			// bright rings around the dark cores of a bright-field movie, inverted). Below: the helper's background lies
			// under the frame's darkest pixel (no dark gap between particles packed edge to edge).
			final double t = v.get(TrackingSettings.THRESHOLD);
			if (!within(t, range)) { // (the helper's own threshold, t == own: at the blobs' it lies within)
				final boolean above = t > range[1];
				final String side = above ? "above" : "below";
				if (fallBack && imageCanTake(settings) && !otherContrast) {
					// isolated blurred spheres whose rim the helper measured (only no threshold keeps two apart at
					// contact): its diameter and r_out stand
					final boolean rim = measuredRim(r);
					final Said kept = new Said();
					if (!particlesGiven && v.dark()) kept.add(TrackingSettings.PARTICLES, TrackingSettings.DARK);
					SettingValues fallen = settings.withText(TrackingSettings.PARTICLES, v.get(TrackingSettings.PARTICLES));
					if (rim && !diameter) {
						fallen = fallen.with(TrackingSettings.DIAMETER, r.suggestedDiameter());
						kept.add(TrackingSettings.DIAMETER, optionValue(r.suggestedDiameter()));
					}
					if (rim && !rOutGiven) {
						fallen = fallen.with(TrackingSettings.R_OUT, r.suggestedROut());
						kept.add(TrackingSettings.R_OUT, optionValue(r.suggestedROut()));
					}
					final Result image = byImage(name, number, frame, fallen, false, rOutGiven || rim, kept, rim &&
						(!diameter || !rOutGiven), new InvalidInputException("its threshold " + optionValue(t) + " lies " +
							side + " every pixel"), words);
					// (the helper measured the particles, though not the threshold: counted)
					return rim ? new Result(image.settings(), image.notice(), r.particles()) : image;
				}
				throw new InvalidInputException("cannot measure " + words.name(TrackingSettings.THRESHOLD) + " on the first " +
					"frame of " + name + ": the helper's " + optionValue(t) + " lies " + side + " its every pixel (" +
					optionValue(above ? range[1] : range[0]) + ")" + (above && !v.dark() ? "; if the particles are darker " +
						"than the background, give " + words.value(TrackingSettings.PARTICLES, TrackingSettings.DARK) : "") +
					byImageHint(frame, v, words) + "; or give the values (" + words.measuresOne() + " measures one particle)");
			}
		}
		if (!rOutGiven) {
			v = v.with(TrackingSettings.R_OUT, r.suggestedROut());
			said.add(TrackingSettings.R_OUT, optionValue(v.get(TrackingSettings.R_OUT)));
		}
		if (!diameter) {
			v = v.with(TrackingSettings.DIAMETER, r.suggestedDiameter());
			said.add(TrackingSettings.DIAMETER, optionValue(v.diameter()));
		}
		final int minArea = r.suggestedMinArea(v.get(TrackingSettings.THRESHOLD));
		if (!given.contains(TrackingSettings.MIN_AREA) && minArea < v.get(TrackingSettings.MIN_AREA)) {
			v = v.with(TrackingSettings.MIN_AREA, minArea);
			said.add(TrackingSettings.MIN_AREA, String.valueOf(minArea));
		}
		return new Result(v, "contact-tracker: " + name + ": measured on frame " + number + " by the profile helper" + (blobs
			? " at the diameter of the frame's blobs (its own threshold lay outside the frame's range)" : "") + ":" + said
				.in(words) + " (given values win; " + words.showsHow(name, number) + (blobs ? " with " + words.value(
					TrackingSettings.DIAMETER, optionValue(v.diameter())) : "") + " shows how)" + (!rOutGiven &&
						imageCanTake(v) ? shortReach(v.get(TrackingSettings.R_OUT), v.diameter(), words) : ""), r
							.particles());
	}

	/**
	 * @return what to try where the measured {@code r_out} reaches less than {@link Margins#R_OUT_MARGIN_PX} past the
	 *         particles' radius (empty otherwise): the fit reads a particle's pixels out to {@code r_out} times its
	 *         scale, so in a packed field of particles of several sizes, whose measured profile is the mean particle's,
	 *         that window cuts the larger ones' edges, where the information on their centres lies, and many are
	 *         missed. The helper's reach is where the profile meets the background it measured, which in a packed
	 *         field lies on the neighbours' light: on the detection study's dense-polydisperse scene (D 7 to 13.3 px,
	 *         seeds 3 to 5) it measured r_out 5 at a diameter of 5.3 to 7.8 px, and 77% to 88% of the particles were
	 *         found; with r_out 6 or 7, 97.6% to 99.9%. Where the profile's reach is the truth (a confocal stack of
	 *         spheres 8 px across, r_out 4), a larger one can leave the profile rounds without a fixed point, every
	 *         spot flagged: so it is said, not done.
	 */
	static String shortReach(final double rOut, final double diameter, final FrontEnd words) {
		final double least = diameter / 2 + Margins.R_OUT_MARGIN_PX;
		if (!(diameter > 0) || !(rOut < least - 1e-9)) return "";
		return "; its " + words.name(TrackingSettings.R_OUT) + " reaches less than " + optionValue(
			Margins.R_OUT_MARGIN_PX) + " px past the particles' radius (" + optionValue(diameter / 2) + " px): where " +
			"their sizes differ, the larger ones' edges are cut and some are missed: try " + words.value(
				TrackingSettings.R_OUT, optionValue(Math.ceil(least - 1e-9))) + " and check the flags";
	}

	/** @return whether the helper measured the particles' diameter on their rim (at half height) */
	private static boolean measuredRim(final ProfileAnalysis.Result r) {
		return r.findings().stream().anyMatch(f -> f instanceof Finding.DiameterFromHalfHeight);
	}

	/** @return whether {@code t} lies within {@code range} (lowest, highest) */
	private static boolean within(final double t, final double[] range) {
		return t >= range[0] && t <= range[1];
	}

	/**
	 * The helper again, at the diameter of the frame's blobs ({@link ParticleScale}), where at its own it suggested a
	 * threshold outside the frame's range, no diameter was given and the helper did not measure the particles' rim
	 * (isolated blurred discs: their rim's diameter is within 3-4% of the truth where the blobs' is 8% off, and a pair of
	 * them tracked at the blobs' merged once at half a diameter apart). Its own diameter is where the particles' profile
	 * returns to the background, which the photon noise of a confocal slice hides: on a stack of dense polydisperse
	 * spheres with bright cores 8 px across it read 3.2 px, and a threshold above every pixel, where the blobs read
	 * 8.0 px and the helper at 8 px measures a threshold and r_out that track the spheres (with the threshold's areas
	 * or by the image, as auto then chooses), as if the user had given that diameter.
	 *
	 * @return the helper's result at the blobs' diameter where it suggests a threshold within {@code range}, else null
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static ProfileAnalysis.Result atTheBlobs(final Seen seen, final double[] range, final boolean integerData) {
		if (!(seen.blobs() > 0)) return null;
		try {
			final ProfileAnalysis.Result again = ProfileAnalysis.analyse(seen.frame, seen.diameter(), 0);
			return within(again.suggestedThreshold(integerData), range) ? again : null;
		}
		catch (final InvalidInputException e) {
			return null;
		}
	}

	/**
	 * Where the helper cannot measure r_out, it is at most this share of the particles' spacing ({@link #SPACING}):
	 * the profile reaches 1.5 r_out, and a profile that reaches the neighbours' centres takes their light for its own
	 * tail in a packed field (on a public dense monolayer of spheres 18-20 px apart the fits settled at r_out 12 and
	 * slid off at 14 and above).
	 */
	static final double SPACED = 2 / 3.0;

	/**
	 * The particles' spacing is this quantile of the distances from a seed to its nearest one: the distance at contact
	 * where particles touch, as the helper's diameter is. Not the median: a seed missed in a packed field leaves its
	 * neighbours' nearest distance at the next one out (on that monolayer the seeds' median is 21.2 px against 19.7
	 * between the spheres, and its r_out, 14.1, loses a fifth of them; the 10th percentile gives 12.8 and finds them
	 * all).
	 */
	static final double SPACING = 0.1;

	/**
	 * @return the largest r_out for particles of diameter {@code d} that the particles' spacing allows ({@link #SPACED}
	 *         of the {@link #SPACING} quantile of the distances between the image's seeds and their nearest ones, at
	 *         least 3 px, to 0.1 px), and never below {@link #SPACED} of the diameter: the profile then reaches a
	 *         diameter from the centre, the particle's radius and as much again for its blurred edge. (A packed field's
	 *         seeds lie at its particles' diameter apart, and their 10th percentile, shortened by the seeds' own errors,
	 *         below it: on a simulated monolayer of discs of 14 px whose blurred edges reach 10 px from the centre the
	 *         spacing gave 7.8 px, the profile's reach fell short of the edges, and a fifth of the particles were
	 *         found; from 9 px all were.)
	 */
	private static double spacedROut(final Plane plane, final double d) {
		// a diameter beyond the frame's diagonal is refused by the tracker itself; no seeds are sought at its scale
		if (!(d <= Math.hypot(plane.width(), plane.height()))) return Double.POSITIVE_INFINITY;
		final double spacing = ImageDetection.seeds(plane, d, NoiseEstimate.sigma(plane)).spacing(SPACING);
		return Math.round(10 * Math.max(3, Math.min(1e6, SPACED * Math.max(d, spacing)))) / 10.0;
	}

	/**
	 * @return whether detection by the image was asked for, or may be chosen (auto, a profile method): it needs the
	 *         diameter, not the threshold
	 */
	private static boolean imageCanTake(final SettingValues v) {
		return v.get(TrackingSettings.DETECTION).equals(TrackingSettings.IMAGE) || auto(v) && Method.parse(v.get(
			TrackingSettings.METHOD)).needsProfile();
	}

	/**
	 * @return whether the detection is to be chosen (auto): by the image only where the threshold cannot be had, so
	 *         a threshold and r_out given keep it
	 */
	private static boolean auto(final SettingValues v) {
		return v.get(TrackingSettings.DETECTION).equals(TrackingSettings.AUTO);
	}

	/**
	 * @return whether the detection is auto and the frame looks like dark cores in bright rings rather than bright
	 *         particles packed edge to edge ({@link DetectionChoice#otherContrastStronger}): auto then refuses, with
	 *         what to try, as the threshold does, instead of tracking the rings by their image; not where both the
	 *         particles' contrast and their diameter were given: the user has said what the particles are, such as a
	 *         tweezer's bead dark inside a bright rim, whose rim's pieces the frame's other contrast shows as blobs
	 * @param particlesGiven whether the particles' contrast was given
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static boolean autoSeesOtherContrast(final SettingValues v, final Seen seen, final boolean particlesGiven) {
		if (!auto(v) || particlesGiven && v.diameter() > 0) return false;
		// (at a diameter given, as the contrast was judged: Contrast#looksDark)
		if (v.diameter() > 0) return DetectionChoice.otherContrastStrongerAt(seen.plane(), seen.inverted(), v
			.diameter());
		final double d = seen.blobs();
		return d > 0 && DetectionChoice.otherContrastStronger(seen.plane(), seen.inverted(), d);
	}

	/**
	 * @return where the helper could not measure, what else the frame shows: the diameter of its blobs
	 *         ({@link ParticleScale}) and the options that track them by their image; empty where it holds none, or
	 *         the method is the paper's (which keeps its threshold)
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static String byImageHint(final Seen seen, final SettingValues v, final FrontEnd words) {
		if (v.get(TrackingSettings.METHOD).equals(Method.PAPER.key())) return "";
		final double d = seen.blobs();
		if (!(d > 0)) return "";
		final String dd = optionValue(Math.round(d * 10) / 10.0);
		final Said image = new Said();
		image.add(TrackingSettings.DETECTION, TrackingSettings.IMAGE);
		if (!(v.diameter() > 0)) image.add(TrackingSettings.DIAMETER, dd);
		return "; its blobs are about " + dd + " px across:" + image.in(words) + " tracks them by their image, without " +
			"a threshold";
	}

	/**
	 * Detection by the image needs the diameter, not the threshold: where the helper cannot measure (a dense field
	 * without an isolated particle, a particle cut by the edge, one at low contrast), the diameter, when not given,
	 * is the scale of the frame's blobs ({@link ParticleScale}), a missing threshold is the middle of the frame's range
	 * (the threshold's components then only start the profile where they are single particles) and a missing r_out one
	 * diameter (a particle's image reaches about a radius beyond its edge), or less where the particles are packed
	 * closer ({@link #SPACED}), all said in the notice.
	 *
	 * @param number the frame's number in the movie, counted from 1, for the notice where the helper measured its rim
	 * @param rimKept whether {@code said} holds the helper's rim diameter or r_out, kept where only its threshold lies
	 *        outside the frame's range: the notice then says what the helper measured (on which frame, after the
	 *        first), and what it did not
	 * @throws InvalidInputException where the frame holds no blob to measure the diameter on
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static Result byImage(final String name, final int number, final Seen seen, final SettingValues given,
		final boolean thresholdGiven, final boolean rOutGiven, final Said said, final boolean rimKept,
		final InvalidInputException why, final FrontEnd words)
	{
		SettingValues v = given;
		if (!v.get(TrackingSettings.DETECTION).equals(TrackingSettings.IMAGE)) { // auto: no threshold to choose by
			v = v.withText(TrackingSettings.DETECTION, TrackingSettings.IMAGE);
			said.add(TrackingSettings.DETECTION, TrackingSettings.IMAGE);
		}
		if (!(v.diameter() > 0)) {
			if (!(seen.blobs() > 0)) throw new InvalidInputException("cannot measure the particles on the first frame of " +
				name + ": " + InvalidInputException.oneLine(why.getMessage()) + ", and the frame holds no blob to measure " +
				"their diameter on; give " + words.name(TrackingSettings.DIAMETER) + " (" + words.measuresOne() + " measures " +
				"one particle)", why);
			v = v.with(TrackingSettings.DIAMETER, seen.diameter());
			said.add(TrackingSettings.DIAMETER, optionValue(v.diameter()));
		}
		if (!thresholdGiven) {
			final double[] range = ImagePlusFrames.range(seen.frame, 0);
			// (float data: as the helper writes a value it suggests)
			final double middle = 0.5 * (range[0] + range[1]);
			v = v.with(TrackingSettings.THRESHOLD, range[0] == Math.rint(range[0]) && range[1] == Math.rint(range[1])
				? middle : HelperFormat.rounded(middle));
			said.add(TrackingSettings.THRESHOLD, optionValue(v.get(TrackingSettings.THRESHOLD)));
		}
		if (!rOutGiven) {
			final long w = seen.frame.dimension(0), h = seen.frame.dimension(1);
			v = v.with(TrackingSettings.R_OUT, Math.min(Math.min(v.diameter(), Math.hypot(w, h)), spacedROut(seen.plane(),
				v.diameter())));
			said.add(TrackingSettings.R_OUT, optionValue(v.get(TrackingSettings.R_OUT)));
		}
		return new Result(v, "contact-tracker: " + name + ": the profile helper " + (rimKept ? "measured the particles' " +
			"rim" + (number > 1 ? " on frame " + number : "") + " but no threshold (" : "could not measure (") +
			InvalidInputException.oneLine(why.getMessage()) +
			"); tracked by the particles' image:" + said.in(words) + " (given values win)");
	}

	/** The values a notice says were measured, in order, said in a front end's words ({@link FrontEnd#values}). */
	private static final class Said {
		private final List<Setting<?>> settings = new ArrayList<>();
		private final List<String> values = new ArrayList<>();

		void add(final Setting<?> setting, final String value) {
			settings.add(setting);
			values.add(value);
		}

		/** @return the values with a space before them, or nothing */
		String in(final FrontEnd words) {
			return settings.isEmpty() ? "" : " " + words.values(settings, values);
		}
	}

	/**
	 * A frame the helper could not measure on, as the tracker sees it, with what the fallbacks read from it made once
	 * and kept: its plane, and the diameter of its blobs ({@link ParticleScale}), which the contrast check, detection by
	 * the image and the refusal's hint all use.
	 */
	private static final class Seen {
		@SuppressWarnings("rawtypes")
		final RandomAccessibleInterval frame;
		private Plane plane;
		private double blobs;
		private boolean measured;

		@SuppressWarnings("rawtypes")
		Seen(final RandomAccessibleInterval frame) {
			this.frame = frame;
		}

		@SuppressWarnings("unchecked")
		Plane plane() {
			if (plane == null) plane = Plane.of(frame);
			return plane;
		}

		/** @return the frame inverted, as a plane */
		@SuppressWarnings("unchecked")
		Plane inverted() {
			return Plane.of(Inversion.of(frame));
		}

		/** @return the diameter of the frame's blobs to 0.01 px, as a value tracked with and said */
		double diameter() {
			return Math.round(blobs() * 100) / 100.0;
		}

		/** @return the diameter of the frame's blobs (not above 0 where it holds none) */
		double blobs() {
			if (!measured) {
				blobs = ParticleScale.diameter(plane());
				measured = true;
			}
			return blobs;
		}
	}

	/** @return a number as an option's value: exact, shortest, no exponent ({@code 174}, {@code 31.65}) */
	public static String optionValue(final double v) {
		return BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
	}
}
