package fiji.plugin.trackmate.gui.components;

import java.util.Map;

import javax.swing.JPanel;

/** Compile-only mirror of TrackMate's {@code ConfigurationPanel} (abstract class, extends JPanel). Never packaged. */
public abstract class ConfigurationPanel extends JPanel {

	private static final long serialVersionUID = 1L;

	public abstract void setSettings(Map<String, Object> settings);

	public abstract Map<String, Object> getSettings();

	public abstract void clean();
}
