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
package io.github.contacttracker.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ij.ImagePlus;
import ij.ImageStack;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.TiffLayoutsTest;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * A grey movie saved as a compressed TIFF stack (one sample per pixel, in strips: LZW, Deflate under both its codes,
 * PackBits, with and without the horizontal predictor), the way TIFF writers compress it, is read by the Spark job
 * as {@code track} reads it, and tracked to {@code track}'s CSV byte for byte; a compression {@code track} refuses
 * (JPEG) is refused by the job in {@code track}'s line. The movies are simulated touching pairs, written here.
 */
class SparkCompressedTiffTest {

	@TempDir
	static Path dir;

	/** The simulated movie's frames (6 frames of 206 x 140, 8- or 16-bit as the simulator writes them). */
	private static ImageStack frames;
	private static int bits;

	@BeforeAll
	static void simulate() {
		final Path pair = dir.resolve("pair.tif");
		final Object[] r = SparkTestMovies.cli("simulate", "--scenario", "pair", "--separation", "1.0", "--frames", "6",
			"--seed", "3", "--out", pair.toString(), "--truth", dir.resolve("truth.csv").toString());
		assertEquals(0, r[0], (String) r[2]);
		final ImagePlus imp = new ImagePlus(pair.toString());
		frames = imp.getStack();
		bits = imp.getBitDepth();
		assertTrue(bits == 8 || bits == 16, "an integer movie: " + bits + "-bit");
	}

	/** @return the simulated movie written as one-sample pages in strips of 16 rows, compressed so */
	private static Path compressed(final String name, final int compression, final int predictor) throws IOException {
		final TiffLayoutsTest.Page p = new TiffLayoutsTest.Page(frames.getWidth(), frames.getHeight(), bits, 1, 1, 1, 1,
			compression, predictor, 0, 16);
		return TiffLayoutsTest.write(dir.resolve(name), p, frames.getSize(), ByteOrder.LITTLE_ENDIAN, (t, s, x,
			y) -> frames.getProcessor(t + 1).getf(x, y));
	}

	/**
	 * Through the job's own reader ({@link Movies#open}: the file through Hadoop, every strip by its offset): every
	 * compression gives every frame with the values {@code track}'s reader gives, which are the simulated ones.
	 */
	@Test
	void everyCompressionIsReadThroughHadoopAsTrackReadsIt() throws IOException {
		for (final int compression : new int[] { 5, 8, 32946, 32773 })
			for (final int predictor : new int[] { 1, 2 }) {
				final Path file = compressed("read-" + compression + "-" + predictor + ".tif", compression, predictor);
				final ImagePlusFrames job = Movies.open(file.toUri().toString(), file.toString(), 0).frames();
				final ImagePlusFrames track = ImagePlusFrames.of(ImageFiles.open(file), 0);
				assertEquals(frames.getSize(), job.frameCount(), file.toString());
				assertEquals(track.frameCount(), job.frameCount(), file.toString());
				assertEquals(track.calibration(), job.calibration(), file.toString());
				for (int t = 0; t < frames.getSize(); t++) {
					final double[] simulated = new double[frames.getWidth() * frames.getHeight()];
					for (int i = 0; i < simulated.length; i++)
						simulated[i] = frames.getProcessor(t + 1).getf(i % frames.getWidth(), i / frames.getWidth());
					assertArrayEquals(simulated, values(job.frame(t)), file + " frame " + (t + 1));
					assertArrayEquals(values(track.frame(t)), values(job.frame(t)), file + " frame " + (t + 1));
				}
			}
	}

	/**
	 * The whole job on {@code local[2]}: LZW with the predictor, Deflate and PackBits movies tracked to
	 * {@code track}'s CSVs byte for byte, and a JPEG one refused with {@code track}'s message, the others written.
	 */
	@Test
	void theJobTracksCompressedMoviesAsTrackDoes() throws IOException {
		final List<String> movies = new ArrayList<>();
		movies.add(compressed("lzw.tif", 5, 2).toString());
		movies.add(compressed("deflate.tif", 8, 1).toString());
		movies.add(compressed("packbits.tif", 32773, 1).toString());
		final Path jpeg = compressed("jpeg.tif", 7, 1);
		movies.add(jpeg.toString());
		final Path cliDir = Files.createDirectories(dir.resolve("cli")), sparkDir = dir.resolve("spark");

		final List<String> cliArgs = new ArrayList<>(List.of("track"));
		cliArgs.addAll(movies);
		cliArgs.addAll(List.of("--out-dir", cliDir.toString()));
		final Object[] c = SparkTestMovies.cli(cliArgs.toArray(String[]::new));
		assertEquals(2, c[0], "the JPEG movie is refused: " + c[2]);
		final String trackError = ((String) c[2]).lines().filter(l -> l.startsWith("contact-tracker: error: " + jpeg))
			.findFirst().orElseThrow(() -> new AssertionError((String) c[2])).substring("contact-tracker: ".length());
		assertTrue(trackError.contains("JPEG-compressed TIFF is not supported"), trackError);

		final List<String> sparkArgs = new ArrayList<>(movies);
		sparkArgs.addAll(List.of("--out-dir", sparkDir.toString(), "--master", "local[2]"));
		final Object[] s = SparkTrackTest.spark(sparkArgs.toArray(String[]::new));
		assertEquals(SparkTrack.EXIT_BAD_INPUT, s[0], (String) s[2]);
		final List<String> errors = ((String) s[2]).lines().filter(l -> l.startsWith("contact-tracker-spark: error:"))
			.toList();
		assertEquals(List.of("contact-tracker-spark: " + trackError), errors);
		for (final String name : List.of("lzw.csv", "deflate.csv", "packbits.csv")) {
			final byte[] expected = Files.readAllBytes(cliDir.resolve(name));
			assertTrue(Files.readAllLines(cliDir.resolve(name)).size() > 1, name + " has spots");
			assertArrayEquals(expected, Files.readAllBytes(sparkDir.resolve(name)), name);
		}
	}

	private static double[] values(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		final List<Double> v = new ArrayList<>();
		frame.forEach(p -> v.add(p.getRealDouble()));
		return v.stream().mapToDouble(Double::doubleValue).toArray();
	}
}
