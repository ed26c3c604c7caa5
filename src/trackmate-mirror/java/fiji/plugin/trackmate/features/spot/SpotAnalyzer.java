package fiji.plugin.trackmate.features.spot;

import fiji.plugin.trackmate.Spot;

/** Compile-only mirror of TrackMate's {@code SpotAnalyzer} (type parameter unbounded, as released). Never packaged. */
public interface SpotAnalyzer<T> {

	void process(Iterable<Spot> spots);
}
