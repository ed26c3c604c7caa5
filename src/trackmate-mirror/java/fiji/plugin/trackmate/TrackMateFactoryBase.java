package fiji.plugin.trackmate;

import java.util.Map;

import org.jdom2.Element;

/**
 * Compile-only mirror of TrackMate 8's {@code TrackMateFactoryBase}: never packaged. Abstract:
 * {@code getDefaultSettings}; default: {@code marshal}, {@code unmarshal}, {@code checkSettings},
 * {@code toString(Map)}, {@code copy} (the returned strings are error messages, {@code null} when fine).
 * Contact Tracker overrides every default except {@code copy()}, so these bodies never matter; they throw so a
 * test that reaches one fails.
 */
public interface TrackMateFactoryBase<F extends TrackMateFactoryBase<F>> extends TrackMateModule {

	default String marshal(final Map<String, Object> settings, final Element element) {
		throw new UnsupportedOperationException("TrackMate mirror: marshal() must be overridden");
	}

	default String unmarshal(final Element element, final Map<String, Object> settings) {
		throw new UnsupportedOperationException("TrackMate mirror: unmarshal() must be overridden");
	}

	Map<String, Object> getDefaultSettings();

	default String checkSettings(final Map<String, Object> settings) {
		throw new UnsupportedOperationException("TrackMate mirror: checkSettings() must be overridden");
	}

	default String toString(final Map<String, Object> sm) {
		throw new UnsupportedOperationException("TrackMate mirror: toString(Map) must be overridden");
	}

	/** Real TrackMate: a new instance through the public no-argument constructor. */
	default F copy() {
		try {
			@SuppressWarnings("unchecked")
			final F f = (F) getClass().getDeclaredConstructor().newInstance();
			return f;
		}
		catch (final ReflectiveOperationException e) {
			throw new RuntimeException("Could not copy the factory: " + e.getMessage(), e);
		}
	}
}
