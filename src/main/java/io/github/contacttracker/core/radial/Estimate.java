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
package io.github.contacttracker.core.radial;

import io.github.contacttracker.core.Flag;

/**
 * A particle's centre as a method leaves it, immutable.
 *
 * @param x centre x (frame pixels)
 * @param y centre y
 * @param flags {@link Flag} bits
 * @param secondArea pixels used by the last radial-symmetry pass (the whole active area if none excluded)
 * @param iterations solves (radial-symmetry methods) or fit iterations behind the centre
 * @param solve the radial-symmetry solve behind (x, y), for its error propagation; {@code null} if none
 * @param sigmaX standard error the method estimated itself (the joint fit); NaN to propagate it from
 *        {@code solve}
 * @param sigmaY likewise along y
 * @param amplitude the joint fit's amplitude relative to the profile, NaN if none
 * @param scale the joint fit's radial scale relative to the profile, NaN if none
 * @param coupledX the standard error along x with the uncertainty of the neighbours whose light the fit held (a
 *        member fitted in turn), where it differs from {@code sigmaX}: the error to report; NaN: {@code sigmaX}. The
 *        fit's own {@code sigmaX} stays the scale its iterations and rounds settle by.
 * @param coupledY likewise along y
 */
public record Estimate(double x, double y, int flags, int secondArea, int iterations, Solve solve, double sigmaX,
	double sigmaY, double amplitude, double scale, double coupledX, double coupledY)
{
	/** An estimate whose errors are its own fit's. */
	public Estimate(final double x, final double y, final int flags, final int secondArea, final int iterations,
		final Solve solve, final double sigmaX, final double sigmaY, final double amplitude, final double scale)
	{
		this(x, y, flags, secondArea, iterations, solve, sigmaX, sigmaY, amplitude, scale, Double.NaN, Double.NaN);
	}

	/** An estimate without amplitude and scale. */
	public Estimate(final double x, final double y, final int flags, final int secondArea, final int iterations,
		final Solve solve, final double sigmaX, final double sigmaY)
	{
		this(x, y, flags, secondArea, iterations, solve, sigmaX, sigmaY, Double.NaN, Double.NaN);
	}

	/** A first-pass estimate: one solve, no self-estimated error. */
	static Estimate first(final double x, final double y, final int flags, final int area, final Solve solve) {
		return new Estimate(x, y, flags, area, 1, solve, Double.NaN, Double.NaN);
	}

	public Estimate withFlags(final int newFlags) {
		return new Estimate(x, y, newFlags, secondArea, iterations, solve, sigmaX, sigmaY, amplitude, scale, coupledX,
			coupledY);
	}

	/** @return this estimate with the amplitude {@code newAmplitude} (a fit's, where the rest is its start) */
	public Estimate withAmplitude(final double newAmplitude) {
		return new Estimate(x, y, flags, secondArea, iterations, solve, sigmaX, sigmaY, newAmplitude, scale, coupledX,
			coupledY);
	}

	public Estimate withIterations(final int newIterations) {
		return new Estimate(x, y, flags, secondArea, newIterations, solve, sigmaX, sigmaY, amplitude, scale, coupledX,
			coupledY);
	}

	/** @return this estimate with the errors to report {@code errorX}, {@code errorY} ({@link #coupledX}) */
	public Estimate withCoupled(final double errorX, final double errorY) {
		return new Estimate(x, y, flags, secondArea, iterations, solve, sigmaX, sigmaY, amplitude, scale, errorX, errorY);
	}

	/** @return the standard error along x to report: {@link #coupledX} where known, else {@link #sigmaX} */
	public double reportedX() {
		return Double.isNaN(coupledX) ? sigmaX : coupledX;
	}

	/** @return the standard error along y to report: {@link #coupledY} where known, else {@link #sigmaY} */
	public double reportedY() {
		return Double.isNaN(coupledY) ? sigmaY : coupledY;
	}

	public boolean has(final Flag flag) {
		return flag.isSet(flags);
	}

	/** @return the distance from this centre to {@code other}'s */
	public double distanceTo(final Estimate other) {
		return Math.hypot(x - other.x, y - other.y);
	}

	/**
	 * @return {@code distanceTo(other) < limit}, the same verdict to the last bit, without the root where the centres
	 *         lie {@code limit} or more apart along x or along y (the distance is never below either; the margin of a
	 *         part in 10^9 keeps the root's rounding out of it): the test of every pair of a large field, most of which
	 *         lie far apart
	 */
	public boolean closerThan(final Estimate other, final double limit) {
		final double bound = limit * (1 + 1e-9);
		if (Math.abs(x - other.x) > bound || Math.abs(y - other.y) > bound) return false;
		return distanceTo(other) < limit;
	}
}
