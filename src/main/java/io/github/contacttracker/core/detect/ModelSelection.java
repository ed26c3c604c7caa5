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

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.fit.ProfileRefinement;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.radial.Refinement;

/**
 * Which particles a frame holds, decided by the fit: seeds from the image ({@link ImageDetection}), the profile
 * fit of them all, then moves that change the model where the data ask for it, until none does (at most
 * {@value #ROUNDS} rounds):
 * <ul>
 * <li><b>remove</b> a member the fit does not need: one whose fitted amplitude is not positive (no particle of its
 * kind: a bright fringe between dark-ringed particles), one that sits on another member (within a quarter
 * diameter: both fitted one particle), and one whose light lowers the residual sum of squares by less than
 * {@value #SIGNIFICANCE}&sup2; noise variances (the likelihood ratio of the model with and without it, at the
 * others' fitted values: a bump of noise);</li>
 * <li><b>add</b> a particle where the residuals, band-passed as the frame was, hold a peak that stands out as the
 * seeds did, twice as high ({@link #ADD_LEVEL}, {@link ImageDetection#PROMINENCE}, in units of the band-passed
 * residuals' noise, the larger of the pixel noise's and the residuals' own robust spread, so that a model that
 * does not match the particles everywhere adds nothing) farther than a quarter diameter from every member: a
 * particle the seeds missed, such as the second of a pair closer than the filter resolves, which the fit of one
 * member leaves as a peak beside it.</li>
 * </ul>
 * After a move, every particle is seeded again at its fitted centre (an added one at its residual peak) and the frame
 * fitted again with the same profiles. A particle's significance, the square root of that drop of the residual sum of
 * squares in noise units, ranks the spots (their {@code QUALITY}).
 */
public final class ModelSelection {

	/**
	 * The threshold's components teach a frame's profile when at least this many, and this share of them, are one
	 * particle each (not suspected merges): else the seeds of the image do.
	 */
	static final int MIN_BOOTSTRAP = 3;
	/** See {@link #MIN_BOOTSTRAP}. */
	static final double HEALTHY = 0.8;

	/** At most this many rounds of moves and refits. */
	public static final int ROUNDS = 3;
	/** A member must lower the residual sum of squares by this many noise standard deviations, squared. */
	public static final double SIGNIFICANCE = 5;
	/**
	 * A residual peak adds a particle at this many times the band-passed residuals' noise: twice a seed's level, so
	 * that a particle once added is not removed again by the next round (a missed particle leaves a residual peak of
	 * its whole height; a profile that is still being measured leaves ripples near every particle).
	 */
	public static final double ADD_LEVEL = 2 * ImageDetection.LEVEL;

	private ModelSelection() {}

	/**
	 * The particles of a frame, their estimates and significance.
	 *
	 * @param particles the particles, seeded by the image and kept by the fit
	 * @param outcome their refinement, same order
	 * @param significance each particle's significance (noise units; NaN where not measured)
	 * @param removed seeds the fit did not need
	 */
	public record Result(Particle[] particles, Refinement.Outcome outcome, double[] significance, int removed) {}

	/**
	 * @param plane the frame
	 * @param params the parameters ({@link TrackerParameters#diameter()} {@code > 0})
	 * @param refinement the profile method ({@link ProfileRefinement#FIT} or {@link ProfileRefinement#DEBLEND})
	 * @param given the profiles measured beforehand, or {@code null} (measured on this frame)
	 * @param noise the frame's pixel noise (grey levels)
	 */
	public static Result track(final Plane plane, final TrackerParameters params, final ProfileRefinement refinement,
		final KindProfiles given, final double noise)
	{
		return track(plane, params, refinement, given, noise, null);
	}

