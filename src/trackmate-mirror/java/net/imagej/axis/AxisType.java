package net.imagej.axis;

/** Compile-only mirror of imagej-common's {@code AxisType} (an interface): never packaged. */
public interface AxisType {

	String getLabel();

	boolean isXY();

	boolean isSpatial();
}
