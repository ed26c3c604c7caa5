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
package io.github.contacttracker.io;

import io.github.contacttracker.settings.TrackMateSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.jdom2.Attribute;
import org.jdom2.Document;
import org.jdom2.Element;
import org.jdom2.JDOMException;
import org.jdom2.input.SAXBuilder;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.settings.SettingsOf;

/**
 * The TrackMate XML must hold every element and attribute TrackMate 8's reader needs (TmXmlReader), with
 * numbers wherever TrackMate parses numbers, and agree with the CSV table.
 */
class TrackMateXmlWriterTest {

	@TempDir
	Path dir;

	private static final Calibration CAL = new Calibration(0.0847, 0.0923, "µm", 0.5, "s");
	private static final TrackerParameters PARAMS = new TrackerParameters(112.5, 33.25, 20, Connectivity.EIGHT, 50,
		Method.PAPER);

	/** Spots in frames 0, 2, 0 (out of order), one with flags and NaN standard errors. */
	private static List<Localization> spots() {
		return List.of(
			new Localization(0, 10.25, 20.5, 10.3, 20.4, 120, 120, 5400.5, 6.18, 0, 1, 0.01, 0.02, Double.NaN,
				Double.NaN, 0),
			new Localization(2, 30.125, 15.0, 30.6, 15.2, 150, 96, 7000, 6.9,
				Flag.SECOND_PASS.bit() | Flag.AT_BORDER.bit(), 2, 0.015, 0.012, Double.NaN, Double.NaN, 0),
			new Localization(0, 44.0, 5.75, 44.1, 5.7, 90, 40, 3000, 5.35, Flag.FELL_BACK.bit(), 1, Double.NaN,
				Double.NaN, Double.NaN, Double.NaN, 0));
	}

	private static final ImageSource SRC = new ImageSource("movie.tif", "/data/experiment", 64, 48, 1, 3);

	private Document writeAndParse(final List<Localization> spots) throws IOException, JDOMException {
		final Path out = dir.resolve("spots.xml");
		TrackMateXmlWriter.write(out, spots, CAL, SRC, SettingsOf.values(PARAMS, 2));
		return new SAXBuilder().build(out.toFile());
	}

	private static Element child(final Element parent, final String name) {
		final Element e = parent.getChild(name);
		assertNotNull(e, "<" + parent.getName() + "> lacks <" + name + ">");
		return e;
	}

	private static String attr(final Element e, final String name) {
		final String v = e.getAttributeValue(name);
		assertNotNull(v, "<" + e.getName() + "> lacks attribute " + name);
		return v;
	}

	/** A finite number, as TrackMate's own spot features must be. */
	private static double number(final Element e, final String name) {
		final double d = parsable(e, name);
		assertTrue(Double.isFinite(d), name + " = " + d);
		return d;
	}

	/** A number TrackMate's reader parses ({@code Double.valueOf}): NaN allowed, as for an unestimated error. */
	private static double parsable(final Element e, final String name) {
		final String v = attr(e, name);
		try {
			return Double.valueOf(v);
		}
		catch (final NumberFormatException x) {
			throw new AssertionError("<" + e.getName() + "> " + name + " = '" + v + "' is not a number");
		}
	}

	private static int integer(final Element e, final String name) {
		final String v = attr(e, name);
		try {
			return Integer.parseInt(v);
		}
		catch (final NumberFormatException x) {
			throw new AssertionError("<" + e.getName() + "> " + name + " = '" + v + "' is not an integer");
		}
	}

