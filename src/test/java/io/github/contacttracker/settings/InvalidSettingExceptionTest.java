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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A refused value names its setting as data: a front end reads {@link InvalidSettingException#key()}, never the
 * message's words.
 */
class InvalidSettingExceptionTest {

	/** Text that reads as no value of any setting: not a number, not a choice. */
	@Test
	void everySettingsUnreadableTextNamesThatSetting() {
		for (final Setting<?> s : TrackingSettings.ALL) {
			final InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> SettingValues
				.defaults().withText(s, "nonsense"), s::name);
			assertEquals(s.name(), e.key());
			assertTrue(e.getMessage().contains("'nonsense'"), e::getMessage);
		}
	}

	/** Values of the right type past a limit: r_out at its exclusive lower bound, min_area below its least. */
	@Test
	void aValuePastItsLimitNamesItsSettingAndNoOther() {
		final InvalidSettingException rOut = assertThrows(InvalidSettingException.class, () -> SettingValues.defaults()
			.with(TrackingSettings.R_OUT, TrackingSettings.R_OUT.min().doubleValue()));
		assertEquals(TrackingSettings.R_OUT.name(), rOut.key());
		final InvalidSettingException minArea = assertThrows(InvalidSettingException.class, () -> SettingValues
			.defaults().with(TrackingSettings.MIN_AREA, TrackingSettings.MIN_AREA.min().intValue() - 1));
		assertEquals(TrackingSettings.MIN_AREA.name(), minArea.key());
		// a missing value too
		assertEquals(TrackingSettings.METHOD.name(), assertThrows(InvalidSettingException.class,
			() -> TrackingSettings.METHOD.check(null)).key());
	}
}
