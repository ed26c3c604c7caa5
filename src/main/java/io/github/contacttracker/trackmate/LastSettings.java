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
package io.github.contacttracker.trackmate;

import java.util.LinkedHashMap;
import java.util.Map;

import io.github.contacttracker.settings.TrackMateSettings;

/**
 * The detector settings last used in this Fiji session, so that they survive a detector switch in TrackMate's
 * wizard.
 * <p>
 * TrackMate 8.0.0's wizard (ChooseDetectorDescriptor, TrackMateWizardSequence) replaces the settings with the new
 * detector's {@code getDefaultSettings()} when the old ones fail its {@code checkSettings}, and then copies into
 * them, key by key, what the previous detector's panel and settings hold. Going to LoG and back to Contact Tracker
 * thus lost r_out and the diameter. The factory's defaults are therefore the values last taken from our panel
 * (TrackMate's own defaults until then), as Fiji's dialogs remember their last values.
 */
final class LastSettings {

	private static Map<String, Object> last;

	private LastSettings() {}

	/** @return a new, modifiable map: the settings last used in this session, else the defaults */
	static synchronized Map<String, Object> get() {
		return last == null ? TrackMateSettings.defaults() : new LinkedHashMap<>(last);
	}

	/** Remembers a complete, valid settings map (anything else is ignored). */
	static synchronized void remember(final Map<String, Object> settings) {
		if (settings != null && TrackMateSettings.check(settings) == null) last = new LinkedHashMap<>(settings);
	}

	/** Forgets the remembered settings (for tests). */
	static synchronized void forget() {
		last = null;
	}
}
