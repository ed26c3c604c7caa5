package fiji.plugin.trackmate;

/**
 * Compile-only mirror of TrackMate's {@code Model} (a class with a public no-argument constructor): only passed
 * on to TrackMate's own {@code DetectionPreview}. Never packaged.
 */
public class Model {

	public Model() {}
}
