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

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import ij.ImagePlus;
import ij.process.ImageProcessor;

/**
 * A folder of frames (TIFF, PNG or JPEG, one 2D image per file) as a virtual stack, in natural order
 * ({@code frame2} before {@code frame10}); each file is opened when its frame is needed. Every frame must have the
 * first one's size and bit depth. A frame stored in colour whose red, green and blue are equal is grey (JPEG codes
 * grey pictures in colour too: {@link RgbPixels#grey}); a folder of colour frames is a colour movie, of which one
 * channel is tracked.
 */
final class FolderMovie {

	private FolderMovie() {}

	/** The file name extensions taken as frames. */
	static final List<String> EXTENSIONS = List.of(".tif", ".tiff", ".png", ".jpg", ".jpeg");

	/** Natural order: runs of digits compare as numbers, the rest ignoring case; ties by the plain name. */
	static final Comparator<String> NATURAL = FolderMovie::compareNatural;

	static ImagePlus open(final Path folder) throws IOException {
		final List<Path> files;
		try (Stream<Path> s = Files.list(folder)) {
			files = s.filter(Files::isRegularFile).filter(p -> !p.getFileName().toString().startsWith(".")).filter(
				FolderMovie::isFrame).sorted(Comparator.comparing(p -> p.getFileName().toString(), NATURAL)).toList();
		}
		if (files.isEmpty()) throw new IOException("cannot read folder " + folder + ": it holds no TIFF, PNG or JPEG " +
			"frames");
		final ImageProcessor first = read(files.get(0), 0, 0, 0);
		final int w = first.getWidth(), h = first.getHeight(), bits = first.getBitDepth();
		final FileStack stack = new FileStack(folder.resolve(files.get(0).getFileName()), files.size(), w, h, false,
			t -> read(files.get(t), w, h, bits));
		stack.setBitDepth(bits);
		return new ImagePlus(folder.getFileName() == null ? folder.toString() : folder.getFileName().toString(), stack);
	}

	private static boolean isFrame(final Path p) {
		final String name = p.getFileName().toString().toLowerCase(Locale.ROOT);
		return EXTENSIONS.stream().anyMatch(name::endsWith);
	}

	/** Reads one frame file; {@code w = 0} for the first (which sets the size and bit depth). */
	private static ImageProcessor read(final Path file, final int w, final int h, final int bits) throws IOException {
		// each frame file through the checked readers: a folder may hold a broken or hostile file too
		final ImagePlus imp = ImageFiles.openFile(file);
		if (imp.getStackSize() > 1) throw new IOException("frame " + file + " has " + imp.getStackSize() + " planes: a " +
			"folder must hold one 2D image per frame");
		ImageProcessor ip;
		try {
			ip = imp.getProcessor();
		}
		catch (final java.io.UncheckedIOException e) {
			throw e.getCause();
		}
		// a grey picture stored in colour (JPEG often codes grey in colour) is grey, in a folder of grey frames or
		// first: exactly its grey levels
		if (ip.getBitDepth() == 24 && (w == 0 || bits == 8)) {
			final ImageProcessor grey = RgbPixels.grey(ip);
			if (grey != null) ip = grey;
		}
		if (w > 0 && (ip.getWidth() != w || ip.getHeight() != h || ip.getBitDepth() != bits))
			throw new IOException("frame " + file + " is " + ip.getWidth() + " x " + ip.getHeight() + ", " + ip
				.getBitDepth() + "-bit, unlike the first frame (" + w + " x " + h + ", " + bits + "-bit)");
		return ip;
	}

	private static int compareNatural(final String a, final String b) {
		int i = 0, j = 0;
		while (i < a.length() && j < b.length()) {
			final char ca = a.charAt(i), cb = b.charAt(j);
			if (Character.isDigit(ca) && Character.isDigit(cb)) {
				final int si = i, sj = j;
				while (i < a.length() && Character.isDigit(a.charAt(i)))
					i++;
				while (j < b.length() && Character.isDigit(b.charAt(j)))
					j++;
				// compare the numbers by value without parsing (any length): strip zeros, then length, then digits
				final String na = a.substring(si, i).replaceFirst("^0+(?=.)", ""), nb = b.substring(sj, j).replaceFirst(
					"^0+(?=.)", "");
				final int c = na.length() != nb.length() ? Integer.compare(na.length(), nb.length()) : na.compareTo(nb);
				if (c != 0) return c;
			}
			else {
				final int c = Character.compare(Character.toLowerCase(ca), Character.toLowerCase(cb));
				if (c != 0) return c;
				i++;
				j++;
			}
		}
		final int c = Integer.compare(a.length() - i, b.length() - j);
		return c != 0 ? c : a.compareTo(b);
	}
}
