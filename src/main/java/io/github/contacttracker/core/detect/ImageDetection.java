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
package io.github.contacttracker.core.detect;

import java.util.Arrays;

import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.image.RunList;
import io.github.contacttracker.core.radial.Particle;

/**
 * Finds the particles of a frame by their image, not by a threshold: the peaks of the frame
 * {@link BandPass band-passed} at the particles' scale that stand out of the noise ({@link Peaks}: high enough,
 * and dipping towards any higher peak by enough), each the seed of one particle. A particle's first-pass area is
 * the disc of half a diameter around its seed, cut where another seed lies nearer (two touching particles share
 * no pixel), so that the first pass, the iterative pass and the fit start from one seed per particle however
 * much the particles' images overlap, on any background.
 * <p>
 * The levels are in units of the band-passed frame's noise (the frame's pixel noise times the filter's
 * {@link BandPass#noiseGain gain}): a peak {@value #LEVEL} times as high as that noise, and
 * {@value #PROMINENCE} times as prominent; besides, no higher seed within half a diameter (a particle's own
 * rings) and at least {@value #RELATIVE} of the particles' typical peak. A seed that holds no particle (a bright fringe between particles, a
 * bump of noise) is removed after the fit, and a particle the seeds missed (a pair closer than the filter
 * resolves) is added from the fit's residuals: {@link ModelSelection}.
 */
public final class ImageDetection {

	/** A peak must be this many times the band-passed frame's noise high... */
	public static final double LEVEL = 5;
	/** ...and dip this many times that noise towards any higher peak. */
	public static final double PROMINENCE = 3;

	private ImageDetection() {}

	/**
	 * The filter's scale for particles of diameter {@code d} (px): the smoothing's standard deviation, an eighth of
	 * the diameter and at least a pixel (it takes out the pixel noise, not the particle's own shape: two particles
	 * at 0.6 diameters stay two peaks where their profiles are peaked), and the background square's half side, one
	 * diameter (the local background holds the particle and its surroundings, so that a particle's flat top is not
	 * cratered by its own light in the background).
	 */
	public record Scale(double sigma, int halfWidth) {

		/** @return the scale for particles of diameter {@code d} (px, {@code > 0}) */
		public static Scale of(final double d) {
			return new Scale(Math.max(1, d / 8), Math.max(2, (int) Math.ceil(d)));
		}

		/** @return the band-passed frame's noise for pixel noise {@code noise} */
		public double noise(final double noise) {
			return noise * BandPass.noiseGain(sigma, halfWidth);
		}
	}

	/**
	 * @param plane the frame
	 * @param diameter the particles' diameter (px, {@code > 0})
	 * @param noise the frame's pixel noise (grey levels)
	 * @return the seeds: the band-passed frame's peaks that stand out, highest first
	 */
	public static Peaks seeds(final Plane plane, final double diameter, final double noise) {
		final Scale scale = Scale.of(diameter);
		return seeds(BandPass.of(plane, scale.sigma(), scale.halfWidth()), plane.width(), plane.height(), diameter,
			noise);
	}

	/**
	 * {@link #seeds(Plane, double, double)} of a frame already band-passed at {@link Scale#of the particles' scale}
	 * (where the caller needs that frame too: it is the detection's largest cost)
	 *
	 * @param bandPassed the frame band-passed at {@code Scale.of(diameter)} (read only)
	 * @param w the frame's width
	 * @param h the frame's height
	 */
	public static Peaks seeds(final float[] bandPassed, final int w, final int h, final double diameter,
		final double noise)
	{
		final double unit = unit(Scale.of(diameter).noise(noise), bandPassed);
		final Peaks peaks = Peaks.find(bandPassed, w, h, 0, LEVEL * unit, PROMINENCE * unit);
		return peaks.sparse(diameter / 2, RELATIVE * peaks.typicalHeight());
	}

	/**
	 * A seed is at least this fraction of the particles' typical peak ({@link Peaks#typicalHeight}): the bright rings
	 * that bright-field and defocused particles wear around their core (on the paper's 5.53 um profile, 0.08 of the
	 * core, a particle's radius out) and the fringes where neighbours' halos meet are peaks that stand out of the
	 * noise, but are no particles.
	 */
	public static final double RELATIVE = 0.2;