	@Test
	void holdsEveryMandatoryElementAndAttributeWithNumbersWhereTrackMateParsesNumbers() throws Exception {
		final List<Localization> spots = spots();
		final Element root = writeAndParse(spots).getRootElement();

		assertEquals("TrackMate", root.getName());
		final String[] version = attr(root, "version").split("\\.");
		assertTrue(Integer.parseInt(version[0]) > 2 || (Integer.parseInt(version[0]) == 2 &&
			Integer.parseInt(version[1]) >= 1), "version must be >= 2.1.0");
		assertEquals("8.0.0", attr(root, "version"));

		final Element model = child(root, "Model");
		assertEquals("µm", attr(model, "spatialunits"));
		assertEquals("s", attr(model, "timeunits"));

		// feature declarations: spot, edge and track sections; every extra spot attribute declared
		final Element decl = child(model, "FeatureDeclarations");
		child(decl, "EdgeFeatures");
		child(decl, "TrackFeatures");
		final Map<String, Element> declared = new HashMap<>();
		for (final Element f : child(decl, "SpotFeatures").getChildren("Feature")) {
			final String key = attr(f, "feature");
			attr(f, "name");
			attr(f, "shortname");
			assertTrue(Set.of("NONE", "POSITION", "LENGTH", "TIME", "QUALITY", "INTENSITY", "ANGLE", "AREA", "VELOCITY",
				"RATE", "STRING").contains(attr(f, "dimension")), key);
			assertTrue(Set.of("true", "false").contains(attr(f, "isint")), key);
			assertNull(declared.put(key, f), "declared twice: " + key);
		}

		final Element allSpots = child(model, "AllSpots");
		assertEquals(spots.size(), integer(allSpots, "nspots"));
		final Set<String> trackMateAttributes = Set.of("ID", "name", "POSITION_X", "POSITION_Y", "POSITION_Z",
			"POSITION_T", "FRAME", "RADIUS", "QUALITY", "VISIBILITY");
		final Set<Integer> ids = new HashSet<>();
		final Set<Integer> frames = new HashSet<>();
		int n = 0;
		for (final Element inFrame : allSpots.getChildren("SpotsInFrame")) {
			final int frame = integer(inFrame, "frame");
			assertTrue(frames.add(frame), "frame listed twice: " + frame);
			for (final Element s : inFrame.getChildren("Spot")) {
				n++;
				final int id = integer(s, "ID");
				assertTrue(ids.add(id), "duplicate spot ID " + id);
				assertFalse(attr(s, "name").isEmpty());
				for (final String a : List.of("POSITION_X", "POSITION_Y", "POSITION_Z", "POSITION_T", "RADIUS", "QUALITY"))
					number(s, a);
				assertEquals(frame, integer(s, "FRAME"), "FRAME must equal its SpotsInFrame");
				assertEquals("1", attr(s, "VISIBILITY"));
				for (final Attribute a : s.getAttributes()) {
					if (a.getName().equals("ID") || a.getName().equals("name")) continue;
					parsable(s, a.getName()); // every other attribute is parsed as a number by TrackMate
					if (trackMateAttributes.contains(a.getName())) number(s, a.getName());
					else assertTrue(declared.containsKey(a.getName()), a.getName() + " is not declared");
				}
				// positions in physical units: pixels times calibration
				final Localization l = spots.get(id);
				assertEquals(l.x() * CAL.pixelWidth(), number(s, "POSITION_X"), 0);
				assertEquals(l.y() * CAL.pixelHeight(), number(s, "POSITION_Y"), 0);
				assertEquals(0, number(s, "POSITION_Z"), 0);
				assertEquals(l.frame() * CAL.frameInterval(), number(s, "POSITION_T"), 0);
				assertEquals(l.frame(), frame);
			}
		}
		assertEquals(spots.size(), n);
		assertEquals(Set.of(0, 1, 2), frames, "one SpotsInFrame per frame of the image, empty ones included");
		assertEquals(Set.of(0, 1, 2), ids, "IDs are the list positions, as in the CSV");
		assertTrue(child(model, "AllTracks").getChildren().isEmpty());
		assertTrue(child(model, "FilteredTracks").getChildren().isEmpty());

		// settings: ImageData (numbers), filters, our detector with our parameters
		final Element settings = child(root, "Settings");
		final Element image = child(settings, "ImageData");
		assertEquals("movie.tif", attr(image, "filename"));
		assertEquals("/data/experiment", attr(image, "folder"));
		assertEquals(64, integer(image, "width"));
		assertEquals(48, integer(image, "height"));
		assertEquals(1, integer(image, "nslices"));
		assertEquals(3, integer(image, "nframes"));
		assertEquals(CAL.pixelWidth(), number(image, "pixelwidth"), 0);
		assertEquals(CAL.pixelHeight(), number(image, "pixelheight"), 0);
		number(image, "voxeldepth");
		assertEquals(CAL.frameInterval(), number(image, "timeinterval"), 0);
		final Element initial = child(settings, "InitialSpotFilter");
		assertEquals("QUALITY", attr(initial, "feature"));
		assertEquals(0, number(initial, "value"), 0);
		assertEquals("true", attr(initial, "isabove"));
		child(settings, "SpotFilterCollection");
		child(settings, "TrackFilterCollection");
		assertEquals("MANUAL_TRACKER", attr(child(settings, "TrackerSettings"), "TRACKER_NAME"));
		final Element analyzers = child(settings, "AnalyzerCollection");
		child(analyzers, "SpotAnalyzers");
		child(analyzers, "EdgeAnalyzers");
		child(analyzers, "TrackAnalyzers");

		final Element detector = child(settings, "DetectorSettings");
		assertEquals(TrackMateSettings.DETECTOR_KEY, attr(detector, "DETECTOR_NAME"));
		final Map<String, Object> parsed = new HashMap<>();
		for (final Attribute a : detector.getAttributes())
			if (!a.getName().equals("DETECTOR_NAME")) parsed.put(a.getName(), TrackMateSettings.parse(a.getName(), a.getValue()));
		assertEquals(SettingsOf.map(PARAMS, 2), parsed);
		assertNull(TrackMateSettings.check(parsed));

		assertEquals("ConfigureViews", attr(child(root, "GUIState"), "state"));
		assertTrue(child(root, "DisplaySettings").getText().isEmpty(), "empty: TrackMate uses the user's defaults");
		assertFalse(child(root, "Log").getText().isBlank());
	}

