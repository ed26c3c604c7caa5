package io.github.contacttracker.cli;

import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.core.InvalidInputException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Command-line arguments: positional words and {@code --name value} options. Every problem is an
 * {@link IllegalArgumentException} with a one-line message naming the option.
 */
final class Options {

	private final List<String> positional = new ArrayList<>();
	private final Map<String, String> values = new LinkedHashMap<>();

	/**
	 * @param args the arguments after the subcommand
	 * @param known the option names this subcommand accepts (without "--")
	 */
	Options(final String[] args, final Set<String> known) {
		for (int i = 0; i < args.length; i++) {
			final String a = args[i];
			if (a.startsWith("--")) {
				String name = a.substring(2), value;
				final int eq = name.indexOf('=');
				if (eq >= 0) {
					value = name.substring(eq + 1);
					name = name.substring(0, eq);
				}
				else {
					if (i + 1 >= args.length) throw new InvalidInputException("option --" + name + " needs a value");
					value = args[++i];
				}
				if (!known.contains(name))
					throw new InvalidInputException("unknown option --" + name + " (valid: --" + String.join(", --",
						known) + ")");
				if (values.put(name, value) != null)
					throw new InvalidInputException("option --" + name + " given twice");
			}
			else positional.add(a);
		}
	}

	List<String> positional() {
		return positional;
	}

	boolean has(final String name) {
		return values.containsKey(name);
	}

	String string(final String name, final String fallback) {
		return values.getOrDefault(name, fallback);
	}

	String required(final String name) {
		final String v = values.get(name);
		if (v == null) throw new InvalidInputException("option --" + name + " is required");
		return v;
	}

	double number(final String name) {
		return parseDouble(name, required(name));
	}

	double number(final String name, final double fallback) {
		return has(name) ? parseDouble(name, values.get(name)) : fallback;
	}

	int integer(final String name, final int fallback) {
		if (!has(name)) return fallback;
		try {
			return Integer.parseInt(values.get(name).trim());
		}
		catch (final NumberFormatException e) {
			throw new InvalidInputException("option --" + name + " must be a whole number, not '" + values.get(name) +
				"'");
		}
	}

	long longInteger(final String name, final long fallback) {
		if (!has(name)) return fallback;
		try {
			return Long.parseLong(values.get(name).trim());
		}
		catch (final NumberFormatException e) {
			throw new InvalidInputException("option --" + name + " must be a whole number, not '" + values.get(name) +
				"'");
		}
	}

	Path path(final String name) {
		return has(name) ? Path.of(values.get(name)) : null;
	}

	/**
	 * An output file's path, checked before any work is done: its folder must exist.
	 *
	 * @return the path, or null when the option is absent
	 */
	Path outputPath(final String name) {
		final Path file = path(name);
		if (file != null) AtomicFile.checkFolder("--" + name, file);
		return file;
	}

	private static double parseDouble(final String name, final String text) {
		try {
			final double v = Double.parseDouble(text.trim());
			if (!Double.isFinite(v)) throw new NumberFormatException();
			return v;
		}
		catch (final NumberFormatException e) {
			throw new InvalidInputException("option --" + name + " must be a number, not '" + text + "'");
		}
	}
}
