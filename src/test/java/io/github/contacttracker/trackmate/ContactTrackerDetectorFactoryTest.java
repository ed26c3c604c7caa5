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

import io.github.contacttracker.settings.TrackMateSettings;
import io.github.contacttracker.settings.TrackingSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JSpinner;

import org.jdom2.Element;
import org.junit.jupiter.api.Test;
import org.scijava.Context;
import org.scijava.plugin.PluginInfo;
import org.scijava.plugin.PluginService;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;
import fiji.plugin.trackmate.detection.SpotGlobalDetectorFactory;
import fiji.plugin.trackmate.features.spot.SpotAnalyzerFactory;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import ij.IJ;
import ij.ImagePlus;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.TrackMateXmlWriter;
import net.imglib2.type.numeric.real.FloatType;
import io.github.contacttracker.settings.SettingsOf;

class ContactTrackerDetectorFactoryTest {

	private final ContactTrackerDetectorFactory<FloatType> factory = new ContactTrackerDetectorFactory<>();

	/** Each test starts from the documented defaults, not the values another test's panel left. */
	@org.junit.jupiter.api.BeforeEach
	void freshSession() {
		LastSettings.forget();
	}

	@Test
	void identityAndInfoText() {
		assertEquals("CONTACT_TRACKER_DETECTOR", factory.getKey());
		assertFalse(factory.getName().isBlank());
		final String info = factory.getInfoText();
		assertTrue(info.startsWith("<html>") && info.endsWith("</html>"));
		assertTrue(info.contains("465101"), "must cite the paper");
		assertTrue(info.contains("RADIUS") && info.contains("QUALITY"), "must document radius and quality");
		assertNotNull(factory.getIcon());
		// as wide as TrackMate's own detector icons (64 x 64): the names in its detector list line up
		assertEquals(64, factory.getIcon().getIconWidth());
		assertEquals(64, factory.getIcon().getIconHeight());
		assertFalse(factory.forbidMultithreading());
		assertFalse(factory.has2Dsegmentation());
		assertFalse(factory.has3Dsegmentation());
		assertEquals("https://doi.org/10.1088/1361-648X/aa908e", factory.getUrl(), "a link that exists: the paper");
	}

	@Test
	void defaultSettingsHoldTheDocumentedKeysAndPassTheCheck() {
		final Map<String, Object> d = factory.getDefaultSettings();
		for (final String key : List.of("TARGET_CHANNEL", "GREY_THRESHOLD", "R_OUT", "MIN_AREA", "METHOD"))
			assertTrue(d.containsKey(key), key);
		assertEquals(Integer.class, d.get("TARGET_CHANNEL").getClass());
		assertEquals(Double.class, d.get("GREY_THRESHOLD").getClass());
		assertFalse(d.containsKey("THRESHOLD"), "LoG and DoG use THRESHOLD for a quality cut-off");
		assertEquals(Double.class, d.get("R_OUT").getClass());
		assertEquals(Integer.class, d.get("MIN_AREA").getClass());
		assertNull(factory.checkSettings(d));
		assertTrue(factory.toString(d).contains("R_OUT = "));
	}

	/** Marshal then unmarshal, as TrackMate does when it saves and re-opens a session. */
	private Map<String, Object> roundTrip(final Map<String, Object> settings) {
		final Element element = new Element("DetectorSettings");
		assertNull(factory.marshal(settings, element));
		assertEquals(factory.getKey(), element.getAttributeValue("DETECTOR_NAME"));
		final Map<String, Object> back = new HashMap<>();
		back.put("LEFTOVER", "must be cleared");
		assertNull(factory.unmarshal(element, back));
		return back;
	}

