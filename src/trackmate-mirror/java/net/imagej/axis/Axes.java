package net.imagej.axis;

/**
 * Compile-only mirror of imagej-common's {@code Axes}: never packaged. The real constants are
 * {@code public static final AxisType} fields (not compile-time constants), read with {@code getstatic}.
 */
public final class Axes {

	public static final AxisType X = new Type("X", true);
	public static final AxisType Y = new Type("Y", true);
	public static final AxisType Z = new Type("Z", true);
	public static final AxisType TIME = new Type("Time", false);
	public static final AxisType CHANNEL = new Type("Channel", false);

	private Axes() {}

	private static final class Type implements AxisType {

		private final String label;
		private final boolean spatial;

		Type(final String label, final boolean spatial) {
			this.label = label;
			this.spatial = spatial;
		}

		@Override
		public String getLabel() {
			return label;
		}

		@Override
		public boolean isXY() {
			return this == X || this == Y;
		}

		@Override
		public boolean isSpatial() {
			return spatial;
		}

		@Override
		public String toString() {
			return label;
		}
	}
}
