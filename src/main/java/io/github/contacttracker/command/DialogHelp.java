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

import java.io.IOException;
import java.net.URL;

import org.scijava.log.LogService;
import org.scijava.platform.PlatformService;

import ij.IJ;

/**
 * Help on our dialogs: tooltips wrapped to a readable width, the manual's pages for the Help buttons.
 * <p>
 * SciJava's Swing dialog puts a parameter's description as the tooltip of its label, on one line however long:
 * up to about 1,200 px wide. Swing renders a tooltip that starts with {@code <html>} as HTML, and a paragraph of a
 * given width wraps; {@link #TIP} is a compile-time constant, so annotations can prefix it.
 */
final class DialogHelp {

	/** Prefix of every description: wraps the tooltip at about 320 px. */
	static final String TIP = "<html><p width=320>";

	/** The manual (the project's README). */
	static final String MANUAL = "https://github.com/contact-tracker/contact-tracker";
	/** The manual's pages (README sections) of the three commands. */
	static final String TRACKER_PAGE = MANUAL + "#fiji", PROFILE_PAGE = MANUAL +
		"#contact-tracker-profile-choosing-threshold-and-r_out", POTENTIAL_PAGE = MANUAL + "#pair-potentials";

	private DialogHelp() {}

	/**
	 * Opens a page of the manual in the web browser (a Help button's callback); says so in the Log, with the
	 * address, when it cannot.
	 */
	static void open(final PlatformService platform, final LogService log, final String page) {
		try {
			if (platform == null) throw new IOException("no platform service");
			platform.open(new URL(page));
		}
		catch (final IOException e) {
			IJ.log("Contact Tracker: the manual is at " + page + " (" + e.getMessage() + ")");
			if (log != null) log.debug(e);
		}
	}

	/** @return a description without the {@link #TIP} prefix */
	static String plain(final String description) {
		return description != null && description.startsWith(TIP) ? description.substring(TIP.length()) : description;
	}
}
