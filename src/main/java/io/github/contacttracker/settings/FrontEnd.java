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

/**
 * Where a user changes the settings, and so how a message names one: an option on the command line, a field of
 * Fiji's dialog (and its key in a macro call), a field of TrackMate's panel. Advice such as "use --method fit" helps
 * only the user who types options; one who fills in a dialog must be pointed to the dialog's field.
 */
public enum FrontEnd {

	/** The command line: {@code --method fit}. */
	COMMAND_LINE("contact-tracker profile MOVIE"),
	/** Fiji's dialog and macros: {@code 'Method: fit' (macro method=fit)}. */
	FIJI("Plugins > Tracking > Contact Tracker Profile, or the dialog's 'Measure from the image'"),
	/** TrackMate's detector panel: {@code 'Method: fit'}. */
	TRACKMATE("the panel's 'Measure from the image'");

	private final String measuresSize;

	FrontEnd(final String measuresSize) {
		this.measuresSize = measuresSize;
	}

	/**
	 * @param setting a tracking setting
	 * @return how a user of this front end finds the setting: {@code --r-out}, {@code 'r_out' (macro r_out)}
	 */
	public String name(final Setting<?> setting) {
		return switch (this) {
			case COMMAND_LINE -> setting.cliOption();
			case FIJI -> "'" + setting.label() + "' (macro " + setting.name() + ")";
			case TRACKMATE -> "'" + setting.label() + "'";
		};
	}

	/**
	 * @param setting a tracking setting
	 * @param value a value of it, as typed
	 * @return how a user of this front end gives the setting that value: {@code --method fit},
	 *         {@code 'Method: fit' (macro method=fit)}
	 */
	public String name(final Setting<?> setting, final String value) {
		return switch (this) {
			case COMMAND_LINE -> setting.cliOption() + " " + value;
			case FIJI -> "'" + setting.label() + ": " + value + "' (macro " + setting.name() + "=" + value + ")";
			case TRACKMATE -> "'" + setting.label() + ": " + value + "'";
		};
	}

	/** @return what in this front end measures the particles' size and profile on a movie */
	public String measuresSize() {
		return measuresSize;
	}
}
