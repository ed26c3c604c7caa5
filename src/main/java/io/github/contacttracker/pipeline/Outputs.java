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
package io.github.contacttracker.pipeline;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SettingsFile;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.io.TrackMateXmlWriter;
import io.github.contacttracker.settings.SettingValues;

/**
 * The files a run writes: a spots CSV (with its settings file beside it, {@link SettingsFile}), a TrackMate XML,
 * both or neither. Their folders are checked before the run ({@link #check()}); the files are written all or none
 * ({@link #write}). Both record the run's settings as the front end gave them, so that every setting, the dark
 * particles' inversion too, can be read back.
 *
 * @param csv the spots table, or {@code null}
 * @param trackMateXml the TrackMate file, or {@code null}
 * @param source the image the XML names (needed with {@code trackMateXml})
 */
public record Outputs(Path csv, Path trackMateXml, ImageSource source) {

	/** No file. */
	public static final Outputs NONE = new Outputs(null, null, null);

	/**
	 * @param fileName a movie's file name ({@code run1.ome.tif})
	 * @return the name its outputs take in an output folder: without its extension ({@code run1.ome})
	 */
	public static String baseName(final String fileName) {
		final int dot = fileName.lastIndexOf('.');
		return dot > 0 ? fileName.substring(0, dot) : fileName;
	}

	/**
	 * @throws io.github.contacttracker.core.InvalidInputException naming a file whose folder does not exist
	 */
	public void check() {
		if (csv != null) AtomicFile.checkFolder("csv", csv);
		if (trackMateXml != null) AtomicFile.checkFolder("trackmate_xml", trackMateXml);
	}

	/**
	 * Writes every file, all or none.
	 *
	 * @param settings the settings of the run, recorded in the settings file and the XML
	 *
	 * @throws IOException naming the file that failed (no file of this run is left behind)
	 */
	void write(final List<Localization> spots, final Calibration cal, final SettingValues settings)
		throws IOException
	{
		final List<Path> targets = new ArrayList<>();
		final List<AtomicFile.Body> bodies = new ArrayList<>();
		if (csv != null) {
			targets.add(csv);
			bodies.add(SpotCsvWriter.body(spots, cal));
			targets.add(SettingsFile.beside(csv));
			bodies.add(SettingsFile.body(settings));
		}
		if (trackMateXml != null) {
			targets.add(trackMateXml);
			bodies.add(TrackMateXmlWriter.body(spots, cal, source, settings));
		}
		if (!targets.isEmpty()) AtomicFile.writeAll(targets, bodies);
	}
}
