package fiji.plugin.trackmate.detection;

import java.util.List;

import fiji.plugin.trackmate.Spot;
import net.imglib2.algorithm.Benchmark;
import net.imglib2.algorithm.OutputAlgorithm;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/** Compile-only mirror of TrackMate's {@code SpotDetector}: no members of its own. Never packaged. */
public interface SpotDetector<T extends RealType<T> & NativeType<T>> extends OutputAlgorithm<List<Spot>>, Benchmark {}
