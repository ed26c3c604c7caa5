package fiji.plugin.trackmate;

/** Compile-only mirror of TrackMate's {@code Dimension} enum of feature dimensions, every constant. Never packaged. */
public enum Dimension {
	NONE, QUALITY, COST, INTENSITY, INTENSITY_SQUARED, POSITION, VELOCITY, LENGTH, AREA, TIME, ANGLE, RATE,
	ANGLE_RATE, STRING;
}
