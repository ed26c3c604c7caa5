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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.process.FloatProcessor;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;
import io.github.contacttracker.ij.ImagePlusFrames;

/**
 * Reading a TIFF by offset (what the Spark job does through Hadoop) gives the very frames and calibration that
 * {@link ImageFiles#open} gives the command line, for every kind of TIFF the command line reads, uncompressed or
 * compressed; what the command line refuses is refused in its line, and other formats in one line that says how to
 * convert them.
 */
class OpenByOffsetTest {

	@TempDir
	Path dir;

	private static final int FRAMES = 5;

	@Test
	void everyUncompressedKindGivesTheCommandLinesFramesAndCalibration() throws IOException {
		final List<float[]> frames = TestMovies.frames(FRAMES, 20, 220);
		final List<Path> files = new ArrayList<>();
		for (final int[] type : new int[][] { { 8, 1 }, { 16, 1 }, { 16, 2 }, { 32, 1 }, { 32, 3 }, { 64, 3 } })
			for (final boolean big : new boolean[] { false, true }) {
				final Path tif = dir.resolve("m" + type[0] + "-" + type[1] + (big ? "-big" : "") + ".tif");
				TestMovies.writeTiff(tif, big, type[0], type[1], frames, null, 0);
				files.add(tif);
			}
		final Path ome = dir.resolve("movie.ome.tif");
		TestMovies.writeTiff(ome, false, 16, 1, frames, "<?xml version=\"1.0\"?><OME><Image><Pixels " +
			"DimensionOrder=\"XYZCT\" SizeC=\"1\" SizeZ=\"1\" SizeT=\"" + FRAMES + "\" PhysicalSizeX=\"0.5\"/></Image>" +
			"</OME>", 0);
		files.add(ome);
		// ImageJ's own writer: a calibrated hyperstack (pixel size, unit, frame interval in its description)
		final ImageStack stack = new ImageStack(TestMovies.W, TestMovies.H);
		for (final float[] f : frames)
			stack.addSlice(null, new FloatProcessor(TestMovies.W, TestMovies.H, f.clone()).convertToShort(false));
		final ImagePlus imp = new ImagePlus("cal", stack);
		imp.setDimensions(1, 1, FRAMES);
		imp.getCalibration().pixelWidth = imp.getCalibration().pixelHeight = 0.25;
		imp.getCalibration().setUnit("micron");
		imp.getCalibration().frameInterval = 0.01;
		imp.getCalibration().setTimeUnit("s");
		final Path cal = dir.resolve("calibrated.tif");
		assertTrue(new FileSaver(imp).saveAsTiffStack(cal.toString()));
		files.add(cal);

		for (final Path file : files) {
			final ImagePlusFrames cli = ImagePlusFrames.of(ImageFiles.open(file), 0);
			final ImagePlusFrames byOffset = ImagePlusFrames.of(ImageFiles.openByOffset(SeekableBytes.of(file)), 0);
			assertEquals(cli.frameCount(), byOffset.frameCount(), file.toString());
			assertEquals(FRAMES, byOffset.frameCount(), file.toString());
			assertEquals(cli.calibration(), byOffset.calibration(), file.toString());
			for (int t = 0; t < FRAMES; t++)
				assertArrayEquals(values(cli.frame(t)), values(byOffset.frame(t)), file + " frame " + (t + 1));
		}
		assertEquals(0.5, ImagePlusFrames.of(ImageFiles.openByOffset(SeekableBytes.of(ome)), 0).calibration()
			.pixelWidth());
		final Calibration c = ImagePlusFrames.of(ImageFiles.openByOffset(SeekableBytes.of(cal)), 0).calibration();
		assertEquals(0.25, c.pixelWidth());
		assertEquals(0.01, c.frameInterval());
	}

	@Test
	void otherFormatsAreRefusedInOneLineSayingHowToConvert() throws IOException {
		final Path png = dir.resolve("frame.png");
		Files.write(png, new byte[] { (byte) 0x89, 'P', 'N', 'G', 13, 10, 26, 10, 0, 0, 0, 13, 'I', 'H', 'D', 'R' });
		final IOException notTiff = assertThrows(IOException.class, () -> ImageFiles.openByOffset(SeekableBytes.of(
			png)));
		assertTrue(notTiff.getMessage().contains("not a TIFF") && notTiff.getMessage().contains("Save As > Tiff"),
			notTiff.getMessage());
		assertEquals(1, notTiff.getMessage().lines().count());
	}

	/**
	 * A grey movie compressed as TIFF writers do (LZW, Deflate under both its codes, PackBits; with and without the
	 * horizontal predictor; in strips) gives by offset the command line's frames; JPEG, which the command line
	 * refuses, is refused by offset in the very same line.
	 */
	@Test
	void compressedTiffGivesTheCommandLinesFramesOrItsRefusal() throws IOException {
		for (final int compression : new int[] { 5, 8, 32946, 32773 })
			for (final int predictor : new int[] { 1, 2 }) {
				final Path file = TiffLayoutsTest.write(dir.resolve("c" + compression + "-" + predictor + ".tif"),
					new TiffLayoutsTest.Page(TestMovies.W, TestMovies.H, 16, 1, 1, 1, 1, compression, predictor, 0, 7),
					FRAMES, java.nio.ByteOrder.LITTLE_ENDIAN);
				final ImagePlusFrames cli = ImagePlusFrames.of(ImageFiles.open(file), 0);
				final ImagePlusFrames byOffset = ImagePlusFrames.of(ImageFiles.openByOffset(SeekableBytes.of(file)), 0);
				assertEquals(FRAMES, cli.frameCount(), file.toString());
				assertEquals(FRAMES, byOffset.frameCount(), file.toString());
				assertEquals(cli.calibration(), byOffset.calibration(), file.toString());
				for (int t = 0; t < FRAMES; t++)
					assertArrayEquals(values(cli.frame(t)), values(byOffset.frame(t)), file + " frame " + (t + 1));
			}
		final Path jpeg = TiffLayoutsTest.write(dir.resolve("jpeg.tif"), new TiffLayoutsTest.Page(TestMovies.W,
			TestMovies.H, 8, 1, 1, 1, 1, 7, 1, 0, TestMovies.H), FRAMES, java.nio.ByteOrder.LITTLE_ENDIAN);
		final IOException byFile = assertThrows(IOException.class, () -> ImageFiles.open(jpeg));
		final IOException byOffset = assertThrows(IOException.class, () -> ImageFiles.openByOffset(SeekableBytes.of(
			jpeg)));
		assertEquals(byFile.getMessage(), byOffset.getMessage());
		assertTrue(byOffset.getMessage().contains("JPEG-compressed TIFF is not supported"), byOffset.getMessage());
		assertEquals(1, byOffset.getMessage().lines().count());
	}

	private static double[] values(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		final List<Double> v = new ArrayList<>();
		frame.forEach(p -> v.add(p.getRealDouble()));
		return v.stream().mapToDouble(Double::doubleValue).toArray();
	}
}
