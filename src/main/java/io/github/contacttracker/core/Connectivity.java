package io.github.contacttracker.core;

/** Pixel neighbourhood used to join active pixels into one particle. */
public enum Connectivity {
	/** Edge neighbours only (up, down, left, right). */
	FOUR,
	/** Edge and corner neighbours: the paper's choice and the default. */
	EIGHT;

	/**
	 * Parses {@code 4}, {@code 8}, {@code four} or {@code eight} (case-insensitive).
	 *
	 * @throws IllegalArgumentException naming the bad value
	 */
	public static Connectivity parse(final String text) {
		final String t = text == null ? "" : text.trim().toLowerCase();
		switch (t) {
			case "4": case "four": return FOUR;
			case "8": case "eight": return EIGHT;
			default: throw new InvalidInputException("connectivity must be 4 or 8, not '" + text + "'");
		}
	}

	/** @return 4 or 8 */
	public int neighbours() {
		return this == FOUR ? 4 : 8;
	}
}
