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

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

import ij.IJ;
import ij.text.TextWindow;

/**
 * Help on our dialogs: tooltips wrapped to a readable width, and the Help buttons' pages of the manual, which
 * ships inside the plugin's jar (the user documentation, under {@link #MANUAL}): a Help button shows its
 * command's section in a text window, with no network and no address that may not exist.
 * <p>
 * SciJava's Swing dialog puts a parameter's description as the tooltip of its label, on one line however long:
 * up to about 1,200 px wide. Swing renders a tooltip that starts with {@code <html>} as HTML, and a paragraph of a
 * given width wraps; {@link #TIP} is a compile-time constant, so annotations can prefix it.
 */
final class DialogHelp {

	/** Prefix of every description: wraps the tooltip at about 320 px. */
	static final String TIP = "<html><p width=320>";

	/** Where the manual's pages lie in the jar (the documentation's Markdown files, as written). */
	static final String MANUAL = "/io/github/contacttracker/manual/";

	/**
	 * One section of the manual.
	 *
	 * @param file the manual's file ({@code fiji.md})
	 * @param heading the section's heading, as written after its {@code #}s
	 */
	record Page(String file, String heading) {

		/** @return the section: from its heading to the next heading of the same or a higher level; null if absent */
		String text() {
			final java.io.InputStream in = DialogHelp.class.getResourceAsStream(MANUAL + file);
			if (in == null) return null;
			final List<String> lines;
			try (in) {
				lines = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
			}
			catch (final IOException e) {
				return null;
			}
			int level = 0;
			final StringBuilder b = new StringBuilder();
			boolean fenced = false;
			for (final String line : lines) {
				if (line.startsWith("```")) fenced = !fenced;
				final int hashes = fenced ? 0 : line.length() - line.replaceFirst("^#+ ", "").length() - 1;
				if (level == 0) {
					if (hashes > 0 && line.substring(hashes + 1).trim().equals(heading)) level = hashes;
					else continue;
				}
				else if (hashes > 0 && hashes <= level) break;
				b.append(line).append('\n');
			}
			return level == 0 ? null : b.toString();
		}
	}

	/** The pages of the three commands. */
	static final Page TRACKER_PAGE = new Page("fiji.md", "Contact Tracker"), PROFILE_PAGE = new Page("fiji.md",
		"Contact Tracker Profile: choosing `threshold` and `r_out`"), POTENTIAL_PAGE = new Page("potentials.md",
			"Pair potentials");

	private DialogHelp() {}

	/**
	 * Shows a section of the manual in a text window (a Help button's callback); headless, or when the section is
	 * missing, says in the Log where the manual is.
	 */
	static void open(final Page page) {
		final String text = page.text();
		if (text == null || GraphicsEnvironment.isHeadless()) {
			IJ.log("Contact Tracker: the manual's section '" + page.heading() + "' is " + page.file() + " in the " +
				"plugin's jar (" + MANUAL.substring(1) + page.file() + ")" + (text == null ? ", missing from this jar"
					: ""));
			return;
		}
		new TextWindow("Contact Tracker manual: " + page.heading().replace("`", ""), text, 640, 560);
	}

	/** @return a description without the {@link #TIP} prefix */
	static String plain(final String description) {
		return description != null && description.startsWith(TIP) ? description.substring(TIP.length()) : description;
	}
}
