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
package io.github.contacttracker.trackmate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;

import fiji.plugin.trackmate.Dimension;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import net.imglib2.type.numeric.real.FloatType;

/**
 * What TrackMate's spot table shows of our features. TrackMate 8 heads each column with the feature's short name
 * and, under it, the unit its {@code TMUtils.getUnitsFor} gives the feature's dimension: the image's spatial unit
 * for {@code POSITION} and {@code LENGTH}, nothing at all (no brackets) for {@code NONE}, as under its own
 * {@code FRAME} and {@code VISIBILITY}. TrackMate is not on our class path, so the unit a column shows is checked
 * through {@link SpotColumn#unit}, which gives the image's unit for those two dimensions too, and our dimensions are
 * held to those two and {@code NONE}; a value in pixels, which no TrackMate dimension describes, names its unit in
 * its names.
 */
class ContactTrackerSpotFeaturesTest {

	private static final ContactTrackerSpotFeatures<FloatType> FEATURES = new ContactTrackerSpotFeatures<>();

	/** Values that are counts or codes, with no unit: the flags, the number of solves, the kind. */
	private static boolean isUnitless(final String key) {
		return key.startsWith("FLAG_") || key.equals(SpotColumn.ITERATIONS.key()) || key.equals(SpotColumn.KIND
			.key());
	}

	@Test
	void theKeysSavedTrackMateFilesHoldAreUnchanged() {
		assertEquals(List.of("FIRST_PASS_X", "FIRST_PASS_Y", "SIGMA_X", "SIGMA_Y", "SIGMA_X_MPX", "SIGMA_Y_MPX",
			"ACTIVE_AREA", "ACTIVE_RADIUS", "SECOND_AREA", "ITERATIONS", "FLAG_SECOND_PASS", "FLAG_FELL_BACK",
			"FLAG_DEGENERATE", "FLAG_AT_BORDER", "FLAG_MERGED", "FLAG_NOT_CONVERGED", "FLAG_UNMODELLED_NEIGHBOUR", "KIND"),
			FEATURES.getFeatures());
	}

	@Test
	void everyFeatureHasANameAShortNameADimensionAndAType() {
		final Set<String> shortNames = new HashSet<>();
		for (final String key : FEATURES.getFeatures()) {
			final String name = FEATURES.getFeatureNames().get(key);
			final String shortName = FEATURES.getFeatureShortNames().get(key);
			assertNotNull(name, key);
			assertFalse(name.isBlank(), key);
			assertNotNull(shortName, key);
			assertFalse(shortName.isBlank(), key);
			assertFalse(shortName.equals(key), key + ": a short name a person reads, not the key");
			assertTrue(shortNames.add(shortName), key + ": short name '" + shortName + "' heads another column too");
			assertNotNull(FEATURES.getFeatureDimensions().get(key), key);
			assertNotNull(FEATURES.getIsIntFeature().get(key), key);
		}
	}

	@Test
	void everyColumnWithAUnitShowsIt() {
		final Calibration cal = new Calibration(0.0847, 0.0847, "micron", 0.5, "sec");
		final Map<String, Dimension> dimensions = FEATURES.getFeatureDimensions();
		for (final String key : FEATURES.getFeatures()) {
			final Dimension d = dimensions.get(key);
			final String shortName = FEATURES.getFeatureShortNames().get(key);
			if (d != Dimension.NONE) {
				assertTrue(d == Dimension.POSITION || d == Dimension.LENGTH, key + ": " + d
					+ " is not a dimension whose unit comes from the image's calibration");
				final String unit = SpotColumn.valueOf(key).unit(cal);
				assertFalse(unit.isBlank(), key + " shows an empty unit");
				assertEquals(cal.unit(), unit, key);
				assertFalse(shortName.contains("("), key + ": the unit line gives the unit, not the name");
			}
			else if (isUnitless(key)) assertTrue(FEATURES.getIsIntFeature().get(key), key + " is a count or code");
			else assertTrue(shortName.endsWith(" px)") || shortName.endsWith("(px)"), key + " ('" + shortName
				+ "') is in pixels, which TrackMate's unit line cannot say: its name must");
		}
	}

	@Test
	void theStandardErrorsInPixelsSayTheirUnit() {
		assertEquals("SE X (1/1000 px)", FEATURES.getFeatureShortNames().get(ContactTrackerSpotFeatures.SIGMA_X_MPX));
		assertEquals(Dimension.NONE, FEATURES.getFeatureDimensions().get(ContactTrackerSpotFeatures.SIGMA_X_MPX));
		assertEquals(Dimension.LENGTH, FEATURES.getFeatureDimensions().get(SpotColumn.SIGMA_X.key()));
		assertEquals(Dimension.POSITION, FEATURES.getFeatureDimensions().get(SpotColumn.FIRST_PASS_X.key()));
	}
}
