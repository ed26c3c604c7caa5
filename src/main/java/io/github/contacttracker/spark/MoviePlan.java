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
package io.github.contacttracker.spark;

import java.io.Serializable;
import java.util.LinkedHashMap;
import java.util.Map;

import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * What stage 1 learns of a movie, once, and every later task of the movie is sent (broadcast): its size and
 * calibration, the settings it is tracked with (the measured ones filled in), the profile methods' first stage,
 * or why it cannot be tracked.
 *
 * @param index the movie's position on the command line
 * @param movie the movie as the user gave it (for messages)
 * @param uri its address for Hadoop
 * @param settings the settings by name (a {@link SettingValues} is keyed by descriptor, not serializable)
 * @param channelGiven whether {@code --channel} was given (without it a multi-channel image is refused)
 * @param notice what was measured, one line, or ""
 * @param frames the number of frames
 * @param calibration pixel size and frame interval
 * @param stage the profile stage, null for methods without a profile
 * @param error why the movie cannot be tracked, one line, or null
 */
record MoviePlan(int index, String movie, String uri, Map<String, Object> settings, boolean channelGiven,
	String notice, int frames, int width, int height, Calibration calibration, StackTracker.ProfileStage stage,
	String error) implements Serializable
{
	/** @return a movie that cannot be tracked */
	static MoviePlan failed(final int index, final String movie, final String uri, final String error) {
		return new MoviePlan(index, movie, uri, Map.of(), false, "", 0, 0, 0, null, null, error);
	}

	/** @return the settings by name, to ship */
	static Map<String, Object> ship(final SettingValues values) {
		final Map<String, Object> m = new LinkedHashMap<>();
		TrackingSettings.ALL.forEach(s -> m.put(s.name(), values.get(s)));
		return m;
	}

	/** @return the settings back from {@link #ship} */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	SettingValues values() {
		SettingValues v = SettingValues.defaults();
		for (final Map.Entry<String, Object> e : settings.entrySet())
			v = v.with((io.github.contacttracker.settings.Setting) TrackingSettings.named(e.getKey()), e.getValue());
		return v;
	}

	/** @return the channel to read: 0 (single-channel images only) unless {@code --channel} was given */
	int channel() {
		return channelGiven ? values().channel() : 0;
	}
}
