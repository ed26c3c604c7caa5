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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The command line's option parser and its help: values, flags, the error messages, the layout. */
class CommandOptionsTest {

	private final CommandOptions options = new CommandOptions("contact-tracker test", "A command for the tests.");
	private final Option<Path> input = options.add(Option.positionalPath("INPUT", "The input."));
	private final Option<String> method = options.add(Option.text("--method", "M", "How.").withDefault("fit"));
	private final Option<Integer> reps = options.add(Option.integer("--reps", "N", "Repetitions.").withDefault("50"));
	private final Option<Integer> threads = options.add(Option.integer("--threads", "N", "Worker threads (0: all " +
		"processors).").withDefaultExplained("0"));
	private final Option<Double> threshold = options.add(Option.decimal("--threshold", "T", "Grey level.")
		.asRequired());
	private final Option<Long> seed = options.add(Option.longInteger("--seed", "S", "Random seed."));
	private final Option<Boolean> progress = options.add(Option.negatableFlag("--progress", "Show progress."));
	private final Option<Boolean> endToEnd = options.add(Option.negatableFlag("--end-to-end", "Also end to end " +
		"(default: on).").withDefaultExplained("true"));

	private void parse(final String... args) throws CommandOptions.BadOptionException {
		options.parse(args, 0);
	}

	private String error(final String... args) {
		return assertThrows(CommandOptions.BadOptionException.class, () -> parse(args)).getMessage();
	}

	@Test
	void valuesAfterAnEqualsSignOrAsTheNextArgument() throws Exception {
		parse("in.tif", "--method=paper", "--reps", "7", "--threshold", "85.5", "--seed=-3");
		assertEquals(Path.of("in.tif"), options.value(input));
		assertEquals("paper", options.value(method));
		assertEquals(7, options.value(reps));
		assertEquals(85.5, options.value(threshold));
		assertEquals(-3L, options.value(seed), "a negative number is a value, not an option");
		assertTrue(options.given(method));
		assertFalse(options.given(threads));
		assertEquals(0, options.value(threads), "the default of an option not given");
		assertThrows(IllegalArgumentException.class, () -> options.value(Option.integer("--reps", "N", "Other.")),
			"an option of another command");
	}

	@Test
	void positionalParameterAnywhereAndAfterTheEndOfOptions() throws Exception {
		parse("--threshold", "1", "in.tif", "--reps", "3");
		assertEquals(Path.of("in.tif"), options.value(input));
		assertEquals(3, options.value(reps));
		parse("--threshold", "1", "--", "--odd.tif");
		assertEquals(Path.of("--odd.tif"), options.value(input));
		assertEquals(50, options.value(reps), "values of an earlier parse are forgotten");
		assertNull(options.value(seed), "neither given nor defaulted");
	}

	@Test
	void negatableFlags() throws Exception {
		parse("in.tif", "--threshold", "1");
		assertFalse(options.value(progress));
		assertFalse(options.given(progress));
		assertTrue(options.value(endToEnd), "its default");
		parse("in.tif", "--threshold", "1", "--progress", "--no-end-to-end");
		assertTrue(options.value(progress));
		assertTrue(options.given(progress));
		assertFalse(options.value(endToEnd));
		parse("in.tif", "--threshold", "1", "--no-progress", "--end-to-end");
		assertFalse(options.value(progress));
		assertTrue(options.given(progress));
		assertTrue(options.value(endToEnd));
		parse("in.tif", "--threshold", "1", "--progress=false", "--no-end-to-end=false");
		assertFalse(options.value(progress));
		assertTrue(options.value(endToEnd));
		assertEquals("Invalid value for option '--progress': 'maybe' is not a boolean", error("in.tif", "--threshold",
			"1", "--progress=maybe"));
		assertEquals("option '--progress' should be specified only once", error("in.tif", "--threshold", "1",
			"--progress", "--no-progress"));
	}

	@Test
	void missingRequiredOptionsAndParameters() {
		assertEquals("Missing required option: '--threshold=T'", error("in.tif"));
		assertEquals("Missing required parameter: 'INPUT'", error("--threshold", "1"));
		assertEquals("Missing required options and parameters: '--threshold=T', 'INPUT'", error("--reps", "2"));
		final CommandOptions two = new CommandOptions("contact-tracker two");
		two.add(Option.decimal("--threshold", "T", "Grey level.").asRequired());
		two.add(Option.decimal("--r-out", "R", "Reach.").asRequired());
		assertEquals("Missing required options: '--threshold=T', '--r-out=R'", assertThrows(
			CommandOptions.BadOptionException.class, () -> two.parse(new String[] { "two" }, 1)).getMessage());
	}

	@Test
	void unknownOptionsAndLeftOverArguments() {
		assertEquals("Unknown option: '--bogus'", error("in.tif", "--threshold", "1", "--bogus"));
		assertEquals("Unknown options: '--bogus', '1'", error("in.tif", "--threshold", "1", "--bogus", "1"));
		assertEquals("Unmatched argument at index 3: 'more.tif'", error("in.tif", "--threshold", "1", "more.tif"));
		assertEquals("Unmatched arguments from index 3: 'a', '--b'", error("in.tif", "--threshold", "1", "a", "--b"));
	}

