package io.github.contacttracker.trackmate;

import java.util.Map;

import javax.swing.ImageIcon;

import org.jdom2.Attribute;
import org.jdom2.Element;
import org.scijava.plugin.Plugin;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetector;
import fiji.plugin.trackmate.detection.SpotDetectorFactory;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import net.imagej.ImgPlus;
import net.imglib2.Interval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * The Contact Tracker detector for TrackMate 8 ({@code fiji.plugin.trackmate.detection.SpotDetectorFactory}),
 * discovered by SciJava through {@link Plugin} and keyed {@value #DETECTOR_KEY}.
 * <p>
 * TrackMate instantiates it through the public no-argument constructor; it keeps no state. Every method of
 * TrackMate's module and factory interfaces is implemented here (except {@code copy()}), so the class links
 * against TrackMate whether a given 8.x release declares a method abstract or default. Settings: see
 * {@link DetectorSettings}.
 */
@Plugin(type = SpotDetectorFactory.class)
public class ContactTrackerDetectorFactory<T extends RealType<T> & NativeType<T>> implements SpotDetectorFactory<T> {

	/** The key of this detector in TrackMate (settings maps, XML files, scripts). */
	public static final String DETECTOR_KEY = DetectorSettings.DETECTOR_KEY;

	public static final String NAME = "Contact Tracker (particles near contact)";

	public static final String KEY_TARGET_CHANNEL = DetectorSettings.KEY_TARGET_CHANNEL;
	public static final String KEY_THRESHOLD = DetectorSettings.KEY_THRESHOLD;
	public static final String KEY_R_OUT = DetectorSettings.KEY_R_OUT;
	public static final String KEY_MIN_AREA = DetectorSettings.KEY_MIN_AREA;
	public static final String KEY_MIN_SECOND_AREA = DetectorSettings.KEY_MIN_SECOND_AREA;
	public static final String KEY_CONNECTIVITY = DetectorSettings.KEY_CONNECTIVITY;
	public static final String KEY_METHOD = DetectorSettings.KEY_METHOD;

	/** Project page. */
	public static final String URL = "https://github.com/contact-tracker/contact-tracker";

	public static final String INFO_TEXT = "<html>"
		+ "Sub-pixel localization of bright colloidal particles, including particles close to contact whose "
		+ "images overlap, with the radial-symmetry method of Y&uuml;cel and Okumu&#351;o&#287;lu."
		+ "<p>"
		+ "Pixels at or above THRESHOLD (a grey level) form active areas, one per particle; areas smaller than "
		+ "MIN_AREA pixels are noise. Each particle's centre is where its intensity-gradient lines meet. "
		+ "With the <i>paper</i> method, the centre is computed again on the active area outside the other "
		+ "particles' discs of radius R_OUT (pixels), which removes most of the bias from overlapping "
		+ "neighbours.</p>"
		+ "<p>"
		+ "Spots: RADIUS is the equivalent radius of the active area, sqrt(area/&pi;); QUALITY is the "
		+ "integrated intensity above THRESHOLD over the active area. 2D images and 2D time-lapses only.</p>"
		+ "<p>"
		+ "If you use it, please cite: H. Y&uuml;cel and N. T. Okumu&#351;o&#287;lu, <i>A new tracking algorithm "
		+ "for multiple colloidal particles close to contact</i>, J. Phys.: Condens. Matter <b>29</b>, 465101 "
		+ "(2017), doi:10.1088/1361-648X/aa908e.</p>"
		+ "</html>";

	@Override
	public SpotDetector<T> getDetector(final ImgPlus<T> img, final Map<String, Object> settings,
		final Interval interval, final int frame)
	{
		return new ContactTrackerDetector<>(img, interval, frame, settings);
	}

	@Override
	public ConfigurationPanel getDetectorConfigurationPanel(final Settings settings, final Model model) {
		final int channels = settings == null || settings.imp == null ? 1 : Math.max(1, settings.imp.getNChannels());
		return new ContactTrackerConfigurationPanel(channels, settings == null ? null : settings.imp);
	}

	@Override
	public Map<String, Object> getDefaultSettings() {
		return DetectorSettings.defaults();
	}

	@Override
	public String checkSettings(final Map<String, Object> settings) {
		return DetectorSettings.check(settings);
	}

	/**
	 * Writes the settings as attributes of {@code element}: {@code DETECTOR_NAME} and one attribute per key, in
	 * {@link DetectorSettings#keys()} order, with {@code toString()} of the value.
	 */
	@Override
	public String marshal(final Map<String, Object> settings, final Element element) {
		final String error = checkSettings(settings);
		if (error != null) return error;
		element.setAttribute(DetectorSettings.XML_ATTRIBUTE_DETECTOR_NAME, DETECTOR_KEY);
		for (final String key : DetectorSettings.keys())
			element.setAttribute(key, settings.get(key).toString());
		return null;
	}

	/**
	 * Reads settings written by {@link #marshal}. {@code settings} is cleared and filled with the defaults first,
	 * so a file from an older version that lacks a newer key still loads; unknown attributes and unreadable
	 * values are errors.
	 */
	@Override
	public String unmarshal(final Element element, final Map<String, Object> settings) {
		settings.clear();
		settings.putAll(getDefaultSettings());
		for (final Attribute att : element.getAttributes()) {
			final String key = att.getName();
			if (DetectorSettings.XML_ATTRIBUTE_DETECTOR_NAME.equals(key) || "TRACKER_NAME".equals(key)) continue;
			if (!DetectorSettings.keys().contains(key))
				return "When unmarshalling " + NAME + " settings: unknown parameter " + key + ".";
			try {
				settings.put(key, DetectorSettings.parse(key, att.getValue()));
			}
			catch (final IllegalArgumentException e) {
				return "When unmarshalling " + NAME + " settings: " + e.getMessage() + ".";
			}
		}
		return checkSettings(settings);
	}

	@Override
	public String toString(final Map<String, Object> settings) {
		final String error = checkSettings(settings);
		return error != null ? error : DetectorSettings.echo(settings);
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
		return null;
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
