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

import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * Whether the fit needs a member: how much its light lowers the residual sum of squares, at its fitted values or, left
 * undrawn, at its best amplitude, and whether its overlapping neighbours, their amplitudes refitted, explain its
 * pixels as well.
 */
final class MemberTests {

	private MemberTests() {}

	/**
	 * Tests again each kept member that overlaps another (centres nearer than a diameter), weakest first: at fixed
	 * centres and scales the members' amplitudes and a background plane enter the model linearly, so the least
	 * squares over the member's pixels are solved with and without it, the members whose light reaches them free to
	 * take over its light. A member whose removal raises the residual sum of squares by less than
	 * {@value ModelSelection#SIGNIFICANCE}&sup2; noise variances is not needed: a third member between two touching ones, which
	 * at fixed neighbours would carry its own share of their light. A member next to one removed this round is left
	 * for the next round.
	 */
	static void overlapTest(final float[] data, final int w, final int h, final Estimate[] e,
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
			if (!keep[m] || touched[m] || !DrawnModel.drawn(e[m])) continue;
			boolean overlaps = false;
			for (int j = 0; j < e.length && !overlaps; j++)
				overlaps = j != m && keep[j] && DrawnModel.drawn(e[j]) && e[j].closerThan(e[m], d);
			if (!overlaps) continue;
			// the member's pixels: those holding the information on it (its light beyond adds little to the decision)
			final double reach = of[m].informationRadius(ProfileMatch.MATCHED_INFORMATION) * e[m].scale();
			int[] involved = new int[8];
			int n = 0;
			for (int j = 0; j < e.length; j++)
				if (j != m && keep[j] && DrawnModel.drawn(e[j]) && e[j].closerThan(e[m], reach + of[j].radius() *
					e[j].scale())) {
					if (n == involved.length) involved = Arrays.copyOf(involved, 2 * n);
					involved[n++] = j;
				}
			final double with = rss(data, w, h, e, of, m, involved, n, true, reach);
			final double without = rss(data, w, h, e, of, m, involved, n, false, reach);
			if (!(without - with >= ModelSelection.SIGNIFICANCE * ModelSelection.SIGNIFICANCE * noise * noise)) {
				keep[m] = false;
				for (int q = 0; q < n; q++)
					touched[involved[q]] = true;
			}
		}
	}

	/**
	 * @return the least residual sum of squares, over the pixels within {@code reach} of member {@code m}, of a
	 *         background plane plus the light of members {@code involved[0..n)} (and of {@code m} if {@code withM})
	 *         at their fitted centres and scales, with free amplitudes; a column that adds nothing is left out (a
	 *         neighbour whose light ends before these pixels, all 0s: solved as it was, the system was singular and its
	 *         NaN verdict removed real touching particles; or {@code m}'s own light, where it is that of the others)
	 */
	static double rss(final float[] data, final int w, final int h, final Estimate[] e,
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
		return yy - SymmetricSolver.explained(a, b, np);
	}

	/** @return the length of (dx, dy) (not {@code Math.hypot}, whose care for overflow costs in the pixel loops) */
	static double dist(final double dx, final double dy) {
		return Math.sqrt(dx * dx + dy * dy);
	}

	/** @return a member's unit-amplitude light at pixel (x, y): {@code P(r / s)} */
	static double light(final EmpiricalProfile p, final Estimate e, final int x, final int y) {
		return p.lookup(dist(x - e.x(), y - e.y()) / e.scale());
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
			double xd = x0; // (x counted as a double too, exactly: RowRuns#row says why)
			for (int x = x0; x <= x1; x++, xd++) {
				final double dx = xd - e.x();
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
		return undrawn(residual, w, h, e.x(), e.y(), p, noise);
	}

	/** @return the best {@link #undrawn} significance at (x, y) among the kinds' profiles */
	static double undrawnAny(final float[] residual, final int w, final int h, final double x, final double y,
		final KindProfiles profiles, final double noise)
	{
		return ProfileMatch.best(profiles, p -> undrawn(residual, w, h, x, y, p, noise));
	}

	/** @return {@link #undrawn} of a particle at (cx, cy) */
	private static double undrawn(final float[] residual, final int w, final int h, final double cx, final double cy,
		final EmpiricalProfile p, final double noise)
	{
		if (!Double.isFinite(cx) || !Double.isFinite(cy)) return 0;
		final double reach = p.radius();
		final int x0 = Math.max(0, (int) Math.floor(cx - reach)), x1 = Math.min(w - 1, (int) Math.ceil(cx + reach));
		final int y0 = Math.max(0, (int) Math.floor(cy - reach)), y1 = Math.min(h - 1, (int) Math.ceil(cy + reach));
		double rp = 0, pp = 0, r0 = 0;
		int n = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				r0 += residual[y * w + x];
				n++;
			}
		r0 /= Math.max(1, n); // the residuals' local mean: the background the fit would have taken
		for (int y = y0; y <= y1; y++) {
			final double yd = y;
			double xd = x0; // (x counted as a double too, exactly: RowRuns#row says why)
			for (int x = x0; x <= x1; x++, xd++) {
				final double v = p.lookup(dist(xd - cx, yd - cy));
				rp += (residual[y * w + x] - r0) * v;
				pp += v * v;
			}
		}
		if (!(pp > 0) || !(rp > 0)) return 0;
		final double drop = rp * rp / pp;
		return noise > 0 ? Math.sqrt(drop) / noise : Double.POSITIVE_INFINITY;
	}
}
