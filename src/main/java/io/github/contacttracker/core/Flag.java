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

import java.util.EnumSet;
import java.util.Set;

/**
 * What happened while a spot was localized. A spot carries its flags as a bit mask
 * ({@link Localization#flags()}); every fallback that changes a result sets one.
 */
public enum Flag {
	/** The final centre comes from a second active area from which neighbours' discs were removed. */
	SECOND_PASS("second pass applied"),
	/**
	 * The second pass was needed (a neighbour's disc overlaps the active area) but could not be done: too few
	 * pixels were left ({@code min_second_area}) or the remaining lines were degenerate. The spot keeps its
	 * first-pass centre, which is biased towards the neighbour. The profile methods set it too where their own step
	 * gave no centre (a group's fit that could not be done, a deblend solve whose lines meet off its disc): the spot
	 * keeps its centre from before.
	 */
	FELL_BACK("fell back to first pass"),
	/**
	 * A 2x2 system was near-singular (all gradient lines nearly parallel). If it was the first pass, the
	 * reported centre is the intensity-weighted centroid of the active area.
	 */
	DEGENERATE("degenerate system"),
	/**
	 * The active area reaches within 2 px of the image border (pixels there have no gradient); for the profile
	 * methods also a fitted centre whose frame cuts off 5% or more of the information on it (its core cut by the
	 * edge: on real footage such centres move by several of their errors when the frame is cropped). Their pixels
	 * are left out of the profile's measurement.
	 */
	AT_BORDER("touches border"),
	/**
	 * The active area looks like several particles merged into one component ({@code ComponentShape}; the
	 * documentation's Methods, Merge detection).
	 */
	MERGED("suspected merge"),
	/**
	 * An iterative method stopped at its iteration limit before the centres settled; for the profile methods also
	 * when the alternation of profile and centres found no fixed point within its rounds (every spot that rests
	 * on that profile).
	 */
	NOT_CONVERGED("not converged"),
	/**
	 * The profile methods: a particle whose light reaches this spot's pixels was not modelled (a suspected merge, a
	 * first pass without a centre, or a particle cut by the frame's edge that no fit of what is left of it matched), so
	 * its light tilts this centre by an unknown amount.
	 */
	UNMODELLED_NEIGHBOUR("neighbour not modelled");

	private final String description;

	Flag(final String description) {
		this.description = description;
	}

	/** @return a short human-readable description */
	public String description() {
		return description;
	}

	/** @return the bit of this flag in a flag mask */
	public int bit() {
		return 1 << ordinal();
	}

	/** @return whether {@code mask} has this flag */
	public boolean isSet(final int mask) {
		return (mask & bit()) != 0;
	}

	/** @return whether this flag warns the user (every flag but {@link #SECOND_PASS}, which is the normal case) */
	public boolean isWarning() {
		return this != SECOND_PASS;
	}

	/** @return the flags set in {@code mask} */
	public static Set<Flag> decode(final int mask) {
		final EnumSet<Flag> set = EnumSet.noneOf(Flag.class);
		for (final Flag f : values())
			if (f.isSet(mask)) set.add(f);
		return set;
	}
}
