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

import io.github.contacttracker.settings.TrackMateSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;

class TrackMateSettingsTest {

	@Test
	void defaultsAreCompleteValidAndOfTheDeclaredTypes() {
		final Map<String, Object> d = TrackMateSettings.defaults();
		assertEquals(TrackMateSettings.keys(), java.util.List.copyOf(d.keySet()));
		for (final String key : TrackMateSettings.keys())
			assertEquals(TrackMateSettings.type(key), d.get(key).getClass(), key);
		assertNull(TrackMateSettings.check(d));
		assertEquals(1, d.get(TrackMateSettings.KEY_TARGET_CHANNEL));
	}

	@Test
	void mapAndParametersRoundTripForEveryMethodAndConnectivity() {
		for (final Method m : Method.values())
			for (final Connectivity c : Connectivity.values()) {
				final TrackerParameters p = new TrackerParameters(123.456789, 7.25, 13, c, 42, m);
				final Map<String, Object> map = SettingsOf.map(p, 3);
				assertNull(TrackMateSettings.check(map));
				assertEquals(p, TrackMateSettings.parameters(map));
				assertEquals(3, TrackMateSettings.targetChannel(map));
				assertEquals(m.key(), map.get(TrackMateSettings.KEY_METHOD));
			}
	}

	@Test
	void kindsRoundTripsThroughTheMapIntoTheParameters() {
		assertEquals("KINDS", TrackMateSettings.KEY_KINDS);
		assertEquals(0, TrackMateSettings.defaults().get(TrackMateSettings.KEY_KINDS));
		for (int k = 0; k <= TrackerParameters.KINDS_AT_MOST; k++) {
			final TrackerParameters p = TrackerParameters.of(100, 20).withKinds(k);
			final Map<String, Object> map = SettingsOf.map(p, 1);
			assertEquals(k, map.get(TrackMateSettings.KEY_KINDS));
			assertEquals(p, TrackMateSettings.parameters(map));
		}
		assertEquals(3, TrackMateSettings.parse(TrackMateSettings.KEY_KINDS, "3"));
	}

	/**
	 * A map of the version before KINDS (a script's, exactly the keys it documented) still checks and means kinds
	 * found automatically; KINDS given but null, mistyped or out of range is named as every other setting is.
	 */
	@Test
	void aMapWithoutKindsFromAnEarlierVersionMeansKindsFoundAutomatically() {
		final Map<String, Object> older = new HashMap<>(Map.of("TARGET_CHANNEL", 2, "GREY_THRESHOLD", 85.0, "R_OUT",
			61.0, "MIN_AREA", 20, "MIN_SECOND_AREA", 50, "CONNECTIVITY", 8, "METHOD", "deblend", "DIAMETER", 65.3));
		assertNull(TrackMateSettings.check(older));
		final TrackerParameters p = TrackMateSettings.parameters(older);
		assertEquals(0, p.kinds());
		assertEquals(Method.DEBLEND, p.method());
		assertEquals(65.3, p.diameter());
		assertEquals(2, TrackMateSettings.targetChannel(older));
		final Map<String, Object> complete = TrackMateSettings.complete(older);
		assertEquals(TrackMateSettings.keys(), java.util.List.copyOf(complete.keySet()));
		assertEquals(0, complete.get(TrackMateSettings.KEY_KINDS));
		assertEquals(8, older.size(), "the map given is left as it was");

		older.put(TrackMateSettings.KEY_KINDS, null);
		assertTrue(TrackMateSettings.check(older).contains("The value of KINDS is null"), TrackMateSettings.check(older));
		older.put(TrackMateSettings.KEY_KINDS, 2.0);
		assertTrue(TrackMateSettings.check(older).contains("KINDS must be an Integer"), TrackMateSettings.check(older));
		older.put(TrackMateSettings.KEY_KINDS, TrackerParameters.KINDS_AT_MOST + 1);
		assertEquals("Invalid setting KINDS: kinds must be " + TrackerParameters.KINDS_ALLOWED + ", not " +
			(TrackerParameters.KINDS_AT_MOST + 1) + ".", TrackMateSettings.check(older));
		older.put(TrackMateSettings.KEY_KINDS, 2);
		assertEquals(2, TrackMateSettings.parameters(older).kinds());
	}

	@Test
	void checkNamesMissingNullWronglyTypedAndUnknownSettings() {
		final Map<String, Object> map = new HashMap<>(TrackMateSettings.defaults());
		map.remove(TrackMateSettings.KEY_R_OUT);
		map.put(TrackMateSettings.KEY_MIN_AREA, null);
		map.put(TrackMateSettings.KEY_THRESHOLD, 100); // Integer, not Double
		map.put(TrackMateSettings.KEY_METHOD, Method.PAPER); // enum, not String
		map.put("RADIUS", 2.5);
		final String error = TrackMateSettings.check(map);
		assertNotNull(error);
		assertTrue(error.contains("Missing setting R_OUT"), error);
		assertTrue(error.contains("MIN_AREA is null"), error);
		assertTrue(error.contains("THRESHOLD must be a Double, not the Integer '100'"), error);
		assertTrue(error.contains("METHOD must be a String"), error);
		assertTrue(error.contains("Unknown setting RADIUS"), error);
		assertEquals(5, error.split("\n").length, error);
	}

	@Test
	void checkNamesInvalidValues() {
		final Map<String, Object> map = new HashMap<>(TrackMateSettings.defaults());
		map.put(TrackMateSettings.KEY_R_OUT, -3.0);
		assertTrue(TrackMateSettings.check(map).contains("r_out"), TrackMateSettings.check(map));
		map.put(TrackMateSettings.KEY_R_OUT, 5.0);
		map.put(TrackMateSettings.KEY_METHOD, "bogus");
		assertTrue(TrackMateSettings.check(map).contains("bogus"), TrackMateSettings.check(map));
		map.put(TrackMateSettings.KEY_METHOD, "first");
		map.put(TrackMateSettings.KEY_CONNECTIVITY, 6);
		assertTrue(TrackMateSettings.check(map).contains("connectivity"), TrackMateSettings.check(map));
		map.put(TrackMateSettings.KEY_CONNECTIVITY, 4);
		map.put(TrackMateSettings.KEY_TARGET_CHANNEL, 0);
		assertTrue(TrackMateSettings.check(map).contains("TARGET_CHANNEL"), TrackMateSettings.check(map));
		assertNotNull(TrackMateSettings.check(null));
	}

	@Test
	void parseReadsTheTextFormAndNamesBadText() {
		assertEquals(12.5, TrackMateSettings.parse(TrackMateSettings.KEY_THRESHOLD, "12.5"));
		assertEquals(8, TrackMateSettings.parse(TrackMateSettings.KEY_CONNECTIVITY, " 8 "));
		assertEquals("paper", TrackMateSettings.parse(TrackMateSettings.KEY_METHOD, "paper"));
		final IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
			() -> TrackMateSettings.parse(TrackMateSettings.KEY_MIN_AREA, "12.5"));
		assertTrue(e.getMessage().contains("MIN_AREA") && e.getMessage().contains("12.5"), e.getMessage());
		assertThrows(IllegalArgumentException.class, () -> TrackMateSettings.type("NOPE"));
	}
}
