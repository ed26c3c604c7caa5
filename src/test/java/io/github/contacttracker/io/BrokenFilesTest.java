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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.io.ReaderContract.Outcome;

/**
 * The mutation suite: small valid files of every format, each changed the ways archives break and headers lie
 * (sizes, offsets, directory loops, sample formats, compression tags, truncation, random header bytes), and every
 * result held to {@link ReaderContract}: read, or refused in one line naming the file, within a few seconds,
 * ImageJ printing nothing. The cases of issue 24 are asserted refused.
 */
class BrokenFilesTest {

	@TempDir
	static Path dir;

	private static Map<String, byte[]> seeds;

	/** Longest a case may take: any file is read or refused within this. */
	private static final Duration BOUND = Duration.ofSeconds(10);

	@BeforeAll
	static void seeds() throws IOException {
		seeds = SeedFiles.all(Files.createDirectories(dir.resolve("seeds")));
	}

	@AfterAll
	static void forget() {
		seeds = null;
	}

	private static Outcome check(final String name, final byte[] bytes) throws IOException {
		final Path file = dir.resolve(name);
		Files.write(file, bytes);
		return assertTimeoutPreemptively(BOUND, () -> ReaderContract.check(file, 8), name);
	}

	private static Outcome tiff(final String seed, final String name, final UnaryOperator<SeedFiles.Tiff> change)
		throws IOException
	{
		return check(seed.replace(".tif", "") + "-" + name + ".tif", change.apply(new SeedFiles.Tiff(seeds.get(seed)))
			.bytes);
	}

	@Test
	void theSeedsAreRead() throws IOException {
		for (final Map.Entry<String, byte[]> seed : seeds.entrySet())
			assertEquals(Outcome.READ, check("valid-" + seed.getKey(), seed.getValue()), seed.getKey());
	}

