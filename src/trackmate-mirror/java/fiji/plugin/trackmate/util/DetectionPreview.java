package fiji.plugin.trackmate.util;

import java.util.Map;
import java.util.function.Supplier;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;

/**
 * Compile-only mirror of TrackMate's {@code DetectionPreview} and its {@code Builder}: TrackMate's own preview
 * (runs the detector on the current frame and shows the spots on the image), as its own detector panels use it.
 * Only the builder calls Contact Tracker makes are mirrored. Never packaged.
 */
public class DetectionPreview {

	private final DetectionPreviewPanel panel = new DetectionPreviewPanel(null, null);

	private DetectionPreview() {}

	public DetectionPreviewPanel getPanel() {
		return panel;
	}

	public static Builder create() {
		return new Builder();
	}

	public static final class Builder {

		private Builder() {}

		public Builder model(final Model model) {
			return this;
		}

		public Builder settings(final Settings settings) {
			return this;
		}

		public Builder detectorFactory(final SpotDetectorFactoryBase<?> detectorFactory) {
			return this;
		}

		public Builder detectionSettingsSupplier(final Supplier<Map<String, Object>> detectionSettingsSupplier) {
			return this;
		}

		public Builder axisLabel(final String axisLabel) {
			return this;
		}

		public Builder thresholdKey(final String thresholdKey) {
			return this;
		}

		public DetectionPreview get() {
			return new DetectionPreview();
		}
	}
}
