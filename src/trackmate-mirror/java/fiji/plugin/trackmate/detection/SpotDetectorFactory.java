package fiji.plugin.trackmate.detection;

import java.util.Map;

import net.imagej.ImgPlus;
import net.imglib2.Interval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Compile-only mirror of TrackMate 8's {@code SpotDetectorFactory}: never packaged. TrackMate 8 passes the WHOLE
 * image (all channels and frames), the detector settings, the crop interval (no time axis; a one-wide channel
 * axis when the image has channels) and the frame index. (TrackMate 7's {@code setTarget} + 
 * {@code getDetector(Interval, int)} is gone in 8.)
 */
public interface SpotDetectorFactory<T extends RealType<T> & NativeType<T>> extends SpotDetectorFactoryBase<T> {

	SpotDetector<T> getDetector(ImgPlus<T> img, Map<String, Object> settings, Interval interval, int frame);
}
