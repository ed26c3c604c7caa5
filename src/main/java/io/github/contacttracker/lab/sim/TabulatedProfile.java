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
package io.github.contacttracker.lab.sim;

import io.github.contacttracker.core.InvalidInputException;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * A profile given as a table, linearly interpolated between its radii and 0 beyond the last one: the paper's
 * "interpolation of the experimental profile". Also serves as a fine lookup table that makes rendering an
 * analytic profile fast ({@link #sample}).
 */
public final class TabulatedProfile implements RadialProfile {

	private final double[] radii;
	private final double[] values;
	/** Spacing of the radii when they are evenly spaced (fast lookup), else NaN (binary search). */
	private final double uniformStep;

	/**
	 * @param radii strictly increasing radii (px), the first one 0 (copied)
	 * @param values grey levels above background at those radii (copied)
	 * @throws IllegalArgumentException for fewer than two points, mismatched lengths, a first radius other than
	 *         0, radii not strictly increasing, or non-finite numbers
	 */
	public TabulatedProfile(final double[] radii, final double[] values) {
		if (radii.length != values.length)
			throw new InvalidInputException("profile table has " + radii.length + " radii but " + values.length
				+ " values");
		if (radii.length < 2)
			throw new InvalidInputException("profile table needs at least two points, not " + radii.length);
		if (radii[0] != 0)
			throw new InvalidInputException("profile table must start at r = 0, not " + radii[0]);
		for (int i = 0; i < radii.length; i++) {
			if (!Double.isFinite(radii[i]) || !Double.isFinite(values[i]))
				throw new InvalidInputException("profile table point " + i + " is not finite: r = " + radii[i]
					+ ", value = " + values[i]);
			if (i > 0 && !(radii[i] > radii[i - 1]))
				throw new InvalidInputException("profile table radii must increase strictly, but r[" + i + "] = "
					+ radii[i] + " follows " + radii[i - 1]);
		}
		this.radii = radii.clone();
		this.values = values.clone();
		this.uniformStep = evenSpacing(this.radii);
	}

	/**
	 * Tabulates another profile on an even grid, so that evaluating it costs one lookup.
	 *
	 * @param profile the profile to tabulate
	 * @param step grid spacing (px, e.g. 0.01)
	 * @param maxRadius the table covers at least {@code [0, maxRadius]}; the result is 0 beyond
	 * @return the table
	 */
	public static TabulatedProfile sample(final RadialProfile profile, final double step, final double maxRadius) {
		if (!(step > 0) || !(maxRadius > 0) || !Double.isFinite(maxRadius))
			throw new InvalidInputException("tabulation needs step > 0 and a finite maxRadius > 0, not " + step
				+ ", " + maxRadius);
		final int n = Math.max(2, (int) Math.ceil(maxRadius / step) + 1);
		final double[] r = new double[n];
		final double[] v = new double[n];
		for (int i = 0; i < n; i++) {
			r[i] = i * step;
			v[i] = profile.value(r[i]);
		}
		return new TabulatedProfile(r, v);
	}

	/**
	 * Reads a two-column CSV table {@code r_px,value}: one optional header line (any line whose first field is
	 * not a number, first line only), blank lines and lines starting with {@code #} skipped.
	 *
	 * @param file the CSV file
	 * @return the profile
	 * @throws IOException when the file cannot be read
	 * @throws IllegalArgumentException naming the file and line, for a malformed line or an invalid table
	 */
	public static TabulatedProfile fromCsv(final Path file) throws IOException {
		double[] r = new double[64];
		double[] v = new double[64];
		int n = 0;
		int lineNumber = 0;
		boolean seenContent = false;
		try (BufferedReader reader = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
			String line;
			while ((line = reader.readLine()) != null) {
				lineNumber++;
				final String trimmed = line.strip();
				if (trimmed.isEmpty() || trimmed.startsWith("#")) continue;
				final String[] fields = trimmed.split(",", -1);
				final boolean firstContent = !seenContent;
				seenContent = true;
				if (firstContent && fields.length > 0 && !isNumber(fields[0].strip())) continue; // the header
				if (fields.length != 2)
					throw new InvalidInputException(file + " line " + lineNumber + ": expected 2 fields r_px,value, found "
						+ fields.length + ": '" + trimmed + "'");
				final double radius;
				final double value;
				try {
					radius = Double.parseDouble(fields[0].strip());
					value = Double.parseDouble(fields[1].strip());
				}
				catch (final NumberFormatException e) {
					throw new InvalidInputException(file + " line " + lineNumber + ": not a number pair: '" + trimmed
						+ "'", e);
				}
				if (!Double.isFinite(radius) || !Double.isFinite(value))
					throw new InvalidInputException(file + " line " + lineNumber + ": not finite: '" + trimmed + "'");
				if (n > 0 && !(radius > r[n - 1]))
					throw new InvalidInputException(file + " line " + lineNumber + ": radius " + radius
						+ " does not increase (previous " + r[n - 1] + ")");
				if (n == r.length) {
					r = Arrays.copyOf(r, 2 * n);
					v = Arrays.copyOf(v, 2 * n);
				}
				r[n] = radius;
				v[n] = value;
				n++;
			}
		}
		try {
			return new TabulatedProfile(Arrays.copyOf(r, n), Arrays.copyOf(v, n));
		}
		catch (final IllegalArgumentException e) {
			throw new InvalidInputException(file + ": " + e.getMessage(), e);
		}
	}

	@Override
	public double value(final double r) {
		final int last = radii.length - 1;
		final double distance = Math.abs(r);
		if (distance > radii[last]) return 0;
		final int i;
		if (uniformStep == uniformStep) // not NaN: evenly spaced, direct index
			i = Math.min((int) (distance / uniformStep), last - 1);
		else {
			final int found = Arrays.binarySearch(radii, distance);
			i = Math.min(found >= 0 ? found : -found - 2, last - 1);
		}
		final double t = (distance - radii[i]) / (radii[i + 1] - radii[i]);
		return values[i] + t * (values[i + 1] - values[i]);
	}

	/** Exact for the interpolated table: found segment by segment from the outside. */
	@Override
	public double reach(final double level) {
		if (!(level > 0) || !Double.isFinite(level))
			throw new InvalidInputException("reach level must be a positive grey level, not " + level);
		final int last = radii.length - 1;
		if (Math.abs(values[last]) >= level) return radii[last];
		for (int j = last - 1; j >= 0; j--) {
			if (Math.abs(values[j]) >= level) {
				// |value| falls from >= level at r[j] to < level at r[j+1]; on a linear segment it crosses level
				// with the sign of values[j] (if the sign flips, it passes 0 after the crossing)
				final double target = Math.copySign(level, values[j]);
				final double t = (values[j] - target) / (values[j] - values[j + 1]);
				return radii[j] + t * (radii[j + 1] - radii[j]);
			}
		}
		return 0;
	}

	/** @return the last tabulated radius (px); the profile is 0 beyond it */
	public double maxRadius() {
		return radii[radii.length - 1];
	}

	/** @return the number of tabulated points */
	public int size() {
		return radii.length;
	}

	@Override
	public String toString() {
		return "TabulatedProfile[" + radii.length + " points, r = 0.." + maxRadius() + " px]";
	}

	private static double evenSpacing(final double[] r) {
		final double step = r[1] - r[0];
		for (int i = 2; i < r.length; i++)
			if (Math.abs(r[i] - i * step) > 1e-9 * step * i) return Double.NaN;
		return step;
	}

	private static boolean isNumber(final String field) {
		try {
			Double.parseDouble(field);
			return true;
		}
		catch (final NumberFormatException e) {
			return false;
		}
	}
}
