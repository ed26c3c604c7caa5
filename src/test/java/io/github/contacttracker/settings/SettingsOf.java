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
package io.github.contacttracker.settings;

import java.util.Map;

import io.github.contacttracker.core.TrackerParameters;

/**
 * Settings for tests that state the core's parameters ({@link TrackerParameters}) of bright particles: every
 * setting the parameters hold, the channel given, the particles bright. The front ends never go this way (their
 * values are settings from the start); tests of the core's parameters and of the settings map use it to write
 * them briefly.
 */
public final class SettingsOf {

	private SettingsOf() {}

	/** @return the settings of {@code p} (its diameter and kinds too), bright particles, in {@code channel} */
	public static SettingValues values(final TrackerParameters p, final int channel) {
		return SettingValues.defaults().with(TrackingSettings.THRESHOLD, p.threshold()).with(TrackingSettings.R_OUT, p
			.rOut()).with(TrackingSettings.MIN_AREA, p.minArea()).with(TrackingSettings.MIN_SECOND_AREA, p.minSecondArea())
			.with(TrackingSettings.CONNECTIVITY, p.connectivity().neighbours()).with(TrackingSettings.METHOD, p.method()
				.key()).with(TrackingSettings.DIAMETER, p.diameter()).with(TrackingSettings.KINDS, p.kinds()).with(
					TrackingSettings.CHANNEL, channel);
	}

	/** @return the TrackMate settings map of {@link #values} */
	public static Map<String, Object> map(final TrackerParameters p, final int channel) {
		return TrackMateSettings.toMap(values(p, channel));
	}
}
