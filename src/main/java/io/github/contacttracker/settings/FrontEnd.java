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

import java.util.ArrayList;
import java.util.List;

/**
 * Where a user changes the settings, and so how a message names one: an option on the command line, a field of
 * Fiji's dialog (and its key in a macro call), a field of TrackMate's panel. Advice such as "use --method fit" helps
 * only the user who types options; one who fills in a dialog must be pointed to the dialog's field. The phrases read
 * inside a sentence as they are: a field's name is followed by at most one bracket, its macro key.
 */
public enum FrontEnd {

	/** The command line: {@code use --method fit}. */
	COMMAND_LINE("'contact-tracker profile MOVIE'"),
	/** Fiji's dialog and macros: {@code set 'Method' to fit (macro method=fit)}. */
	FIJI("the dialog's 'Measure from the image' or Plugins > Tracking > Contact Tracker Profile"),
	/** TrackMate's detector panel: {@code set 'Method' to fit}. */
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
	 * @return what a user of this front end does to give the setting that value, as an imperative:
	 *         {@code use --method fit}, {@code set 'Method' to fit (macro method=fit)}
	 */
	public String set(final Setting<?> setting, final String value) {
		return set(List.of(setting), List.of(value));
	}

	/**
	 * @return what a user of this front end does to give two settings their values at once:
	 *         {@code use --method fit --detection image},
	 *         {@code set 'Method' to fit and 'Detection' to image (macro method=fit detection=image)}
	 */
	public String set(final Setting<?> first, final String firstValue, final Setting<?> second,
		final String secondValue)
	{
		return set(List.of(first, second), List.of(firstValue, secondValue));
	}

	private String set(final List<Setting<?>> settings, final List<String> values) {
		return (this == COMMAND_LINE ? "use " : "set ") + phrase(settings, values, " to ", " and ");
	}

	/**
	 * @return the settings with their values: options on the command line, else each field's label, {@code to}, its
	 *         value, joined by {@code and} (Fiji: then the macro keys)
	 */
	private String phrase(final List<Setting<?>> settings, final List<String> values, final String to,
		final String and)
	{
		final List<String> fields = new ArrayList<>(), options = new ArrayList<>(), keys = new ArrayList<>();
		for (int i = 0; i < settings.size(); i++) {
			final Setting<?> s = settings.get(i);
			fields.add("'" + s.label() + "'" + to + values.get(i));
			options.add(s.cliOption() + " " + values.get(i));
			keys.add(s.name() + "=" + values.get(i));
		}
		return switch (this) {
			case COMMAND_LINE -> String.join(" ", options);
			case FIJI -> String.join(and, fields) + " (macro " + String.join(" ", keys) + ")";
			case TRACKMATE -> String.join(and, fields);
		};
	}

	/**
	 * @param setting a tracking setting
	 * @param value a value of it, as typed
	 * @return the setting with that value, as this front end's user gives it, to be read after "give":
	 *         {@code --particles dark}, {@code 'Particles' dark (macro particles=dark)}, {@code 'Particles' dark}
	 */
	public String value(final Setting<?> setting, final String value) {
		return values(List.of(setting), List.of(value));
	}

	/**
	 * @return settings with their values as one phrase, as {@link #value} gives one: {@code --detection image
	 *         --diameter 13.8}, {@code 'Detection' image, 'Diameter' 13.8 (macro detection=image diameter=13.8)}
	 */
	public String values(final List<Setting<?>> settings, final List<String> values) {
		return phrase(settings, values, " ", ", ");
	}

	/** @return what measures one particle the user points to, as the subject of "measures one particle" */
	public String measuresOne() {
		return this == COMMAND_LINE ? "contact-tracker profile MOVIE --at X,Y" : "Plugins > Tracking > Contact Tracker " +
			"Profile, a click on the particle,";
	}

	/**
	 * @param frame the frame (counted from 1) the values were measured on
	 * @return what shows how the profile helper measured a movie's values on that frame, as the subject of "shows how"
	 */
	public String showsHow(final String movie, final int frame) {
		if (this == COMMAND_LINE) return "'contact-tracker profile " + (frame > 1 ? "--frame " + frame + " " : "") +
			movie + "'";
		return "Plugins > Tracking > Contact Tracker Profile" + (frame > 1 ? " on frame " + frame : "");
	}

	/**
	 * @return what in this front end measures the particles' size and profile on a movie, as the subject of a
	 *         clause ("which ... measures")
	 */
	public String measuresSize() {
		return measuresSize;
	}
}