	@Test
	void theCasesOfTheIssueAreRefused() throws IOException {
		assertEquals(Outcome.REFUSED, check("empty.tif", new byte[0]));
		assertEquals(Outcome.REFUSED, check("empty.png", new byte[0]));
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			final int first = new SeedFiles.Tiff(seeds.get(seed)).ifd;
			assertEquals(Outcome.REFUSED, tiff(seed, "loop-to-first", t -> t.next(0, first)));
			assertEquals(Outcome.REFUSED, tiff(seed, "last-loops-to-first", t -> t.next(99, first)));
			assertEquals(Outcome.REFUSED, tiff(seed, "huge-width", t -> t.set(256, 0x7fff_fff0L)));
			assertEquals(Outcome.REFUSED, tiff(seed, "huge-both", t -> t.set(256, 60000).set(257, 60000)));
			assertEquals(Outcome.REFUSED, tiff(seed, "zero-height", t -> t.set(257, 0)));
			assertEquals(Outcome.REFUSED, tiff(seed, "strip-past-end", t -> t.set(273, seeds.get(seed).length + 10)));
		}
		// the AVI's 'hdrl' list claims more bytes than there are
		final byte[] avi = seeds.get("movie.avi").clone();
		ByteBuffer.wrap(avi).order(ByteOrder.LITTLE_ENDIAN).putInt(16, 0x7fff_ff00);
		assertEquals(Outcome.REFUSED, check("list-length.avi", avi));
		final byte[] wide = seeds.get("movie.avi").clone();
		final int strf = indexOf(wide, "strf");
		ByteBuffer.wrap(wide).order(ByteOrder.LITTLE_ENDIAN).putInt(strf + 12, 1 << 30);
		assertEquals(Outcome.REFUSED, check("huge-width.avi", wide));
	}

	/**
	 * The Spark job reads a movie by offset ({@link ImageFiles#openByOffset}, through Hadoop): its directories are
	 * checked by the same {@link TiffDirectories}, so the issue's TIFF cases and a stack that claims more images than
	 * it holds are refused there too, in one line naming the file, in bounded time.
	 */
	@Test
	void theCasesOfTheIssueAreRefusedWhenReadByOffset() throws IOException {
		final List<Path> cases = new ArrayList<>();
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			final int first = new SeedFiles.Tiff(seeds.get(seed)).ifd;
			final Map<String, UnaryOperator<SeedFiles.Tiff>> changes = Map.of("loop-to-first", t -> t.next(0, first),
				"last-loops-to-first", t -> t.next(99, first), "huge-width", t -> t.set(256, 0x7fff_fff0L), "huge-both",
				t -> t.set(256, 60000).set(257, 60000), "zero-height", t -> t.set(257, 0), "strip-past-end", t -> t.set(
					273, seeds.get(seed).length + 10));
			for (final Map.Entry<String, UnaryOperator<SeedFiles.Tiff>> c : changes.entrySet()) {
				final Path file = dir.resolve("offset-" + seed.replace(".tif", "") + "-" + c.getKey() + ".tif");
				Files.write(file, c.getValue().apply(new SeedFiles.Tiff(seeds.get(seed))).bytes);
				cases.add(file);
			}
		}
		final byte[] more = seeds.get("imagej.tif").clone();
		final int at = new String(more, StandardCharsets.ISO_8859_1).indexOf("images=3");
		System.arraycopy("images=9".getBytes(StandardCharsets.ISO_8859_1), 0, more, at, 8);
		cases.add(Files.write(dir.resolve("offset-more-images.tif"), more));
		for (final Path file : cases) {
			final IOException e = assertTimeoutPreemptively(BOUND, () -> assertThrows(IOException.class,
				() -> ImageFiles.openByOffset(SeekableBytes.of(file)).getStack().getProcessor(1), file.toString()));
			assertTrue(e.getMessage().startsWith("cannot read " + file + ": "), e.getMessage());
			assertEquals(1, e.getMessage().lines().count(), e.getMessage());
		}
	}

	private static int indexOf(final byte[] bytes, final String fourcc) {
		final byte[] f = fourcc.getBytes(StandardCharsets.ISO_8859_1);
		for (int i = 0; i + 4 <= bytes.length; i++)
			if (Arrays.equals(bytes, i, i + 4, f, 0, 4)) return i;
		throw new IllegalArgumentException(fourcc);
	}

	/** Every mutation of every TIFF seed. */
	@TestFactory
	List<DynamicTest> tiffHeaderMutations() {
		final List<DynamicTest> tests = new ArrayList<>();
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			final List<Object[]> cases = new ArrayList<>();
			for (final long v : new long[] { 0, 1, 65535, 0x7fff_ffffL, 0xffff_ffffL, -1 }) {
				cases.add(new Object[] { "width-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(256, v) });
				cases.add(new Object[] { "height-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(257, v) });
				cases.add(new Object[] { "strip-offset-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(273, v) });
				cases.add(new Object[] { "strip-bytes-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(279, v) });
				cases.add(new Object[] { "strip-count-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.count(273, v) });
				cases.add(new Object[] { "entries-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.entries(v) });
				cases.add(new Object[] { "next-" + v, (UnaryOperator<SeedFiles.Tiff>) t -> t.next(0, v) });
			}
			for (final long bits : new long[] { 0, 1, 4, 12, 24, 64, 128, 65535 })
				cases.add(new Object[] { "bits-" + bits, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(258, bits) });
			for (final long format : new long[] { 0, 2, 3, 4, 6, 99 })
				cases.add(new Object[] { "format-" + format, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(339, format) });
			for (final long c : new long[] { 2, 5, 7, 8, 32773, 34712, 65535 })
				cases.add(new Object[] { "compression-" + c, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(259, c) });
			for (final long s : new long[] { 0, 2, 3, 4, 1000 })
				cases.add(new Object[] { "samples-" + s, (UnaryOperator<SeedFiles.Tiff>) t -> t.set(277, s) });
			cases.add(new Object[] { "next-self", (UnaryOperator<SeedFiles.Tiff>) t -> t.next(0, t.ifd) });
			for (final Object[] c : cases) {
				@SuppressWarnings("unchecked")
				final UnaryOperator<SeedFiles.Tiff> change = (UnaryOperator<SeedFiles.Tiff>) c[1];
				tests.add(DynamicTest.dynamicTest(seed + " " + c[0], () -> tiff(seed, (String) c[0], t -> {
					try {
						return change.apply(t);
					}
					catch (final IllegalArgumentException e) {
						return t; // a tag this seed does not have: the seed itself
					}
				})));
			}
		}
		return tests;
	}

	/** Every seed cut short at lengths inside its header, its directories and its data. */
	@TestFactory
	List<DynamicTest> truncation() {
		final List<DynamicTest> tests = new ArrayList<>();
		for (final Map.Entry<String, byte[]> seed : seeds.entrySet()) {
			final int n = seed.getValue().length;
			for (final int length : new int[] { 1, 4, 8, 12, 16, 24, 64, 200, n / 4, n / 2, n - 100, n - 1 })
				if (length > 0 && length < n) tests.add(DynamicTest.dynamicTest(seed.getKey() + " cut at " + length,
					() -> check("cut" + length + "-" + seed.getKey(), Arrays.copyOf(seed.getValue(), length))));
		}
		return tests;
	}

	/** Random bytes in every seed's first 512 bytes (its header and directories), 40 files per seed, seeded. */
	@TestFactory
	List<DynamicTest> randomHeaderBytes() {
		final List<DynamicTest> tests = new ArrayList<>();
		for (final Map.Entry<String, byte[]> seed : seeds.entrySet()) {
			final Random random = new Random(seed.getKey().hashCode());
			for (int k = 0; k < 40; k++) {
				final byte[] bytes = SeedFiles.randomHeaderBytes(seed.getValue(), random);
				final String name = "random" + k + "-" + seed.getKey();
				tests.add(DynamicTest.dynamicTest(seed.getKey() + " random " + k, () -> check(name, bytes)));
			}
		}
		return tests;
	}

	@Test
	void aPictureThatDeclaresAHugeSizeIsRefused() throws IOException {
		final byte[] png = seeds.get("image.png").clone();
		ByteBuffer.wrap(png).putInt(16, 0x7fff_ffff).putInt(20, 0x7fff_ffff); // IHDR width and height
		assertEquals(Outcome.REFUSED, check("huge.png", png));
		// what the fuzzer found: ImageJ takes it for DICOM and allocates an element's declared length
		final Path dicom = Path.of(System.getProperty("basedir", ".")).resolve(
			"src/test/resources/io/github/contacttracker/io/ReaderFuzzTestInputs/readers/finding-dicom-element-length");
		assertEquals(Outcome.REFUSED, check("dicom-like.dcm", Files.readAllBytes(dicom)));
	}

	@Test
	void aBrokenFrameInAFolderIsRefusedNamingTheFolder() throws IOException {
		for (final String broken : List.of("loop", "cut", "empty")) {
			final Path folder = Files.createDirectories(dir.resolve("frames-" + broken));
			Files.write(folder.resolve("frame1.png"), seeds.get("image.png"));
			final byte[] png = seeds.get("image.png");
			Files.write(folder.resolve("frame2.png"), png);
			final SeedFiles.Tiff loop = new SeedFiles.Tiff(seeds.get("pages16.tif"));
			Files.write(folder.resolve("frame3.tif"), broken.equals("loop") ? loop.next(0, loop.ifd).bytes : broken
				.equals("cut") ? Arrays.copyOf(png, png.length / 2) : new byte[0]);
			assertEquals(Outcome.REFUSED, assertTimeoutPreemptively(BOUND, () -> ReaderContract.check(folder, 8)),
				broken);
		}
	}

	@Test
	void anImageJStackThatClaimsMoreImagesThanItHoldsIsRefused() throws IOException {
		final byte[] bytes = seeds.get("imagej.tif").clone();
		final String text = new String(bytes, StandardCharsets.ISO_8859_1);
		final int at = text.indexOf("images=3");
		System.arraycopy("images=9".getBytes(StandardCharsets.ISO_8859_1), 0, bytes, at, 8);
		assertEquals(Outcome.REFUSED, check("more-images.tif", bytes));
	}
}
