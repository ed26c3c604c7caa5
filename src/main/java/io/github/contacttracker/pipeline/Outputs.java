package io.github.contacttracker.pipeline;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.io.TrackMateXmlWriter;

/**
 * The files a run writes: a spots CSV, a TrackMate XML, both or neither. Their folders are checked before the
 * run ({@link #check()}); the files are written all or none ({@link #write}).
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
	 * @throws IOException naming the file that failed (no file of this run is left behind)
	 */
	void write(final List<Localization> spots, final Calibration cal, final TrackerParameters params,
		final int channel) throws IOException
	{
		final List<Path> targets = new ArrayList<>();
		final List<AtomicFile.Body> bodies = new ArrayList<>();
		if (csv != null) {
			targets.add(csv);
			bodies.add(SpotCsvWriter.body(spots, cal));
		}
		if (trackMateXml != null) {
			targets.add(trackMateXml);
			bodies.add(TrackMateXmlWriter.body(spots, cal, source, params, channel));
		}
		if (!targets.isEmpty()) AtomicFile.writeAll(targets, bodies);
	}
}
