package fiji.plugin.trackmate.detection;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.TrackMateFactoryBase;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;

/**
 * Compile-only mirror of TrackMate 8's {@code SpotDetectorFactoryBase}: never packaged. Abstract:
 * {@code getDetectorConfigurationPanel(Settings, Model)}; default: {@code has2Dsegmentation()}.
 */
public interface SpotDetectorFactoryBase<T extends RealType<T> & NativeType<T>>
	extends TrackMateFactoryBase<SpotDetectorFactoryBase<T>>
{

	ConfigurationPanel getDetectorConfigurationPanel(Settings settings, Model model);

	default boolean has2Dsegmentation() {
		throw new UnsupportedOperationException("TrackMate mirror: has2Dsegmentation() must be overridden");
	}
}
