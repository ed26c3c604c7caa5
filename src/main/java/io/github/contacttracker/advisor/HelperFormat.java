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

import io.github.contacttracker.core.Numbers;

/**
 * How the profile helper writes a number in its error messages, warnings and report: {@value #SIGNIFICANT_DIGITS}
 * significant digits, a measured length or level rounded to 0.01 first. One rule for every step of the helper and
 * its report, so that a number reads the same wherever it is shown.
 */
public final class HelperFormat {

	/** Significant digits of the numbers in the helper's messages and warnings ({@link Numbers#significant}). */
	public static final int SIGNIFICANT_DIGITS = 4;

	private HelperFormat() {}

	/** @return {@code v} with {@value #SIGNIFICANT_DIGITS} significant digits */
	public static String fmt(final double v) {
		return Numbers.significant(v, SIGNIFICANT_DIGITS);
	}

	/**
	 * @return {@code v} rounded as {@link #fmt} writes it: a value the helper suggests is the one a person reads and
	 *         copies, and the one tracked with
	 */
	public static double rounded(final double v) {
		return Double.isFinite(v) ? Double.parseDouble(fmt(v)) : v;
	}

	/** @return a measured value: rounded to 0.01 first ({@link #round2}), then written as {@link #fmt} does */
	public static String fmt2(final double v) {
		return fmt(round2(v));
	}

	/** @return {@code v} rounded to 0.01 */
	static double round2(final double v) {
		return Math.round(v * 100) / 100.0;
	}
}
