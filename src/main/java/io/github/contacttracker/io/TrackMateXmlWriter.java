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

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackMateSettings;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.jdom2.Document;
import org.jdom2.Element;
import org.jdom2.output.Format;
import org.jdom2.output.XMLOutputter;

import io.github.contacttracker.core.Localization;

/**
 * Writes spots as a TrackMate session file that TrackMate 8 opens with <i>File &gt; Load a TrackMate file</i>
 * (or the "Load a TrackMate file" command): the spots, in physical units, with the source image opened beside
 * them and our detector and its parameters recorded in the settings.
 * <p>
 * Layout (jdom2; no TrackMate class is needed to write it):
 * <pre>
 * &lt;TrackMate version="8.0.0"&gt;
 *   &lt;Log&gt;provenance&lt;/Log&gt;
 *   &lt;Model spatialunits=".." timeunits=".."&gt;
 *     &lt;FeatureDeclarations&gt; SpotFeatures (TrackMate's standard spot features, then every extra column of
 *       {@link SpotColumn}), EdgeFeatures, TrackFeatures
 *     &lt;AllSpots nspots="N"&gt; &lt;SpotsInFrame frame="f"&gt; &lt;Spot ID name POSITION_X .. VISIBILITY="1" extras/&gt;
 *     &lt;AllTracks/&gt; &lt;FilteredTracks/&gt;
 *   &lt;Settings&gt;
 *     &lt;ImageData filename folder width height nslices nframes pixelwidth pixelheight voxeldepth timeinterval/&gt;
 *     &lt;DetectorSettings DETECTOR_NAME="CONTACT_TRACKER_DETECTOR" TARGET_CHANNEL .. METHOD/&gt;
 *     &lt;InitialSpotFilter feature="QUALITY" value="0.0" isabove="true"/&gt; &lt;SpotFilterCollection/&gt;
 *     &lt;TrackerSettings TRACKER_NAME="MANUAL_TRACKER"/&gt; &lt;TrackFilterCollection/&gt;
 *     &lt;AnalyzerCollection&gt; empty SpotAnalyzers, EdgeAnalyzers, TrackAnalyzers
 *   &lt;GUIState state="ConfigureViews"/&gt;
 *   &lt;DisplaySettings/&gt;   (empty: TrackMate uses the user's defaults)
 * </pre>
 * Spot {@code ID}s are the spots' positions in the list given (0, 1, 2, ...), the same IDs the CSV tables use;
 * every attribute other than {@code ID} and {@code name} is a number (TrackMate parses them all with
 * {@code Double.valueOf}): TrackMate's own features finite, an undefined extra value (an unestimated standard
 * error) {@code NaN}, so every spot carries every declared feature. Tracks are empty: link the spots in TrackMate.
 */
public final class TrackMateXmlWriter {

	/** The TrackMate file-format version written. */
	public static final String TRACKMATE_VERSION = "8.0.0";
	/** Tracker named in the settings: TrackMate's "Manual tracking", which needs no parameter. */
	public static final String TRACKER_KEY = "MANUAL_TRACKER";

	private TrackMateXmlWriter() {}

	/**
	 * Writes the file, atomically (nothing is left behind when writing fails).
	 *
	 * @param out the XML file to create or replace
	 * @param spots the spots, in pixel units, in any frame order; their list positions become their IDs
	 * @param cal the image's calibration
	 * @param src the image the spots come from
	 * @param settings the settings the spots were found with, every one recorded in the detector's settings
	 * @throws IOException naming the file when writing fails
	 * @throws IllegalArgumentException when a spot lies outside the image's frames or has a non-finite position
	 */
	public static void write(final Path out, final List<Localization> spots, final Calibration cal,
		final ImageSource src, final SettingValues settings) throws IOException
	{
		AtomicFile.write(out, body(spots, cal, src, settings));
	}

	/**
	 * @return the file as the body of an {@link AtomicFile} write; the document is built at once, so a spot that
	 *         cannot be written fails here, before any file is opened
	 */
	public static AtomicFile.Body body(final List<Localization> spots, final Calibration cal, final ImageSource src,
		final SettingValues settings)
	{
		final Document doc = document(spots, cal, src, settings);
		final XMLOutputter outputter = new XMLOutputter(Format.getPrettyFormat().setEncoding("UTF-8"));
		return stream -> outputter.output(doc, stream);
	}

	/**
	 * @return the TrackMate document for the spots (see {@link #write})
	 * @throws IllegalArgumentException when a spot lies outside the image's frames or has a non-finite position
	 */
	public static Document document(final List<Localization> spots, final Calibration cal, final ImageSource src,
		final SettingValues settings)
	{
		final Element root = new Element("TrackMate").setAttribute("version", TRACKMATE_VERSION);
		root.addContent(new Element("Log").setText(log(spots.size(), cal, src, settings)));
		root.addContent(model(spots, cal, src));
		root.addContent(settings(cal, src, settings));
		root.addContent(new Element("GUIState").setAttribute("state", "ConfigureViews"));
		root.addContent(new Element("DisplaySettings"));
		return new Document(root);
	}

