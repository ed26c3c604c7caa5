package fiji.plugin.trackmate;

import java.awt.Color;
import java.io.PrintWriter;
import java.io.Writer;

/**
 * Compile-only mirror of TrackMate's {@code Logger}: an abstract class extending {@code PrintWriter}, handed to a
 * global detector through {@code setLogger}. Mirrored members: the abstract {@code log(String, Color)},
 * {@code error(String)}, {@code setProgress(double)}, {@code setStatus(String)} and the concrete
 * {@code log(String)}. Never packaged.
 */
public abstract class Logger extends PrintWriter {

	public Logger() {
		super(Writer.nullWriter());
	}

	public abstract void log(String message, Color color);

	public abstract void error(String message);

	public void log(final String message) {
		log(message, Color.BLACK);
	}

	public abstract void setProgress(double val);

	public abstract void setStatus(String status);
}
