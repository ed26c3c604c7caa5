package fiji.plugin.trackmate.features.spot;

import fiji.plugin.trackmate.features.FeatureAnalyzer;
import net.imagej.ImgPlus;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/** Compile-only mirror of TrackMate's {@code SpotAnalyzerFactoryBase}. Never packaged. */
public interface SpotAnalyzerFactoryBase<T extends RealType<T> & NativeType<T>> extends FeatureAnalyzer {

	SpotAnalyzer<T> getAnalyzer(ImgPlus<T> img, int frame, int channel);

	default void setNChannels(final int nChannels) {}
}
