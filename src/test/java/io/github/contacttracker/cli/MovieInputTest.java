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
package io.github.contacttracker.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ij.IJ;
import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.plugin.filter.AVI_Writer;
import ij.process.ColorProcessor;
import ij.process.ImageProcessor;
import io.github.contacttracker.io.ProfileScenes;
import io.github.contacttracker.io.TestMovies;

/**
 * Real movies in, through the command line: every format the issue lists is written by ImageJ's own writers (or,
 * where ImageJ has none, by our test writer), tracked, and the spots compared with the particle's true track.
 */
class MovieInputTest {

	@TempDir
	Path dir;

	private static final int FRAMES = 4;

	/** Tracks {@code input}; returns the spots' (frame, x, y) from the CSV on stdout, after checking the run. */
	private static List<double[]> track(final Path input, final String threshold, final String... more) {
		final List<String> args = new ArrayList<>(List.of("track", input.toString(), "--threshold", threshold,
			"--r-out", "14", "--method", "paper"));
		args.addAll(List.of(more));
		final Object[] r = ContactTrackerCliTest.run(args.toArray(String[]::new));
		assertEquals(0, r[0], (String) r[2]);
		final List<double[]> spots = new ArrayList<>();
		final List<String> lines = ((String) r[1]).lines().toList();
		for (final String line : lines.subList(1, lines.size())) {
			final String[] c = line.split(",");
			spots.add(new double[] { Double.parseDouble(c[1]), Double.parseDouble(c[2]), Double.parseDouble(c[3]) });
		}
		return spots;
	}

	/** One spot per frame, in frame order, within {@code tolerance} px of the truth. */
	private static void assertTrack(final List<double[]> spots, final int frames, final double tolerance) {
		assertEquals(frames, spots.size(), "one spot per frame");
		for (int t = 0; t < frames; t++) {
			final double[] s = spots.get(t);
			assertEquals(t, (int) s[0]);
			assertEquals(TestMovies.x(t), s[1], tolerance, "x in frame " + t);
			assertEquals(TestMovies.y(), s[2], tolerance, "y in frame " + t);
		}
	}

	private static ImagePlus movie8() {
		return TestMovies.bytes(TestMovies.frames(FRAMES, 20, 220));
	}

	@Test
	void aviUncompressedJpegAndPng() throws IOException {
		for (final int compression : new int[] { AVI_Writer.NO_COMPRESSION, AVI_Writer.PNG_COMPRESSION,
			AVI_Writer.JPEG_COMPRESSION })
		{
			final Path avi = dir.resolve("movie" + compression + ".avi");
			new AVI_Writer().writeImage(movie8(), avi.toString(), compression, 95);
			// JPEG loses a little; the others are exact
			assertTrack(track(avi, "120"), FRAMES, compression == AVI_Writer.JPEG_COMPRESSION ? 0.1 : 0.02);
		}
	}

	/**
	 * A colour camera's movie: the particle in red, a second one mirrored left-right in blue, green a flat 30. Each
	 * chosen channel gives its own particle exactly as a grey movie of that channel would. Not chosen: red and blue
	 * vary alike, so neither holds the particles alone, and the mean of the three is tracked (as a grey scene through
	 * a colour camera would be), and said.
	 */
	@Test
	void aColourMovieTracksTheChosenChannel() throws IOException {
		final List<float[]> red = TestMovies.frames(FRAMES, 20, 220);
		final Path avi = colourAvi("colour.avi", red, 1);
		final Path redOnly = dir.resolve("red.tif");
		new FileSaver(TestMovies.bytes(red)).saveAsTiffStack(redOnly.toString());

		final List<double[]> fromRed = track(avi, "120", "--channel", "1");
		assertTrack(fromRed, FRAMES, 0.02);
		assertEquals(csv(track(redOnly, "120")), csv(fromRed), "the red channel is tracked as a grey movie of it");
		final List<double[]> fromBlue = track(avi, "120", "--channel", "3");
		assertEquals(FRAMES, fromBlue.size());
		for (int t = 0; t < FRAMES; t++)
			assertEquals(TestMovies.W - 1 - TestMovies.x(t), fromBlue.get(t)[1], 0.02, "the blue particle, mirrored");
		final Object[] r = ContactTrackerCliTest.run("track", avi.toString(), "--threshold", "70", "--r-out", "14");
		assertEquals(0, r[0], (String) r[2]);
		assertTrue(((String) r[2]).startsWith("contact-tracker: 'colour.avi' has colour frames: tracked in the mean of " +
			"red, green and blue (the channels' spread in frame 1: "), (String) r[2]);
		assertTrue(((String) r[2]).contains(", 0.0, "), "green is flat: " + r[2]);
	}

