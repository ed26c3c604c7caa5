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

/** Pixel neighbourhood used to join active pixels into one particle. */
public enum Connectivity {
	/** Edge neighbours only (up, down, left, right). */
	FOUR,
	/** Edge and corner neighbours: the paper's choice and the default. */
	EIGHT;

	/**
	 * Parses {@code 4}, {@code 8}, {@code four} or {@code eight} (case-insensitive).
	 *
	 * @throws IllegalArgumentException naming the bad value
	 */
	public static Connectivity parse(final String text) {
		final String t = text == null ? "" : text.trim().toLowerCase();
		switch (t) {
			case "4": case "four": return FOUR;
			case "8": case "eight": return EIGHT;
			default: throw new InvalidInputException("connectivity must be 4 or 8, not '" + text + "'");
		}
	}

	/** @return 4 or 8 */
	public int neighbours() {
		return this == FOUR ? 4 : 8;
	}
}
