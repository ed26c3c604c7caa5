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

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

import io.github.contacttracker.core.InvalidInputException;

/**
 * Every tracking setting as a command-line option ({@code --r-out R}), declared on a command's options from the
 * descriptor ({@link TrackingSettings#ALL}) and read back as {@link SettingValues}: what {@code contact-tracker
 * track} and the Spark job share, so that both take the same options with the same help and the same messages. A
 * setting whose default fits no real image ({@link Setting#isImageSpecific()}) has no default here: the front end
 * measures it from the movie when it is not given.
 */
public final class SettingOptions {

	/** What the help says of the default of a setting measured from the movie. */
	static final String MEASURED = " Default: measured on frame 1 by the profile helper.";

	private final CommandOptions options;
	private final Map<Setting<?>, Option<String>> byOption = new LinkedHashMap<>();

	/** Declares every setting's option on {@code options}. */
	public SettingOptions(final CommandOptions options) {
		this.options = options;
		for (final Setting<?> s : TrackingSettings.ALL) {
			final Option<String> option = Option.text(s.cliOption(), metavar(s), s.help() + (s.isImageSpecific() ?
				MEASURED : ""));
			byOption.put(s, options.add(s.isImageSpecific() ? option : option.withDefault(String.valueOf(s
				.defaultValue()))));
		}
	}

	/** @return how the help writes the value: the choices ({@code fit|deblend|...}), else a letter */
	private static String metavar(final Setting<?> s) {
		if (!s.choices().isEmpty()) return String.join("|", s.choices().stream().map(String::valueOf).toList());
		if (s.type() == Integer.class) return "N";
		return s == TrackingSettings.THRESHOLD ? "T" : s == TrackingSettings.R_OUT ? "R" : "X";
	}

	/** @return whether the setting was given on the command line (not only defaulted) */
	public boolean given(final Setting<?> s) {
		return options.given(byOption.get(s));
	}

	/** @return the settings given on the command line, in {@link TrackingSettings#ALL} order */
	public Set<Setting<?>> given() {
		final Set<Setting<?>> given = new LinkedHashSet<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			if (given(s)) given.add(s);
		return given;
	}

	/**
	 * @return the settings given on the command line, the others at their defaults
	 * @throws InvalidInputException naming the option and what is wrong with its value
	 */
	public SettingValues values() {
		SettingValues v = SettingValues.defaults();
		for (final Map.Entry<Setting<?>, Option<String>> e : byOption.entrySet()) {
			final Setting<?> s = e.getKey();
			if (!options.given(e.getValue())) continue;
			try {
				v = v.withText(s, options.value(e.getValue()));
			}
			catch (final InvalidInputException x) {
				throw new InvalidInputException("option " + s.cliOption() + ": " + x.getMessage(), x);
			}
		}
		return v;
	}
}
