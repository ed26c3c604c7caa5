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
package io.github.contacttracker.core.fit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;

class LeverageTest {

	/** A Gaussian spot, sigma 1.2 px, 30 above a background of 20, sampled every half pixel. */
	private static EmpiricalProfile spot() {
		final double[] c = new double[14];
		for (int j = 0; j < c.length; j++)
			c[j] = 30 * Math.exp(-(0.5 * j) * (0.5 * j) / (2 * 1.2 * 1.2));
		return ProfileAccess.profile(0.5, c, 20, 1000);
	}

	/** The fit's pixels: a square of side {@code 2 half + 1} around (cx, cy), packed, u and v from -1 to 1. */
	private static double[] packed(final int cx, final int cy, final int half) {
		final int side = 2 * half + 1;
		final double[] out = new double[side * side * FitPixels.PACKED];
		for (int j = 0, o = 0; j < side; j++)
			for (int i = 0; i < side; i++, o += FitPixels.PACKED) {
				out[o] = cx - half + i;
				out[o + 1] = cy - half + j;
				out[o + 2] = (i - half) / (double) half;
				out[o + 3] = (j - half) / (double) half;
			}
		return out;
	}

	/**
	 * The factor against its definition computed independently: J by central differences of the profile's value,
	 * each pixel's leverage from the hat matrix {@code J (J^T J)^-1 J^T}, and {@code sqrt(sum w / sum w (1 - h) /
	 * dof)} with {@code w} the squared derivative along x (on a window of 1089 pixels, a regular sample of them). The
	 * all-pixel correction the fit already makes ({@code dof}) covers part of it on a window of 49 pixels and hardly
	 * any on one of 1089, where the spot's information still lies on a score of pixels. Each case with the
	 * background free and held (its rows of J^T J the identity's, as GroupFit holds it).
	 */
	@Test
	void theFactorIsTheLeverageOfTheInformationsPixels() {
		final EmpiricalProfile spot = spot();
		final double[] p = { 10.3, 9.8, 1, 1, 20, 0, 0 };
		final double[] free = new double[2]; // the background free: on 49 pixels, on 1089
		for (final int half : new int[] { 3, 16 }) {
			final double[] px = packed(10, 10, half);
			final int count = px.length / FitPixels.PACKED;
			for (final boolean held : new boolean[] { false, true }) {
				final int np = held ? 4 : 7;
				final double[][] j = new double[count][np];
				final double eps = 1e-5;
				for (int i = 0; i < count; i++) {
					final double x = px[i * FitPixels.PACKED], y = px[i * FitPixels.PACKED + 1];
					final double r = Math.hypot(x - p[0], y - p[1]);
					j[i][0] = (spot.value(Math.hypot(x - p[0] - eps, y - p[1])) - spot.value(Math.hypot(x - p[0] + eps, y -
						p[1]))) / (2 * eps);
					j[i][1] = (spot.value(Math.hypot(x - p[0], y - p[1] - eps)) - spot.value(Math.hypot(x - p[0], y - p[1] +
						eps))) / (2 * eps);
					j[i][2] = spot.value(r);
					j[i][3] = (spot.value(r / (1 + eps)) - spot.value(r / (1 - eps))) / (2 * eps);
					if (!held) {
						j[i][4] = 1;
						j[i][5] = px[i * FitPixels.PACKED + 2];
						j[i][6] = px[i * FitPixels.PACKED + 3];
					}
				}
				final double[][] jtj = new double[7][7];
				for (int a = 0; a < np; a++)
					for (int b = 0; b < np; b++)
						for (int i = 0; i < count; i++)
							jtj[a][b] += j[i][a] * j[i][b];
				for (int a = np; a < 7; a++)
					jtj[a][a] = 1; // (held: the identity's, as GroupFit holds it)
				final double[][] inv = SymmetricSolver.invert(jtj);
				double w = 0, wKept = 0;
				for (int i = 0; i < count; i++) {
					double h = 0;
					for (int a = 0; a < np; a++)
						for (int b = 0; b < np; b++)
							h += j[i][a] * inv[a][b] * j[i][b];
					w += j[i][0] * j[i][0];
					wKept += j[i][0] * j[i][0] * (1 - h);
				}
				final double dof = count / (double) (count - 7);
				final double expected = Math.max(1, Math.sqrt(w / wKept / dof));
				final double[] f = Leverage.factors(px, count, p, 1, new EmpiricalProfile[] { spot }, inv, held, dof);
				final double sampled = half == 16 ? 0.02 : 0.005; // (the large window is sampled: every 17th pixel)
				assertEquals(expected, f[0], sampled * expected, "half " + half + (held ? ", held" : ""));
				if (!held) free[half == 3 ? 0 : 1] = f[0];
			}
		}
		// the spot's information lies on a score of pixels: the all-pixel correction (dof) covers their leverage on 49
		// pixels in part, on 1089 hardly
		assertTrue(free[0] > 1.02 && free[1] > free[0] && free[1] > 1.1, "49 pixels: " + free[0] + ", 1089: " +
			free[1]);
	}
}
