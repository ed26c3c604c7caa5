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

import java.io.Serializable;
import java.util.Set;

/**
 * One localized particle in one frame: an immutable record in pixel units.
 * <p>
 * Coordinates follow TrackMate's convention: the centre of pixel (0,0) is at x = 0, y = 0, x grows to the
 * right and y downwards. Callers convert to calibrated units by multiplying by the pixel size.
 *
 * @param frame frame index (0-based)
 * @param x final x centre (px)
 * @param y final y centre (px)
 * @param firstX first-pass x centre, on the whole active area (px)
 * @param firstY first-pass y centre, on the whole active area (px)
 * @param activeArea pixels in the active area {@code L_k}
 * @param secondArea pixels in the second active area {@code L_k_sec} (equals {@code activeArea} when no
 *        neighbour reaches the particle)
 * @param quality how clearly the active area stands out of the noise, in [0, 1] (real particles 1;
 *        {@code ContactTracker.quality})
 * @param radius the spot's radius (px): the equivalent radius of the active area, {@code sqrt(activeArea / pi)},
 *        unless replaced by the particle's radius ({@link #withRadius(double)})
 * @param flags bit mask of {@link Flag}s
 * @param iterations solves of the final centre (1 for the first pass, 2 for the paper's method, more for
 *        iterative methods)
 * @param sigmaX estimated standard error of x (px), NaN when it could not be estimated
 * @param sigmaY estimated standard error of y (px), NaN when it could not be estimated
 * @param amplitude the {@code fit} method's amplitude of the particle relative to the measured profile, NaN for
 *        the other methods
 * @param scale the {@code fit} method's radial scale of the particle relative to the measured profile (1.2: its
 *        image is 1.2 times larger), NaN for the other methods
 * @param kind the particle's kind, 1, 2, ... in order of size ({@code core.kind.Kinds}), 0 when not classified
 * @param fitSigmaX the {@code fit} method's standard error of x with the neighbours whose light it held taken as
 *        exact (a member of a packed field fitted in turn), where {@code sigmaX} adds their uncertainty: the scale
 *        by which the tracker's rounds judge a centre settled; NaN: {@code sigmaX}
 * @param fitSigmaY likewise along y
 */
public record Localization(int frame, double x, double y, double firstX, double firstY, int activeArea,
	int secondArea, double quality, double radius, int flags, int iterations, double sigmaX, double sigmaY,
	double amplitude, double scale, int kind, double fitSigmaX, double fitSigmaY) implements Serializable
{

	/** A localization whose standard errors are those its rounds settle by. */
	public Localization(final int frame, final double x, final double y, final double firstX, final double firstY,
		final int activeArea, final int secondArea, final double quality, final double radius, final int flags,
		final int iterations, final double sigmaX, final double sigmaY, final double amplitude, final double scale,
		final int kind)
	{
		this(frame, x, y, firstX, firstY, activeArea, secondArea, quality, radius, flags, iterations, sigmaX, sigmaY,
			amplitude, scale, kind, Double.NaN, Double.NaN);
	}

	/** @return the standard error of x the tracker's rounds settle by: {@link #fitSigmaX} where known, else sigmaX */
	public double settlingSigmaX() {
		return Double.isNaN(fitSigmaX) ? sigmaX : fitSigmaX;
	}

	/** @return likewise along y */
	public double settlingSigmaY() {
		return Double.isNaN(fitSigmaY) ? sigmaY : fitSigmaY;
	}

	/** @return whether {@code flag} is set */
	public boolean has(final Flag flag) {
		return flag.isSet(flags);
	}

	/** @return whether any warning flag is set (see {@link Flag#isWarning()}) */
	public boolean isFlagged() {
		for (final Flag f : Flag.values())
			if (f.isWarning() && f.isSet(flags)) return true;
		return false;
	}

	/** @return the flags as a set */
	public Set<Flag> flagSet() {
		return Flag.decode(flags);
	}

	/** @return a copy with another frame index */
	public Localization withFrame(final int newFrame) {
		return new Localization(newFrame, x, y, firstX, firstY, activeArea, secondArea, quality, radius, flags,
			iterations, sigmaX, sigmaY, amplitude, scale, kind, fitSigmaX, fitSigmaY);
	}

	/** @return a copy with other flags */
	public Localization withFlags(final int newFlags) {
		return new Localization(frame, x, y, firstX, firstY, activeArea, secondArea, quality, radius, newFlags,
			iterations, sigmaX, sigmaY, amplitude, scale, kind, fitSigmaX, fitSigmaY);
	}

	/** @return a copy with another radius (px), e.g. half the particle diameter the user gave */
	public Localization withRadius(final double newRadius) {
		return new Localization(frame, x, y, firstX, firstY, activeArea, secondArea, quality, newRadius, flags,
			iterations, sigmaX, sigmaY, amplitude, scale, kind, fitSigmaX, fitSigmaY);
	}

	/** @return a copy of another kind (0: not classified) */
	public Localization withKind(final int newKind) {
		return new Localization(frame, x, y, firstX, firstY, activeArea, secondArea, quality, radius, flags,
			iterations, sigmaX, sigmaY, amplitude, scale, newKind, fitSigmaX, fitSigmaY);
	}
}
