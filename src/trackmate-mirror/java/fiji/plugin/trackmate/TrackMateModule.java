package fiji.plugin.trackmate;

import javax.swing.ImageIcon;

import org.scijava.plugin.SciJavaPlugin;

/**
 * Compile-only mirror of TrackMate 8's {@code TrackMateModule}: never packaged. Abstract: {@code getInfoText},
 * {@code getKey}, {@code getName}; default: {@code getIcon}, {@code forbidMultithreading}, {@code getUrl}.
 * Contact Tracker's factory implements all six, so it links whichever way a TrackMate version declares them.
 */
public interface TrackMateModule extends SciJavaPlugin {

	String getInfoText();

	default ImageIcon getIcon() {
		throw new UnsupportedOperationException("TrackMate mirror: getIcon() must be overridden");
	}

	String getKey();

	String getName();

	default boolean forbidMultithreading() {
		throw new UnsupportedOperationException("TrackMate mirror: forbidMultithreading() must be overridden");
	}

	default String getUrl() {
		throw new UnsupportedOperationException("TrackMate mirror: getUrl() must be overridden");
	}
}
