package fiji.plugin.trackmate.features;

import java.util.List;
import java.util.Map;

import fiji.plugin.trackmate.Dimension;
import fiji.plugin.trackmate.TrackMateModule;

/** Compile-only mirror of TrackMate's {@code FeatureAnalyzer}: the feature declarations. Never packaged. */
public interface FeatureAnalyzer extends TrackMateModule {

	List<String> getFeatures();

	Map<String, String> getFeatureShortNames();

	Map<String, String> getFeatureNames();

	Map<String, Dimension> getFeatureDimensions();

	Map<String, Boolean> getIsIntFeature();

	boolean isManualFeature();
}