	@Test
	void settingsSurviveMarshalAndUnmarshal() {
		assertEquals(factory.getDefaultSettings(), roundTrip(factory.getDefaultSettings()));
		for (final Method m : Method.values()) {
			final Map<String, Object> s = SettingsOf.map(new TrackerParameters(0.1 + 1e-13, 12.345678901234, 7,
				Connectivity.FOUR, 31, m), 2);
			final Map<String, Object> back = roundTrip(s);
			assertEquals(s, back);
			for (final String key : s.keySet())
				assertEquals(s.get(key).getClass(), back.get(key).getClass(), key);
		}
	}

	@Test
	void unmarshalNamesUnknownAndUnreadableAttributesAndFillsMissingOnesWithDefaults() {
		final Element unknown = new Element("DetectorSettings").setAttribute("DETECTOR_NAME", factory.getKey())
			.setAttribute("RADIUS", "2.5");
		String error = factory.unmarshal(unknown, new HashMap<>());
		assertNotNull(error);
		assertTrue(error.contains("RADIUS"), error);

		final Element unreadable = new Element("DetectorSettings").setAttribute("R_OUT", "ten");
		error = factory.unmarshal(unreadable, new HashMap<>());
		assertTrue(error.contains("R_OUT") && error.contains("ten"), error);

		final Element invalid = new Element("DetectorSettings").setAttribute("METHOD", "bogus");
		error = factory.unmarshal(invalid, new HashMap<>());
		assertTrue(error.contains("bogus"), error);

		final Element older = new Element("DetectorSettings").setAttribute("THRESHOLD", "55.5");
		final Map<String, Object> map = new HashMap<>();
		assertNull(factory.unmarshal(older, map));
		assertEquals(55.5, map.get("GREY_THRESHOLD"), "an earlier file's THRESHOLD is read");
		assertFalse(map.containsKey("THRESHOLD"));
		assertEquals(factory.getDefaultSettings().get("METHOD"), map.get("METHOD"));
	}

	/** The settings of the version before KINDS: every key then written, in a file or in a script's map. */
	private static Map<String, Object> olderSettings() {
		final Map<String, Object> older = new HashMap<>(Map.of("TARGET_CHANNEL", 1, "GREY_THRESHOLD", 85.0, "R_OUT",
			61.0, "MIN_AREA", 20, "MIN_SECOND_AREA", 50, "CONNECTIVITY", 4, "METHOD", "deblend", "DIAMETER", 65.3));
		assertFalse(older.containsKey(TrackMateSettings.KEY_KINDS));
		return older;
	}

	/**
	 * A session saved by the version before KINDS (every other attribute, no KINDS) loads with kinds found
	 * automatically, and is saved again with KINDS; so does a script's map of that version.
	 */
	@Test
	void settingsOfAnEarlierVersionWithoutKindsLoadWithKindsFoundAutomatically() {
		final Element older = new Element("DetectorSettings").setAttribute("DETECTOR_NAME", factory.getKey());
		olderSettings().forEach((k, v) -> older.setAttribute(k, v.toString()));
		final Map<String, Object> map = new HashMap<>();
		assertNull(factory.unmarshal(older, map));
		assertEquals(0, map.get("KINDS"));
		final Map<String, Object> expected = new HashMap<>(olderSettings());
		expected.put("KINDS", 0);
		expected.put("PARTICLES", "bright"); // added later still: bright, as every earlier version tracked
		expected.put("DETECTION", "threshold"); // and later: by the threshold, as every earlier version found them
		assertEquals(expected, map);
		assertEquals(0, TrackMateSettings.parameters(map).kinds());

		// a script's map of that version: checked, saved with KINDS = 0, described with it
		final Map<String, Object> script = olderSettings();
		assertNull(factory.checkSettings(script));
		final Element saved = new Element("DetectorSettings");
		assertNull(factory.marshal(script, saved));
		assertEquals("0", saved.getAttributeValue("KINDS"));
		assertEquals("bright", saved.getAttributeValue("PARTICLES"));
		assertTrue(factory.toString(script).contains("KINDS = 0"), factory.toString(script));
		assertEquals(expected, roundTrip(script));
	}

