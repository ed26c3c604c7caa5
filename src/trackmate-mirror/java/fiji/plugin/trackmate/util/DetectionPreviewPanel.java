package fiji.plugin.trackmate.util;

import java.util.function.DoubleConsumer;

import javax.swing.JPanel;

/**
 * Compile-only mirror of TrackMate's {@code DetectionPreviewPanel}: the Preview button, its log line and the
 * quality histogram every TrackMate detector panel shows. Only its type is used. Never packaged.
 */
public class DetectionPreviewPanel extends JPanel {

	private static final long serialVersionUID = 1L;

	public DetectionPreviewPanel(final DoubleConsumer thresholdUpdater, final String axisLabel) {}
}
