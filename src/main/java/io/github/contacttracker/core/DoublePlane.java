package io.github.contacttracker.core;

/** A plane over a {@code double[]} (row-major), for images the methods compute themselves. */
final class DoublePlane extends Plane {
	final double[] data;

	DoublePlane(final double[] data, final int width, final int height) {
		super(width, height, 0, 0);
		this.data = data;
	}

	@Override
	public double get(final int x, final int y) {
		return data[y * width + x];
	}

	@Override
	protected boolean floatingPoint() {
		return true;
	}
}