	/**
	 * TrackMate's standard spot features are declared as TrackMate 8.0.0's {@code Spot} declares them (first, in its
	 * order: pytrackmate builds its tables from the declarations and fails without QUALITY), then every extra column
	 * with its dimension and integer flag.
	 */
	@Test
	void declaresTrackMatesStandardFeaturesThenEveryExtraColumn() throws Exception {
		final Element decl = writeAndParse(spots()).getRootElement().getChild("Model").getChild("FeatureDeclarations")
			.getChild("SpotFeatures");
		final List<String> order = new ArrayList<>();
		final Map<String, Element> byKey = new HashMap<>();
		for (final Element f : decl.getChildren("Feature")) {
			order.add(f.getAttributeValue("feature"));
			byKey.put(f.getAttributeValue("feature"), f);
		}
		// name, short name, dimension, isint: from TrackMate 8.0.0's Spot (git show TrackMate-8.0.0:.../Spot.java)
		final String[][] trackMate = { { "QUALITY", "Quality", "Quality", "QUALITY", "false" },
			{ "POSITION_X", "X", "X", "POSITION", "false" }, { "POSITION_Y", "Y", "Y", "POSITION", "false" },
			{ "POSITION_Z", "Z", "Z", "POSITION", "false" }, { "POSITION_T", "T", "T", "TIME", "false" },
			{ "FRAME", "Frame", "Frame", "NONE", "true" }, { "RADIUS", "Radius", "R", "LENGTH", "false" },
			{ "VISIBILITY", "Visibility", "Visibility", "NONE", "true" } };
		for (int i = 0; i < trackMate.length; i++) {
			final Element f = decl.getChildren("Feature").get(i);
			assertEquals(List.of(trackMate[i]), List.of(f.getAttributeValue("feature"), f.getAttributeValue("name"), f
				.getAttributeValue("shortname"), f.getAttributeValue("dimension"), f.getAttributeValue("isint")));
		}
		for (final SpotColumn c : SpotColumn.values()) {
			if (c.isTrackMateKey()) continue;
			final Element f = byKey.get(c.key());
			assertNotNull(f, c.key());
			assertEquals(c.title(), f.getAttributeValue("name"));
			assertEquals(c.shortName(), f.getAttributeValue("shortname"));
			assertEquals(c.dimension().name(), f.getAttributeValue("dimension"));
			assertEquals(Boolean.toString(c.isInteger()), f.getAttributeValue("isint"));
		}
		assertEquals(new HashSet<>(order).size(), order.size(), "a feature declared twice: " + order);
		assertFalse(byKey.containsKey("ID"), "ID is an attribute, not a feature");
	}

	@Test
	void nonFiniteExtraValuesAreWrittenAsNaNAndIntegersHaveNoDecimalPoint() throws Exception {
		final Element allSpots = writeAndParse(spots()).getRootElement().getChild("Model").getChild("AllSpots");
		Element third = null;
		for (final Element f : allSpots.getChildren("SpotsInFrame"))
			for (final Element s : f.getChildren("Spot"))
				if ("2".equals(s.getAttributeValue("ID"))) third = s;
		assertNotNull(third);
		// every declared feature on every spot (pytrackmate refuses a spot that lacks one); TrackMate reads "NaN"
		assertEquals("NaN", third.getAttributeValue("SIGMA_X"));
		assertEquals("NaN", third.getAttributeValue("SIGMA_Y"));
		assertTrue(Double.isNaN(Double.valueOf(third.getAttributeValue("SIGMA_X"))));
		assertEquals("1", third.getAttributeValue("FLAG_FELL_BACK"));
		assertEquals("0", third.getAttributeValue("FLAG_SECOND_PASS"));
		assertEquals("90", third.getAttributeValue("ACTIVE_AREA"));
		assertEquals("0", third.getAttributeValue("FRAME"));
	}

