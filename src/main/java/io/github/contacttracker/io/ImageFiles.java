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
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.process.ImageProcessor;
import ij.io.Opener;
import ij.plugin.AVI_Reader;

/** Opening and saving images with ImageJ's readers and writers (headless). */
public final class ImageFiles {

	private ImageFiles() {}

	/**
	 * Opens a movie or an image for tracking, frames read from disk as they are needed wherever the format allows
	 * (a virtual stack), so that a movie of any size fits a fixed heap:
	 * <ul>
	 * <li>TIFF, multi-page TIFF, ImageJ hyperstacks, BigTIFF, OME-TIFF, 64-bit float TIFF ({@link TiffMovie});</li>
	 * <li>AVI: uncompressed, MJPEG or PNG-coded, what ImageJ 1's {@code AVI_Reader} reads; colour frames stay RGB
	 * (MJPEG codes even grey movies in colour: {@link RgbPixels} tells those from colour ones);</li>
	 * <li>a folder of TIFF, PNG or JPEG frames, one image per file, in natural order ({@link FolderMovie});</li>
	 * <li>any other single image ImageJ 1 opens (PNG, JPEG, GIF, BMP, ...), read whole.</li>
	 * </ul>
	 *
	 * @throws IOException with a one-line message naming the file and the reason when it cannot be read
	 */
	public static ImagePlus open(final Path file) throws IOException {
		if (!Files.exists(file)) throw new IOException("file not found: " + file);
		if (!Files.isReadable(file)) throw new IOException("cannot read " + file + ": permission denied");
		try {
			return Files.isDirectory(file) ? FolderMovie.open(file) : openFile(file);
		}
		catch (final UncheckedIOException e) {
			throw e.getCause();
		}
		catch (final RuntimeException e) {
			throw new IOException("cannot read " + file + " as an image: " + e, e);
		}
	}

	/** Opens a file (not a folder): what its first bytes say it is, each reader checking what the file declares. */
	static ImagePlus openFile(final Path file) throws IOException {
		if (Files.size(file) == 0) throw new IOException("cannot read " + file + ": it is empty (0 bytes)");
		final byte[] head = head(file);
		if (TiffMovie.isTiff(head)) return TiffMovie.open(file);
		if (isAvi(head)) return avi(file);
		return single(file);
	}

	/**
	 * Opens one image of a format other than TIFF and AVI (PNG, JPEG, GIF, BMP, ...) with ImageJ's opener, its
	 * messages caught and turned into the one line.
	 */
	private static ImagePlus single(final Path file) throws IOException {
		PictureHeader.check(file);
		final ImageJMessages.Result<ImagePlus> imp = ImageJMessages.call(file, () -> new Opener().openImage(file
			.toAbsolutePath().toString()));
		if (imp.value() == null) throw new IOException("cannot read " + file + " as an image: " + (imp.messages()
			.isEmpty() || imp.messages().startsWith("Unsupported format") ? "not a format ImageJ reads (TIFF, AVI, " +
				"PNG, JPEG, a folder of frames, ...)" : imp.messages()));
		return imp.value();
	}

	private static byte[] head(final Path file) throws IOException {
		try (InputStream in = Files.newInputStream(file)) {
			return in.readNBytes(16);
		}
	}

	private static boolean isAvi(final byte[] head) {
		return head.length >= 12 && new String(head, 0, 4, StandardCharsets.ISO_8859_1).equals("RIFF") && new String(
			head, 8, 4, StandardCharsets.ISO_8859_1).equals("AVI ");
	}

	private static ImagePlus avi(final Path file) throws IOException {
		AviHeader.check(file);
		final AVI_Reader reader = new AVI_Reader();
		// virtual, colour kept, not flipped; its messages caught (its error text is our line)
		final ImageJMessages.Result<ImageStack> made = ImageJMessages.call(file, () -> reader.makeStack(file
			.toAbsolutePath().toString(), 1, 0, true, false, false));
		final ImageStack avi = made.value();
		if (avi == null || avi.size() == 0 || reader.getErrorText() != null) throw new IOException("cannot read " +
			file + " as an AVI movie: " + InvalidInputException.oneLine(reader.getErrorText() != null ? reader
				.getErrorText() : made.messages().isEmpty() ? "no frames" : made.messages()));
		final FileStack stack = new FileStack(file, avi.size(), avi.getWidth(), avi.getHeight(), false, t -> {
			// AVI_Reader reports a bad frame as null (and a message): name the file and frame instead
			final ImageJMessages.Result<ImageProcessor> ip = ImageJMessages.call(file, () -> avi.getProcessor(t + 1));
			if (ip.value() == null) throw new IOException("cannot read frame " + (t + 1) + " of " + file + " (damaged " +
				"AVI" + (ip.messages().isEmpty() ? "?)" : ": " + ip.messages() + ")"));
			return ip.value();
		});
		final ImageProcessor first = stack.getProcessor(1);
		stack.setBitDepth(first.getBitDepth());
		return new ImagePlus(file.getFileName().toString(), stack);
	}

	/**
	 * Opens a TIFF, BigTIFF or OME-TIFF movie read plane by plane by offset from {@code bytes}, wherever they live
	 * (the Spark job reads through Hadoop's file systems): the same frames and calibration as {@link #open(Path)} for
	 * uncompressed data. Other formats and compressed TIFF are refused in one line that says how to convert them.
	 *
	 * @throws IOException with a one-line message naming the file
	 */
	public static ImagePlus openByOffset(final SeekableBytes bytes) throws IOException {
		final String name = bytes.name();
		final String title = name.substring(name.lastIndexOf('/') + 1);
		try {
			return TiffMovie.openByOffset(bytes, title);
		}
		catch (final UncheckedIOException e) {
			throw e.getCause();
		}
		catch (final RuntimeException e) {
			throw new IOException("cannot read " + name + " as an image: " + e, e);
		}
	}

	/**
	 * @param stack the planes of an image these readers opened (or any other)
	 * @return whether its planes may be read from several threads at once: each read of a TIFF plane opens the file
	 *         itself; ImageJ's virtual stacks (its AVI reader shares one file handle) and those of others are read
	 *         one at a time
	 */
	public static boolean readsConcurrently(final ImageStack stack) {
		return stack instanceof FileStack files && files.readsConcurrently();
	}

	/**
	 * @return of an image whose channels are a TIFF file's samples, what they are and, for a user who wrote frames
	 *         so, how to write them as frames (said when a run does not choose a channel); null for any other image
	 */
	public static String samples(final ImagePlus imp) {
		return imp.getProperty(TiffMovie.SAMPLES) instanceof String samples ? samples : null;
	}

	/** Saves {@code imp} as a TIFF (stack), atomically: nothing appears at {@code file} if saving fails. */
	public static void saveTiff(final ImagePlus imp, final Path file) throws IOException {
		final Path abs = file.toAbsolutePath();
		if (abs.getParent() == null || !Files.isDirectory(abs.getParent()))
			throw new IOException("cannot write " + file + ": folder " + abs.getParent() + " does not exist");
		final Path tmp = Files.createTempFile(abs.getParent(), "." + abs.getFileName(), ".part.tif");
		boolean done = false;
		try {
			final FileSaver saver = new FileSaver(imp);
			final boolean ok = imp.getStackSize() > 1 ? saver.saveAsTiffStack(tmp.toString()) : saver.saveAsTiff(tmp
				.toString());
			if (!ok) throw new IOException("could not write " + file);
			Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
			done = true;
		}
		finally {
			if (!done) Files.deleteIfExists(tmp);
		}
	}
}
