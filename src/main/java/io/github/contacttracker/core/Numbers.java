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

import java.math.BigDecimal;
import java.util.Locale;

/**
 * How a number is written for people and command lines: messages, suggested option values, report text. (Data
 * files keep their own fixed formats.) The one place for it: a front end or the core that prints a number uses
 * one of these, not a format of its own.
 */
public final class Numbers {

	private Numbers() {}

	/**
	 * @return {@code v} exactly, as short as it reads back: a whole number without a decimal point ({@code 85}),
	 *         any other as {@link Double#toString} ({@code 61.5}); for values a user may pass back as an option
	 */
	public static String fmt(final double v) {
		return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
	}

	/**
	 * @param decimals how many decimals at most
	 * @return {@code v} rounded to {@code decimals} decimals (half up), trailing zeros dropped: {@code 85},
	 *         {@code 12.5}, {@code 2.887}; for measured values shown to people
	 */
	public static String fmt(final double v, final int decimals) {
		if (!Double.isFinite(v)) return Double.toString(v);
		return new BigDecimal(String.format(Locale.ROOT, "%." + decimals + "f", v)).stripTrailingZeros()
			.toPlainString();
	}

	/**
	 * @param digits how many significant digits
	 * @return a whole {@code v} without a decimal point ({@code 85}), any other with {@code digits} significant
	 *         digits, trailing zeros kept ({@code 13.98}, {@code 124.0}, {@code 1.750} for 4); for the measured
	 *         values the profile helper quotes in its warnings and errors, which span grey levels, pixels and
	 *         ratios and so read best at a fixed precision rather than with a fixed number of decimals
	 */
	public static String significant(final double v, final int digits) {
		if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
		return String.format(Locale.ROOT, "%." + digits + "g", v);
	}
}
