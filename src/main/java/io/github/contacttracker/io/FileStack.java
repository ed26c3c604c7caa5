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
import java.io.UncheckedIOException;
import java.nio.file.Path;

import ij.VirtualStack;
import ij.process.ImageProcessor;

/**
 * A virtual stack whose planes are read from a file (or folder) when asked for. A plane that cannot be read is an
 * {@link UncheckedIOException} naming the file and the reason: ImageJ's own virtual stacks log the error and
 * return a blank plane (or {@code null}), which would be tracked as data.
 */
final class FileStack extends VirtualStack {

	/** Reads one plane, 0-based. */
	@FunctionalInterface
	interface PlaneReader {
		/** @throws IOException naming the file and the reason */
		ImageProcessor read(int t) throws IOException;
	}

	private final int size;
	private final boolean concurrent;
	private final PlaneReader reader;
	private final String path;

	/**
	 * @param file the file or folder the planes come from, for messages
	 * @param size the number of planes
	 * @param concurrent whether {@code reader} may be called from several threads at once (each call opens the
	 *        file itself); if not, callers serialise ({@link #readsConcurrently()})
	 * @param reader reads plane {@code t} (0-based)
	 */
	FileStack(final Path file, final int size, final int width, final int height, final boolean concurrent,
		final PlaneReader reader)
	{
		this(file.toString(), file.toAbsolutePath().getParent() == null ? "/" : file.toAbsolutePath().getParent()
			.toString(), size, width, height, concurrent, reader);
	}

	/**
	 * @param file the file's name or address, for messages
	 * @param folder the folder ImageJ's virtual stack names ("" for none)
	 */
	FileStack(final String file, final String folder, final int size, final int width, final int height,
		final boolean concurrent, final PlaneReader reader)
	{
		super(width, height, null, folder);
		this.size = size;
		this.concurrent = concurrent;
		this.reader = reader;
		this.path = file;
	}

	/** @return whether planes may be read from several threads at once */
	boolean readsConcurrently() {
		return concurrent;
	}

	@Override
	public ImageProcessor getProcessor(final int n) {
		if (n < 1 || n > size) throw new IllegalArgumentException("plane " + n + " of " + size);
		try {
			final ImageProcessor ip = reader.read(n - 1);
			// a plane unlike the first is a damaged file, not a frame to track
			if (ip != null && (ip.getWidth() != getWidth() || ip.getHeight() != getHeight())) throw new IOException(
				"cannot read plane " + n + " of " + path + ": it is " + ip.getWidth() + " x " + ip.getHeight() +
					" pixels, not " + getWidth() + " x " + getHeight() + " like the first (damaged file?)");
			return ip;
		}
		catch (final IOException e) {
			throw new UncheckedIOException(e);
		}
		catch (final UncheckedIOException e) {
			throw e; // a reader's own message, naming the file
		}
		catch (final RuntimeException e) {
			throw new UncheckedIOException(new IOException("cannot read plane " + n + " of " + path + ": " + e, e));
		}
	}

	@Override
	public int getSize() {
		return size;
	}

	@Override
	public int size() {
		return size;
	}

	@Override
	public String getSliceLabel(final int n) {
		return null;
	}

	@Override
	public String getFileName(final int n) {
		return path;
	}
}