	private static Element model(final List<Localization> spots, final Calibration cal, final ImageSource src) {
		final Element model = new Element("Model")
			.setAttribute("spatialunits", SpotColumn.POSITION_X.unit(cal))
			.setAttribute("timeunits", SpotColumn.POSITION_T.unit(cal));

		// TrackMate's own spot features first, in the order TrackMate declares them (third-party readers such as
		// pytrackmate build their tables from these declarations), then ours
		final Element spotFeatures = new Element("SpotFeatures");
		for (final SpotColumn c : TRACKMATE_SPOT_FEATURES)
			spotFeatures.addContent(declaration(c));
		for (final SpotColumn c : SpotColumn.values())
			if (!c.isTrackMateKey()) spotFeatures.addContent(declaration(c));
		model.addContent(new Element("FeatureDeclarations")
			.addContent(spotFeatures)
			.addContent(new Element("EdgeFeatures"))
			.addContent(new Element("TrackFeatures")));

		// one SpotsInFrame per frame of the image, spots in list order within it
		final List<List<Integer>> byFrame = new ArrayList<>(src.nframes());
		for (int f = 0; f < src.nframes(); f++)
			byFrame.add(new ArrayList<>());
		for (int i = 0; i < spots.size(); i++) {
			final int f = spots.get(i).frame();
			if (f < 0 || f >= src.nframes())
				throw new InvalidInputException("spot " + i + " is in frame " + f + " but the image has " +
					src.nframes() + " frames");
			byFrame.get(f).add(i);
		}
		final Element allSpots = new Element("AllSpots").setAttribute("nspots", Integer.toString(spots.size()));
		for (int f = 0; f < byFrame.size(); f++) {
			final Element inFrame = new Element("SpotsInFrame").setAttribute("frame", Integer.toString(f));
			for (final int i : byFrame.get(f))
				inFrame.addContent(spot(spots.get(i), i, cal));
			allSpots.addContent(inFrame);
		}
		model.addContent(allSpots);
		model.addContent(new Element("AllTracks"));
		model.addContent(new Element("FilteredTracks"));
		return model;
	}

	/** TrackMate's standard spot features, in the order of its {@code Spot.FEATURES}. */
	private static final List<SpotColumn> TRACKMATE_SPOT_FEATURES = List.of(SpotColumn.QUALITY, SpotColumn.POSITION_X,
		SpotColumn.POSITION_Y, SpotColumn.POSITION_Z, SpotColumn.POSITION_T, SpotColumn.FRAME, SpotColumn.RADIUS,
		SpotColumn.VISIBILITY);

	private static Element declaration(final SpotColumn c) {
		return new Element("Feature")
			.setAttribute("feature", c.key())
			.setAttribute("name", c.title())
			.setAttribute("shortname", c.shortName())
			.setAttribute("dimension", c.dimension().name())
			.setAttribute("isint", Boolean.toString(c.isInteger()));
	}

	private static Element spot(final Localization loc, final int id, final Calibration cal) {
		final Element e = new Element("Spot").setAttribute("ID", Integer.toString(id)).setAttribute("name", "ID" + id);
		for (final SpotColumn c : SpotColumn.values()) {
			if (c == SpotColumn.ID) continue;
			final double v = c.value(loc, id, cal);
			if (!Double.isFinite(v) && c.isTrackMateKey())
				throw new InvalidInputException("spot " + id + " has " + c.key() + " = " + v + ", not a finite number");
			// an undefined extra value is written as NaN (TrackMate reads it with Double.valueOf), never left out:
			// third-party readers (pytrackmate) refuse a spot that lacks a declared feature
			e.setAttribute(c.key(), c.format(loc, id, cal));
		}
		return e;
	}

	private static Element settings(final Calibration cal, final ImageSource src, final SettingValues values) {
		final Element settings = new Element("Settings");
		settings.addContent(new Element("ImageData")
			.setAttribute("filename", src.filename())
			.setAttribute("folder", src.folder())
			.setAttribute("width", Integer.toString(src.width()))
			.setAttribute("height", Integer.toString(src.height()))
			.setAttribute("nslices", Integer.toString(src.nslices()))
			.setAttribute("nframes", Integer.toString(src.nframes()))
			.setAttribute("pixelwidth", Double.toString(cal.pixelWidth()))
			.setAttribute("pixelheight", Double.toString(cal.pixelHeight()))
			.setAttribute("voxeldepth", Double.toString(1.0))
			.setAttribute("timeinterval", Double.toString(cal.frameInterval())));

		final Element detector = new Element("DetectorSettings")
			.setAttribute(TrackMateSettings.XML_ATTRIBUTE_DETECTOR_NAME, TrackMateSettings.DETECTOR_KEY);
		for (final Map.Entry<String, Object> e : TrackMateSettings.toMap(values).entrySet())
			detector.setAttribute(e.getKey(), e.getValue().toString());
		settings.addContent(detector);

		settings.addContent(new Element("InitialSpotFilter")
			.setAttribute("feature", "QUALITY")
			.setAttribute("value", "0.0")
			.setAttribute("isabove", "true"));
		settings.addContent(new Element("SpotFilterCollection"));
		settings.addContent(new Element("TrackerSettings").setAttribute("TRACKER_NAME", TRACKER_KEY));
		settings.addContent(new Element("TrackFilterCollection"));
		settings.addContent(new Element("AnalyzerCollection")
			.addContent(new Element("SpotAnalyzers"))
			.addContent(new Element("EdgeAnalyzers"))
			.addContent(new Element("TrackAnalyzers")));
		return settings;
	}

	private static String log(final int n, final Calibration cal, final ImageSource src,
		final SettingValues settings)
	{
		return "Written by Contact Tracker " + ProjectVersion.get() +
			": radial-symmetry localization of particles near contact (Yucel & Okumusoglu, " +
			"J. Phys.: Condens. Matter 29, 465101, 2017).\n" +
			n + " spots in " + src.nframes() + " frames of " + (src.filename().isEmpty() ? "an unsaved image"
				: src.filename()) + ", pixel size " + cal.pixelWidth() + " x " + cal.pixelHeight() + " " + cal.unit() +
			", frame interval " + cal.frameInterval() + " " + cal.timeUnit() + ".\nDetector settings: " +
			TrackMateSettings.echo(TrackMateSettings.toMap(settings)) + ".\n" +
			"No tracks: link the spots with a tracker in TrackMate.";
	}
}
