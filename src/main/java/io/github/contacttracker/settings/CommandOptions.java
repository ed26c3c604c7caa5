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
import java.util.Comparator;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The options of one command of the command line or of the Spark job: declared by the command ({@link #add}),
 * parsed from its arguments ({@link #parse}), read back typed ({@link #value}) and described in its help
 * ({@link #usage}). Every command has {@code -h}/{@code --help}; the tracking settings' options are declared once
 * for all of them by {@link SettingOptions}.
 * <p>
 * Our own small parser rather than a library's, because start-up is part of every run (a cluster job runs one
 * process per movie) and a general parser library cost about 0.1 s of it: class files too old for class-data
 * sharing, and reflection over annotations. This one is plain code over a list.
 * <p>
 * Syntax: {@code --name VALUE} or {@code --name=VALUE}; a flag takes no value ({@code --name=true|false} is also
 * read), a negatable flag also {@code --no-name}; positional parameters in order, anywhere among the options;
 * {@code --} ends the options. Each option at most once, but those declared repeatable ({@link #addRepeatable}). Errors are {@link BadOptionException}s with a one-line
 * message for the user.
 */
public final class CommandOptions {

	/** The help is wrapped to this many columns. */
	public static final int WIDTH = 100;

	/** Options written up to this long set the column of the descriptions; longer ones stick out into it. */
	private static final int LONG_COLUMN_MAX = 20;

	/** Stands for a space where the help must not break a line (as in {@code Default: 0.0.}); printed as a space. */
	public static final char NO_BREAK = '\u00a0';

	private static final String NEWLINE = System.lineSeparator();

	private final String commandLine;
	private final List<String> description;
	private final List<Option<?>> declared = new ArrayList<>();
	private final Option<Boolean> help = Option.flag(List.of("-h", "--help"), "Show this help and exit.");
	private Option<Boolean> version;
	private boolean declarationOrder;
	private final List<CommandOptions> subcommands = new ArrayList<>();
	private String footer;

	// by identity: each declared option is its own key (and a record's generated hashCode links method handles,
	// a millisecond or more of start-up)
	private final Map<Option<?>, Object> values = new IdentityHashMap<>();
	/** The last positional parameter's further values, when it repeats ({@link #withRepeatedLastParameter()}). */
	private final List<Object> repeated = new ArrayList<>();
	private boolean repeatLast;
	private final Set<Option<?>> given = Collections.newSetFromMap(new IdentityHashMap<>());
	/** Options that may be given more than once ({@link #addRepeatable}), and their values in order. */
	private final Map<Option<?>, List<Object>> repeatable = new IdentityHashMap<>();

	/**
	 * @param commandLine how the command is called, e.g. {@code contact-tracker demo}
	 * @param description the help's paragraphs; the first one also lists the command in its parent's help
	 */
	public CommandOptions(final String commandLine, final String... description) {
		this.commandLine = commandLine;
		this.description = List.of(description);
	}

	/**
	 * Declares an option or positional parameter.
	 *
	 * @return {@code option}, to read its value with later
	 */
	public <T> Option<T> add(final Option<T> option) {
		for (final String name : option.names())
			if (named(name) != null) throw new IllegalArgumentException(commandLine + ": " + name + " declared twice");
		declared.add(option);
		return option;
	}

	/**
	 * Declares an option that may be given more than once ({@code --conf A=1 --conf B=2}); {@link #values} reads
	 * every value given, in order.
	 *
	 * @return {@code option}, to read its values with later
	 */
	public <T> Option<T> addRepeatable(final Option<T> option) {
		add(option);
		repeatable.put(option, new ArrayList<>());
		return option;
	}

	/**
	 * Lets the last positional parameter be given more than once ({@code MOVIE...}); {@link #values} reads them all.
	 */
	public CommandOptions withRepeatedLastParameter() {
		repeatLast = true;
		return this;
	}

	/** Adds {@code -V}/{@code --version}; see {@link #versionRequested()}. */
	public CommandOptions withVersion() {
		version = Option.flag(List.of("-V", "--version"), "Print version information and exit.");
		return this;
	}

	/** Lists the options in the help in the order they were declared (the help option last), not sorted by name. */
	public CommandOptions inDeclarationOrder() {
		declarationOrder = true;
		return this;
	}

	/** Lists these commands in the help, each with the first paragraph of its description. */
	public CommandOptions withSubcommands(final List<CommandOptions> commands) {
		subcommands.addAll(commands);
		return this;
	}

	/** Ends the help with this paragraph. */
	public CommandOptions withFooter(final String text) {
		footer = text;
		return this;
	}

	/** @return how the command is called, e.g. {@code contact-tracker demo} */
	public String commandLine() {
		return commandLine;
	}

	/** @return the command's own name, the last word of {@link #commandLine()} */
	public String name() {
		return commandLine.substring(commandLine.lastIndexOf(' ') + 1);
	}

	/**
	 * Reads {@code args} from index {@code first} on (the earlier ones name the command): every option's value
	 * converted, the defaults of those not given filled in. When help or the version is asked for, what is
	 * missing or left over is not an error.
	 *
	 * @throws BadOptionException an unknown option, an unconvertible or missing value, a missing required
	 *         option or parameter, an argument left over
	 */
	public void parse(final String[] args, final int first) throws BadOptionException {
		values.clear();
		given.clear();
		repeated.clear();
		repeatable.values().forEach(List::clear);
		final Option<?> last = lastParameter();
		final List<Integer> unmatched = new ArrayList<>();
		final Iterator<Option<?>> positionals = declared.stream().filter(Option::positional).iterator();
		boolean optionsEnded = false;
		for (int i = first; i < args.length; i++) {
			final String arg = args[i];
			if (!optionsEnded && arg.equals("--")) optionsEnded = true;
			else if (!optionsEnded && looksLikeOption(arg)) {
				final int equals = arg.indexOf('=');
				final String name = equals < 0 ? arg : arg.substring(0, equals);
				final Option<?> option = named(name);
				if (option == null) {
					unmatched.add(i);
					continue;
				}
				if (!given.add(option) && !repeatable.containsKey(option)) throw new BadOptionException("option '" + option.mainName() + "'" + (option
					.isFlag() ? "" : " (" + option.label() + ")") + " should be specified only once");
				if (option.isFlag()) {
					final boolean set = equals < 0 || (Boolean) convert(option, arg.substring(equals + 1));
					values.put(option, option.names().contains(name) == set);
					continue;
				}
				if (equals < 0 && i + 1 == args.length) throw new BadOptionException(
					"Missing required parameter for option '" + option.mainName() + "' (" + option.label() + ")");
				final String text = equals < 0 ? args[++i] : arg.substring(equals + 1);
				if (looksLikeOption(text) && named(text.split("=", 2)[0]) != null) throw new BadOptionException(
					"Expected parameter for option '" + option.mainName() + "' but found '" + text + "'");
				final Object value = convert(option, text);
				if (repeatable.containsKey(option)) repeatable.get(option).add(value);
				values.putIfAbsent(option, value);
			}
			else if (positionals.hasNext()) {
				final Option<?> positional = positionals.next();
				given.add(positional);
				values.put(positional, convert(positional, arg));
			}
			else if (repeatLast && last != null && given.contains(last)) repeated.add(convert(last, arg));
			else unmatched.add(i);
		}
		if (helpRequested() || versionRequested()) return;
		checkRequired();
		if (!unmatched.isEmpty()) throw new BadOptionException(leftOver(args, unmatched));
		for (final Option<?> option : all())
			if (!given.contains(option) && option.defaultValue() != null)
				values.put(option, option.converter().apply(option.defaultValue())); // a bad default is a bug
	}

	/** @return whether {@code -h}/{@code --help} was given */
	public boolean helpRequested() {
		return given.contains(help);
	}

	/** @return whether {@code -V}/{@code --version} was given (see {@link #withVersion()}) */
	public boolean versionRequested() {
		return version != null && given.contains(version);
	}

	/** @return whether the option was given on the command line (not only defaulted) */
	public boolean given(final Option<?> option) {
		checkDeclared(option);
		return given.contains(option);
	}

	/** @return the option's value as given, else its default; null when neither */
	@SuppressWarnings("unchecked")
	public <T> T value(final Option<T> option) {
		checkDeclared(option);
		return (T) values.get(option);
	}

	/**
	 * @return every value given to a positional parameter that repeats (see {@link #withRepeatedLastParameter()}) or
	 *         to a repeatable option ({@link #addRepeatable}), in order; one value (or none) for any other option
	 */
	@SuppressWarnings("unchecked")
	public <T> List<T> values(final Option<T> option) {
		if (repeatable.containsKey(option)) return (List<T>) List.copyOf(repeatable.get(option));
		final List<T> all = new ArrayList<>();
		final T first = value(option);
		if (first != null) all.add(first);
		if (option == lastParameter()) for (final Object more : repeated)
			all.add((T) more);
		return all;
	}

	/** @return the help: usage line, description, options (and subcommands), wrapped to {@value #WIDTH} columns */
	public String usage() {
		final String usage = "Usage: " + commandLine;
		final List<String> lines = new ArrayList<>(row(usage, usage.length() + 1, 0, synopsis()));
		for (final String paragraph : description)
			lines.addAll(wrap(paragraph, WIDTH, WIDTH));
		final List<Option<?>> listed = listed();
		final int column = 6 + listed.stream().mapToInt(o -> o.synopsis().length()).filter(n -> n <= LONG_COLUMN_MAX)
			.max().orElse(LONG_COLUMN_MAX) + 3;
		for (final Option<?> option : listed)
			lines.addAll(row("  " + (option.shortName() != null ? option.shortName() + ", " : "    ") + option
				.synopsis(), column, 2, option.help()));
		if (!subcommands.isEmpty()) {
			lines.add("Commands:");
			final int commandColumn = 2 + subcommands.stream().mapToInt(c -> c.name().length()).max().getAsInt() + 2;
			for (final CommandOptions command : subcommands)
				lines.addAll(row("  " + command.name(), commandColumn, 2, command.description.get(0)));
		}
		if (footer != null) {
			lines.add("");
			lines.addAll(wrap(footer, WIDTH, WIDTH));
		}
		return String.join(NEWLINE, lines) + NEWLINE;
	}

	/** The user's mistake on the command line, in one line. */
	public static final class BadOptionException extends Exception {

		private static final long serialVersionUID = 1L;

		public BadOptionException(final String message) {
			super(message);
		}
	}

	/** @return the last positional parameter declared, or null */
	private Option<?> lastParameter() {
		Option<?> last = null;
		for (final Option<?> option : declared)
			if (option.positional()) last = option;
		return last;
	}

	private List<Option<?>> all() {
		final List<Option<?>> all = new ArrayList<>(declared);
		all.add(help);
		if (version != null) all.add(version);
		return all;
	}

	/** @return the option called {@code name}, by one of its names or its negative form; null if none */
	private Option<?> named(final String name) {
		for (final Option<?> option : all())
			if (option.names().contains(name) || option.negatable() && name.equals(Option.NEGATION + option.mainName()
				.substring(2))) return option;
		return null;
	}

	private static boolean looksLikeOption(final String arg) {
		return arg.length() > 1 && arg.startsWith("-");
	}

	private void checkDeclared(final Option<?> option) {
		for (final Option<?> o : all())
			if (o == option) return; // by identity, as the values are kept
		throw new IllegalArgumentException(option.mainName() + " is not an option of " + commandLine);
	}

	private static Object convert(final Option<?> option, final String text) throws BadOptionException {
		try {
			return option.converter().apply(text);
		}
		catch (final IllegalArgumentException e) {
			throw new BadOptionException("Invalid value for " + (option.positional() ? "parameter '" : "option '") +
				option.mainName() + "': " + e.getMessage());
		}
	}

	/** Throws when a required option or positional parameter is missing, naming all of them (options first). */
	private void checkRequired() throws BadOptionException {
		final List<Option<?>> missing = all().stream().filter(o -> o.required() && !given.contains(o)).sorted(
			Comparator.comparing(Option::positional)).toList();
		if (missing.isEmpty()) return;
		final long parameters = missing.stream().filter(Option::positional).count();
		final String what = parameters == 0 ? "option" : parameters == missing.size() ? "parameter" :
			"options and parameters";
		throw new BadOptionException("Missing required " + what + (missing.size() > 1 && !what.endsWith("s") ? "s" :
			"") + ": " + missing.stream().map(o -> "'" + o.synopsis() + "'").collect(Collectors.joining(", ")));
	}

	/** @return the message for arguments that no option or parameter took */
	private static String leftOver(final String[] args, final List<Integer> unmatched) {
		final String listed = unmatched.stream().map(i -> "'" + args[i] + "'").collect(Collectors.joining(", "));
		final boolean one = unmatched.size() == 1;
		if (looksLikeOption(args[unmatched.get(0)])) return "Unknown option" + (one ? "" : "s") + ": " + listed;
		return (one ? "Unmatched argument at index " : "Unmatched arguments from index ") + unmatched.get(0) + ": " +
			listed;
	}

	/** @return e.g. {@code [-h] [--[no-]progress] [--csv=OUT.csv] --r-out=R MOVIE}: flags, options, parameters */
	private String synopsis() {
		final List<String> items = new ArrayList<>();
		// each short flag on its own ([-h] [-V]): the parser does not read them combined
		for (final Option<?> option : all())
			if (option.isFlag() && option.shortName() != null) items.add("[" + option.shortName() + "]");
		final List<Option<?>> sorted = sorted(all().stream().filter(o -> !o.positional()));
		for (final boolean flags : new boolean[] { true, false })
			for (final Option<?> option : sorted)
				if (option.isFlag() == flags && (!flags || option.shortName() == null)) items.add(item(option) + (repeatable
					.containsKey(option) ? "..." : ""));
		if (!subcommands.isEmpty()) items.add("[COMMAND]");
		for (final Option<?> option : declared)
			if (option.positional()) items.add(item(option) + (repeatLast && option == lastParameter() ? "..." : ""));
		return String.join(" ", items);
	}

	/** @return how the usage line shows it: in brackets unless required */
	private static String item(final Option<?> option) {
		return option.required() ? option.synopsis() : "[" + option.synopsis() + "]";
	}

	/** @return the options in the order the help lists them: positional parameters first */
	private List<Option<?>> listed() {
		final List<Option<?>> listed = new ArrayList<>(declared.stream().filter(Option::positional).toList());
		final Stream<Option<?>> named = all().stream().filter(o -> !o.positional());
		listed.addAll(declarationOrder ? named.toList() : sorted(named));
		return listed;
	}

	/** @return the options sorted by their first name, dashes left out ({@code csv}, {@code h} for -h, --help) */
	private static List<Option<?>> sorted(final Stream<Option<?>> options) {
		return options.sorted(Comparator.comparing(o -> o.names().get(0).replaceFirst("^-+", "").toLowerCase(
			Locale.ROOT))).toList();
	}

	/**
	 * @param lead what stands left of the text, e.g. {@code "      --reps=N"}: on a line of its own when it reaches
	 *        the column
	 * @param indent how much further in than the column the text's later lines start
	 * @return {@code text} wrapped from {@code column} on, after {@code lead}
	 */
	private static List<String> row(final String lead, final int column, final int indent, final String text) {
		final List<String> lines = new ArrayList<>();
		if (lead.length() >= column) lines.add(lead);
		final String head = lead.length() >= column ? "" : lead;
		final List<String> wrapped = wrap(text, WIDTH - column, WIDTH - column - indent);
		lines.add(head + " ".repeat(column - head.length()) + wrapped.get(0));
		for (final String line : wrapped.subList(1, wrapped.size()))
			lines.add(" ".repeat(column + indent) + line);
		return lines;
	}

	/** @return {@code text}'s words in lines of at most {@code firstWidth}, then {@code width} characters */
	public static List<String> wrap(final String text, final int firstWidth, final int width) {
		final List<String> lines = new ArrayList<>();
		final StringBuilder line = new StringBuilder();
		for (final String word : text.strip().split(" +")) {
			if (line.length() > 0 && line.length() + 1 + word.length() > (lines.isEmpty() ? firstWidth : width)) {
				lines.add(line.toString());
				line.setLength(0);
			}
			line.append(line.length() > 0 ? " " : "").append(word);
		}
		lines.add(line.toString());
		lines.replaceAll(l -> l.replace(NO_BREAK, ' '));
		return lines;
	}
}
