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

import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.Scene;

/**
 * The Cramer-Rao bound of a {@link Scene}: the Fisher matrix over every particle's centre, amplitude and (if
 * asked) radial scale, and the background plane {@code B + bx x + by y}, with each pixel's own variance (photon
 * noise: expected value times gain plus read variance; additive noise: its variance; plus 1/12 for the rounding).
 * Pixels whose expected value is clipped (at or above 254.5 on 8 bits, or at or below 0.5: a dark ring that bright
 * particles push below 0) are censored: they carry no information here, as in the fit. The bound is the method's
 * ideal: it keeps the band near the clip levels that the fit leaves out to avoid a selection bias (see
 * {@code core.Censoring}), so the fit's spread can exceed it a little where pixels clip. Derivatives by central
 * differences of the pixel-integrated model, each particle drawn with its own kind's profile.
 */
public final class SceneCramerRao {

	static final double STEP = 1e-3;
	/** Expected values at or above this are clipped on 8 bits: censored. */
	public static final double SATURATION = 254.5;
	/**
	 * @return the expected value at or above which a camera of {@code bitDepth} bits clips: {@link #SATURATION} on 8
	 *         bits, 65534.5 on more (the scenes' camera offset, at most 500 grey levels, far below it)
	 */
	public static double saturation(final int bitDepth) {
		return bitDepth > 8 ? 65534.5 : SATURATION;
	}

	/** Expected values at or below this read 0 on 8 bits: censored. */
	public static final double FLOOR = 0.5;

	private final double[][] inverse;
	private final int perParticle;

	/**
	 * @param scene the scene
	 * @param centres the particles' centres in the frame (px)
	 * @param width frame width
	 * @param height frame height
	 * @param scales whether the radial scales are free parameters (as in the fit)
	 */
	public SceneCramerRao(final Scene scene, final List<double[]> centres, final int width, final int height,
		final boolean scales)
	{
		this(scene, centres, width, height, scales, SATURATION);
	}

	/**
	 * The bound of a scene whose camera clips at {@code saturation} (expected values at or above it are censored:
	 * {@link #saturation(int)}).
	 */
	public SceneCramerRao(final Scene scene, final List<double[]> centres, final int width, final int height,
		final boolean scales, final double saturation)
	{
		final int n = centres.size();
		perParticle = scales ? 4 : 3;
		final int np = perParticle * n + 3;
		final List<ImageSimulator> sims = scene.simulators();
		final NoiseFreeImage model = scene.render(sims, centres, width, height);
		final List<double[]> d = new ArrayList<>();
		for (int k = 0; k < n; k++) {
			final Scene.Particle p = scene.particles().get(k);
			final ImageSimulator sim = sims.get(p.kind()); // each particle with its own profile
			final double x = centres.get(k)[0], y = centres.get(k)[1];
			d.add(diff(single(sim, x + STEP, y, p.scale(), p.amplitude(), width, height), single(sim, x - STEP, y, p
				.scale(), p.amplitude(), width, height)));
			d.add(diff(single(sim, x, y + STEP, p.scale(), p.amplitude(), width, height), single(sim, x, y - STEP, p
				.scale(), p.amplitude(), width, height)));
			d.add(single(sim, x, y, p.scale(), 1, width, height));
			if (scales) d.add(diff(single(sim, x, y, p.scale() + STEP, p.amplitude(), width, height), single(sim, x, y, p
				.scale() - STEP, p.amplitude(), width, height)));
		}
		final double[] ones = new double[width * height], gx = new double[width * height], gy = new double[width *
			height];
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++) {
				ones[y * width + x] = 1;
				gx[y * width + x] = x - 0.5 * (width - 1);
				gy[y * width + x] = y - 0.5 * (height - 1);
			}
		d.add(ones);
		d.add(gx);
		d.add(gy);
		final double[] weight = new double[width * height];
		for (int i = 0; i < weight.length; i++) {
			final double v = model.pixels()[i];
			weight[i] = v >= saturation || v <= FLOOR ? 0 : 1 / scene.variance(v);
		}
		final double[][] fisher = new double[np][np];
		for (int a = 0; a < np; a++)
			for (int b = 0; b <= a; b++) {
				final double[] da = d.get(a), db = d.get(b);
				double s = 0;
				for (int i = 0; i < weight.length; i++)
					s += da[i] * db[i] * weight[i];
				fisher[a][b] = fisher[b][a] = s;
			}
		inverse = SymmetricSolver.invert(fisher);
	}

	/** @return the bound on the distance between particles i and j at {@code centres} (px) */
	public double distance(final List<double[]> centres, final int i, final int j) {
		if (inverse == null) return Double.NaN;
		final double[] ci = centres.get(i), cj = centres.get(j);
		final double dist = Math.hypot(ci[0] - cj[0], ci[1] - cj[1]);
		final int np = inverse.length;
		final double[] g = new double[np];
		g[perParticle * i] = (ci[0] - cj[0]) / dist;
		g[perParticle * i + 1] = (ci[1] - cj[1]) / dist;
		g[perParticle * j] = -g[perParticle * i];
		g[perParticle * j + 1] = -g[perParticle * i + 1];
		double v = 0;
		for (int a = 0; a < np; a++)
			for (int b = 0; b < np; b++)
				v += g[a] * inverse[a][b] * g[b];
		return Math.sqrt(v);
	}

	/** @return the bound on particle k's x (axis 0) or y (axis 1) (px) */
	public double position(final int k, final int axis) {
		return inverse == null ? Double.NaN : Math.sqrt(inverse[perParticle * k + axis][perParticle * k + axis]);
	}

	private static double[] diff(final double[] a, final double[] b) {
		final double[] g = new double[a.length];
		for (int i = 0; i < g.length; i++)
			g[i] = (a[i] - b[i]) / (2 * STEP);
		return g;
	}

	private static double[] single(final ImageSimulator sim, final double x, final double y, final double scale,
		final double amplitude, final int w, final int h)
	{
		final NoiseFreeImage img = NoiseFreeImage.uniform(w, h, 0);
		sim.addParticle(img, x, y, scale, amplitude);
		return img.pixels();
	}
}