	/**
	 * The particle in red only (blue a tenth as bright, green flat), as in the paper authors' colour footage: red is
	 * chosen by itself, and said; the spots are those of the red channel chosen.
	 */
	@Test
	void aColourMovieWithTheParticlesInOneChannelTracksThatOne() throws IOException {
		final Path avi = colourAvi("red.avi", TestMovies.frames(FRAMES, 20, 220), 10);
		final Object[] chosen = ContactTrackerCliTest.run("track", avi.toString(), "--threshold", "120", "--r-out", "14",
			"--method", "paper");
		assertEquals(0, chosen[0], (String) chosen[2]);
		assertTrue(((String) chosen[2]).startsWith("contact-tracker: 'red.avi' has colour frames: tracked in red, the " +
			"channel with the particles' contrast"), (String) chosen[2]);
		assertEquals(csv(track(avi, "120", "--channel", "1")), csv(track(avi, "120")));
	}

	/**
	 * @param blueDivisor the blue particle (mirrored left-right) is the red one's brightness over this
	 * @return an uncompressed RGB AVI: the frames in red, a mirrored copy in blue, green a flat 30
	 */
	private Path colourAvi(final String name, final List<float[]> red, final int blueDivisor) throws IOException {
		final ImageStack rgb = new ImageStack(TestMovies.W, TestMovies.H);
		for (final float[] f : red) {
			final int[] px = new int[f.length];
			for (int i = 0; i < px.length; i++) {
				final int x = i % TestMovies.W, mirrored = i - x + TestMovies.W - 1 - x;
				px[i] = (int) f[i] << 16 | 30 << 8 | (int) f[mirrored] / blueDivisor;
			}
			rgb.addSlice(null, new ColorProcessor(TestMovies.W, TestMovies.H, px));
		}
		final Path avi = dir.resolve(name);
		new AVI_Writer().writeImage(new ImagePlus(name, rgb), avi.toString(), AVI_Writer.NO_COMPRESSION, 0);
		return avi;
	}

	/** A grey movie stored in colour (as MJPEG codes grey) is tracked as the grey movie, without a channel. */
	@Test
	void aGreyMovieStoredInColourIsGrey() throws IOException {
		final ImagePlus grey = movie8();
		final ImageStack rgb = new ImageStack(TestMovies.W, TestMovies.H);
		for (int t = 1; t <= FRAMES; t++)
			rgb.addSlice(null, grey.getStack().getProcessor(t).convertToRGB());
		final Path colour = dir.resolve("grey-in-colour.avi"), plain = dir.resolve("grey.avi");
		new AVI_Writer().writeImage(new ImagePlus("grey in colour", rgb), colour.toString(), AVI_Writer.NO_COMPRESSION,
			0);
		new AVI_Writer().writeImage(grey, plain.toString(), AVI_Writer.NO_COMPRESSION, 0);
		final List<double[]> spots = track(colour, "120");
		assertTrack(spots, FRAMES, 0.02);
		assertEquals(csv(track(plain, "120")), csv(spots));
		// frame 1, read to see that it is grey, is kept, not read again
		final io.github.contacttracker.ij.ImagePlusFrames frames = io.github.contacttracker.ij.ImagePlusFrames.of(
			io.github.contacttracker.io.ImageFiles.open(colour), 0);
		assertEquals(1, frames.reads(), "read to see its colours");
		frames.frame(0);
		assertEquals(1, frames.reads(), "not read again");
	}