	@Test
	void badAndMissingValues() {
		assertEquals("Invalid value for option '--reps': 'two' is not an int", error("in.tif", "--threshold", "1",
			"--reps", "two"));
		assertEquals("Invalid value for option '--reps': '1.5' is not an int", error("in.tif", "--threshold", "1",
			"--reps=1.5"));
		assertEquals("Invalid value for option '--seed': '99999999999999999999' is not a long", error("--seed",
			"99999999999999999999"));
		assertEquals("Invalid value for option '--threshold': 'high' is not a double", error("--threshold", "high"));
		assertEquals("Missing required parameter for option '--reps' (N)", error("in.tif", "--reps"));
		assertEquals("Expected parameter for option '--reps' but found '--threads'", error("in.tif", "--reps",
			"--threads", "2"));
		assertEquals("option '--reps' (N) should be specified only once", error("--reps", "1", "--reps", "2"));
	}

	@Test
	void helpSkipsTheChecksButNotTheConversions() throws Exception {
		parse("--bogus", "-h");
		assertTrue(options.helpRequested());
		assertFalse(options.versionRequested());
		assertEquals("Invalid value for option '--reps': 'x' is not an int", error("--help", "--reps", "x"));
	}

	@Test
	void helpListsEveryOptionWithItsDefault() {
		final String help = options.usage();
		final List<String> lines = help.lines().toList();
		assertEquals("Usage: contact-tracker test [-h] [--[no-]end-to-end] [--[no-]progress] [--method=M] [--reps=N]",
			lines.get(0));
		assertEquals("                            [--seed=S] [--threads=N] --threshold=T INPUT", lines.get(1));
		assertEquals("A command for the tests.", lines.get(2));
		assertEquals(List.of( //
			"      INPUT               The input.", //
			"      --[no-]end-to-end   Also end to end (default: on).", //
			"  -h, --help              Show this help and exit.", //
			"      --method=M          How. Default: fit.", //
			"      --[no-]progress     Show progress.", //
			"      --reps=N            Repetitions. Default: 50.", //
			"      --seed=S            Random seed.", //
			"      --threads=N         Worker threads (0: all processors).", //
			"      --threshold=T       Grey level."), lines.subList(3, lines.size()));
	}

	@Test
	void helpIsWrappedToTheWidthWithLongNamesStickingOut() {
		final CommandOptions wide = new CommandOptions("contact-tracker wide", "word ".repeat(40));
		wide.add(Option.text("--a", "X", "long ".repeat(40)));
		wide.add(Option.text("--a-rather-long-option", "VALUE", "Short."));
		wide.add(Option.decimal("--b", "Y", "long ".repeat(15)).withDefault("0.0"));
		final List<String> lines = wide.usage().lines().toList();
		for (final String line : lines)
			assertTrue(line.length() <= CommandOptions.WIDTH, line);
		assertEquals("word ".repeat(20).strip(), lines.get(1), "the description: 20 words of 5 fill 99 columns");
		// the column follows the longest name up to 20 characters (--help): 6 + 6 + 3
		assertEquals("      --a=X    " + "long ".repeat(17).strip(), lines.get(3));
		assertEquals(" ".repeat(17) + "long ".repeat(16).strip(), lines.get(4), "2 further in");
		assertEquals(" ".repeat(17) + "long ".repeat(7).strip(), lines.get(5));
		assertEquals("      --a-rather-long-option=VALUE", lines.get(6), "too long: on a line of its own");
		assertEquals(" ".repeat(15) + "Short.", lines.get(7));
		assertEquals("      --b=Y    " + "long ".repeat(15).strip(), lines.get(8), "'Default:' would fit, not its value");
		assertEquals(" ".repeat(17) + "Default: 0.0.", lines.get(9), "the default is not split from its value");
		assertEquals("  -h, --help   Show this help and exit.", lines.get(10));
	}

	@Test
	void versionAndSubcommandsOfTheTopLevel() throws Exception {
		final CommandOptions root = new CommandOptions("contact-tracker", "Top.").withVersion().withSubcommands(List.of(
			options, new CommandOptions("contact-tracker longer-name", "Another."))).withFooter("The end.");
		root.parse(new String[] { "-V" }, 0);
		assertTrue(root.versionRequested());
		assertEquals(List.of("Usage: contact-tracker [-h] [-V] [COMMAND]", "Top.", //
			"  -h, --help      Show this help and exit.", //
			"  -V, --version   Print version information and exit.", //
			"Commands:", //
			"  test         A command for the tests.", //
			"  longer-name  Another.", "", "The end."), root.usage().lines().toList());
	}

	/** A last parameter that repeats takes every further argument, in order; without that they are left over. */
	@Test
	void lastParameterThatRepeats() throws Exception {
		assertEquals("Unmatched arguments from index 1: 'b.tif', 'c.tif'", error("a.tif", "b.tif", "--threshold", "1",
			"c.tif"));
		options.withRepeatedLastParameter();
		parse("a.tif", "b.tif", "--threshold", "1", "c.tif");
		assertEquals(List.of(Path.of("a.tif"), Path.of("b.tif"), Path.of("c.tif")), options.values(input));
		assertEquals(Path.of("a.tif"), options.value(input));
		assertEquals(List.of(1.0), options.values(threshold), "one value for an option");
		parse("a.tif", "--threshold", "1");
		assertEquals(List.of(Path.of("a.tif")), options.values(input), "nothing left from the previous parse");
		assertTrue(options.usage().contains(" INPUT...\n") || options.usage().contains(" INPUT..." + System.lineSeparator()),
			options.usage());
	}
}
