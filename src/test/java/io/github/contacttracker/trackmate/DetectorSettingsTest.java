package io.github.contacttracker.trackmate;

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

class DetectorSettingsTest {

	@Test
	void defaultsAreCompleteValidAndOfTheDeclaredTypes() {
		final Map<String, Object> d = DetectorSettings.defaults();
		assertEquals(DetectorSettings.keys(), java.util.List.copyOf(d.keySet()));
		for (final String key : DetectorSettings.keys())
			assertEquals(DetectorSettings.type(key), d.get(key).getClass(), key);
		assertNull(DetectorSettings.check(d));
		assertEquals(1, d.get(DetectorSettings.KEY_TARGET_CHANNEL));
	}

	@Test
	void mapAndParametersRoundTripForEveryMethodAndConnectivity() {
		for (final Method m : Method.values())
			for (final Connectivity c : Connectivity.values()) {
				final TrackerParameters p = new TrackerParameters(123.456789, 7.25, 13, c, 42, m);
				final Map<String, Object> map = DetectorSettings.toMap(p, 3);
				assertNull(DetectorSettings.check(map));
				assertEquals(p, DetectorSettings.parameters(map));
				assertEquals(3, DetectorSettings.targetChannel(map));
				assertEquals(m.key(), map.get(DetectorSettings.KEY_METHOD));
			}
	}

	@Test
	void checkNamesMissingNullWronglyTypedAndUnknownSettings() {
		final Map<String, Object> map = new HashMap<>(DetectorSettings.defaults());
		map.remove(DetectorSettings.KEY_R_OUT);
		map.put(DetectorSettings.KEY_MIN_AREA, null);
		map.put(DetectorSettings.KEY_THRESHOLD, 100); // Integer, not Double
		map.put(DetectorSettings.KEY_METHOD, Method.PAPER); // enum, not String
		map.put("RADIUS", 2.5);
		final String error = DetectorSettings.check(map);
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
		final Map<String, Object> map = new HashMap<>(DetectorSettings.defaults());
		map.put(DetectorSettings.KEY_R_OUT, -3.0);
		assertTrue(DetectorSettings.check(map).contains("r_out"), DetectorSettings.check(map));
		map.put(DetectorSettings.KEY_R_OUT, 5.0);
		map.put(DetectorSettings.KEY_METHOD, "bogus");
		assertTrue(DetectorSettings.check(map).contains("bogus"), DetectorSettings.check(map));
		map.put(DetectorSettings.KEY_METHOD, "first");
		map.put(DetectorSettings.KEY_CONNECTIVITY, 6);
		assertTrue(DetectorSettings.check(map).contains("connectivity"), DetectorSettings.check(map));
		map.put(DetectorSettings.KEY_CONNECTIVITY, 4);
		map.put(DetectorSettings.KEY_TARGET_CHANNEL, 0);
		assertTrue(DetectorSettings.check(map).contains("TARGET_CHANNEL"), DetectorSettings.check(map));
		assertNotNull(DetectorSettings.check(null));
	}

	@Test
	void parseReadsTheTextFormAndNamesBadText() {
		assertEquals(12.5, DetectorSettings.parse(DetectorSettings.KEY_THRESHOLD, "12.5"));
		assertEquals(8, DetectorSettings.parse(DetectorSettings.KEY_CONNECTIVITY, " 8 "));
		assertEquals("paper", DetectorSettings.parse(DetectorSettings.KEY_METHOD, "paper"));
		final IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
			() -> DetectorSettings.parse(DetectorSettings.KEY_MIN_AREA, "12.5"));
		assertTrue(e.getMessage().contains("MIN_AREA") && e.getMessage().contains("12.5"), e.getMessage());
		assertThrows(IllegalArgumentException.class, () -> DetectorSettings.type("NOPE"));
	}
}
