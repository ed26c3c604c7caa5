/*-
 * #%L
 * Contact Tracker: sub-pixel localization of colloidal particles, also when they touch.
 * %%
 * Copyright (C) 2026 Contact Tracker developers
 * %%
 * This program is free software: you can redistribute it and/or modify
 * it under the terms of the GNU General Public License as
 * published by the Free Software Foundation, either version 3 of the
 * License, or (at your option) any later version.
 * 
 * This program is distributed in the hope that it will be useful,
 * but WITHOUT ANY WARRANTY; without even the implied warranty of
 * MERCHANTABILITY or FITNESS FOR A PARTICULAR PURPOSE.  See the
 * GNU General Public License for more details.
 * 
 * You should have received a copy of the GNU General Public
 * License along with this program.  If not, see
 * <http://www.gnu.org/licenses/gpl-3.0.html>.
 * #L%
 */
package io.github.contacttracker.core.radial;

import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;

/**
 * The gradients of one active area: for every pixel of the region that has a gradient (see
 * {@link GradientOperator}'s border rule), its position and (gx, gy). Computed once per particle
 * and reused by every pass, since the image does not change between passes.
 */
public final class GradientField {
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

	public static GradientField compute(final Plane plane, final Region region) {
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
