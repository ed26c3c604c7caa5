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
package io.github.contacttracker.core.track;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.image.Region;

/**
 * The spots of one frame, with the regions behind them when they were asked for (for overlays).
 *
 * @param spots the spots, in the frame's coordinates
 * @param activeAreas each spot's active area {@code L_k}, or empty when regions were not kept
 * @param secondAreas each spot's second active area {@code L_k_sec}, or empty when regions were not kept
 * @param noiseSigma the frame's estimated pixel-noise standard deviation (grey levels)
 * @param discarded components above threshold that gave no spot: smaller than {@code min_area}, or without
 *        any non-zero gradient (a flat plateau, or an area lying wholly within 2 px of the border)
 * @param ownProfile whether a profile method ({@code deblend}, {@code fit}) measured the particles' profile on
 *        this frame alone: on a single frame, or when no profile could be measured over the stack (a fallback the
 *        front ends report)
 * @param detection the detection {@code auto} chose for the movie, with its reason, or null where it was given
 */
public record FrameResult(List<Localization> spots, List<Region> activeAreas, List<Region> secondAreas,
	double noiseSigma, int discarded, boolean ownProfile, DetectionChoice detection) implements Serializable
{
	// serializable without regions (a distributed front end ships results without them)
	private static final long serialVersionUID = 1L;

	/** Copies the lists. */
	public FrameResult {
		spots = List.copyOf(spots);
		activeAreas = List.copyOf(activeAreas);
		secondAreas = List.copyOf(secondAreas);
	}

	/** A result whose detection was not chosen by {@code auto}. */
	public FrameResult(final List<Localization> spots, final List<Region> activeAreas,
		final List<Region> secondAreas, final double noiseSigma, final int discarded, final boolean ownProfile)
	{
		this(spots, activeAreas, secondAreas, noiseSigma, discarded, ownProfile, null);
	}

	/** @return this result with other spots (the same particles, e.g. flagged) */
	public FrameResult withSpots(final List<Localization> newSpots) {
		return new FrameResult(newSpots, activeAreas, secondAreas, noiseSigma, discarded, ownProfile, detection);
	}

	/** @return all spots of {@code results}, in frame order */
	static List<Localization> allSpots(final List<FrameResult> results) {
		final List<Localization> all = new ArrayList<>();
		for (final FrameResult r : results)
			all.addAll(r.spots());
		return all;
	}

	/** @return this result with the detection {@code auto} chose for its movie */
	public FrameResult withDetection(final DetectionChoice choice) {
		return new FrameResult(spots, activeAreas, secondAreas, noiseSigma, discarded, ownProfile, choice);
	}
}
