package fiji.plugin.trackmate.detection;

import java.util.Map;

import net.imagej.ImgPlus;
import net.imglib2.Interval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Compile-only mirror of TrackMate's {@code SpotGlobalDetectorFactory} (8.0.0+): a factory whose detector
 * processes the whole movie at once; the interval includes the time axis (and never a channel axis). Never
 * packaged.
 */
public interface SpotGlobalDetectorFactory<T extends RealType<T> & NativeType<T>> extends SpotDetectorFactoryBase<T> {

	SpotGlobalDetector<T> getDetector(ImgPlus<T> img, Map<String, Object> settings, Interval interval);
}