	/**
	 * @param bootstrap without profiles given: the particles the threshold's components give, whose fit measures the
	 *        profiles that tell the image's seeds apart (a seed is kept where the frame matches a profile); null, or
	 *        a fit of them that measures no profile: the frame's own profile is measured on every seed
	 */
	public static Result track(final Plane plane, final TrackerParameters params, final ProfileRefinement refinement,
		final KindProfiles given, final double noise, final java.util.function.Supplier<Particle[]> bootstrap)
	{
		if (given == null && bootstrap != null) {
			final Particle[] first = bootstrap.get();
			int reliable = 0;
			for (final Particle p : first)
				if (p.reliable()) reliable++;
			// only components that are particles teach the profile: most of them one particle each
			if (reliable >= MIN_BOOTSTRAP && reliable >= HEALTHY * first.length) {
				final KindProfiles measured = refinement.fit(plane, first, params, null, noise).profiles();
				if (measured != null) return track(plane, params, refinement, measured, noise, null);
			}
		}
		final double d = params.diameter();
		final int w = plane.width(), h = plane.height();
		final float[] data = BandPass.pixels(plane);
		final Peaks seeds = ImageDetection.seeds(plane, d, noise);
		final double least = ImageDetection.RELATIVE * seeds.typicalHeight();
		final ImageDetection.Scale scale = ImageDetection.Scale.of(d);
		final float[][] cache = new float[1][];
		final float[] bpData = dataBp(plane, scale, data, w, h, cache);
		final double strong = STRONG * typicalMatching(seeds, data, w, h, given, noise);
		// with the profiles known, a weak seed is fitted only where the frame matches a particle's profile (a halo's
		// fringe does not)
		final Moves start = new Moves(seeds.count());
		int removed = 0;
		for (int i = 0; i < seeds.count(); i++)
			if (given == null || seeds.height()[i] >= strong || matchedAny(data, w, h, seeds.x()[i], seeds.y()[i], given,
				noise) >= MATCH) start.add(seeds.x()[i], seeds.y()[i]);
			else removed++;
		Particle[] ps = ImageDetection.particles(plane, start.x(), start.y(), ImageDetection.radius(d), ImageDetection
			.margin(d));
		ProfileRefinement.Fitted fitted = refinement.fit(plane, ps, params, given, noise, false);
		final KindProfiles profiles = fitted.profiles();
		double[] significance = new double[ps.length];
		Arrays.fill(significance, Double.NaN);
		if (profiles == null) return new Result(ps, fitted.outcome(), significance, removed);
		for (int round = 0; round <= ROUNDS; round++) {
			final Estimate[] e = fitted.outcome().estimates();
			final int[] kinds = fitted.outcome().kinds() != null ? fitted.outcome().kinds() : new int[e.length];
			final EmpiricalProfile[] of = profiles.byParticle(kinds);
			final float[] residual = data.clone();
			for (int k = 0; k < e.length; k++)
				if (drawn(e[k])) draw(residual, w, h, e[k], of[k], -1);
			significance = new double[e.length];
			for (int k = 0; k < e.length; k++)
				significance[k] = drawn(e[k]) ? significance(residual, w, h, e[k], of[k], noise) : undrawn(residual, w, h,
					e[k], of[k], noise);
			if (round == ROUNDS) break;
			// remove
			final double[] match = new double[e.length];
			for (int k = 0; k < e.length; k++)
				match[k] = weak(bpData, w, h, e[k].x(), e[k].y(), strong) ? matched(data, w, h, e[k].x(), e[k].y(), of[k],
					noise) : 1;
			final boolean[] keep = new boolean[e.length];
			int kept = 0;
			for (int k = 0; k < e.length; k++) {
				keep[k] = !(e[k].amplitude() <= 0) && !(e[k].scale() <= PINNED_LOW) && !pinned(e[k]) && !(significance[
					k] < SIGNIFICANCE) && !(match[k] < MATCH);
				for (int j = 0; j < k && keep[k]; j++)
					if (keep[j] && e[j].distanceTo(e[k]) < d / 4) {
						// two members on one particle: the weaker goes
						if (e[k].amplitude() > e[j].amplitude()) keep[j] = false;
						else keep[k] = false;
					}
			}
			overlapTest(data, w, h, e, of, keep, significance, d, noise);
			for (final boolean b : keep)
				if (b) kept++;
			// split and add
			final float[] bp = BandPass.of(residual, w, h, scale.sigma(), scale.halfWidth());
			final double unit = Math.max(ImageDetection.unit(scale.noise(noise), bp), robustSpread(bp, near(w, h, e, of)));
			final Peaks more = Peaks.find(bp, w, h, 0, Math.max(ADD_LEVEL * unit, least), ImageDetection.PROMINENCE *
				unit);
			final Moves moves = new Moves(e.length + 2 * more.count() + e.length);
			final boolean[] split = new boolean[e.length];
			for (int k = 0; k < e.length; k++)
				if (keep[k]) moves.add(e[k].x(), e[k].y());
				else if (pinned(e[k]) && significance[k] >= SIGNIFICANCE) {
					// a blob too large for one particle of its kind: two if it is elongated, else kept as it is
					if (split(dataBp(plane, scale, data, w, h, cache), w, h, e[k], d, moves)) split[k] = true;
					else moves.add(e[k].x(), e[k].y());
				}
			for (int p = 0; p < more.count(); p++) {
				final double px = more.x()[p], py = more.y()[p];
				int nearest = -1;
				double dn = Double.POSITIVE_INFINITY;
				for (int k = 0; k < e.length; k++) {
					final double dk = dist(e[k].x() - px, e[k].y() - py);
					if (keep[k] && dk < dn) {
						dn = dk;
						nearest = k;
					}
				}
				if (dn < d / 4 || moves.near(px, py, d / 4)) continue; // on a member, or on one just added
				if (nearest >= 0 && dn < d && !split[nearest]) {
					// a peak beside a member: the member held two particles; it splits along the peak's direction
					split[nearest] = true;
					moves.replace(e[nearest].x(), e[nearest].y(), e[nearest].x() + 0.5 * (px - e[nearest].x()),
						e[nearest].y() + 0.5 * (py - e[nearest].y()), e[nearest].x() - 0.5 * (px - e[nearest].x()),
						e[nearest].y() - 0.5 * (py - e[nearest].y()));
				}
				else if ((nearest < 0 || dn >= d) && (more.height()[p] >= strong || matchedAny(data, w, h, px, py, profiles,
					noise) >= MATCH)) moves.add(px, py);
			}
			int splits = 0;
			for (final boolean b : split)
				if (b) splits++;
			final int added = moves.size() - kept;
			if (kept == e.length && added == 0 && splits == 0) break;
			removed += Math.max(0, e.length - moves.size());
			ps = ImageDetection.particles(plane, moves.x(), moves.y(), ImageDetection.radius(d), ImageDetection.margin(d));
			fitted = refinement.fit(plane, ps, params, profiles, noise, false);
		}
		return new Result(ps, fitted.outcome(), significance, removed);
	}

