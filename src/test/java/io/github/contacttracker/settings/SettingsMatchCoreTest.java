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

import java.util.function.Function;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import org.junit.jupiter.api.Test;

/**
 * The descriptor's limits are the core's: at each limit and just past it, a setting ({@link Setting#check}) and
 * {@link TrackerParameters} accept and refuse the same values, with the same message where the descriptor words it
 * as the core does. The core is asked with the paper method: the profile methods' rule for r_out (above
 * {@link TrackerParameters#PROFILE_R_OUT_ABOVE}) is one of two settings together, which no single setting checks.
 */
class SettingsMatchCoreTest {

	private static TrackerParameters with(final double threshold, final double rOut, final int minArea,
		final int minSecondArea, final double diameter)
	{
		return new TrackerParameters(threshold, rOut, minArea, Connectivity.EIGHT, minSecondArea, Method.PAPER,
			diameter);
	}

	/** @return the message of the exception, or "accepted" */
	private static String outcome(final Runnable r) {
		try {
			r.run();
			return "accepted";
		}
		catch (final IllegalArgumentException e) {
			return e.getMessage();
		}
	}

	private static <V> void sameOutcome(final Setting<V> setting, final V value, final Function<V, TrackerParameters> core,
		final boolean sameWords)
	{
		final String bySetting = outcome(() -> setting.check(value));
		final String byCore = outcome(() -> core.apply(value));
		if (sameWords) assertEquals(byCore, bySetting, setting + " = " + value);
		else assertEquals(byCore.equals("accepted"), bySetting.equals("accepted"), setting + " = " + value + ": " +
			byCore + " / " + bySetting);
	}

	@Test
	void numberSettingsAcceptWhatTheCoreAccepts() {
		final double[] decimals = { Double.NEGATIVE_INFINITY, -1, -1e-9, 0, 1e-9, 1, 20, Double.POSITIVE_INFINITY,
			Double.NaN };
		for (final double v : decimals) {
			sameOutcome(TrackingSettings.THRESHOLD, v, t -> with(t, 10, 20, 50, 0), true);
			sameOutcome(TrackingSettings.R_OUT, v, r -> with(100, r, 20, 50, 0), true);
			sameOutcome(TrackingSettings.DIAMETER, v, d -> with(100, 10, 20, 50, d), false);
		}
		for (int v = -1; v <= 5; v++) {
			sameOutcome(TrackingSettings.MIN_AREA, v, a -> with(100, 10, a, 50, 0), true);
			sameOutcome(TrackingSettings.MIN_SECOND_AREA, v, a -> with(100, 10, 20, a, 0), true);
		}
		for (int v = TrackingSettings.KINDS_AT_LEAST - 2; v <= TrackerParameters.KINDS_AT_MOST + 2; v++)
			sameOutcome(TrackingSettings.KINDS, v, k -> with(100, 10, 20, 50, 0).withKinds(k), true);
	}

	@Test
	void kindsHasTheCoresLimitsAndWordsAndReachesTheCore() {
		assertEquals(TrackingSettings.KINDS_AT_LEAST, TrackingSettings.KINDS.min().intValue());
		assertEquals(TrackerParameters.KINDS_AT_MOST, TrackingSettings.KINDS.max().intValue());
		assertEquals(TrackerParameters.KINDS_ALLOWED, TrackingSettings.KINDS.allowedText());
		assertEquals("kinds must be " + TrackerParameters.KINDS_ALLOWED + ", not 5", outcome(() -> TrackingSettings.KINDS
			.parse("5")));
		assertEquals(0, TrackingSettings.KINDS.defaultValue());
		assertEquals(0, SettingValues.defaults().parameters().kinds(), "found automatically unless set");
		for (int k = TrackingSettings.KINDS_AT_LEAST; k <= TrackerParameters.KINDS_AT_MOST; k++) {
			final SettingValues v = SettingValues.defaults().withText(TrackingSettings.KINDS, String.valueOf(k));
			assertEquals(k, v.parameters().kinds());
			assertEquals(v, SettingsOf.values(v.parameters(), v.channel()), "kinds " + k + " round trip");
		}
	}

	@Test
	void theDescriptorsSmallestValuesAreTheCoresLimits() {
		assertEquals(TrackerParameters.R_OUT_ABOVE, TrackingSettings.R_OUT.min().doubleValue());
		assertEquals(TrackerParameters.MIN_AREA_AT_LEAST, TrackingSettings.MIN_AREA.min().intValue());
		assertEquals(TrackerParameters.MIN_SECOND_AREA_AT_LEAST, TrackingSettings.MIN_SECOND_AREA.min().intValue());
		assertEquals(TrackerParameters.DIAMETER_AT_LEAST, TrackingSettings.DIAMETER.min().doubleValue());
		assertEquals(null, TrackingSettings.THRESHOLD.min());
		for (final Setting<?> s : TrackingSettings.ALL)
			if (s != TrackingSettings.KINDS) assertEquals(null, s.max(), s + ": the core states no largest value");
	}
}
