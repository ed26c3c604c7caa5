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

import java.util.Set;
import java.util.function.IntFunction;

import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.pipeline.MeasuredSettings.Result;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import net.imglib2.RandomAccessibleInterval;

/**
 * Which frame of a movie the profile helper measures on: the first, unless it is blank, its contrast is in doubt, or
 * it sizes a lone blob unlike the movie's other frames.
 */
final class HelperFrames {

	private HelperFrames() {}

	/**
	 * The helper's values for a movie of {@code count} frames, as
	 * {@link MeasuredSettings#of(String, RandomAccessibleInterval, boolean, SettingValues, Set)} measures them on one
	 * frame. Where the first frame is blank ({@link Contrast#blank}: a frame before the shutter opened, the slices of a
	 * stack below the coverslip), the helper measures on the middle one, then the last, and the notice names the
	 * frame. So it does where the helper cannot measure on the first frame and another frame shows the particles in
	 * the other contrast ({@link Contrast#looksDark}), the particles' contrast not given: the first frame's contrast is
	 * then in doubt (a tweezer pair of particles dark inside a bright ring, overlapping on the first frame and pulled
	 * apart later: where the rings cross they are as bright as the cores are dark, and the frame was taken for bright
	 * particles). Only where it measures on none do the first frame's fallbacks apply (detection by the image, or the
	 * refusal, naming the first frame). A first frame that holds particles the helper cannot measure (a dense field)
	 * otherwise keeps its own fallbacks: another frame of the same field gives no better values, and the helper's
	 * values on a crowded frame (an r_out reaching the neighbours, a diameter from a pair nearer than contact) are
	 * worse than detection by the image's (the detection study's pair of blurred discs, measured on its middle frame
	 * where the helper could not measure on its first: 97% of the particles found nearer than 1 diameter, against all
	 * by the image). Where the first frame is measured on, its values stand unless they size a lone blob unlike the
	 * other frames ({@link #consistent}).
	 *
	 * @param frame supplies frame {@code t} (0-based) of the movie
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	static Result of(final String name, final IntFunction<? extends RandomAccessibleInterval<?>> frame,
		final int count, final boolean integerData, final SettingValues settings, final Set<Setting<?>> given,
		final FrontEnd words)
	{
		final RandomAccessibleInterval<?> first = frame.apply(0);
		if (count >= 3) {
			final boolean blank = Contrast.blank((RandomAccessibleInterval) first);
			final boolean judged = MeasuredSettings.contrastJudged(settings, given), sized = settings.diameter() > 0;
			if (!blank && (judged || !sized)) try {
				final Result measured = MeasuredSettings.of(name, first, 1, false, integerData, settings, given, words);
				return sized ? measured : consistent(measured, name, frame, count, integerData, settings, given, words);
			}
			catch (final InvalidInputException e) {
				// the frames that show the other contrast, then the first frame's fallbacks
			}
			if (blank || judged) {
				final boolean dark = !blank && Contrast.looksDark((RandomAccessibleInterval) first);
				for (final int t : new int[] { count / 2, count - 1 }) {
					final RandomAccessibleInterval<?> other = frame.apply(t);
					if (blank || Contrast.looksDark((RandomAccessibleInterval) other) != dark) try {
						return MeasuredSettings.of(name, other, t + 1, false, integerData, settings, given, words);
					}
					catch (final InvalidInputException e) {
						// the next frame, then the first frame's fallbacks
					}
				}
			}
		}
		return MeasuredSettings.of(name, first, 1, true, integerData, settings, given, words);
	}

	/**
	 * Particles keep their size through a movie: where the first frame's diameter and the middle frame's differ by
	 * more than this factor, the frames disagree.
	 */
	static final double SIZES_DISAGREE = 1.3;

	/**
	 * @return the first frame's measurement where the helper profiled several particles there (of one size they are
	 *         not all blobs of several), where the middle frame's diameter agrees with it ({@link #SIZES_DISAGREE}), or
	 *         where the middle frame cannot be measured on; else, of the first, middle and last frames' (the last where
	 *         the helper measures particles there, if only their rim), the measurement of the smallest diameter. Where
	 *         particles crowd, the helper's diameter errs large, never small: a blob of two overlapping ones is
	 *         measured as one particle twice as wide, and two standing closer than their size apart set the spots'
	 *         spacing it reads. So a tweezer pair held overlapping on the first frame and pulled apart was tracked with
	 *         the diameter of the overlap (the detection study's blurred pair played backwards: 22.6 px on the first frame, 15.2 on the
	 *         middle one at 1.27 diameters, 11.6 on the last, true 12).
	 */
	private static Result consistent(final Result first, final String name,
		final IntFunction<? extends RandomAccessibleInterval<?>> frame, final int count, final boolean integerData,
		final SettingValues settings, final Set<Setting<?>> given, final FrontEnd words)
	{
		if (first.profiled() != 1) return first;
		final Result middle = measuredOn(name, frame, count / 2, integerData, settings, given, words);
		if (middle == null || agree(first, middle)) return first;
		final Result last = measuredOn(name, frame, count - 1, integerData, settings, given, words);
		if (last == null) return first;
		Result smallest = first;
		for (final Result r : new Result[] { middle, last })
			if (r.settings().diameter() > 0 && r.settings().diameter() < smallest.settings().diameter()) smallest = r;
		return smallest;
	}

	/**
	 * @return the helper's measurement on frame {@code t} (0-based), its rim's where it measured the particles but no
	 *         threshold there; null where it measured no particle
	 */
	private static Result measuredOn(final String name, final IntFunction<? extends RandomAccessibleInterval<?>> frame,
		final int t, final boolean integerData, final SettingValues settings, final Set<Setting<?>> given,
		final FrontEnd words)
	{
		try {
			final Result r = MeasuredSettings.of(name, frame.apply(t), t + 1, true, integerData, settings, given, words);
			return r.profiled() > 0 ? r : null;
		}
		catch (final InvalidInputException e) {
			return null;
		}
	}

	/** @return whether two measurements' diameters lie within {@link #SIZES_DISAGREE} of each other */
	private static boolean agree(final Result a, final Result b) {
		final double da = a.settings().diameter(), db = b.settings().diameter();
		return !(da > 0 && db > 0) || Math.max(da, db) <= SIZES_DISAGREE * Math.min(da, db);
	}
}
