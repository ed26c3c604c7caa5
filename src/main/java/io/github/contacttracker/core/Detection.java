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

/** How the profile methods find the particles of a frame before they fit them. */
public enum Detection {
	/**
	 * By their image: the peaks of the frame band-passed at the particles' scale, then particles added where the
	 * fit's residuals ask and removed where the fit does not need them ({@code core.detect}). Touching particles
	 * whose images merge at every grey level are found apart; the background may vary across the frame.
	 */
	IMAGE,
	/** By the threshold: each connected component of the pixels at or above it is one particle (the paper's step 1). */
	THRESHOLD,
	/**
	 * Chosen per movie from its sample frames ({@code core.detect.DetectionChoice}): by the image where the
	 * threshold joins touching particles into one component, by the threshold where each of its components is one
	 * particle (the same particles, at a fraction of the cost). Only the profile methods choose; the others, and a
	 * frame analysed on its own, use the threshold.
	 */
	AUTO;

	/**
	 * The default: {@link #AUTO}. Detection by the image finds touching particles that the threshold merges, dim
	 * particles it misses and particles on ramps and clipped backgrounds (the documentation's Methods, Detection by
	 * the image), but it costs several fits per frame; where the threshold's components are single particles it
	 * finds the same ones, and the threshold is kept.
	 */
	public static final Detection DEFAULT = AUTO;

	/** @return the name used in settings ({@code image}, {@code threshold}, {@code auto}) */
	public String key() {
		return name().toLowerCase(Locale.ROOT);
	}

	/** @return the detection of that name (case-insensitive) */
	public static Detection of(final String key) {
		for (final Detection d : values())
			if (d.key().equalsIgnoreCase(key.trim())) return d;
		throw new InvalidInputException("detection must be auto, image or threshold, not '" + key + "'");
	}
}