	@Test
	void kindsSurvivesMarshalAndUnmarshal() {
		for (int k = 0; k <= TrackerParameters.KINDS_AT_MOST; k++) {
			final Map<String, Object> s = SettingsOf.map(TrackerParameters.of(90, 30).withKinds(k), 1);
			assertEquals(s, roundTrip(s));
			assertEquals(k, TrackMateSettings.parameters(roundTrip(s)).kinds());
		}
		final Element invalid = new Element("DetectorSettings").setAttribute("KINDS", "5");
		final String error = factory.unmarshal(invalid, new HashMap<>());
		assertTrue(error.contains("KINDS") && error.contains("kinds must be " + TrackerParameters.KINDS_ALLOWED), error);
	}

	/**
	 * The panel's field of KINDS spins from 0 to the core's largest number; a map without KINDS (an earlier
	 * version's) shows 0, not the value last used, which a key the map holds as null shows.
	 */
	@Test
	void panelAsksKindsWithinTheCoresLimits() {
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(), new Model());
		final JSpinner kinds = allComponents(panel).stream().filter(c -> c instanceof JSpinner && TrackingSettings.KINDS
			.help().equals(((JSpinner) c).getToolTipText())).map(c -> (JSpinner) c).findFirst().orElse(null);
		assertNotNull(kinds, "no field for kinds");
		final javax.swing.SpinnerNumberModel model = (javax.swing.SpinnerNumberModel) kinds.getModel();
		assertEquals(0, model.getMinimum());
		assertEquals(TrackerParameters.KINDS_AT_MOST, model.getMaximum());

		final Map<String, Object> three = TrackMateSettings.defaults();
		three.put("KINDS", 3);
		three.put("METHOD", "paper");
		panel.setSettings(three);
		assertEquals(three, panel.getSettings()); // now the values last used
		assertEquals(3, kinds.getValue());

