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

import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.math.Statistics;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * How well a frame matches a particle's measured profile at a point: what tells a weak seed that is a particle from
 * one that is not (a fringe where bright-field halos meet), once the profile is known.
 */
final class ProfileMatch {

	private ProfileMatch() {}

	/**
	 * @return how well the frame around (x, y) matches a particle's profile there: the correlation of the pixels with
	 *         {@code P(r)} over the disc holding {@value #MATCHED_INFORMATION} of the information on a centre, the
	 *         pixels' variance taken less the noise's (so that a dim particle matches as a bright one does). A
	 *         particle's own image correlates near 1, short of it by what a touching neighbour's light adds to the
	 *         disc; a peak where neighbours' halos meet, lit where the profile's core is and dark where its ring is
	 *         bright (the rings of a particle the other way round), far less; noise alone, 0.
	 */
	static double matched(final float[] data, final int w, final int h, final double x, final double y,
		final EmpiricalProfile p, final double noise)
	{
		final double[] m = sums(data, w, h, x, y, p);
		if (m == null) return Double.NaN;
		// the image's variance less the noise's: a dim particle matches as well as a bright one
		return correlation(m[0], m[1], m[2], m[3], m[4], (int) m[5], noise);
	}

	/**
	 * @return as {@link #matched}, for a fitted member, on its own light: the fit's {@code residual} with the member's
	 *         drawn light {@code a P(r / s)} added back, correlated with its drawn shape {@code P(r / s)} over its disc
	 *         (scaled as the member is). The frame itself is the member's light plus its fitted neighbours'; in a dense
	 *         field theirs fills the disc around every particle, and the frame matches no single profile there even at
	 *         a particle. NaN for a member not drawn (no finite centre, amplitude or scale) or off the frame.
	 */
	static double matchedOwn(final float[] residual, final int w, final int h, final Estimate e,
		final EmpiricalProfile p, final double noise)
	{
		final double[] m = ownSums(residual, w, h, e, p);
		return m == null ? Double.NaN : correlation(m[0], m[1], m[2], m[3], m[4], (int) m[5], noise);
	}

	/**
	 * @return the sums of a fitted member's own light (the residuals with its drawn light added back) against its
	 *         drawn shape; null for a member not drawn or off the frame
	 */
	private static double[] ownSums(final float[] residual, final int w, final int h, final Estimate e,
		final EmpiricalProfile p)
	{
		final double s = e.scale(), a = e.amplitude();
		return s > 0 && Double.isFinite(a) ? sums(residual, w, h, e.x(), e.y(), p, s, a) : null;
	}

	/**
	 * @return the correlation of the profile's values with the pixels' from their sums over {@code n} pixels, the
	 *         pixels' variance taken less the noise's; NaN for fewer than 2 pixels, 0 where either varies not at all
	 */
	private static double correlation(final double sp, final double si, final double spi, final double spp,
		final double sii, final int n, final double noise)
	{
		if (n < 2) return Double.NaN;
		final double cov = spi - sp * si / n, vp = spp - sp * sp / n, vi = sii - si * si / n - (n - 1) * noise * noise;
		return vp > 0 && vi > 0 ? Math.min(1, cov / Math.sqrt(vp * vi)) : 0;
	}

	/**
	 * @return the shape verdict on a fitted member's own light: 1 where it differs from its drawn shape by no more
	 *         than the noise makes it differ ({@link #WITHIN_NOISE}), else its correlation ({@link #matchedOwn}); NaN
	 *         as there
	 */
	static double shapeOwn(final float[] residual, final int w, final int h, final Estimate e, final EmpiricalProfile p,
		final double noise)
	{
		return shape(ownSums(residual, w, h, e, p), noise);
	}

	/** @return the best shape verdict at (x, y) among the kinds' profiles: as {@link #shapeOwn}, on the image as it is */
	static double shapeAny(final float[] data, final int w, final int h, final double x, final double y,
		final KindProfiles profiles, final double noise)
	{
		return best(profiles, p -> shape(sums(data, w, h, x, y, p), noise));
	}

