package fiji.plugin.trackmate;

import java.util.Map;

import net.imglib2.EuclideanSpace;
import net.imglib2.Localizable;
import net.imglib2.RealInterval;
import net.imglib2.RealLocalizable;
import net.imglib2.RealPositionable;

/**
 * Compile-only mirror of TrackMate's {@code Spot}. Since TrackMate 7.11 (and in 8.x) {@code Spot} is an
 * INTERFACE; the plain implementation is {@link SpotBase}. Calling {@code new Spot(...)} would compile against
 * an old class-shaped mirror and fail inside Fiji with {@code InstantiationError}. Never packaged.
 * <p>
 * Abstract members kept here are the ones Contact Tracker calls ({@code putFeature}, {@code getFeature}) and the
 * ones the real interface leaves to implementations; defaults stand in for the real interface's defaults.
 */
public interface Spot extends RealLocalizable, RealPositionable, RealInterval, Comparable<Spot>, EuclideanSpace {

	String QUALITY = "QUALITY";
	String RADIUS = "RADIUS";
	String POSITION_X = "POSITION_X";
	String POSITION_Y = "POSITION_Y";
	String POSITION_Z = "POSITION_Z";
	String POSITION_T = "POSITION_T";
	String FRAME = "FRAME";
	String[] POSITION_FEATURES = { POSITION_X, POSITION_Y, POSITION_Z };

	@Override
	default int compareTo(final Spot o) {
		return ID() - o.ID();
	}

	Spot copy();

	void scale(double alpha);

	String getName();

	void setName(String name);

	int ID();

	Map<String, Double> getFeatures();

	Double getFeature(String feature);

	void putFeature(String feature, Double value);

	@Override
	default int numDimensions() {
		return 3;
	}

	@Override
	default double getDoublePosition(final int d) {
		return getFeature(POSITION_FEATURES[d]);
	}

	@Override
	default void move(final float distance, final int d) {
		move((double) distance, d);
	}

	@Override
	default void move(final double distance, final int d) {
		putFeature(POSITION_FEATURES[d], getFeature(POSITION_FEATURES[d]) + distance);
	}

	@Override
	default void move(final RealLocalizable distance) {
		for (int d = 0; d < 3; d++)
			move(distance.getDoublePosition(d), d);
	}

	@Override
	default void move(final float[] distance) {
		for (int d = 0; d < 3; d++)
			move(distance[d], d);
	}

	@Override
	default void move(final double[] distance) {
		for (int d = 0; d < 3; d++)
			move(distance[d], d);
	}

	@Override
	default void setPosition(final RealLocalizable position) {
		for (int d = 0; d < 3; d++)
			setPosition(position.getDoublePosition(d), d);
	}

	@Override
	default void setPosition(final float[] position) {
		for (int d = 0; d < 3; d++)
			setPosition(position[d], d);
	}

	@Override
	default void setPosition(final double[] position) {
		for (int d = 0; d < 3; d++)
			setPosition(position[d], d);
	}

	@Override
	default void setPosition(final float position, final int d) {
		setPosition((double) position, d);
	}

	@Override
	default void setPosition(final double position, final int d) {
		putFeature(POSITION_FEATURES[d], position);
	}

	@Override
	default void fwd(final int d) {
		move(1., d);
	}

	@Override
	default void bck(final int d) {
		move(-1., d);
	}

	@Override
	default void move(final int distance, final int d) {
		move((double) distance, d);
	}

	@Override
	default void move(final long distance, final int d) {
		move((double) distance, d);
	}

	@Override
	default void move(final Localizable distance) {
		move((RealLocalizable) distance);
	}

	@Override
	default void move(final int[] distance) {
		for (int d = 0; d < 3; d++)
			move(distance[d], d);
	}

	@Override
	default void move(final long[] distance) {
		for (int d = 0; d < 3; d++)
			move(distance[d], d);
	}

	@Override
	default void setPosition(final Localizable position) {
		setPosition((RealLocalizable) position);
	}

	@Override
	default void setPosition(final int[] position) {
		for (int d = 0; d < 3; d++)
			setPosition(position[d], d);
	}

	@Override
	default void setPosition(final long[] position) {
		for (int d = 0; d < 3; d++)
			setPosition(position[d], d);
	}

	@Override
	default void setPosition(final int position, final int d) {
		setPosition((double) position, d);
	}

	@Override
	default void setPosition(final long position, final int d) {
		setPosition((double) position, d);
	}
}