	/**
	 * @return the unit of the detection levels: the band-passed noise, or for a frame without noise (a simulation)
	 *         a millionth of the band-passed frame's range, so that only real peaks count
	 */
	static double unit(final double bandPassedNoise, final float[] bp) {
		if (bandPassedNoise > 0) return bandPassedNoise;
		float lo = Float.POSITIVE_INFINITY, hi = Float.NEGATIVE_INFINITY;
		for (final float v : bp) {
			lo = Math.min(lo, v);
			hi = Math.max(hi, v);
		}
		return hi > lo ? 1e-6 * (hi - lo) : 1;
	}

	/**
	 * @return the particles of a frame seeded by its image ({@link #seeds}), before any fit
	 */
	public static Particle[] particles(final Plane plane, final double diameter, final double noise) {
		final Peaks seeds = seeds(plane, diameter, noise);
		return particles(plane, seeds.x(), seeds.y(), radius(diameter), margin(diameter));
	}

	/**
	 * The particles at seeds {@code (x, y)}: each first-passed on the pixels within {@code radius} of its seed that
	 * lie nearer to it than to any other seed.
	 *
	 * @param margin a seed nearer than this to the frame's edge is {@code AT_BORDER} (its image is cut)
	 * @return one particle per seed, in the seeds' order (a seed off the frame gives none)
	 */
	public static Particle[] particles(final Plane plane, final double[] x, final double[] y, final double radius,
		final double margin)
	{
		return particles(plane, x, y, radius, margin, null);
	}

	/**
	 * As {@link #particles(Plane, double[], double[], double, double)}, with the seed each particle stands at.
	 *
	 * @param seedOf null, or filled with each particle's seed's index (its length at least the seeds')
	 */
	static Particle[] particles(final Plane plane, final double[] x, final double[] y, final double radius,
		final double margin, final int[] seedOf)
	{
		final int w = plane.width(), h = plane.height(), n = x.length;
		final int[] owner = new int[w * h];
		final float[] best = new float[w * h];
		Arrays.fill(owner, -1);
		final int r = (int) Math.ceil(radius);
		final double r2 = radius * radius;
		for (int k = 0; k < n; k++) {
			final int cx = (int) Math.round(x[k]), cy = (int) Math.round(y[k]);
			for (int yy = Math.max(0, cy - r); yy <= Math.min(h - 1, cy + r); yy++)
				for (int xx = Math.max(0, cx - r); xx <= Math.min(w - 1, cx + r); xx++) {
					final double d2 = (xx - x[k]) * (xx - x[k]) + (yy - y[k]) * (yy - y[k]);
					final int i = yy * w + xx;
					if (d2 <= r2 && (owner[i] < 0 || d2 < best[i])) {
						owner[i] = k;
						best[i] = (float) d2;
					}
				}
		}
		final Particle[] out = new Particle[n];
		int found = 0;
		for (int k = 0; k < n; k++) {
			final int cx = (int) Math.round(x[k]), cy = (int) Math.round(y[k]);
			final RunList runs = new RunList();
			final int own = k;
			for (int yy = Math.max(0, cy - r); yy <= Math.min(h - 1, cy + r); yy++) {
				final int row = yy * w;
				runs.addWhere(yy, Math.max(0, cx - r), Math.min(w - 1, cx + r), xx -> owner[row + xx] == own);
			}
			final Region region = runs.toRegion();
			final boolean atBorder = x[k] < margin || y[k] < margin || x[k] > w - 1 - margin || y[k] > h - 1 - margin;
			final Particle p = Particle.atSeed(plane, region, x[k], y[k], atBorder);
			if (p == null) continue;
			if (seedOf != null) seedOf[found] = k;
			out[found++] = p;
		}
		return Arrays.copyOf(out, found);
	}

	/**
	 * @return the margin within which a particle of diameter {@code d} counts as cut by the edge for its first
	 *         pass: a quarter diameter and the gradient operator's reach (the fit decides again from the
	 *         information its profile loses)
	 */
	public static double margin(final double d) {
		return d / 4 + 2;
	}

	/** @return the radius of a seed's first-pass area for particles of diameter {@code d}: half of it, at least 2 px */
	public static double radius(final double d) {
		return Math.max(2, d / 2);
	}
}
