package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
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
 * {@link TrackingSettings} and this test pins every other property (name, type, default, smallest value, choices)
 * to the descriptor. A setting added to the descriptor without its input here fails this test.
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
