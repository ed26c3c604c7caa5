package fiji.plugin.trackmate;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import net.imglib2.AbstractEuclideanSpace;
import net.imglib2.RealLocalizable;

/**
 * Compile-only mirror of TrackMate's {@code Spot} as RELEASED in TrackMate 8.0.0 to 8.1.6: a concrete CLASS
 * extending {@code AbstractEuclideanSpace}, implementing {@code RealLocalizable} and {@code Comparable<Spot>},
 * built with {@code new Spot(x, y, z, radius, quality)}. ({@code SpotBase} and a {@code Spot} interface exist only
 * on unreleased development branches; code compiled against them dies in every released Fiji.) Only the members
 * Contact Tracker and its tests call are mirrored. Never packaged.
 */
public class Spot extends AbstractEuclideanSpace implements RealLocalizable, Comparable<Spot> {

	private static final AtomicInteger IDS = new AtomicInteger(-1);

	public static final String QUALITY = "QUALITY";
	public static final String RADIUS = "RADIUS";
	public static final String POSITION_X = "POSITION_X";
	public static final String POSITION_Y = "POSITION_Y";
	public static final String POSITION_Z = "POSITION_Z";
	public static final String POSITION_T = "POSITION_T";
	public static final String FRAME = "FRAME";

	private final Map<String, Double> features = new ConcurrentHashMap<>();
	private final int id;
	private String name;

	public Spot(final double x, final double y, final double z, final double radius, final double quality,
		final String name)
	{
		super(3);
		this.id = IDS.incrementAndGet();
		this.name = name == null ? "ID" + id : name;
		putFeature(POSITION_X, x);
		putFeature(POSITION_Y, y);
		putFeature(POSITION_Z, z);
		putFeature(RADIUS, radius);
		putFeature(QUALITY, quality);
	}

	public Spot(final double x, final double y, final double z, final double radius, final double quality) {
		this(x, y, z, radius, quality, null);
	}

	public String getName() {
		return name;
	}

	public void setName(final String name) {
		this.name = name;
	}

	public int ID() {
		return id;
	}

	public Map<String, Double> getFeatures() {
		return features;
	}

	public Double getFeature(final String feature) {
		return features.get(feature);
	}

	public void putFeature(final String feature, final Double value) {
		features.put(feature, value);
	}

	@Override
	public int compareTo(final Spot o) {
		return Integer.compare(id, o.id);
	}

	@Override
	public double getDoublePosition(final int d) {
		return getFeature(d == 0 ? POSITION_X : d == 1 ? POSITION_Y : POSITION_Z);
	}

	@Override
	public float getFloatPosition(final int d) {
		return (float) getDoublePosition(d);
	}

	@Override
	public void localize(final float[] position) {
		for (int d = 0; d < n; d++)
			position[d] = getFloatPosition(d);
	}

	@Override
	public void localize(final double[] position) {
		for (int d = 0; d < n; d++)
			position[d] = getDoublePosition(d);
	}
}
