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

import io.github.contacttracker.core.InvalidInputException;

/**
 * A value refused for one named input: a setting of the descriptor ({@link Setting#parse}, {@link Setting#check})
 * or a front end's own input of the same kind. It carries the input's name as data, so that a front end that
 * must act on the input (set it back, mark its field) reads {@link #key()} instead of parsing the message, whose
 * words are for people and may change.
 */
public class InvalidSettingException extends InvalidInputException {

	private static final long serialVersionUID = 1L;

	private final String key;

	/**
	 * @param key the input's name: a setting's {@link Setting#name()} ({@code r_out}), which is also its macro key
	 * @param message one line naming the problem
	 */
	public InvalidSettingException(final String key, final String message) {
		super(message);
		this.key = key;
	}

	/** @return the name of the refused input: its macro key ({@code r_out}, {@code pair_cutoff}) */
	public String key() {
		return key;
	}
}
