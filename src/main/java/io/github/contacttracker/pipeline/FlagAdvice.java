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

import java.util.EnumMap;
import java.util.Map;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;

/**
 * What a run that flags many of its spots says about it: the flag most spots carry, its cause in words and what to
 * try. A result most of whose spots are flagged is not one to use as it is, and the user must hear why.
 */
public final class FlagAdvice {

	/** A run says why when more than this share of its spots carry a warning flag. */
	public static final double SHARE = 0.2;

	private FlagAdvice() {}

	/**
	 * The warning flags, causes first: where as many spots carry two flags, the one that explains the other is named
	 * (a merge is not refined, so it falls back; an unmodelled neighbour or a fit that does not settle leaves
	 * centres where the first pass put them).
	 */
	private static final List<Flag> CAUSES = List.of(Flag.MERGED, Flag.DEGENERATE, Flag.UNMODELLED_NEIGHBOUR,
		Flag.NOT_CONVERGED, Flag.FELL_BACK, Flag.AT_BORDER);

	/** @return the warning for these spots, or null when at most {@link #SHARE} of them are flagged */
	public static String of(final List<Localization> spots) {
		final Map<Flag, Integer> count = new EnumMap<>(Flag.class);
		int flagged = 0;
		for (final Localization s : spots) {
			if (!s.isFlagged()) continue;
			flagged++;
			for (final Flag f : Flag.decode(s.flags()))
				if (f.isWarning()) count.merge(f, 1, Integer::sum);
		}
		if (spots.isEmpty() || flagged <= SHARE * spots.size()) return null;
		Flag main = null;
		for (final Flag f : CAUSES)
			if (count.containsKey(f) && (main == null || count.get(f) > count.get(main))) main = f;
		return String.format(Locale.ROOT, "%d of %d spots (%.0f%%) are flagged, most %s (%d): %s", flagged, spots
			.size(), 100.0 * flagged / spots.size(), main.name(), count.get(main), advice(main));
	}

	/** @return the flag's usual cause and what to try, in words */
	static String advice(final Flag flag) {
		return switch (flag) {
			case AT_BORDER -> "particles cut by the frame's edge; their centres move when the frame is cropped, use the " +
				"others (a larger field of view, or a selection away from the edge)";
			case MERGED -> "active areas holding several particles; the threshold joins touching particles: use the " +
				"detection by the image (--detection image) with the particles' --diameter, or raise --threshold";
			case FELL_BACK -> "centres kept from a first pass because the refinement could not be made (too few pixels " +
				"left, or a fit without enough light; on a background clipped at 0, as confocal images have, the fit " +
				"leaves out every pixel near 0 and cannot place the background); check --r-out against the particles' " +
				"size ('contact-tracker profile MOVIE' shows it), or use --method iterative, whose centres need no fit";
			case NOT_CONVERGED -> "fits or profile rounds that did not settle; the particles' profile may differ between " +
				"them (give --kinds), or the field is denser than the fit can hold: try a smaller --r-out";
			case UNMODELLED_NEIGHBOUR -> "a neighbour the fit could not model lies within reach; it is usually a merge " +
				"of particles: use --detection image with the particles' --diameter";
			case DEGENERATE -> "areas without gradient lines that meet (flat tops or noise); raise --min-area or give " +
				"--diameter";
			case SECOND_PASS -> "";
		};
	}
}
