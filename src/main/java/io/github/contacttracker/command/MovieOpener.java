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
