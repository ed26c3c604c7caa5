package io.github.contacttracker.core;

import java.util.Locale;

/** How centres are computed. */
public enum Method {
	/** One pass of radial symmetry on each particle's whole active area: the reference, biased near contact. */
	FIRST,
	/** The paper's method: first pass, then a second pass on the active area outside the neighbours' discs. */
	PAPER;

	/** @return the lower-case name used on the command line, in macros and in TrackMate settings */
	public String key() {
		return name().toLowerCase(Locale.ROOT);
	}

	/**
	 * Parses a method name (case-insensitive).
	 *
	 * @throws IllegalArgumentException naming the bad value and the valid ones
	 */
	public static Method parse(final String text) {
		for (final Method m : values())
			if (m.key().equalsIgnoreCase(text == null ? "" : text.trim())) return m;
		final StringBuilder valid = new StringBuilder();
		for (final Method m : values())
			valid.append(valid.length() == 0 ? "" : ", ").append(m.key());
		throw new IllegalArgumentException("method must be one of " + valid + ", not '" + text + "'");
	}
}
