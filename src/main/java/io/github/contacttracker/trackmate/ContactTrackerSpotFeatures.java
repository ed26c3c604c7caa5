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

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.swing.ImageIcon;

import org.scijava.plugin.Plugin;

import fiji.plugin.trackmate.Dimension;
import fiji.plugin.trackmate.features.spot.SpotAnalyzer;
import fiji.plugin.trackmate.features.spot.SpotAnalyzerFactory;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Declares Contact Tracker's per-spot values ({@code SIGMA_X}, {@code SIGMA_Y}, the first-pass position, the
 * areas, the number of solves and the {@code FLAG_...} columns) as TrackMate spot features.
 * <p>
 * TrackMate shows, filters, colours by and saves only the spot features its {@code FeatureModel} declares, and
 * it fills that model from the spot analyzers it discovers ({@code Settings.addAllAnalyzers()}, which its GUI
 * calls). Our detector already puts the values on each spot, so the analyzer computes nothing
 * ({@link #isManualFeature()} is {@code true}, like TrackMate's own manual features); spots from another
 * detector simply have no value for these features.
 */
@Plugin(type = SpotAnalyzerFactory.class)
public class ContactTrackerSpotFeatures<T extends RealType<T> & NativeType<T>> implements SpotAnalyzerFactory<T> {

	/**
	 * The standard errors in thousandths of a pixel, for TrackMate only: its spot table shows 3 decimals, so the
	 * calibrated {@code SIGMA_X} of a well-localized particle (a few nm) reads 0.001 um in every row, and in pixels
	 * errors of 0.003 to 0.006 px, usual on real footage, read as one digit; in thousandths of a pixel they read e.g.
	 * 4.412.
	 */
	public static final String SIGMA_X_MPX = "SIGMA_X_MPX", SIGMA_Y_MPX = "SIGMA_Y_MPX";

	/** Thousandths of a pixel per pixel. */
	public static final double MPX_PER_PX = 1000;

	/** The key of this analyzer in TrackMate. */
	public static final String KEY = "CONTACT_TRACKER_SPOT_FEATURES";

	private static final List<String> FEATURES;
	private static final Map<String, String> NAMES = new LinkedHashMap<>();
	private static final Map<String, String> SHORT_NAMES = new LinkedHashMap<>();
	private static final Map<String, Dimension> DIMENSIONS = new LinkedHashMap<>();
	private static final Map<String, Boolean> IS_INT = new LinkedHashMap<>();

	static {
		final List<String> features = new ArrayList<>();
		for (final SpotColumn c : SpotColumn.values()) {
			if (c.isTrackMateKey()) continue;
			features.add(c.key());
			NAMES.put(c.key(), c.title());
			SHORT_NAMES.put(c.key(), c.shortName());
			DIMENSIONS.put(c.key(), Dimension.valueOf(c.dimension().name()));
			IS_INT.put(c.key(), c.isInteger());
			if (c == SpotColumn.SIGMA_Y) for (final String px : List.of(SIGMA_X_MPX, SIGMA_Y_MPX)) {
				features.add(px);
				final String axis = px.equals(SIGMA_X_MPX) ? "X" : "Y";
				NAMES.put(px, "Standard error of " + axis + " (1/1000 px)");
				SHORT_NAMES.put(px, "SE " + axis + " (1/1000 px)");
				DIMENSIONS.put(px, Dimension.NONE);
				IS_INT.put(px, false);
			}
		}
		FEATURES = Collections.unmodifiableList(features);
	}

	/** The values are already on the spots; nothing to compute. */
	private static final SpotAnalyzer<?> NOTHING_TO_COMPUTE = spots -> {};

	@SuppressWarnings("unchecked")
	@Override
	public SpotAnalyzer<T> getAnalyzer(final ImgPlus<T> img, final int frame, final int channel) {
		return (SpotAnalyzer<T>) NOTHING_TO_COMPUTE;
	}

	@Override
	public void setNChannels(final int nChannels) {
		// one set of features whatever the number of channels: the detector works on its target channel
	}

	@Override
	public List<String> getFeatures() {
		return FEATURES;
	}

	@Override
	public Map<String, String> getFeatureShortNames() {
		return Collections.unmodifiableMap(SHORT_NAMES);
	}

	@Override
	public Map<String, String> getFeatureNames() {
		return Collections.unmodifiableMap(NAMES);
	}

	@Override
	public Map<String, Dimension> getFeatureDimensions() {
		return Collections.unmodifiableMap(DIMENSIONS);
	}

	@Override
	public Map<String, Boolean> getIsIntFeature() {
		return Collections.unmodifiableMap(IS_INT);
	}

	@Override
	public boolean isManualFeature() {
		return true;
	}

	@Override
	public String getInfoText() {
		return "<html>Contact Tracker's per-spot values (standard errors, first-pass position, areas, flags), "
			+ "set by the Contact Tracker detector.</html>";
	}

	@Override
	public ImageIcon getIcon() {
		return null;
	}

	@Override
	public String getKey() {
		return KEY;
	}

	@Override
	public String getName() {
		return "Contact Tracker spot values";
	}

	@Override
	public boolean forbidMultithreading() {
		return false;
	}

	@Override
	public String getUrl() {
		return ContactTrackerDetectorFactory.URL;
	}
}
