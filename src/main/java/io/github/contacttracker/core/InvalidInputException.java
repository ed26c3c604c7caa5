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
