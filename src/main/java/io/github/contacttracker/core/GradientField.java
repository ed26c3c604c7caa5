package io.github.contacttracker.core;

/**
 * The gradients of one active area: for every pixel of the region that has a gradient (see
 * {@link GradientOperator}'s border rule), its position and (gx, gy). Computed once per particle
 * and reused by every pass, since the image does not change between passes.
 */
final class GradientField {
	final int size;
	final int[] x;
	final int[] y;
	final double[] gx;
	final double[] gy;
	/** Active pixels without a gradient (within 2 px of the border). */
	final int withoutGradient;

	private GradientField(final int size, final int[] x, final int[] y, final double[] gx, final double[] gy,
		final int withoutGradient)
	{
		this.size = size;
		this.x = x;
		this.y = y;
		this.gx = gx;
		this.gy = gy;
		this.withoutGradient = withoutGradient;
	}

	static GradientField compute(final Plane plane, final Region region) {
		final int area = region.area();
		final int[] xs = new int[area], ys = new int[area];
		final double[] gx = new double[area], gy = new double[area];
		final int xLo = GradientOperator.MARGIN, xHi = plane.width() - 1 - GradientOperator.MARGIN;
		final int yLo = GradientOperator.MARGIN, yHi = plane.height() - 1 - GradientOperator.MARGIN;
		int maxRun = 0;
		for (int r = 0; r < region.runCount(); r++)
			maxRun = Math.max(maxRun, region.runEnd(r) - region.runStart(r) + 1);
		final double[] scratch = new double[GradientOperator.scratchLength(maxRun)];
		int n = 0;
		for (int r = 0; r < region.runCount(); r++) {
			final int y = region.runY(r);
			if (y < yLo || y > yHi) continue;
			final int a = Math.max(region.runStart(r), xLo), b = Math.min(region.runEnd(r), xHi);
			if (a > b) continue;
			GradientOperator.alongRun(plane, y, a, b, gx, gy, n, scratch);
			for (int x = a; x <= b; x++, n++) {
				xs[n] = x;
				ys[n] = y;
			}
		}
		return new GradientField(n, xs, ys, gx, gy, area - n);
	}
}