	/** The seeds of the next round: kept members' centres, children of split members, added particles. */
	private static final class Moves {
		double[] x, y;
		int n;

		Moves(final int capacity) {
			x = new double[Math.max(1, capacity)];
			y = new double[x.length];
		}

		void add(final double px, final double py) {
			if (n == x.length) {
				x = Arrays.copyOf(x, 2 * n);
				y = Arrays.copyOf(y, 2 * n);
			}
			x[n] = px;
			y[n++] = py;
		}

		/** Replaces the seed at (ox, oy), if there, by two; adds both otherwise. */
		void replace(final double ox, final double oy, final double x1, final double y1, final double x2,
			final double y2)
		{
			for (int i = 0; i < n; i++)
				if (x[i] == ox && y[i] == oy) {
					x[i] = x1;
					y[i] = y1;
					add(x2, y2);
					return;
				}
			add(x1, y1);
			add(x2, y2);
		}

		boolean near(final double px, final double py, final double within) {
			for (int i = 0; i < n; i++)
				if (dist(x[i] - px, y[i] - py) < within) return true;
			return false;
		}

		int size() {
			return n;
		}

		double[] x() {
			return Arrays.copyOf(x, n);
		}

		double[] y() {
			return Arrays.copyOf(y, n);
		}
	}

	/**
	 * @return whether a member's fitted scale is pressed against the fit's upper limit: a blob of two particles
	 *         fitted as one (pressed against the lower one: no particle of its kind, removed)
	 */
	private static boolean pinned(final Estimate e) {
		return e.scale() >= PINNED_HIGH && e.amplitude() > 0;
	}

	/**
	 * The scales from which a member counts as pressed against the fit's range (0.5 to 2): near the top,
	 * {@link #pinned}; near the bottom, no particle of its kind (removed).
	 */
	static final double PINNED_HIGH = 1.9, PINNED_LOW = 0.52;

	/** The band-passed frame, computed once per frame on first use. */
	private static float[] dataBp(final Plane plane, final ImageDetection.Scale scale, final float[] data, final int w,
		final int h, final float[][] cache)
	{
		if (cache[0] == null) cache[0] = BandPass.of(data, w, h, scale.sigma(), scale.halfWidth());
		return cache[0];
	}

