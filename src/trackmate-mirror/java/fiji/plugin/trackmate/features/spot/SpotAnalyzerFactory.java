package fiji.plugin.trackmate.features.spot;

import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Compile-only mirror of TrackMate's {@code SpotAnalyzerFactory}, the SciJava plugin type TrackMate discovers spot
 * analyzers by (no members of its own). Never packaged.
 */
public interface SpotAnalyzerFactory<T extends RealType<T> & NativeType<T>> extends SpotAnalyzerFactoryBase<T> {}
