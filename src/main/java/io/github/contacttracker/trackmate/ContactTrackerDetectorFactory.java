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

import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.TrackMateSettings;
import io.github.contacttracker.settings.TrackingSettings;
import java.util.Map;

import javax.swing.ImageIcon;

import org.jdom2.Attribute;
import org.jdom2.Element;
import org.scijava.plugin.Plugin;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;
import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import fiji.plugin.trackmate.detection.SpotGlobalDetectorFactory;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import net.imagej.ImgPlus;
import net.imglib2.Interval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * The Contact Tracker detector for TrackMate 8.0.0 to 8.1.x, a
 * {@code fiji.plugin.trackmate.detection.SpotGlobalDetectorFactory}: TrackMate hands it the whole movie at once,
 * so the profile methods measure the particles' profile over the movie exactly as the command line does, and
 * TrackMate's spots equal the command line's. Discovered by SciJava through {@link Plugin}, keyed
 * {@value #DETECTOR_KEY}; its spot features are declared by {@link ContactTrackerSpotFeatures}.
 * <p>
 * TrackMate instantiates it through the public no-argument constructor; it keeps no state. Every method of
 * TrackMate's module and factory interfaces is implemented here (except {@code copy()}), so the class links
 * against TrackMate whether a given 8.x release declares a method abstract or default. Settings: see
 * {@link TrackMateSettings}.
 */
// Registered under the type TrackMate's DetectorProvider asks SciJava for, so it is found by exact type.
@Plugin(type = SpotDetectorFactoryBase.class)
public class ContactTrackerDetectorFactory<T extends RealType<T> & NativeType<T>> implements SpotGlobalDetectorFactory<T> {

	/** The key of this detector in TrackMate (settings maps, XML files, scripts). */
	public static final String DETECTOR_KEY = TrackMateSettings.DETECTOR_KEY;

	public static final String NAME = "Contact Tracker (particles near contact)";

	/** The name on the configuration panel's title line. */
	static final String SHORT_NAME = "Contact Tracker detector";

	/** The detector's icon (two touching particles), shown in TrackMate's detector list and panel. */
	static final ImageIcon ICON = ContactTrackerConfigurationPanel.icon();

	/** The paper the method comes from (its DOI page). */
	public static final String URL = "https://doi.org/10.1088/1361-648X/aa908e";

	public static final String INFO_TEXT = "<html>"
		+ "Sub-pixel centres of bright colloidal particles, also when they touch and their images overlap "
		+ "(Y&uuml;cel &amp; Okumu&#351;o&#287;lu, J. Phys.: Condens. Matter 29, 465101, 2017)."
		+ "<p>"
		+ "Pixels at or above GREY_THRESHOLD (a grey level) form one active area per particle. Each centre is found by "
		+ "radial symmetry, then refined away from its neighbours, whose images reach R_OUT pixels. The default "
		+ "method, fit, fits touching particles jointly with their profile measured over the movie: unbiased at "
		+ "contact.</p>"
		+ "<p>"
		+ "Spots: RADIUS is half the particle diameter if given (DIAMETER), else the active area's equivalent "
		+ "radius; QUALITY how clearly it stands out of the noise "
		+ "(0 to 1; particles 1); SIGMA_X/Y the standard errors; FLAG_... what happened. 2D images and "
		+ "time-lapses only.</p>"
		+ "<p>"
		+ "A colour (RGB) movie, e.g. an AVI, is refused by TrackMate itself: convert it first with "
		+ "<i>Image &gt; Type &gt; 8-bit</i> (Contact Tracker's own command takes one colour channel instead).</p>"
		+ "</html>";

	/**
	 * @param img the whole image (every channel and frame)
	 * @param settings the detector settings ({@link TrackMateSettings})
	 * @param interval what to analyse: X, Y, Z and time, no channel axis (TrackMate's
	 *        {@code TMUtils.getIntervalWithTime}); {@code null} for the whole movie
	 */
	@Override
	public SpotGlobalDetector<T> getDetector(final ImgPlus<T> img, final Map<String, Object> settings,
		final Interval interval)
	{
		return new ContactTrackerDetector<>(img, interval, settings);
	}

	@Override
	public ConfigurationPanel getDetectorConfigurationPanel(final Settings settings, final Model model) {
		return new ContactTrackerConfigurationPanel(settings, model, this);
	}

	/**
	 * The settings last used in this Fiji session (the documented defaults until then), so that they survive a
	 * detector switch in TrackMate's wizard ({@link LastSettings}).
	 */
	@Override
	public Map<String, Object> getDefaultSettings() {
		return LastSettings.get();
	}

	@Override
	public String checkSettings(final Map<String, Object> settings) {
		return TrackMateSettings.check(settings);
	}

	/**
	 * Writes the settings as attributes of {@code element}: {@code DETECTOR_NAME} and one attribute per key, in
	 * {@link TrackMateSettings#keys()} order, with {@code toString()} of the value; a key the map may lack (a map of
	 * an earlier version, without {@code KINDS}) is written with its default.
	 */
	@Override
	public String marshal(final Map<String, Object> settings, final Element element) {
		final String error = checkSettings(settings);
		if (error != null) return error;
		final Map<String, Object> complete = TrackMateSettings.complete(settings);
		element.setAttribute(TrackMateSettings.XML_ATTRIBUTE_DETECTOR_NAME, DETECTOR_KEY);
		for (final String key : TrackMateSettings.keys())
			element.setAttribute(key, complete.get(key).toString());
		return null;
	}

	/**
	 * Reads settings written by {@link #marshal}. {@code settings} is cleared and filled with the defaults first,
	 * so a file from an older version that lacks a newer key still loads (a setting added since means what that
	 * version tracked with, {@link Setting#absentInMaps()}), and its {@code THRESHOLD} is read as
	 * {@code GREY_THRESHOLD}; unknown attributes and unreadable values are errors.
	 */
	@Override
	public String unmarshal(final Element element, final Map<String, Object> settings) {
		settings.clear();
		settings.putAll(TrackMateSettings.defaults()); // a file means what it says: the documented defaults
		for (final Attribute att : element.getAttributes()) {
			String key = att.getName();
			if (TrackMateSettings.XML_ATTRIBUTE_DETECTOR_NAME.equals(key) || "TRACKER_NAME".equals(key)) continue;
			// files of earlier versions, whose threshold key was TrackMate's THRESHOLD (a new key wins)
			if (TrackMateSettings.OLD_KEY_THRESHOLD.equals(key)) {
				if (element.getAttribute(TrackMateSettings.KEY_THRESHOLD) != null) continue;
				key = TrackMateSettings.KEY_THRESHOLD;
			}
			if (!TrackMateSettings.keys().contains(key))
				return "When unmarshalling " + NAME + " settings: unknown parameter " + key + ".";
			try {
				settings.put(key, TrackMateSettings.parse(key, att.getValue()));
			}
			catch (final IllegalArgumentException e) {
				return "When unmarshalling " + NAME + " settings: " + e.getMessage() + ".";
			}
		}
		// a setting added since the file was written means what that version tracked with
		for (final Setting<?> s : TrackingSettings.ALL)
			if (s.isOptionalInMaps() && element.getAttribute(s.trackMateKey()) == null) settings.put(s.trackMateKey(), s
				.absentInMaps());
		return checkSettings(settings);
	}

	@Override
	public String toString(final Map<String, Object> settings) {
		final String error = checkSettings(settings);
		return error != null ? error : TrackMateSettings.echo(TrackMateSettings.complete(settings));
	}

	@Override
	public boolean has2Dsegmentation() {
		return false;
	}

	/**
	 * Declared by some TrackMate releases (7.12+) next to {@link #has2Dsegmentation()}; implemented here so the
	 * class links whichever way a release declares it. No meshes: Contact Tracker is 2D.
	 */
	public boolean has3Dsegmentation() {
		return false;
	}

	@Override
	public String getInfoText() {
		return INFO_TEXT;
	}

	@Override
	public ImageIcon getIcon() {
		return ICON;
	}

	@Override
	public String getKey() {
		return DETECTOR_KEY;
	}

	@Override
	public String getName() {
		return NAME;
	}

	@Override
	public boolean forbidMultithreading() {
		return false;
	}

	@Override
	public String getUrl() {
		return URL;
	}

	@Override
	public String toString() {
		return NAME;
	}
}