	/**
	 * Splits a member whose fit failed on an elongated blob: the second moments of the band-passed frame's positive
	 * part within a diameter of it; where the long axis exceeds the short one by a spread of at least a quarter
	 * diameter, two seeds at {@code c +- u sqrt(l1 - l2)} (two equal particles a distance {@code s} apart add
	 * {@code (s/2)^2} to the variance along their axis).
	 *
	 * @return whether it was split (its two seeds added to {@code moves})
	 */
	static boolean split(final float[] bp, final int w, final int h, final Estimate e, final double d,
		final Moves moves)
	{
		final double cx = e.x(), cy = e.y();
		final int x0 = Math.max(0, (int) Math.floor(cx - d)), x1 = Math.min(w - 1, (int) Math.ceil(cx + d));
		final int y0 = Math.max(0, (int) Math.floor(cy - d)), y1 = Math.min(h - 1, (int) Math.ceil(cy + d));
		double s = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				final double v = bp[y * w + x];
				if (!(v > 0) || dist(x - cx, y - cy) > d) continue;
				s += v;
				sx += v * x;
				sy += v * y;
				sxx += v * x * x;
				syy += v * y * y;
				sxy += v * x * y;
			}
		if (!(s > 0)) return false;
		final double mx = sx / s, my = sy / s;
		final double vxx = sxx / s - mx * mx, vyy = syy / s - my * my, vxy = sxy / s - mx * my;
		final double tr = vxx + vyy, det = vxx * vyy - vxy * vxy, disc = Math.sqrt(Math.max(0, tr * tr / 4 - det));
		final double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
		final double half = Math.sqrt(Math.max(0, l1 - l2));
		if (half < d / 8) return false;
		double ux = vxy, uy = l1 - vxx;
		if (dist(ux, uy) < 1e-12) {
			ux = vxx >= vyy ? 1 : 0;
			uy = vxx >= vyy ? 0 : 1;
		}
		final double norm = dist(ux, uy);
		ux /= norm;
		uy /= norm;
		moves.add(mx + half * ux, my + half * uy);
		moves.add(mx - half * ux, my - half * uy);
		return true;
	}

	/**
	 * Tests again each kept member that overlaps another (centres nearer than a diameter), weakest first: at fixed
	 * centres and scales the members' amplitudes and a background plane enter the model linearly, so the least
	 * squares over the member's pixels are solved with and without it, the members whose light reaches them free to
	 * take over its light. A member whose removal raises the residual sum of squares by less than
	 * {@value #SIGNIFICANCE}&sup2; noise variances is not needed: a third member between two touching ones, which
	 * at fixed neighbours would carry its own share of their light. A member next to one removed this round is left
	 * for the next round.
	 */
	private static void overlapTest(final float[] data, final int w, final int h, final Estimate[] e,
		final EmpiricalProfile[] of, final boolean[] keep, final double[] significance, final double d,
		final double noise)
	{
		if (!(noise > 0)) return;
		final Integer[] order = new Integer[e.length];
		for (int k = 0; k < order.length; k++)
			order[k] = k;
		java.util.Arrays.sort(order, (a, b) -> Double.compare(significance[a], significance[b]));
		final boolean[] touched = new boolean[e.length];
		for (final int m : order) {
			if (!keep[m] || touched[m] || !drawn(e[m])) continue;
			boolean overlaps = false;
			for (int j = 0; j < e.length && !overlaps; j++)
				overlaps = j != m && keep[j] && drawn(e[j]) && e[j].distanceTo(e[m]) < d;
			if (!overlaps) continue;
			// the member's pixels: those holding the information on it (its light beyond adds little to the decision)
			final double reach = of[m].informationRadius(MATCHED_INFORMATION) * e[m].scale();
			int[] involved = new int[8];
			int n = 0;
			for (int j = 0; j < e.length; j++)
				if (j != m && keep[j] && drawn(e[j]) && e[j].distanceTo(e[m]) < reach + of[j].radius() * e[j].scale()) {
					if (n == involved.length) involved = Arrays.copyOf(involved, 2 * n);
					involved[n++] = j;
				}
			final double with = rss(data, w, h, e, of, m, involved, n, true, reach);
			final double without = rss(data, w, h, e, of, m, involved, n, false, reach);
			if (!(without - with >= SIGNIFICANCE * SIGNIFICANCE * noise * noise)) {
				keep[m] = false;
				for (int q = 0; q < n; q++)
					touched[involved[q]] = true;
			}
		}
	}

	/**
	 * @return the least residual sum of squares, over the pixels within {@code reach} of member {@code m}, of a
	 *         background plane plus the light of members {@code involved[0..n)} (and of {@code m} if {@code withM})
	 *         at their fitted centres and scales, with free amplitudes
	 */
	private static double rss(final float[] data, final int w, final int h, final Estimate[] e,
		final EmpiricalProfile[] of, final int m, final int[] involved, final int n, final boolean withM,
		final double reach)
	{
		final int np = 3 + n + (withM ? 1 : 0);
		final double[][] a = new double[np][np];
		final double[] b = new double[np], f = new double[np];
		double yy = 0;
		final double cx = e[m].x(), cy = e[m].y();
		final int x0 = Math.max(0, (int) Math.floor(cx - reach)), x1 = Math.min(w - 1, (int) Math.ceil(cx + reach));
		final int y0 = Math.max(0, (int) Math.floor(cy - reach)), y1 = Math.min(h - 1, (int) Math.ceil(cy + reach));
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				if (dist(x - cx, y - cy) > reach) continue;
				f[0] = 1;
				f[1] = x - cx;
				f[2] = y - cy;
				for (int q = 0; q < n; q++)
					f[3 + q] = light(of[involved[q]], e[involved[q]], x, y);
				if (withM) f[np - 1] = light(of[m], e[m], x, y);
				final double v = data[y * w + x];
				yy += v * v;
				for (int i = 0; i < np; i++) {
					b[i] += f[i] * v;
					for (int j = 0; j <= i; j++)
						a[i][j] += f[i] * f[j];
				}
			}
		for (int i = 0; i < np; i++)
			for (int j = i + 1; j < np; j++)
				a[i][j] = a[j][i];
		final double[] p = io.github.contacttracker.core.math.SymmetricSolver.solve(a, b);
		if (p == null) return Double.NaN;
		double fit = 0;
		for (int i = 0; i < np; i++)
			fit += p[i] * b[i];
		return yy - fit; // at the least-squares point, RSS = y.y - p.b
	}

	/** @return the length of (dx, dy) (not {@code Math.hypot}, whose care for overflow costs in the pixel loops) */
	private static double dist(final double dx, final double dy) {
		return Math.sqrt(dx * dx + dy * dy);
	}

	/** @return a member's unit-amplitude light at pixel (x, y): {@code P(r / s)} */
	private static double light(final EmpiricalProfile p, final Estimate e, final int x, final int y) {
		return p.lookup(dist(x - e.x(), y - e.y()) / e.scale());
	}

	/**
	 * @return how well the frame around (x, y) matches a particle's profile there: the correlation of the pixels with
	 *         {@code P(r)} over the disc holding {@value #MATCHED_INFORMATION} of the information on a centre, the
	 *         pixels' variance taken less the noise's (so that a dim particle matches as a bright one does). A
	 *         particle's own image correlates near 1 (on the paper authors' 1.avi 0.83-0.98); a peak where neighbours'
	 *         halos meet, lit where the profile's core is and dark where its ring is bright, far less (0.64 at most);
	 *         noise alone, 0.
	 */
	static double matched(final float[] data, final int w, final int h, final double x, final double y,
		final EmpiricalProfile p, final double noise)
	{
		if (!Double.isFinite(x) || !Double.isFinite(y)) return Double.NaN;
		final double reach = Math.min(p.radius(), p.informationRadius(MATCHED_INFORMATION));
		final int x0 = Math.max(0, (int) Math.floor(x - reach)), x1 = Math.min(w - 1, (int) Math.ceil(x + reach));
		final int y0 = Math.max(0, (int) Math.floor(y - reach)), y1 = Math.min(h - 1, (int) Math.ceil(y + reach));
		double sp = 0, si = 0, spi = 0, spp = 0, sii = 0;
		int n = 0;
		for (int yy = y0; yy <= y1; yy++)
			for (int xx = x0; xx <= x1; xx++) {
				final double r = dist(xx - x, yy - y);
				if (r > reach) continue;
				final double v = p.lookup(r), im = data[yy * w + xx];
				sp += v;
				si += im;
				spi += v * im;
				spp += v * v;
				sii += im * im;
				n++;
			}
		if (n < 2) return Double.NaN;
		// the image's variance less the noise's: a dim particle matches as well as a bright one
		final double cov = spi - sp * si / n, vp = spp - sp * sp / n, vi = sii - si * si / n - (n - 1) * noise * noise;
		return vp > 0 && vi > 0 ? Math.min(1, cov / Math.sqrt(vp * vi)) : 0;
	}

	/** The matched filter reads the disc that holds this share of the information on a particle's centre. */
	static final double MATCHED_INFORMATION = 0.9;

	/** @return the best {@link #matched} correlation at (x, y) among the kinds' profiles */
	static double matchedAny(final float[] data, final int w, final int h, final double x, final double y,
		final KindProfiles profiles, final double noise)
	{
		double best = Double.NEGATIVE_INFINITY;
		for (int c = 0; c < profiles.count(); c++)
			best = Math.max(best, matched(data, w, h, x, y, profiles.profile(c), noise));
		return best;
	}

	/**
	 * A weak seed or member is a particle only where the frame matches a particle's profile at least this well (see
	 * {@link #matched}): between the halo junctions' 0.64 and the particles' 0.83 on the authors' bright-field movie.
	 */
	public static final double MATCH = 0.75;
	/**
	 * Weak: a band-passed height below this fraction of the typical seed's. The fringes where bright-field halos meet
	 * are weak (on the authors' 1.avi at most 0.5 of the typical core); a blob of two merged particles, which no
	 * single profile matches, is not.
	 */
	public static final double STRONG = 0.6;

	/**
	 * @return the typical height of the seeds that are particles: of those that match a profile, where profiles are
	 *         given and some do (a sparse field of particles on a textured background has more seeds on the texture
	 *         than on particles); else of all
	 */
	private static double typicalMatching(final Peaks seeds, final float[] data, final int w, final int h,
		final KindProfiles given, final double noise)
	{
		if (given == null) return seeds.typicalHeight();
		final double[] hs = new double[seeds.count()];
		int n = 0;
		for (int i = 0; i < seeds.count(); i++)
			if (matchedAny(data, w, h, seeds.x()[i], seeds.y()[i], given, noise) >= MATCH) hs[n++] = seeds.height()[i];
		if (n == 0) return seeds.typicalHeight();
		Arrays.sort(hs, 0, n);
		return hs[(int) Math.floor(0.9 * (n - 1))];
	}

	/** @return whether the band-passed frame at (x, y) is below {@code strong} (or (x, y) is off the frame) */
	private static boolean weak(final float[] bp, final int w, final int h, final double x, final double y,
		final double strong)
	{
		final int ix = (int) Math.round(x), iy = (int) Math.round(y);
		return ix < 0 || iy < 0 || ix >= w || iy >= h || bp[iy * w + ix] < strong;
	}

	/** @return whether a fitted estimate is drawn in the model (a finite amplitude and a positive scale) */
	private static boolean drawn(final Estimate e) {
		return Double.isFinite(e.amplitude()) && e.scale() > 0 && Double.isFinite(e.x()) && Double.isFinite(e.y()) &&
			!e.has(Flag.MERGED);
	}

	/** Adds {@code sign} times the particle's light, {@code a P(r / s)}, to the image (within its profile's radius). */
	static void draw(final float[] image, final int w, final int h, final Estimate e, final EmpiricalProfile p,
		final int sign)
	{
		final double s = e.scale(), a = sign * e.amplitude(), reach = p.radius() * s;
		final int x0 = Math.max(0, (int) Math.floor(e.x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e.x() + reach));
		final int y0 = Math.max(0, (int) Math.floor(e.y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e.y() + reach));
		for (int y = y0; y <= y1; y++) {
			final double dy = y - e.y();
			for (int x = x0; x <= x1; x++) {
				final double dx = x - e.x();
				image[y * w + x] += (float) (a * p.lookup(Math.sqrt(dx * dx + dy * dy) / s));
			}
		}
	}

	/**
	 * @return the significance of a member: the square root of how much its light lowers the residual sum of squares
	 *         ({@code sum M^2 + 2 r M} over its pixels, {@code r} the residuals with it drawn less their mean there,
	 *         the background, {@code M} its light) in units of the pixel noise; for a frame without noise, infinite
	 */
	static double significance(final float[] residual, final int w, final int h, final Estimate e,
		final EmpiricalProfile p, final double noise)
	{
		final double s = e.scale(), a = e.amplitude(), reach = p.radius() * s;
		final int x0 = Math.max(0, (int) Math.floor(e.x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e.x() + reach));
		final int y0 = Math.max(0, (int) Math.floor(e.y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e.y() + reach));
		// the residuals hold the background (the model drawn is the particles' light alone): their mean over the
		// member's pixels stands for it
		double r0 = 0;
		int n = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				r0 += residual[y * w + x];
				n++;
			}
		r0 /= Math.max(1, n);
		double drop = 0;
		for (int y = y0; y <= y1; y++) {
			final double dy = y - e.y();
			for (int x = x0; x <= x1; x++) {
				final double dx = x - e.x();
				final double m = a * p.lookup(Math.sqrt(dx * dx + dy * dy) / s);
				drop += m * m + 2 * (residual[y * w + x] - r0) * m;
			}
		}
		if (!(noise > 0)) return drop > 0 ? Double.POSITIVE_INFINITY : 0;
		return drop > 0 ? Math.sqrt(drop) / noise : 0;
	}

	/**
	 * @return the significance of a member the fit left undrawn (it could not be fitted): its light at the best
	 *         amplitude where it stands, at scale 1, {@code a = sum r P / sum P^2}, lowers the residual sum of squares
	 *         by {@code a^2 sum P^2}; 0 for an amplitude not above 0 (nothing of its kind there)
	 */
	static double undrawn(final float[] residual, final int w, final int h, final Estimate e,
		final EmpiricalProfile p, final double noise)
	{
		if (!Double.isFinite(e.x()) || !Double.isFinite(e.y())) return 0;
		final double reach = p.radius();
		final int x0 = Math.max(0, (int) Math.floor(e.x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e.x() + reach));
		final int y0 = Math.max(0, (int) Math.floor(e.y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e.y() + reach));
		double rp = 0, pp = 0, r0 = 0;
		int n = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				r0 += residual[y * w + x];
				n++;
			}
		r0 /= Math.max(1, n); // the residuals' local mean: the background the fit would have taken
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				final double v = p.lookup(dist(x - e.x(), y - e.y()));
				rp += (residual[y * w + x] - r0) * v;
				pp += v * v;
			}
		if (!(pp > 0) || !(rp > 0)) return 0;
		final double drop = rp * rp / pp;
		return noise > 0 ? Math.sqrt(drop) / noise : Double.POSITIVE_INFINITY;
	}

	/** @return which pixels lie within reach of a drawn member's light (its profile's radius times its scale) */
	private static boolean[] near(final int w, final int h, final Estimate[] e, final EmpiricalProfile[] of) {
		final boolean[] near = new boolean[w * h];
		for (int k = 0; k < e.length; k++) {
			if (!drawn(e[k])) continue;
			final double reach = of[k].radius() * e[k].scale();
			final int x0 = Math.max(0, (int) Math.floor(e[k].x() - reach)), x1 = Math.min(w - 1, (int) Math.ceil(e[k].x() +
				reach));
			final int y0 = Math.max(0, (int) Math.floor(e[k].y() - reach)), y1 = Math.min(h - 1, (int) Math.ceil(e[k].y() +
				reach));
			for (int y = y0; y <= y1; y++)
				for (int x = x0; x <= x1; x++)
					if (dist(x - e[k].x(), y - e[k].y()) <= reach) near[y * w + x] = true;
		}
		return near;
	}

	/**
	 * @return 1.4826 times the median absolute deviation from the median of the values where {@code where} holds (all
	 *         when none does), on a sample of at most 65536 of them: the spread of the residuals where the model
	 *         draws particles, which its mismatch with real particles raises
	 */
	static double robustSpread(final float[] v, final boolean[] where) {
		int count = 0;
		for (final boolean b : where)
			if (b) count++;
		final boolean all = count == 0;
		if (all) count = v.length;
		final int step = Math.max(1, count / 65536);
		final int n = (count + step - 1) / step;
		if (n == 0) return 0;
		final double[] s = new double[n];
		for (int i = 0, seen = 0, j = 0; i < v.length && j < n; i++)
			if (all || where[i]) {
				if (seen++ % step == 0) s[j++] = v[i];
			}
		Arrays.sort(s);
		final double median = s[n / 2];
		for (int j = 0; j < n; j++)
			s[j] = Math.abs(s[j] - median);
		Arrays.sort(s);
		return 1.4826 * s[n / 2];
	}
}