	/**
	 * Dark particles (as the paper authors' toolbox's "inverted image"): a movie of the particle darker than the
	 * background, in 8 and 16 bits and 32-bit float, tracked with {@code --particles dark} gives exactly the spots of
	 * the bright movie it is the inverse of (255 - v, 65535 - v, -v), at the same threshold, and with the values the
	 * helper measures on each; the profile helper measures the same on both.
	 */
	@Test
	void darkParticlesAreTrackedAsTheInvertedMovie() throws IOException {
		final List<float[]> bright = TestMovies.frames(FRAMES, 20, 220);
		for (final int[] type : new int[][] { { 8, 1, 255 }, { 16, 1, 65535 }, { 32, 3, 0 } }) {
			final List<float[]> dark = new ArrayList<>();
			for (final float[] f : bright) {
				final float[] d = new float[f.length];
				for (int i = 0; i < d.length; i++)
					d[i] = type[2] - f[i];
				dark.add(d);
			}
			final Path b = dir.resolve("bright" + type[0] + ".tif"), d = dir.resolve("dark" + type[0] + ".tif");
			TestMovies.writeTiff(b, false, type[0], type[1], bright, null, 0);
			TestMovies.writeTiff(d, false, type[0], type[1], dark, null, 0);
			final List<double[]> fromDark = track(d, "120", "--particles", "dark");
			assertTrack(fromDark, FRAMES, 0.02);
			assertEquals(csv(track(b, "120")), csv(fromDark), type[0] + " bits");
		}
		// a frame the profile helper can measure on: several isolated particles
		final ImagePlus particles = ProfileScenes.particles("particles", 2, io.github.contacttracker.io.Calibration.PIXELS);
		assertEquals(8, particles.getBitDepth());
		final Path b = dir.resolve("bright8.tif"), d = dir.resolve("dark8.tif");
		new FileSaver(particles).saveAsTiffStack(b.toString());
		for (int t = 1; t <= particles.getStackSize(); t++)
			particles.getStack().getProcessor(t).invert(); // 255 - v
		new FileSaver(particles).saveAsTiffStack(d.toString());
		final Object[] measuredBright = ContactTrackerCliTest.run("track", b.toString());
		assertEquals(0, measuredBright[0], (String) measuredBright[2]);
		final String time = "[0-9.]+ s \\([0-9.]+ frames/s\\)";
		final Object[] measuredDark = ContactTrackerCliTest.run("track", d.toString(), "--particles", "dark");
		assertEquals(0, measuredDark[0], (String) measuredDark[2]);
		assertEquals(measuredBright[1], measuredDark[1], "the same values measured, the same spots");
		assertEquals(((String) measuredBright[2]).replace("bright8", "dark8").replaceAll(time, ""), ((String) measuredDark[2])
			.replaceAll(time, ""), "the same values measured");
		// not said: the helper sees that the frame is dark (its darkest pixel far further below its median than its
		// brightest above), says so, and measures the rest on the inverted frame
		final Object[] measured = ContactTrackerCliTest.run("track", d.toString());
		assertEquals(0, measured[0], (String) measured[2]);
		assertEquals(measuredBright[1], measured[1], "taken for dark particles");
		assertEquals(((String) measuredBright[2]).replace("bright8", "dark8").replace("profile helper:",
			"profile helper: --particles dark").replaceAll(time, ""), ((String) measured[2]).replaceAll(time, ""));
		// said bright: as said
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, ContactTrackerCliTest.run("track", d.toString(), "--particles",
			"bright")[0]);
		for (final String[] said : new String[][] { { "--particles", "dark" }, {} }) {
			final List<String> args = new ArrayList<>(List.of("profile", d.toString()));
			args.addAll(List.of(said));
			final Object[] profile = ContactTrackerCliTest.run(args.toArray(String[]::new));
			assertEquals(0, profile[0], (String) profile[2]);
			final String suggestion = ((String) profile[1]).lines().filter(l -> l.startsWith("suggested:")).findFirst()
				.orElseThrow();
			assertTrue(suggestion.endsWith(" --particles dark"), suggestion);
			assertEquals(((String) ContactTrackerCliTest.run("profile", b.toString())[1]).replace("bright8", "dark8")
				.replace(suggestion.replace(" --particles dark", ""), suggestion), profile[1]);
		}
	}

	private static String csv(final List<double[]> spots) {
		final StringBuilder b = new StringBuilder();
		for (final double[] s : spots)
			b.append(java.util.Arrays.toString(s)).append('\n');
		return b.toString();
	}

	@Test
	void aFolderOfFramesInNaturalOrder() throws IOException {
		final int n = 12; // frame2 must come before frame10
		final ImagePlus movie = TestMovies.bytes(TestMovies.frames(n, 20, 220));
		final Path folder = Files.createDirectories(dir.resolve("frames"));
		for (int t = 0; t < n; t++) {
			final ImagePlus one = new ImagePlus("f", movie.getStack().getProcessor(t + 1));
			final String name = "frame" + (t + 1);
			// a mix of formats, as exports are: PNG, TIFF and JPEG frames in one folder
			if (t % 3 == 0) new FileSaver(one).saveAsPng(folder.resolve(name + ".png").toString());
			else if (t % 3 == 1) new FileSaver(one).saveAsTiff(folder.resolve(name + ".tif").toString());
			else new FileSaver(one).saveAsJpeg(folder.resolve(name + ".jpg").toString());
		}
		Files.writeString(folder.resolve("notes.txt"), "not a frame");
		assertTrack(track(folder, "120"), n, 0.1);
	}

	@Test
	void multiPageTiffsOfEveryIntegerAndFloatType() throws IOException {
		final List<float[]> frames = TestMovies.frames(FRAMES, 20, 220);
		for (final int[] type : new int[][] { { 8, 1 }, { 16, 1 }, { 32, 1 }, { 32, 2 }, { 32, 3 }, { 64, 3 } }) {
			final Path tif = dir.resolve("movie" + type[0] + "-" + type[1] + ".tif");
			TestMovies.writeTiff(tif, false, type[0], type[1], frames, null, 0);
			assertTrack(track(tif, "120"), FRAMES, 0.02);
		}
	}

	@Test
	void signed16BitDataInTheFilesOwnValues() throws IOException {
		// data from -3000 to 3000: ImageJ stores them as 29768..35768 with a calibration function
		final List<float[]> frames = TestMovies.frames(FRAMES, -3000, 3000);
		final Path tif = dir.resolve("signed.tif");
		TestMovies.writeTiff(tif, false, 16, 2, frames, null, 0);
		assertTrack(track(tif, "150"), FRAMES, 0.02);
		final Object[] r = ContactTrackerCliTest.run("track", tif.toString(), "--threshold", "30000", "--r-out", "14");
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0]);
		assertTrue(((String) r[2]).contains("threshold 30000 is outside the data range [-3000, 29"), (String) r[2]);
		// the same through ImageJ's writer (which stores the offset values and the calibration function)
		final Path bigTiffSigned = dir.resolve("signed-big.tif");
		TestMovies.writeTiff(bigTiffSigned, true, 16, 2, frames, null, 0);
		assertTrack(track(bigTiffSigned, "150"), FRAMES, 0.02);
	}

	@Test
	void bigTiffWithPixelsBeyondFourGigabytes() throws IOException {
		final Path tif = dir.resolve("big.tif");
		final long beyond = (1L << 32) + 12345; // sparse: the gap takes no disk space
		TestMovies.writeTiff(tif, true, 16, 1, TestMovies.frames(FRAMES, 20, 220), null, beyond);
		assertTrue(Files.size(tif) > beyond);
		assertTrack(track(tif, "120"), FRAMES, 0.02);
	}

	@Test
	void omeTiffPlanesAreTimePointsAndOtherOrdersAreRefused() throws IOException {
		final List<float[]> frames = TestMovies.frames(FRAMES, 20, 220);
		final Path ome = dir.resolve("movie.ome.tif");
		TestMovies.writeTiff(ome, false, 16, 1, frames, "<?xml version=\"1.0\"?><OME><Image><Pixels " +
			"DimensionOrder=\"XYZCT\" SizeC=\"1\" SizeZ=\"1\" SizeT=\"" + FRAMES + "\" PhysicalSizeX=\"0.5\"/></Image>" +
			"</OME>", 0);
		final Object[] r = ContactTrackerCliTest.run("track", ome.toString(), "--threshold", "120", "--r-out", "14",
			"--method", "paper");
		assertEquals(0, r[0], (String) r[2]);
		final List<String> lines = ((String) r[1]).lines().toList();
		assertEquals(FRAMES + 1, lines.size());
		// PhysicalSizeX sets the calibration: positions in microns
		assertEquals(TestMovies.x(1) * 0.5, Double.parseDouble(lines.get(2).split(",")[2]), 0.01);

		final Path mixed = dir.resolve("mixed.ome.tif");
		TestMovies.writeTiff(mixed, false, 16, 1, frames, "<OME><Pixels DimensionOrder=\"XYTCZ\" SizeC=\"2\" " +
			"SizeZ=\"1\" SizeT=\"2\"/></OME>", 0);
		final Object[] bad = ContactTrackerCliTest.run("track", mixed.toString(), "--threshold", "120", "--r-out", "14");
		assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, bad[0]);
		assertTrue(((String) bad[2]).contains("OME-TIFF with planes in XYTCZ order"), (String) bad[2]);
	}

	/**
	 * A TIFF saved at 96 pixels per inch (a camera program's or a screenshot's resolution tags): ImageJ reads it in
	 * inches, and so are the spots' positions; the run says so. A movie in pixels or in microns says nothing.
	 */
	@Test
	void aMovieCalibratedInInchesSaysThePositionsAreInInches() throws IOException {
		final ImagePlus particles = ProfileScenes.particles("particles", 2, io.github.contacttracker.io.Calibration.PIXELS);
		final Path pixels = dir.resolve("pixels.tif"), inches = dir.resolve("inches.tif");
		new FileSaver(particles).saveAsTiffStack(pixels.toString());
		final ij.measure.Calibration dpi = particles.getCalibration().copy();
		dpi.setUnit("inch");
		dpi.pixelWidth = dpi.pixelHeight = 1 / 96.0;
		particles.setCalibration(dpi);
		new FileSaver(particles).saveAsTiffStack(inches.toString());
		final Object[] inPixels = ContactTrackerCliTest.run("track", pixels.toString());
		final Object[] inInches = ContactTrackerCliTest.run("track", inches.toString());
		assertEquals(0, inInches[0], (String) inInches[2]);
		assertFalse(((String) inPixels[2]).contains("is calibrated"), (String) inPixels[2]);
		assertTrue(((String) inInches[2]).contains("inches.tif is calibrated: the spots' positions and sizes are in " +
			"inch, a pixel 0.010417 x 0.010417 inch"), (String) inInches[2]);
		final String[] first = ((String) inPixels[1]).lines().skip(1).findFirst().orElseThrow().split(",");
		final String[] firstInches = ((String) inInches[1]).lines().skip(1).findFirst().orElseThrow().split(",");
		assertEquals(Double.parseDouble(first[2]) / 96, Double.parseDouble(firstInches[2]), 1e-9);
	}

	@Test
	void anUnreadableMovieIsOneLineNamingTheFileAndTheReason() throws IOException {
		final Path avi = dir.resolve("broken.avi");
		new AVI_Writer().writeImage(movie8(), avi.toString(), AVI_Writer.JPEG_COMPRESSION, 90);
		final byte[] all = Files.readAllBytes(avi);
		Files.write(avi, java.util.Arrays.copyOf(all, 300)); // truncated inside the header
		final Path empty = Files.createDirectories(dir.resolve("empty"));
		final Path compressedBig = dir.resolve("half-float.tif");
		TestMovies.writeTiff(compressedBig, true, 16, 3, TestMovies.frames(1, 0, 1), null, 0);
		for (final Path bad : List.of(avi, empty, compressedBig)) {
			final Object[] r = ContactTrackerCliTest.run("track", bad.toString(), "--threshold", "120", "--r-out", "14");
			final String err = ((String) r[2]).trim();
			assertEquals(ContactTrackerCli.EXIT_BAD_INPUT, r[0], err);
			assertEquals(1, err.lines().count(), err);
			assertTrue(err.contains(bad.toString()), err);
			assertFalse(err.contains("null"), err);
		}
	}

	@Test
	void aVirtualStackIsReadFrameByFrame() throws IOException {
		final Path tif = dir.resolve("stack.tif");
		IJ.saveAsTiff(movie8(), tif.toString());
		final ImagePlus imp = io.github.contacttracker.io.ImageFiles.open(tif);
		assertTrue(imp.getStack().isVirtual());
		final io.github.contacttracker.ij.ImagePlusFrames frames = io.github.contacttracker.ij.ImagePlusFrames.of(imp,
			0);
		assertEquals(FRAMES, frames.frameCount());
		assertEquals(0, frames.reads(), "nothing is read before it is asked for");
		final ImageProcessor expected = movie8().getStack().getProcessor(3);
		final var f = frames.frame(2).randomAccess();
		f.setPosition(new int[] { 25, 23 });
		assertEquals(expected.get(25, 23), f.get().getRealDouble());
		frames.frame(2);
		assertEquals(1, frames.reads(), "a frame asked for twice in a row is read once");
	}
}
