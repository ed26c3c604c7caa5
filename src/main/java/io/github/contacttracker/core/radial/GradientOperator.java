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

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.image.Plane;

/**
 * The paper's 5x3 gradient operators (Ma et al. 2012), as a convolution:
 * <pre>
 * gx(x, y) = sum over rows y-1..y+1 of [ I(x+1) + I(x+2) - I(x-1) - I(x-2) ]
 * gy(x, y) = sum over columns x-1..x+1 of [ I(y+1) + I(y+2) - I(y-1) - I(y-2) ]
 * </pre>
 * so the gradient points uphill, sits on the pixel centre, and y grows downwards.
 * <p>
 * <b>Border rule:</b> a gradient exists only where the whole 5x5 footprint of both operators lies inside the
 * image ({@code 2 <= x < width-2} and {@code 2 <= y < height-2}). Padding would invent intensity steps at
 * the border and bend the lines, so pixels closer than 2 px to the border carry no gradient and no weight;
 * the spots they belong to are flagged {@link Flag#AT_BORDER}.
 * <p>
 * Gradients are evaluated only where needed (active pixels), never as a full-frame convolution.
 */
public final class GradientOperator {

	/** Half-width of the operators' footprint (px). */
	public static final int MARGIN = 2;

	private GradientOperator() {}

	/** @return whether (x, y) of {@code plane} has a gradient under the border rule */
	static boolean hasGradient(final Plane plane, final int x, final int y) {
		return x >= MARGIN && y >= MARGIN && x < plane.width() - MARGIN && y < plane.height() - MARGIN;
	}

	static double gx(final Plane p, final int x, final int y) {
		double s = 0;
		for (int dy = -1; dy <= 1; dy++)
			s += p.get(x + 1, y + dy) + p.get(x + 2, y + dy) - p.get(x - 1, y + dy) - p.get(x - 2, y + dy);
		return s;
	}

	static double gy(final Plane p, final int x, final int y) {
		double s = 0;
		for (int dx = -1; dx <= 1; dx++)
			s += p.get(x + dx, y + 1) + p.get(x + dx, y + 2) - p.get(x + dx, y - 1) - p.get(x + dx, y - 2);
		return s;
	}

	/**
	 * Gradients along one run {@code (y, x0..x1)} whose pixels all have gradients, by running sums: about 7
	 * reads a pixel instead of 24, from the five rows of the footprint read in one call ({@link Plane#read}). Writes
	 * {@code gx[off + x - x0]} and {@code gy[...]}.
	 */
	static void alongRun(final Plane p, final int y, final int x0, final int x1, final double[] gx,
		final double[] gy, final int off, final double[] scratch)
	{
		final int n = x1 - x0 + 1, m = n + 4;
		// col[k] = I(x, y-1) + I(x, y) + I(x, y+1) for x = x0-2+k, k in 0..n+3
		// dv[k]  = I(x, y+1) + I(x, y+2) - I(x, y-1) - I(x, y-2) for x = x0-1+k, k in 0..n+1
		final double[] col = scratch;
		final int dvOff = n + 4;
		final byte[] bytes = p.unsignedBytes();
		if (bytes != null) {
			// 8-bit pixels straight from the array, in integers: these sums are exact either way, so identical
			final int w = p.width(), mid = y * w + x0 - 2, up1 = mid - w, up2 = up1 - w, down1 = mid + w, down2 = down1 + w;
			for (int k = 0; k < n + 4; k++)
				col[k] = (bytes[up1 + k] & 0xff) + (bytes[mid + k] & 0xff) + (bytes[down1 + k] & 0xff);
			for (int k = 0; k < n + 2; k++)
				col[dvOff + k] = (bytes[down1 + k + 1] & 0xff) + (bytes[down2 + k + 1] & 0xff) - (bytes[up1 + k + 1] & 0xff) -
					(bytes[up2 + k + 1] & 0xff);
		}
		else {
			// rows y-2 .. y+2 over x0-2 .. x1+2, read in one call: row j at scratch[rows + (j + 2) * m]
			final int rows = 2 * n + 6;
			p.read(x0 - 2, x1 + 2, y - 2, y + 2, scratch, rows);
			final int up2 = rows, up1 = rows + m, mid = rows + 2 * m, down1 = rows + 3 * m, down2 = rows + 4 * m;
			for (int k = 0; k < n + 4; k++)
				col[k] = scratch[up1 + k] + scratch[mid + k] + scratch[down1 + k];
			for (int k = 0; k < n + 2; k++)
				col[dvOff + k] = scratch[down1 + k + 1] + scratch[down2 + k + 1] - scratch[up1 + k + 1] - scratch[up2 + k +
					1];
		}
		for (int k = 0; k < n; k++) {
			gx[off + k] = col[k + 3] + col[k + 4] - col[k + 1] - col[k];
			gy[off + k] = col[dvOff + k] + col[dvOff + k + 1] + col[dvOff + k + 2];
		}
	}

	/** @return the scratch length {@link #alongRun} needs for runs up to {@code maxRun} pixels */
	static int scratchLength(final int maxRun) {
		return 2 * maxRun + 6 + 5 * (maxRun + 4);
	}
}
