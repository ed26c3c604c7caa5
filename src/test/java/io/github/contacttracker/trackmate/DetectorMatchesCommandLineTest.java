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
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.SpotCollection;
import fiji.plugin.trackmate.detection.SpotGlobalDetector;
import ij.ImagePlus;
import io.github.contacttracker.cli.ContactTrackerCli;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import io.github.contacttracker.settings.SettingsOf;
import io.github.contacttracker.lab.cli.ContactTrackerLab;

/**
 * TrackMate's spots equal the command line's CSV, value for value, for the same movie and settings, with every
 * method: the detector sees the whole movie, so the profile methods measure the same profile on the same frames.
 * The movie is a simulated touching triple (the profile methods' hard case), read back from its TIFF file by both.
 */
class DetectorMatchesCommandLineTest {

	private static final int FRAMES = 3;

	@TempDir
	static Path dir;
	private static Path movie;
	private static ImgPlus<UnsignedByteType> img;

	@BeforeAll
	static void simulate() throws Exception {
		movie = dir.resolve("triple.tif");
		cli("simulate", "--scenario", "triple", "--separation", "1.0", "--frames", Integer.toString(FRAMES), "--seed",
			"7", "--out", movie.toString(), "--truth", dir.resolve("truth.csv").toString());
		// what TrackMate's TMUtils.rawWraps does for an 8-bit time-lapse: X, Y, T over the same pixels, calibrated
		final ImagePlus imp = ImageFiles.open(movie);
		assertEquals(FRAMES, imp.getNFrames(), "the simulator writes frames as time points");
		final int w = imp.getWidth(), h = imp.getHeight();
		final byte[] pixels = new byte[w * h * FRAMES];
		for (int t = 0; t < FRAMES; t++)
			System.arraycopy((byte[]) imp.getStack().getPixels(t + 1), 0, pixels, t * w * h, w * h);
		final ArrayImg<UnsignedByteType, ByteArray> raw = ArrayImgs.unsignedBytes(pixels, w, h, FRAMES);
		img = new ImgPlus<>(raw, "triple", new AxisType[] { Axes.X, Axes.Y, Axes.TIME }, new double[] { imp
			.getCalibration().pixelWidth, imp.getCalibration().pixelHeight, imp.getCalibration().frameInterval });
	}

	private static String cli(final String... args) {
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		final int status = ContactTrackerLab.run(args, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(
			err, true, StandardCharsets.UTF_8));
		assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
		return out.toString(StandardCharsets.UTF_8);
	}

	@ParameterizedTest
	@EnumSource(Method.class)
	void spotsEqualTheCommandLinesCsv(final Method method) throws Exception {
		// the diameter given to both (the command line measures it when it is not given; TrackMate reads its field)
		final TrackerParameters params = new TrackerParameters(85, 61, 20, Connectivity.EIGHT, 50, method, 65.3);
		final Path csv = dir.resolve(method.key() + ".csv");
		cli("track", movie.toString(), "--threshold", "85", "--r-out", "61", "--diameter", "65.3", "--method", method
			.key(), "--csv", csv.toString());
		final List<Map<String, String>> rows = readCsv(csv);
		assertEquals(3 * FRAMES, rows.size(), "three particles in every frame");

		final SpotGlobalDetector<UnsignedByteType> detector = new ContactTrackerDetectorFactory<UnsignedByteType>()
			.getDetector(img, SettingsOf.map(params, 1), ContactTrackerDetectorTest.trackMateInterval(img, 0,
				FRAMES - 1));
		assertTrue(detector.checkInput() && detector.process(), () -> detector.getErrorMessage());
		final SpotCollection spots = detector.getResult();
		final List<Spot> all = new ArrayList<>();
		for (int t = 0; t < FRAMES; t++) {
			final List<Spot> inFrame = new ArrayList<>();
			spots.iterable(t, false).forEach(inFrame::add);
			inFrame.sort(null); // creation order = the core's order = the CSV's order
			all.addAll(inFrame);
		}
		assertEquals(rows.size(), all.size());
		for (int i = 0; i < rows.size(); i++) {
			final Map<String, String> row = rows.get(i);
			final Spot spot = all.get(i);
			for (final SpotColumn c : SpotColumn.values()) {
				if (c == SpotColumn.ID || c == SpotColumn.VISIBILITY) continue; // TrackMate's own, set by its filters
				if (c == SpotColumn.POSITION_T) continue; // TrackMate sets it from FRAME and its dt
				final double expected = Double.parseDouble(row.get(c.key()));
				final Double actual = spot.getFeature(c.key());
				assertEquals(expected, actual, 0, method.key() + ": " + c.key() + " of row " + i);
			}
		}
	}

	private static List<Map<String, String>> readCsv(final Path csv) throws Exception {
		final List<String> lines = Files.readAllLines(csv);
		final String[] header = lines.get(0).split(",");
		final List<Map<String, String>> rows = new ArrayList<>();
		for (final String line : lines.subList(1, lines.size())) {
			final String[] cells = line.split(",", -1);
			final Map<String, String> row = new HashMap<>();
			for (int i = 0; i < header.length; i++)
				row.put(header[i], cells[i]);
			rows.add(row);
		}
		return rows;
	}
}