	/** @return the shape verdict on sums: 1 where {@link #withinNoise}, else their correlation; NaN for none */
	private static double shape(final double[] m, final double noise) {
		return m == null ? Double.NaN : withinNoise(m, noise) ? 1 : correlation(m[0], m[1], m[2], m[3], m[4], (int) m[5],
			noise);
	}

	/**
	 * @return whether the pixels of the sums differ from their best {@code a P + b} ({@code a > 0}) by no more than the
	 *         noise makes them: the squared misfit in noise variances, a chi-square of {@code n - 2} degrees of
	 *         freedom, within {@link #WITHIN_NOISE} of its standard deviations of its mean
	 */
	private static boolean withinNoise(final double[] m, final double noise) {
		final int n = (int) m[5];
		if (n <= 2 || !(noise > 0)) return false;
		final double cov = m[2] - m[0] * m[1] / n, vp = m[3] - m[0] * m[0] / n, raw = m[4] - m[1] * m[1] / n;
		return cov > 0 && vp > 0 && raw - cov * cov / vp <= noise * noise * (n - 2 + WITHIN_NOISE * Math.sqrt(2.0 * (n -
			2)));
	}

	/**
	 * The shape verdicts ({@link #shapeOwn}, {@link #shapeAny}) take a lit disc for a particle's however low its
	 * correlation where its pixels differ from the best {@code a P + b} ({@code a > 0}) by no more than the noise
	 * makes them: their squared misfit in noise variances, a chi-square of {@code n - 2} degrees of freedom, is within
	 * this many of its standard deviations of its mean. At a peak signal to noise of 3 to 4 the noise alone takes a
	 * particle's correlation below {@link #MATCH} one time in four; a fringe whose rings lie where the profile's do not
	 * differs from it by far more than the noise. Whether a faint bump is a particle at all is the significance's
	 * question.
	 */
	static final double WITHIN_NOISE = 3;

	/**
	 * @return the amplitude of the profile that best matches the frame around (x, y), {@code a} in {@code a P(r) + b}
	 *         by least squares over the disc {@link #matched} reads: in units of the particles the profile was measured
	 *         on (1 for a typical one); NaN off the frame
	 */
	static double amplitude(final float[] data, final int w, final int h, final double x, final double y,
		final EmpiricalProfile p)
	{
		final double[] m = sums(data, w, h, x, y, p);
		if (m == null) return Double.NaN;
		final double sp = m[0], si = m[1], spi = m[2], spp = m[3];
		final int n = (int) m[5];
		final double vp = spp - sp * sp / n;
		return n >= 2 && vp > 0 ? (spi - sp * si / n) / vp : Double.NaN;
	}

	/** @return the largest {@link #amplitude} at (x, y) among the kinds' profiles */
	static double amplitudeAny(final float[] data, final int w, final int h, final double x, final double y,
		final KindProfiles profiles)
	{
		return best(profiles, p -> amplitude(data, w, h, x, y, p));
	}

	/** @return the largest of {@code value} over the kinds' profiles (NaN if it is NaN for one) */
	static double best(final KindProfiles profiles, final java.util.function.ToDoubleFunction<EmpiricalProfile> value) {
		double best = Double.NEGATIVE_INFINITY;
		for (int c = 0; c < profiles.count(); c++)
			best = Math.max(best, value.applyAsDouble(profiles.profile(c)));
		return best;
	}

	/** @return {@link #sums(float[], int, int, double, double, EmpiricalProfile, double, double)} of the image as it is */
	private static double[] sums(final float[] data, final int w, final int h, final double x, final double y,
		final EmpiricalProfile p)
	{
		return sums(data, w, h, x, y, p, 1, 0);
	}

