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
package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.scijava.Context;
import org.scijava.command.CommandInfo;
import org.scijava.command.CommandService;
import org.scijava.module.ModuleItem;

import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * The Fiji command's inputs are the settings descriptor's: SciJava reads {@code @Parameter} annotations, which
 * take only compile-time constants, so the command takes its help texts and defaults from
 * {@link TrackingSettings}, its smallest values from the constants the descriptor takes them from
 * ({@code TrackerParameters}' limits), and this test pins every property (name, type, default, smallest and largest
 * value, choices) to the descriptor. A setting added to the descriptor without its input here fails this test.
 */
class CommandMatchesSettingsTest {

	@Test
	void everyTrackingSettingIsAnInputWithTheDescriptorsProperties() {
		try (Context context = new Context(CommandService.class)) {
			final CommandInfo info = context.service(CommandService.class).getCommand(ContactTrackerCommand.class);
			for (final Setting<?> s : TrackingSettings.ALL) {
				final ModuleItem<?> item = info.getInput(s.name());
				assertNotNull(item, "no input " + s.name());
				assertEquals(DialogHelp.TIP + s.help(), item.getDescription(), s.name());
				assertTrue(item.getLabel().startsWith(s.label()), item.getLabel() + " vs " + s.label());
				final Class<?> type = item.getType();
				if (!s.choices().isEmpty()) {
					assertEquals(String.class, type, s.name());
					assertEquals(s.choices().stream().map(String::valueOf).toList(), List.copyOf(item.getChoices()), s.name());
				}
				else assertEquals(s.type() == Integer.class ? int.class : double.class, type, s.name());
				if (s.min() != null) assertEquals(s.min().doubleValue(), Double.parseDouble(String.valueOf(item
					.getMinimumValue())), 0, s.name());
				else assertNull(item.getMinimumValue(), s.name());
				if (s.max() != null) assertEquals(s.max().doubleValue(), Double.parseDouble(String.valueOf(item
					.getMaximumValue())), 0, s.name());
				else assertNull(item.getMaximumValue(), s.name() + ": the descriptor has no largest value");
			}
		}
	}

	/** The defaults are the fields' initial values, read from a fresh instance. */
	@Test
	void defaultsAreTheDescriptors() throws Exception {
		final ContactTrackerCommand command = new ContactTrackerCommand();
		for (final Setting<?> s : TrackingSettings.ALL) {
			final java.lang.reflect.Field f = ContactTrackerCommand.class.getDeclaredField(s.name());
			f.setAccessible(true);
			assertEquals(String.valueOf(s.defaultValue()), String.valueOf(f.get(command)), s.name());
		}
	}
}
