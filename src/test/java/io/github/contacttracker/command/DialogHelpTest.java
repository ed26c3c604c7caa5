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

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import javax.swing.JToolTip;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.scijava.Context;
import org.scijava.ItemVisibility;
import org.scijava.command.Command;
import org.scijava.command.CommandInfo;
import org.scijava.command.CommandService;
import org.scijava.module.ModuleItem;
import org.scijava.widget.Button;

/** Help where a person looks: a one-line description, a Help button to a page that exists, wrapped tooltips. */
class DialogHelpTest {

	private static Context context;
	private static final List<Class<? extends Command>> COMMANDS = List.of(ContactTrackerCommand.class,
		ContactTrackerProfileCommand.class, ContactTrackerPotentialCommand.class);

	@BeforeAll
	static void start() {
		context = new Context(CommandService.class);
	}

	@AfterAll
	static void stop() {
		context.dispose();
	}

	private static CommandInfo info(final Class<? extends Command> c) {
		return context.service(CommandService.class).getCommand(c);
	}

	/** Every tooltip wraps: the longest (about 300 characters) used to be one line of about 1,200 px. */
	@Test
	void tooltipsWrapToAReadableWidth() {
		int described = 0;
		for (final Class<? extends Command> c : COMMANDS)
			for (final ModuleItem<?> item : info(c).inputs()) {
				final String d = item.getDescription();
				if (d == null || d.isEmpty()) continue;
				described++;
				assertTrue(d.startsWith(DialogHelp.TIP), c.getSimpleName() + " " + item.getName() + ": " + d);
				final JToolTip tip = new JToolTip();
				tip.setTipText(d);
				final int width = tip.getPreferredSize().width;
				assertTrue(width <= 420, item.getName() + " is " + width + " px wide");
				final JToolTip plain = new JToolTip();
				plain.setTipText(DialogHelp.plain(d));
				if (DialogHelp.plain(d).length() > 100) assertTrue(plain.getPreferredSize().width > width,
					item.getName() + ": unwrapped it would be wider");
			}
		assertTrue(described >= 25, "descriptions: " + described);
	}

	/** Each dialog opens with one line saying what the command does, and a Help button. */
	@Test
	void oneLineDescriptionAndHelpButton() {
		for (final Class<? extends Command> c : COMMANDS) {
			final CommandInfo info = info(c);
			// the first item the dialog shows (services are not shown)
			final ModuleItem<?> first = java.util.stream.StreamSupport.stream(info.inputs().spliterator(), false).filter(
				i -> !org.scijava.service.Service.class.isAssignableFrom(i.getType()) && i.getType() != Context.class)
				.findFirst().get();
			assertEquals(ItemVisibility.MESSAGE, first.getVisibility(), c.getSimpleName());
			final String text = String.valueOf(first.getDefaultValue() != null ? first.getDefaultValue() : "");
			final ModuleItem<?> help = info.getInput("help");
			assertNotNull(help, c.getSimpleName());
			assertEquals(Button.class, help.getType());
			assertEquals("openManual", help.getCallback());
			assertTrue(text.isEmpty() || text.replaceAll("<[^>]+>", "").length() <= 100, text);
		}
		final ContactTrackerProfileCommand profile = new ContactTrackerProfileCommand();
		assertTrue(header(profile).contains("isolated particle with the point tool"), header(profile));
	}

	private static String header(final Object command) {
		try {
			final java.lang.reflect.Field f = OwnCommand.class.getDeclaredField("header");
			f.setAccessible(true);
			final String h = (String) f.get(command);
			assertTrue(h.replaceAll("<[^>]+>", "").length() <= 100, h);
			return h;
		}
		catch (final ReflectiveOperationException e) {
			throw new AssertionError(e);
		}
	}

	/**
	 * The Help buttons' pages are sections of the manual bundled in the jar (the documentation's own files), each
	 * found from its heading up to the next of its level.
	 */
	@Test
	void helpPagesAreSectionsOfTheBundledManual() throws Exception {
		for (final DialogHelp.Page page : List.of(DialogHelp.TRACKER_PAGE, DialogHelp.PROFILE_PAGE,
			DialogHelp.POTENTIAL_PAGE))
		{
			final String text = page.text();
			assertNotNull(text, page.toString());
			assertTrue(text.startsWith("#") && text.lines().findFirst().get().endsWith(page.heading()), text);
			assertTrue(text.lines().count() > 20, page + ": " + text.lines().count() + " lines");
			// the same as the documentation's file, from the heading on
			final String doc = Files.readString(Path.of(System.getProperty("basedir", ".")).resolve("src/site/markdown")
				.resolve(page.file()));
			assertTrue(doc.contains(text), page.toString());
		}
		// the tracker's section ends where the Profile's begins (same level)
		assertTrue(!DialogHelp.TRACKER_PAGE.text().contains("## Contact Tracker Profile"));
		assertTrue(DialogHelp.TRACKER_PAGE.text().contains("### The overlay"));
		assertNull(new DialogHelp.Page("fiji.md", "No such section").text());
		for (final Class<? extends Command> c : COMMANDS)
			assertTrue(info(c).getInput("help") != null);
		for (final Object command : List.of(new ContactTrackerCommand(), new ContactTrackerPotentialCommand()))
			header(command);
	}
}
