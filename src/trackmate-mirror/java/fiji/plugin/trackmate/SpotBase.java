package fiji.plugin.trackmate;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import net.imglib2.AbstractEuclideanSpace;

/**
 * Compile-only mirror of TrackMate's {@code SpotBase} (class, extends {@code AbstractEuclideanSpace}, implements
 * {@link Spot}): the concrete spot detectors create, with the constructor
 * {@code (double x, double y, double z, double radius, double quality)}. Never packaged.
 */
public class SpotBase extends AbstractEuclideanSpace implements Spot {

	private static final AtomicInteger COUNTER = new AtomicInteger(-1);

	private final Map<String, Double> features = new ConcurrentHashMap<>();
	private final int id;
	private String name;

	public SpotBase(final double x, final double y, final double z, final double radius, final double quality,
		final String name)
	{
		super(3);
		this.id = COUNTER.incrementAndGet();
		putFeature(POSITION_X, x);
		putFeature(POSITION_Y, y);
		putFeature(POSITION_Z, z);
		putFeature(RADIUS, radius);
		putFeature(QUALITY, quality);
		this.name = name == null ? "ID" + id : name;
	}

	public SpotBase(final double x, final double y, final double z, final double radius, final double quality) {
		this(x, y, z, radius, quality, null);
	}

	@Override
	public SpotBase copy() {
		final SpotBase s = new SpotBase(getFeature(POSITION_X), getFeature(POSITION_Y), getFeature(POSITION_Z),
			getFeature(RADIUS), getFeature(QUALITY), name);
		s.features.putAll(features);
		return s;
	}

	@Override
	public void scale(final double alpha) {
		putFeature(RADIUS, getFeature(RADIUS) * alpha);
	}

	@Override
	public String getName() {
		return name;
	}

	@Override
	public void setName(final String name) {
		this.name = name;
	}

	@Override
	public int ID() {
		return id;
	}

	@Override
	public Map<String, Double> getFeatures() {
		return features;
	}

	@Override
	public Double getFeature(final String feature) {
		return features.get(feature);
	}

	@Override
	public void putFeature(final String feature, final Double value) {
		features.put(feature, value);
	}

	@Override
	public double realMin(final int d) {
		return getDoublePosition(d) - getFeature(RADIUS);
	}

	@Override
	public double realMax(final int d) {
		return getDoublePosition(d) + getFeature(RADIUS);
	}

	@Override
	public String toString() {
		return name;
	}
}
