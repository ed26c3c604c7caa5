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
package io.github.contacttracker.core;

/**
 * Bad input from the user: a setting out of range, an unreadable file, an image that cannot be tracked. Every
 * front end reports it as a one-line error (the command line exits with status 2); any other exception is a bug
 * and is reported with its stack trace. It extends {@link IllegalArgumentException} so that code calling the API
 * with bad arguments sees the usual type.
 */
public class InvalidInputException extends IllegalArgumentException {

	private static final long serialVersionUID = 1L;

	/** @param message one line naming the problem */
	public InvalidInputException(final String message) {
		super(message);
	}

	/**
	 * @param message one line naming the problem
	 * @param cause what it came from
	 */
	public InvalidInputException(final String message, final Throwable cause) {
		super(message, cause);
	}

	/**
	 * @param message a message, perhaps of several lines (another library's)
	 * @return it on one line, each run of white space one space; "(no message)" for null
	 */
	public static String oneLine(final String message) {
		return message == null ? "(no message)" : message.replaceAll("\\s+", " ").strip();
	}
}
