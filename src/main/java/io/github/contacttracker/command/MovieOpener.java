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
package io.github.contacttracker.command;

import java.io.IOException;
import java.nio.file.Path;

import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.ImageFiles;

/**
 * Opens a movie for an ImageJ macro through Contact Tracker's checked readers ({@link ImageFiles#open}), the same
 * as the command line: a broken or hostile file is refused with one line naming it, where ImageJ's own
 * {@code open()} may stop the macro with an error dialog, print several lines, run out of memory or not end (a
 * TIFF whose directories loop). For batch loops:
 *
 * <pre>
 * error = call("io.github.contacttracker.command.MovieOpener.open", path);
 * if (error != "") { print(path + ": FAILED: " + error); continue; }
 * </pre>
 *
 * The movie is opened as a virtual stack (frames read as they are needed) and becomes the current image.
 */
public final class MovieOpener {

	private MovieOpener() {}

	/**
	 * @param path the movie: a file or a folder of frames
	 * @return "" when the movie was opened (it is then the current image), else the one-line reason
	 */
	public static String open(final String path) {
		try {
			final ImagePlus imp = ImageFiles.open(Path.of(path));
			imp.show();
			return "";
		}
		catch (final IOException | RuntimeException e) {
			return InvalidInputException.oneLine(e.getMessage());
		}
		catch (final OutOfMemoryError e) {
			return "cannot open " + path + ": out of memory (" + e.getMessage() + "): give Fiji more with Edit > " +
				"Options > Memory & Threads";
		}
	}
}
