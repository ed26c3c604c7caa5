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
package io.github.contacttracker.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.settings.SettingValues;

/** The Spark job takes {@code --kinds} as {@code contact-tracker track} does and ships it to the executors. */
class SparkOptionsTest {

	@Test
	void kindsIsAnOptionWithItsHelpAndDefault() {
		final String usage = SparkOptions.usage();
		assertTrue(usage.contains("      --kinds=N             Kinds of particle the profile methods"), usage);
		assertTrue(usage.replaceAll("\\s+", " ").contains(" [--conf=KEY=VALUE]... "), "a repeatable option says so: " + usage);
		assertTrue(usage.replaceAll("\\s+", " ").contains("The KIND column says each spot's kind. Default: 0."), usage);
		assertEquals(0, SparkOptions.parse("m.tif", "--out-dir", "out").settings().parameters().kinds());
	}

	/** The job parses as {@code track} does: the same messages, options repeated only where declared so. */
	@Test
	void parsesAsTheCommandLineDoes() {
		assertEquals("Missing required option: '--out-dir=DIR' (--help lists the options)", assertThrows(
			InvalidInputException.class, () -> SparkOptions.parse("m.tif")).getMessage());
		assertEquals("Invalid value for option '--chunk': '0' is not a whole number >= 1 (--help lists the options)",
			assertThrows(InvalidInputException.class, () -> SparkOptions.parse("m.tif", "--out-dir", "o", "--chunk", "0"))
				.getMessage());
		assertEquals("option '--master' (URL) should be specified only once (--help lists the options)", assertThrows(
			InvalidInputException.class, () -> SparkOptions.parse("m.tif", "--out-dir", "o", "--master", "a", "--master",
				"b")).getMessage());
		final SparkOptions o = SparkOptions.parse("hdfs://nn/a.tif", "b.tif", "--conf", "spark.a=1", "--out-dir=o",
			"--conf=spark.b=2", "--particles", "dark", "--trackmate-xml");
		assertEquals(java.util.List.of("hdfs://nn/a.tif", "b.tif"), o.movies, "URIs as they are written");
		assertEquals(java.util.Map.of("spark.a", "1", "spark.b", "2"), o.conf);
		assertTrue(o.trackMateXml);
		assertEquals(java.util.Set.of(io.github.contacttracker.settings.TrackingSettings.PARTICLES), o.given);
		assertTrue(o.settings().dark());
		assertEquals(SparkOptions.DEFAULT_CHUNK, o.chunk);
	}

	@Test
	void kindsGivenIsCheckedAndReachesTheExecutorsParameters() {
		final SettingValues v = SparkOptions.parse("m.tif", "--kinds", "3", "--out-dir", "out").settings();
		assertEquals(3, v.parameters().kinds());
		final MoviePlan plan = new MoviePlan(0, "m.tif", "file:///m.tif", MoviePlan.ship(v), false, "", 1, 8, 8, null,
			null, null);
		assertEquals(3, plan.values().parameters().kinds(), "shipped by name and read back");
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> SparkOptions.parse("m.tif",
			"--kinds=" + (TrackerParameters.KINDS_AT_MOST + 1), "--out-dir", "out"));
		assertEquals("option --kinds: kinds must be " + TrackerParameters.KINDS_ALLOWED + ", not " +
			(TrackerParameters.KINDS_AT_MOST + 1), e.getMessage());
	}
}
