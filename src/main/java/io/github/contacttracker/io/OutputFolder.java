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

import io.github.contacttracker.core.InvalidInputException;

/** The folder a run writes its files into ({@code --out-dir}): made when it does not exist, as users expect. */
public final class OutputFolder {

	private OutputFolder() {}

	/**
	 * Makes the folder (and its parents) when it does not exist.
	 *
	 * @return the folder
	 * @throws InvalidInputException in one line when it is a file, cannot be made, or cannot be written
	 */
	public static Path prepare(final Path dir) {
		if (Files.exists(dir) && !Files.isDirectory(dir)) throw new InvalidInputException("--out-dir " + dir +
			" is a file, not a folder");
		try {
			Files.createDirectories(dir);
		}
		catch (final IOException | SecurityException e) {
			throw new InvalidInputException("--out-dir " + dir + " cannot be made: " + e.getMessage());
		}
		if (!Files.isWritable(dir)) throw new InvalidInputException("--out-dir " + dir + " cannot be written");
		return dir;
	}

	/**
	 * @return the outermost folder {@link #prepare} would make for {@code dir} (itself or a parent), or null when
	 *         {@code dir} exists
	 */
	public static Path missing(final Path dir) {
		Path first = null;
		for (Path p = dir.toAbsolutePath().normalize(); p != null && !Files.exists(p); p = p.getParent())
			first = p;
		return first;
	}

	/**
	 * Removes the folders a refused run made ({@code made}, from {@link #missing}, down to {@code dir}) while they
	 * are empty: a run that wrote nothing leaves nothing behind. A folder that holds anything is kept.
	 */
	public static void removeEmpty(final Path made, final Path dir) {
		if (made == null) return;
		for (Path p = dir.toAbsolutePath().normalize(); p != null && p.startsWith(made); p = p.getParent()) {
			try {
				Files.deleteIfExists(p); // refuses a folder that is not empty
			}
			catch (final IOException | SecurityException e) {
				return;
			}
		}
	}

	/** A run that writes into an output folder: its exit status. */
	@FunctionalInterface
	public interface Run {
		int run() throws IOException;
	}

	/**
	 * Runs {@code run}, which writes into {@code dir} (null: none); when it ends with a status other than 0, or throws,
	 * the folders it made for {@code dir} are removed while empty ({@link #removeEmpty}): a refused run leaves nothing
	 * behind.
	 *
	 * @return the run's status
	 */
	public static int removedIfRefused(final Path dir, final Run run) throws IOException {
		final Path made = dir == null ? null : missing(dir);
		try {
			final int status = run.run();
			if (status != 0 && dir != null) removeEmpty(made, dir);
			return status;
		}
		catch (final RuntimeException | IOException e) {
			if (dir != null) removeEmpty(made, dir);
			throw e;
		}
	}
}
