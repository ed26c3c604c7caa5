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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.ij.ImagePlusFrames;
import ij.ImagePlus;

/**
 * One TIFF page of several samples stored plane after plane (PlanarConfiguration 2), as Python's
 * {@code tifffile.imwrite(path, stack)} stores a stack of 3 or 4 frames: ImageJ 1 reads the 16-bit ones not at all
 * and the 4-sample 8-bit one wrongly. Each sample is read as a channel, with its values, by file and by offset; a run
 * that does not choose one is refused in one line that says so and how to write frames instead.
 */
class PlanarSamplesTest {

	@TempDir
	Path dir;

	/** @return value of sample s at pixel (x, y): distinct per sample and pixel */
	private static int value(final int s, final int x, final int y, final int bits) {
		return (bits == 8 ? 10 : 1000) + 40 * s + x + 3 * y;
	}

	/** Writes one page, w x h, {@code samples} samples of {@code bits} bits, planar, photometric RGB, one strip each. */
	static Path write(final Path file, final int samples, final int bits, final int w, final int h) throws IOException {
		final int bytes = bits / 8, plane = w * h * bytes, entries = samples > 3 ? 12 : 11;
		final int ifd = 8, ifdSize = 2 + entries * 12 + 4;
		final int bitsAt = ifd + ifdSize, offsetsAt = bitsAt + 2 * samples, countsAt = offsetsAt + 4 * samples;
		final int extraAt = countsAt + 4 * samples, dataAt = extraAt + 2 * samples;
		final ByteBuffer b = ByteBuffer.allocate(dataAt + samples * plane).order(ByteOrder.LITTLE_ENDIAN);
		b.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt(ifd);
		b.putShort((short) entries);
		entry(b, 256, 4, 1, w);
		entry(b, 257, 4, 1, h);
		entry(b, 258, 3, samples, bitsAt);
		entry(b, 259, 3, 1, 1);
		entry(b, 262, 3, 1, 2);
		entry(b, 273, 4, samples, offsetsAt);
		entry(b, 277, 3, 1, samples);
		entry(b, 278, 4, 1, h);
		entry(b, 279, 4, samples, countsAt);
		entry(b, 284, 3, 1, 2);
		if (samples > 3) entry(b, 338, 3, samples - 3, samples - 3 == 1 ? 2 : extraAt);
		entry(b, 339, 3, 1, 1);
		b.putInt(0);
		for (int s = 0; s < samples; s++)
			b.putShort(bitsAt + 2 * s, (short) bits);
		for (int s = 0; s < samples; s++) {
			b.putInt(offsetsAt + 4 * s, dataAt + s * plane);
			b.putInt(countsAt + 4 * s, plane);
			b.putShort(extraAt + 2 * s, (short) 2);
		}
		b.position(dataAt);
		for (int s = 0; s < samples; s++)
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++)
					if (bits == 8) b.put((byte) value(s, x, y, bits));
					else b.putShort((short) value(s, x, y, bits));
		Files.write(file, b.array());
		return file;
	}

	/** An entry of count values of a type (3 SHORT, 4 LONG): the value itself when one, else where the values are. */
	private static void entry(final ByteBuffer b, final int tag, final int type, final int count, final int value) {
		b.putShort((short) tag).putShort((short) type).putInt(count);
		if (count == 1 && type == 3) b.putShort((short) value).putShort((short) 0);
		else b.putInt(value);
	}

	@ParameterizedTest
	@CsvSource({ "3, 16", "4, 16", "4, 8", "5, 8" })
	void eachSampleIsAChannelWithItsValues(final int samples, final int bits) throws IOException {
		final Path file = write(dir.resolve("t" + samples + "-" + bits + ".tif"), samples, bits, 12, 9);
		for (final ImagePlus imp : new ImagePlus[] { ImageFiles.open(file), ImageFiles.openByOffset(SeekableBytes.of(
			file)) })
		{
			assertEquals(samples, imp.getNChannels(), "channels");
			assertEquals(1, imp.getNFrames());
			assertEquals(bits, imp.getBitDepth());
			for (int s = 0; s < samples; s++) {
				final ij.process.ImageProcessor ip = imp.getStack().getProcessor(s + 1);
				for (int y = 0; y < 9; y++)
					for (int x = 0; x < 12; x++)
						assertEquals(value(s, x, y, bits), ip.get(x, y), "sample " + s + " at " + x + "," + y);
			}
			final InvalidInputException e = assertThrows(InvalidInputException.class, () -> ImagePlusFrames.of(imp, 0));
			assertTrue(e.getMessage().contains("has " + samples + " channels: choose one") && e.getMessage().contains(
				"photometric='minisblack'"), e.getMessage());
			assertEquals(value(1, 5, 4, bits), ImagePlusFrames.of(imp, 2).frame(0).getAt(5, 4).getRealDouble(), 1e-9);
		}
	}
}
