package fiji.plugin.trackmate;

/** Compile-only mirror of TrackMate's {@code Model}: only used as a parameter type. Never packaged. */
public class Model {

	public Model() {}
}
