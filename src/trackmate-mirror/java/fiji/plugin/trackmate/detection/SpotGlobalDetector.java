package fiji.plugin.trackmate.detection;

import fiji.plugin.trackmate.Logger;
import fiji.plugin.trackmate.SpotCollection;
import net.imglib2.algorithm.Benchmark;
import net.imglib2.algorithm.OutputAlgorithm;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Compile-only mirror of TrackMate's {@code SpotGlobalDetector} (8.0.0+): returns the spots of every frame as a
 * {@link SpotCollection}; TrackMate hands it its logger first. Never packaged.
 */
public interface SpotGlobalDetector<T extends RealType<T> & NativeType<T>> extends OutputAlgorithm<SpotCollection>, Benchmark {

	default void setLogger(final Logger logger) {}
}