	/**
	 * @return over the disc around (x, y) that holds {@link #MATCHED_INFORMATION} of the information on a centre (its
	 *         radius times {@code scale}), the sums of {@code P}, {@code I}, {@code P I}, {@code P^2}, {@code I^2} and
	 *         the pixels' count, {@code P} the profile at {@code r / scale} and {@code I} the image plus
	 *         {@code added P}; null off the frame
	 */
	private static double[] sums(final float[] data, final int w, final int h, final double x, final double y,
		final EmpiricalProfile p, final double scale, final double added)
	{
		if (!Double.isFinite(x) || !Double.isFinite(y)) return null;
		final double reach = Math.min(p.radius(), p.informationRadius(MATCHED_INFORMATION)) * scale;
		final int x0 = Math.max(0, (int) Math.floor(x - reach)), x1 = Math.min(w - 1, (int) Math.ceil(x + reach));
		final int y0 = Math.max(0, (int) Math.floor(y - reach)), y1 = Math.min(h - 1, (int) Math.ceil(y + reach));
		double sp = 0, si = 0, spi = 0, spp = 0, sii = 0;
		int n = 0;
		for (int yy = y0; yy <= y1; yy++) {
			final double dy = yy - y;
			double xd = x0; // (x counted as a double too, exactly: RowRuns#row says why)
			for (int xx = x0; xx <= x1; xx++, xd++) {
				final double r = MemberTests.dist(xd - x, dy);
				if (r > reach) continue;
				final double v = p.lookup(r / scale), im = data[yy * w + xx] + added * v;
				sp += v;
				si += im;
				spi += v * im;
				spp += v * v;
				sii += im * im;
				n++;
			}
		}
		return new double[] { sp, si, spi, spp, sii, n };
	}

	/** The matched filter reads the disc that holds this share of the information on a particle's centre. */
	static final double MATCHED_INFORMATION = 0.9;

	/** @return the best {@link #matched} correlation at (x, y) among the kinds' profiles */
	static double matchedAny(final float[] data, final int w, final int h, final double x, final double y,
		final KindProfiles profiles, final double noise)
	{
		return best(profiles, p -> matched(data, w, h, x, y, p, noise));
	}

	/**
	 * A weak member is a particle only where its own light ({@link #matchedOwn}; where it is not drawn, or for a peak
	 * of the residuals, the frame: {@link #matched}) matches a particle's profile at least this well: a correlation of
	 * 0.75 leaves the profile more than half (0.56) of the pixels' variance above the noise to explain. A particle's
	 * own image is explained far better; a junction where halos meet, whose bright and dark rings lie where a
	 * particle's are not, far worse.
	 */
	public static final double MATCH = 0.75;
	/**
	 * Weak: a band-passed height below this fraction of the typical seed's. The fringes where bright-field halos meet
	 * are weak: a halo is much fainter than the core it surrounds, so where two overlap their sum stays near half a
	 * core's height or below; a blob of two merged particles, which no single profile matches, holds two cores' light
	 * and is not.
	 */
	public static final double STRONG = 0.6;

	/**
	 * @return the typical height of the seeds that are particles: of those that match a profile, where profiles are
	 *         given and some do (a sparse field of particles on a textured background has more seeds on the texture
	 *         than on particles); else of all
	 */
	static double typicalMatching(final Peaks seeds, final float[] data, final int w, final int h,
		final KindProfiles given, final double noise)
	{
		if (given == null) return seeds.typicalHeight();
		final double[] hs = new double[seeds.count()];
		int n = 0;
		for (int i = 0; i < seeds.count(); i++)
			if (matchedAny(data, w, h, seeds.x()[i], seeds.y()[i], given, noise) >= MATCH) hs[n++] = seeds.height()[i];
		if (n == 0) return seeds.typicalHeight();
		return Statistics.quantile(hs, n, Peaks.STRONG_QUANTILE);
	}

	/** @return whether the band-passed frame at (x, y) is below {@code strong} (or (x, y) is off the frame) */
	static boolean weak(final float[] bp, final int w, final int h, final double x, final double y,
		final double strong)
	{
		final int ix = (int) Math.round(x), iy = (int) Math.round(y);
		return ix < 0 || iy < 0 || ix >= w || iy >= h || bp[iy * w + ix] < strong;
	}
}
