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
package io.github.contacttracker.pipeline;

import java.util.List;
import java.util.ArrayList;
import java.util.Locale;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.track.FrameResult;

/**
 * What a run found.
 *
 * @param frames one result per frame (regions kept only when asked for)
 * @param spots every spot, in frame order, {@code RADIUS} from the particle diameter where one was given
 * @param flagged spots with a warning flag
 * @param discarded components dropped (below {@code min_area}, or without any gradient)
 * @param seconds the run's wall-clock time
 * @param warnings what the user must know about how the result was obtained (a fallback), one line each
 */
public record TrackingResult(List<FrameResult> frames, List<Localization> spots, int flagged, int discarded,
	double seconds, List<String> warnings, String detection)
{
	/**
	 * The summary in short lines, for windows that cut long ones (ImageJ's Log): the spots and flags, then the
	 * time, then each warning.
	 */
	public List<String> summaryLines(final String name) {
		final int n = frames.size();
		final List<String> lines = new ArrayList<>();
		lines.add(String.format(Locale.ROOT, "%d spots in %d frame%s of '%s', %d flagged", spots.size(), n, n == 1 ?
			"" : "s", name, flagged));
		lines.add(String.format(Locale.ROOT, "  %d components discarded, %.2f s (%.1f frames/s)", discarded, seconds,
			n / Math.max(seconds, 1e-9)));
		if (!detection.isEmpty()) lines.add("  " + detection);
		for (final String w : warnings)
			lines.add("  warning: " + w);
		return lines;
	}

	/**
	 * @return "12 spots in 4 frames of 'movie.tif', 0 flagged, 0 components discarded, 0.31 s (12.9 frames/s)",
	 *         then "; warning: ..." for each warning
	 */
	public String summary(final String name) {
		final int n = frames.size();
		final StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%d spots in %d frame%s of '%s', %d " +
			"flagged, %d components discarded, %.2f s (%.1f frames/s)", spots.size(), n, n == 1 ? "" : "s", name,
			flagged, discarded, seconds, n / Math.max(seconds, 1e-9)));
		if (!detection.isEmpty()) sb.append("; ").append(detection);
		for (final String w : warnings)
			sb.append("; warning: ").append(w);
		return sb.toString();
	}
}
