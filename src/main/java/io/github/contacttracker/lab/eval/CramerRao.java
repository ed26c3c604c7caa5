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
package io.github.contacttracker.lab.eval;

import java.util.List;

import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.ParticleType;

/**
 * The Cramer-Rao bound on a measured centre-to-centre distance: the smallest standard deviation any unbiased
 * estimator can reach on images of known profile with additive Gaussian noise. The Fisher matrix is built
 * over every centre, every particle's amplitude and the background, from the pixel-integrated model the
 * simulator renders (derivatives by central differences), and inverted:
 * {@code var(d) >= g^T F^-1 g}, {@code g = dd/dtheta}.
 * <p>
 * Noise: the pixel-noise variance of the type's noise model plus 1/12 grey level^2 for the rounding to
 * integers (uniform noise is treated through its variance, as is usual).
 */
public final class CramerRao {

	/** Step of the central differences (px). */
	static final double STEP = 1e-3;

	private CramerRao() {}

	/**
	 * @param type the particles (profile and noise)
	 * @param centres all particle centres (px)
	 * @param pair the indices of the two particles whose distance is measured
	 * @param width image width (px)
	 * @param height image height (px)
	 * @return the bound on the distance's standard deviation (px)
	 */
	public static double distanceBound(final ParticleType type, final List<double[]> centres, final int[] pair,
		final int width, final int height)
	{
		final int n = centres.size(), np = 3 * n + 1;
		final ImageSimulator sim = new ImageSimulator(type.profile());
		final double[][] d = new double[np][];
		for (int k = 0; k < n; k++) {
			for (int axis = 0; axis < 2; axis++) {
				final double[] plus = centres.get(k).clone(), minus = centres.get(k).clone();
				plus[axis] += STEP;
				minus[axis] -= STEP;
				final double[] a = single(sim, plus, width, height), b = single(sim, minus, width, height);
				final double[] g = new double[a.length];
				for (int i = 0; i < g.length; i++)
					g[i] = (a[i] - b[i]) / (2 * STEP);
				d[3 * k + axis] = g;
			}
			d[3 * k + 2] = single(sim, centres.get(k), width, height); // amplitude scale a_k at 1
		}
		final double[] ones = new double[width * height];
		java.util.Arrays.fill(ones, 1);
		d[np - 1] = ones;
		final double variance = type.noise().sigma() * type.noise().sigma() + 1.0 / 12;
		final double[][] fisher = new double[np][np];
		for (int a = 0; a < np; a++)
			for (int b = 0; b <= a; b++) {
				double s = 0;
				for (int i = 0; i < ones.length; i++)
					s += d[a][i] * d[b][i];
				fisher[a][b] = fisher[b][a] = s / variance;
			}
		final double[][] inv = SymmetricSolver.invert(fisher);
		if (inv == null) return Double.NaN;
		final double[] ci = centres.get(pair[0]), cj = centres.get(pair[1]);
		final double dist = Math.hypot(ci[0] - cj[0], ci[1] - cj[1]);
		final double[] g = new double[np];
		g[3 * pair[0]] = (ci[0] - cj[0]) / dist;
		g[3 * pair[0] + 1] = (ci[1] - cj[1]) / dist;
		g[3 * pair[1]] = -g[3 * pair[0]];
		g[3 * pair[1] + 1] = -g[3 * pair[0] + 1];
		double v = 0;
		for (int a = 0; a < np; a++)
			for (int b = 0; b < np; b++)
				v += g[a] * inv[a][b] * g[b];
		return Math.sqrt(v);
	}

	private static double[] single(final ImageSimulator sim, final double[] centre, final int w, final int h) {
		final NoiseFreeImage img = NoiseFreeImage.uniform(w, h, 0);
		sim.addParticle(img, centre[0], centre[1]);
		return img.pixels();
	}
}