		final Map<String, Object> older = olderSettings();
		older.put("METHOD", null);
		panel.setSettings(older);
		assertEquals(0, panel.getSettings().get("KINDS"), "absent: the default");
		assertEquals("paper", panel.getSettings().get("METHOD"), "null: the value last used");
		assertEquals(65.3, panel.getSettings().get("DIAMETER"));
	}

	/** TrackMate's XML reader hands our file's {@code <DetectorSettings>} to the factory's unmarshal. */
	@Test
	void ourTrackMateXmlDetectorSettingsUnmarshalIntoTheParameters() {
		final TrackerParameters p = new TrackerParameters(87.5, 14.5, 11, Connectivity.FOUR, 40, Method.FIRST);
		final Element detector = TrackMateXmlWriter.document(List.of(), Calibration.PIXELS,
			new ImageSource("a.tif", "", 8, 8, 1, 1), SettingsOf.values(p, 2)).getRootElement().getChild("Settings")
			.getChild("DetectorSettings");
		assertEquals(factory.getKey(), detector.getAttributeValue("DETECTOR_NAME"));
		final Map<String, Object> map = new HashMap<>();
		assertNull(factory.unmarshal(detector, map));
		assertEquals(SettingsOf.map(p, 2), map);
		assertEquals(p, TrackMateSettings.parameters(map));
	}

	@Test
	void marshalRefusesInvalidSettingsAndWritesNothing() {
		final Map<String, Object> s = factory.getDefaultSettings();
		s.put("MIN_AREA", 3.0);
		final Element element = new Element("DetectorSettings");
		final String error = factory.marshal(s, element);
		assertNotNull(error);
		assertTrue(error.contains("MIN_AREA"), error);
		assertTrue(element.getAttributes().isEmpty());
		assertEquals(error, factory.toString(s));
	}

	@Test
	void checkSettingsNamesWhatIsWrong() {
		final Map<String, Object> s = factory.getDefaultSettings();
		s.remove("TARGET_CHANNEL");
		s.put("R_OUT", "20");
		final String error = factory.checkSettings(s);
		assertTrue(error.contains("TARGET_CHANNEL") && error.contains("R_OUT"), error);
	}

	@Test
	void trackMateCanInstantiateItThroughAPublicNoArgumentConstructor() throws Exception {
		final Object copy = ContactTrackerDetectorFactory.class.getConstructor().newInstance();
		assertEquals(factory.getKey(), ((ContactTrackerDetectorFactory<?>) copy).getKey());
	}

	/**
	 * TrackMate finds detectors and spot analyzers through SciJava's plugin service: its DetectorProvider asks for
	 * {@code SpotDetectorFactoryBase} plugins, its SpotAnalyzerProvider for {@code SpotAnalyzerFactory} plugins.
	 */
	@Test
	void sciJavaDiscoversTheDetectorAndTheSpotFeatures() {
		try (Context context = new Context(PluginService.class)) {
			final PluginService plugins = context.service(PluginService.class);
			final Object detector = instanceOf(plugins, SpotDetectorFactoryBase.class, ContactTrackerDetectorFactory.class);
			assertTrue(detector instanceof SpotGlobalDetectorFactory, "TrackMate must drive it as a global detector");
			assertEquals(ContactTrackerDetectorFactory.DETECTOR_KEY, ((SpotDetectorFactoryBase<?>) detector).getKey());
			final Object features = instanceOf(plugins, SpotAnalyzerFactory.class, ContactTrackerSpotFeatures.class);
			assertEquals(ContactTrackerSpotFeatures.KEY, ((SpotAnalyzerFactory<?>) features).getKey());
		}
	}

	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static Object instanceOf(final PluginService plugins, final Class type, final Class<?> ours) {
		final List<PluginInfo<?>> infos = plugins.getPluginsOfType(type);
		final PluginInfo info = infos.stream().filter(i -> i.getClassName().equals(ours.getName())).findFirst()
			.orElse(null);
		assertNotNull(info, ours.getSimpleName() + " is not indexed as a " + type.getSimpleName() + " plugin");
		return plugins.createInstance(info);
	}

	@Test
	void configurationPanelShowsAndReturnsEverySetting() {
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(), new Model());
		assertNotNull(panel);
		assertNull(factory.checkSettings(panel.getSettings()), "the panel's own defaults must be valid");
		assertEquals(factory.getDefaultSettings(), panel.getSettings());

		final Map<String, Object> s = SettingsOf.map(new TrackerParameters(123.456789, 7.75, 12,
			Connectivity.FOUR, 33, Method.values()[0]), 1);
		panel.setSettings(s);
		assertEquals(s, panel.getSettings());
		panel.clean();

		// every method is offered, so new ones appear without touching the panel
		final JComboBox<?> methods = allComponents(panel).stream().filter(c -> c instanceof JComboBox<?>)
			.map(c -> (JComboBox<?>) c).filter(c -> c.getItemCount() > 0 && Method.values()[0].key().equals(c.getItemAt(0)))
			.findFirst().orElse(null);
		assertNotNull(methods);
		assertEquals(Method.values().length, methods.getItemCount());
		for (int i = 0; i < Method.values().length; i++)
			assertEquals(Method.values()[i].key(), methods.getItemAt(i));

		// channels beyond the image's are accepted from saved settings rather than silently changed
		final Map<String, Object> ch3 = new HashMap<>(s);
		ch3.put("TARGET_CHANNEL", 3);
		panel.setSettings(ch3);
		assertEquals(3, panel.getSettings().get("TARGET_CHANNEL"));
	}

	/** On a calibrated image r_out is shown in its units and still returned in pixels, exactly. */
	@Test
	void panelAsksRoutInPhysicalUnitsAndReturnsPixels() {
		final ImagePlus imp = IJ.createImage("calibrated", "8-bit black", 64, 48, 1);
		imp.getCalibration().pixelWidth = imp.getCalibration().pixelHeight = 0.0847;
		imp.getCalibration().setUnit("micron");
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		final Map<String, Object> s = factory.getDefaultSettings();
		s.put("R_OUT", 61.0);
		panel.setSettings(s);
		assertEquals(61.0, panel.getSettings().get("R_OUT"));
		final List<Component> all = allComponents(panel);
		assertTrue(all.stream().anyMatch(c -> c instanceof JLabel && "micron (61 px)".equals(((JLabel) c).getText())),
			"r_out's unit and its value in pixels must be shown");
		assertTrue(all.stream().anyMatch(c -> c instanceof JLabel && "r_out".equals(((JLabel) c).getText()) && ((JLabel) c)
			.getToolTipText().endsWith(" Typed here in micron; its value in pixels shows beside.")), "the help says so");
		// in microns, with the fewest decimals that still mean 61 px: 5.167 (5.1667 is 61 * 0.0847 to 4 decimals)
		assertTrue(all.stream().anyMatch(c -> c instanceof JSpinner && ((Number) ((JSpinner) c).getValue())
			.doubleValue() == 5.167), "r_out must be shown in microns");
		// the particle diameter, a length too, likewise
		s.put("DIAMETER", 65.3);
		panel.setSettings(s);
		assertEquals(65.3, panel.getSettings().get("DIAMETER"));
		assertTrue(allComponents(panel).stream().anyMatch(c -> c instanceof JLabel && "micron (65.3 px)".equals(((JLabel) c)
			.getText())));
	}

	/**
	 * A length typed in the image's units comes back as typed when the panel is shown again (a detector switch, a
	 * new session): seen in the real wizard, 5.53 um typed (65.29 px) came back as 5.5301 um.
	 */
	@Test
	void aLengthTypedInMicronsComesBackAsTyped() {
		final double dx = 0.08470000317625012; // the simulator's pixel, as ImageJ reads it from the TIFF
		final ImagePlus imp = IJ.createImage("calibrated", "8-bit black", 64, 48, 1);
		imp.getCalibration().pixelWidth = imp.getCalibration().pixelHeight = dx;
		imp.getCalibration().setUnit("micron");
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		final JSpinner diameter = (JSpinner) allComponents(panel).stream().filter(c -> c instanceof JSpinner && ((JSpinner) c)
			.getToolTipText().startsWith("The particles' diameter")).findFirst().get();
		diameter.setValue(5.53);
		final Map<String, Object> typed = panel.getSettings();
		assertEquals(65.29, typed.get("DIAMETER"));
		final ConfigurationPanel again = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		again.setSettings(typed);
		assertTrue(allComponents(again).stream().anyMatch(c -> c instanceof JSpinner && ((Number) ((JSpinner) c)
			.getValue()).doubleValue() == 5.53), "5.53 um, not 5.5301 um");
		assertEquals(typed, again.getSettings());
		// every length in pixels to 0.01 px comes back to the same pixels, shown with at most 4 decimals
		for (int hundredths = 0; hundredths <= 20000; hundredths += 7) {
			final double px = hundredths / 100.0;
			final double shown = ContactTrackerConfigurationPanel.units(px, dx);
			assertEquals(px, ContactTrackerConfigurationPanel.pixels(shown, dx), 0, "px " + px);
			assertEquals(shown, Math.round(shown * 1e4) / 1e4, 0, "px " + px);
		}
		assertEquals(61.0, ContactTrackerConfigurationPanel.units(61, 1), "uncalibrated: the pixels themselves");
	}

	/**
	 * A length typed in the image's units, as the spinner shows it (4 decimals), lands on the pixels shown beside
	 * it: 61 px, not 60.999998.
	 */
	@Test
	void aLengthTypedInMicronsLandsOnThePixelsShown() {
		final double dx = 0.123456;
		final ImagePlus imp = IJ.createImage("calibrated", "8-bit black", 64, 48, 1);
		imp.getCalibration().pixelWidth = imp.getCalibration().pixelHeight = dx;
		imp.getCalibration().setUnit("micron");
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		final Map<String, Object> s = factory.getDefaultSettings();
		s.put("R_OUT", 60.0);
		panel.setSettings(s);
		final JSpinner rOut = allComponents(panel).stream().filter(c -> c instanceof JSpinner && Math.abs(((Number) (
			(JSpinner) c).getValue()).doubleValue() - 60 * dx) < 1e-3).map(c -> (JSpinner) c).findFirst().get();
		rOut.setValue(7.5308); // 61 px shown to 4 decimals: 7.530816 um
		assertEquals(61.0, panel.getSettings().get("R_OUT"));
		assertEquals(60.0, ContactTrackerConfigurationPanel.pixels(7.407360, dx));
		assertEquals(31.65, ContactTrackerConfigurationPanel.pixels(31.65 * dx, dx), "the helper's 0.01 px kept");
	}

	/**
	 * What TrackMate 8.0.0's wizard does when the user goes from Contact Tracker to LoG and back
	 * (ChooseDetectorDescriptor.aboutToHidePanel, TrackMateWizardSequence.getConfigDescriptor): our values come
	 * back, and LoG's THRESHOLD (a quality cut-off) does not become our grey level.
	 */
	@Test
	void settingsSurviveADetectorSwitch() {
		final ConfigurationPanel ours = factory.getDetectorConfigurationPanel(new Settings(), new Model());
		final Map<String, Object> mine = SettingsOf.map(new TrackerParameters(172, 34, 20, Connectivity.EIGHT,
			50, Method.values()[1]), 1);
		mine.put("DIAMETER", 31.65);
		ours.setSettings(mine);
		assertEquals(mine, ours.getSettings()); // the wizard reads the panel as the user moves on
		// to LoG: our map fails LoG's check, so the settings become LoG's defaults plus what keys match
		final Map<String, Object> log = new HashMap<>(Map.of("TARGET_CHANNEL", 1, "RADIUS", 2.5, "THRESHOLD", 0.0,
			"DO_MEDIAN_FILTERING", false, "DO_SUBPIXEL_LOCALIZATION", true));
		assertFalse(log.containsKey(TrackMateSettings.KEY_THRESHOLD));
		// back to ours: LoG's map fails our check, so TrackMate takes our getDefaultSettings() ...
		assertNotNull(factory.checkSettings(log));
		final Map<String, Object> settings = factory.getDefaultSettings();
		// ... then fills our keys from LoG's panel, else from those settings
		final Map<String, Object> handed = factory.getDefaultSettings();
		for (final String key : handed.keySet()) {
			final Object previous = log.get(key);
			handed.put(key, previous != null ? previous : settings.get(key));
		}
		final ConfigurationPanel back = factory.getDetectorConfigurationPanel(new Settings(), new Model());
		back.setSettings(handed);
		assertEquals(mine, back.getSettings(), "r_out, the diameter and the threshold survive");
		// a key the previous detector did not have comes as null: the last values, not the defaults
		final Map<String, Object> withNulls = new HashMap<>(mine);
		withNulls.put("R_OUT", null);
		back.setSettings(withNulls);
		assertEquals(34.0, back.getSettings().get("R_OUT"));
	}

	/** The DOI link is not broken across lines at the panel's width (it wrapped mid-string in the real wizard). */
	@Test
	void theDoiLinkStaysOnOneLine() throws Exception {
		final List<String> problems = new java.util.ArrayList<>();
		final java.util.Set<Double> lines = new java.util.HashSet<>();
		// Swing lays text out on its event thread only
		javax.swing.SwingUtilities.invokeAndWait(() -> {
			final javax.swing.JScrollPane scroll = (javax.swing.JScrollPane) ContactTrackerConfigurationPanel.infoPane();
			final javax.swing.JEditorPane pane = (javax.swing.JEditorPane) scroll.getViewport().getView();
			try {
				final javax.swing.text.Document doc = pane.getDocument();
				final String text = doc.getText(0, doc.getLength());
				final int start = text.indexOf(ContactTrackerConfigurationPanel.DOI_TEXT);
				if (start < 0) throw new AssertionError(text);
				final int end = start + ContactTrackerConfigurationPanel.DOI_TEXT.length() - 1;
				// every width the wizard may give (fonts differ between machines: the break moves with them)
				for (int width = 200; width <= 420; width += 4) {
					pane.setSize(width, Short.MAX_VALUE);
					pane.setSize(width, pane.getPreferredSize().height);
					final java.awt.geom.Rectangle2D first = pane.modelToView2D(start), last = pane.modelToView2D(end);
					if (Math.abs(first.getY() - last.getY()) > 0.5) problems.add("at " + width + " px the DOI runs from (" +
						first.getX() + ", " + first.getY() + ") to (" + last.getX() + ", " + last.getY() + ")");
					lines.add(first.getY());
				}
			}
			catch (final javax.swing.text.BadLocationException e) {
				throw new AssertionError(e);
			}
		});
		assertTrue(problems.isEmpty(), String.join("\n", problems));
		assertTrue(lines.size() > 1, "the text is laid out (the DOI's line moves with the width): " + lines);
	}

	/** The panel's fields are the settings descriptor's: one per setting, with its label, help and every choice. */
	@Test
	void panelHasOneFieldPerSettingOfTheDescriptor() {
		final ImagePlus imp = IJ.createImage("two channels", "8-bit black", 64, 48, 2);
		imp.setDimensions(2, 1, 1);
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		final List<Component> all = allComponents(panel);
		for (final io.github.contacttracker.settings.Setting<?> setting : io.github.contacttracker.settings.TrackingSettings.ALL) {
			final JLabel label = all.stream().filter(c -> c instanceof JLabel && setting.label().equals(((JLabel) c)
				.getText())).map(c -> (JLabel) c).findFirst().orElse(null);
			assertNotNull(label, "no field for " + setting.name());
			assertEquals(setting.help(), label.getToolTipText());
		}
		assertEquals(TrackMateSettings.keys(), List.copyOf(panel.getSettings().keySet()));
	}

	/**
	 * TrackMate's wizard gives a detector panel about 300 x 511 pixels and no scroll bar; TrackMate's Preview panel
	 * (histogram at most 150 px, plus its button row) takes the bottom. Everything else must fit above it.
	 */
	@Test
	void panelFitsTheWizardAboveTrackMatesPreview() {
		final ImagePlus imp = IJ.createImage("two channels", "8-bit black", 64, 48, 2);
		imp.setDimensions(2, 1, 1);
		final ConfigurationPanel panel = factory.getDetectorConfigurationPanel(new Settings(imp), new Model());
		final java.awt.Dimension natural = panel.getLayout().preferredLayoutSize(panel);
		final int previewHeight = 150 + 40;
		assertTrue(natural.height + previewHeight <= ContactTrackerConfigurationPanel.WIZARD_SIZE.height,
			"panel too tall for the wizard: " + natural);
		assertTrue(natural.width <= ContactTrackerConfigurationPanel.WIZARD_SIZE.width + 20,
			"panel too wide for the wizard: " + natural);
		assertTrue(allComponents(panel).stream().anyMatch(c -> c instanceof fiji.plugin.trackmate.util.DetectionPreviewPanel),
			"TrackMate's Preview must be on the panel");
	}

	static List<Component> allComponents(final Container root) {
		final List<Component> all = new ArrayList<>();
		for (final Component c : root.getComponents()) {
			all.add(c);
			if (c instanceof Container) all.addAll(allComponents((Container) c));
		}
		return all;
	}
}