	/** The CSV and the XML come from the same column definitions: same keys, same IDs, same numbers and units. */
	@Test
	void csvHeaderAndValuesMatchTheXml() throws Exception {
		final List<Localization> spots = spots();
		final Element model = writeAndParse(spots).getRootElement().getChild("Model");
		final StringWriter csv = new StringWriter();
		SpotCsvWriter.write(csv, spots, CAL);
		final String[] lines = csv.toString().split("\n");
		final String[] header = lines[0].split(",");
		assertEquals("ID", header[0]);

		final Map<String, Element> xmlById = new HashMap<>();
		for (final Element f : model.getChild("AllSpots").getChildren("SpotsInFrame"))
			for (final Element s : f.getChildren("Spot"))
				xmlById.put(s.getAttributeValue("ID"), s);
		assertEquals(spots.size(), lines.length - 1);
		for (int row = 1; row < lines.length; row++) {
			final String[] cells = lines[row].split(",");
			final Element s = xmlById.get(cells[0]);
			assertNotNull(s, "CSV ID " + cells[0] + " is not in the XML");
			final Set<String> xmlKeys = new HashSet<>();
			for (final Attribute a : s.getAttributes())
				xmlKeys.add(a.getName());
			xmlKeys.remove("name");
			for (int c = 0; c < header.length; c++) {
				final String xml = s.getAttributeValue(header[c]);
				if (xml == null) assertEquals("NaN", cells[c], header[c] + ": only non-numbers may be missing from the XML");
				else assertEquals(cells[c], xml, header[c] + " of spot " + cells[0]);
				xmlKeys.remove(header[c]);
			}
			assertTrue(xmlKeys.isEmpty(), "XML attributes missing from the CSV header: " + xmlKeys);
		}
		// the units of the CSV's columns (its calibration) are the XML model's units
		assertEquals(SpotColumn.POSITION_X.unit(CAL), model.getAttributeValue("spatialunits"));
		assertEquals(SpotColumn.RADIUS.unit(CAL), model.getAttributeValue("spatialunits"));
		assertEquals(SpotColumn.POSITION_T.unit(CAL), model.getAttributeValue("timeunits"));
	}

	@Test
	void emptyResultStillMakesAValidFile() throws Exception {
		final Element model = writeAndParse(List.of()).getRootElement().getChild("Model");
		assertEquals("0", model.getChild("AllSpots").getAttributeValue("nspots"));
		assertEquals(3, model.getChild("AllSpots").getChildren("SpotsInFrame").size());
	}

	@Test
	void badInputIsRefusedAndLeavesNoFile() throws Exception {
		final Path out = dir.resolve("bad.xml");
		final List<Localization> late = List.of(new Localization(3, 1, 1, 1, 1, 30, 30, 1, 3, 0, 1, 0, 0, Double.NaN,
			Double.NaN, 0));
		final IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
			() -> TrackMateXmlWriter.write(out, late, CAL, SRC, SettingsOf.values(PARAMS, 1)));
		assertTrue(e.getMessage().contains("frame 3"), e.getMessage());
		final List<Localization> nan = List.of(new Localization(0, Double.NaN, 1, 1, 1, 30, 30, 1, 3, 0, 1, 0, 0,
			Double.NaN, Double.NaN, 0));
		assertThrows(IllegalArgumentException.class, () -> TrackMateXmlWriter.write(out, nan, CAL, SRC, SettingsOf.values(PARAMS, 1)));
		assertFalse(Files.exists(out));

		final Path missingFolder = dir.resolve("no/such/folder/out.xml");
		final IOException io = assertThrows(IOException.class,
			() -> TrackMateXmlWriter.write(missingFolder, spots(), CAL, SRC, SettingsOf.values(PARAMS, 1)));
		assertTrue(io.getMessage().contains("out.xml"), io.getMessage());
		try (var files = Files.list(dir)) {
			assertEquals(0, files.count(), "nothing half-written");
		}
	}

	@Test
	void replacesAnExistingFileAndRecordsChannelOne() throws Exception {
		final Path out = dir.resolve("spots.xml");
		Files.writeString(out, "old");
		TrackMateXmlWriter.write(out, spots(), CAL, SRC, SettingsOf.values(PARAMS, 1));
		final Element detector = new SAXBuilder().build(out.toFile()).getRootElement().getChild("Settings")
			.getChild("DetectorSettings");
		assertEquals("1", detector.getAttributeValue("TARGET_CHANNEL"));
	}

	@Test
	void imageSourceFromAPathSplitsFolderAndName() {
		final ImageSource s = ImageSource.of(Path.of("/data/run1/movie.tif"), 10, 20, 5);
		assertEquals("movie.tif", s.filename());
		assertEquals(Path.of("/data/run1").toString(), s.folder());
		assertEquals(1, s.nslices());
		assertThrows(IllegalArgumentException.class, () -> new ImageSource("a.tif", "", 0, 1, 1, 1));
	}
}
