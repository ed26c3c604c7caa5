package fiji.plugin.trackmate;

import java.util.HashMap;
import java.util.Map;

import ij.ImagePlus;

/**
 * Compile-only mirror of TrackMate's {@code Settings}: the public fields Contact Tracker reads, with their exact
 * types ({@code public final ImagePlus imp}, {@code public double dx, dy, dz, dt}). Never packaged.
 */
public class Settings {

	public final ImagePlus imp;

	public double dt;

	public double dx;

	public double dy;

	public double dz;

	public Map<String, Object> detectorSettings = new HashMap<>();

	public Settings() {
		this(null);
	}

	public Settings(final ImagePlus imp) {
		this.imp = imp;
		if (imp == null) {
			dx = dy = dz = dt = 1;
			return;
		}
		dx = imp.getCalibration().pixelWidth;
		dy = imp.getCalibration().pixelHeight;
		dz = imp.getCalibration().pixelDepth;
		final double interval = imp.getCalibration().frameInterval;
		dt = interval == 0 ? 1 : interval;
	}
}
