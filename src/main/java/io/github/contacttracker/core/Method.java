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

import java.util.Locale;

/** How centres are computed. */
public enum Method {
	/** One pass of radial symmetry on each particle's whole active area: the reference, biased near contact. */
	FIRST,
	/** The paper's method: first pass, then a second pass on the active area outside the neighbours' discs. */
	PAPER,
	/**
	 * The paper's second pass repeated with the discs rebuilt around the refined centres, until no centre moves
	 * more than 1e-4 px (at most 100 passes; flagged if not settled).
	 */
	ITERATIVE,
	/**
	 * Measures the single-particle radial profile from the data, subtracts every neighbour's modelled image and
	 * solves each particle by radial symmetry on a symmetric disc around it (its full active area); iterated.
	 */
	DEBLEND,
	/**
	 * Fits each group of touching particles jointly by least squares with the measured profile, started from the
	 * iterative centres: uses all of every particle's light.
	 */
	FIT;

	/**
	 * The default: the joint fit, the most accurate by the accuracy benchmark (unbiased at contact, spread at
	 * the Cramer-Rao bound, and the only one that measures long-range profiles at contact).
	 */
	public static final Method DEFAULT = FIT;

	/** @return whether the method needs the particles' radial profile measured from the data */
	public boolean needsProfile() {
		return this == DEBLEND || this == FIT;
	}

	/** @return the lower-case name used on the command line, in macros and in TrackMate settings */
	public String key() {
		return name().toLowerCase(Locale.ROOT);
	}

	/**
	 * Parses a method name (case-insensitive).
	 *
	 * @throws IllegalArgumentException naming the bad value and the valid ones
	 */
	public static Method parse(final String text) {
		for (final Method m : values())
			if (m.key().equalsIgnoreCase(text == null ? "" : text.trim())) return m;
		final StringBuilder valid = new StringBuilder();
		for (final Method m : values())
			valid.append(valid.length() == 0 ? "" : ", ").append(m.key());
		throw new InvalidInputException("method must be one of " + valid + ", not '" + text + "'");
	}
}
