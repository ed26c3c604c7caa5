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

import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * The standard errors of members fitted in turn, widened by their neighbours' uncertainty. A member fitted in turn
 * is fitted with its neighbours' light held at their estimates, and its own least squares gives the error of its
 * centre were they exact. They are not: each neighbour's centre, amplitude and scale are uncertain too, and where
 * its light overlaps the member's pixels that uncertainty moves the member's centre. The joint fit of them all
 * would say by how much (the member's block of the inverse of the joint J^T J); here the joint J^T J is taken one
 * neighbour deep: the member's information less what each neighbour's own uncertainty takes of it (the Schur
 * complement {@code A_qq - sum_j A_qj A_jj^-1 A_jq}, with {@code A_qj} summed over the member's pixels and
 * {@code A_jj} the neighbour's own J^T J). On the detection study's packed monolayers the centres' errors were 1.3
 * to 1.5 times the errors that the members' own fits reported, and 1.08 to 1.32 times those widened (what is left:
 * the neighbours' neighbours). The positions and flags do not change: the fit's own error stays the scale by which
 * the iterations and rounds judge a centre settled ({@link Estimate#coupledX}).
 */
final class Coupling {

	/** A member's error is widened at most this many times (the one-deep complement only approximates the joint). */
	static final double MOST = 3;

	/**
	 * The cross blocks are summed over about this many of a member's pixels at most (a regular sample of them, the
	 * sums times the stride: the gradients are smooth): a packed field's members hold a hundred or two, a
	 * bright-field particle of 35 px over a thousand, each lit by a dozen neighbours' profiles 65 px long. Summed over
	 * all of them, the paper authors' {@code 1.avi} took half as long again, for errors widened by 0.3% at the median;
	 * over this sample, 5% longer, the widened errors within 2% of those of the full sums.
	 */
	static final int SAMPLED = 64;

	private Coupling() {}

	/**
	 * Widens the standard errors of the members of {@code group} in {@code e} ({@link MemberSweeps#fitInTurn}'s last
	 * fits, each member's pixels and J^T J in {@code kept}) by their neighbours' uncertainty. A member without a
	 * J^T J of its latest fit (its fit failed), or whose neighbours have none, keeps its own.
	 *
	 * @param window per member, the radius of its pixels and of its information at scale 1 (px)
	 * @param nearby the frame's particles in a grid (null: every member scanned)
	 * @param memberOf per particle, its place in the group (-1: not a member)
	 */
	static void widen(final Estimate[] e, final int[] group, final EmpiricalProfile[] profile,
		final GroupFit.Kept[] kept, final double[] window, final Nearby nearby, final int[] memberOf)
	{
		final int n = group.length;
		final int[] near = new int[n];
		// (a member's widened error is read by no other's: each is replaced as soon as it is known)
		for (int q = 0; q < n; q++) {
			final GroupFit.Kept own = kept[q];
			if (own.candidates == null || own.jtj == null || own.candidates.count() == 0) continue;
			final Estimate eq = e[group[q]];
			// the neighbours whose information reaches the member's pixels, with a J^T J of their own
			final double reach = window[q] * GroupFit.scaleOf(eq);
			int m = 0;
			final int[] candidates = nearby == null ? null : nearby.nearInAnyOrder(eq.x(), eq.x(), eq.y(), eq.y(), reach +
				nearby.reach() + 1);
			for (int i = 0, c = candidates == null ? n : candidates.length; i < c; i++) {
				final int j = candidates == null ? i : memberOf[candidates[i]];
				if (j < 0 || j == q || kept[j].jtj == null) continue;
				final Estimate ej = e[group[j]];
				if (ej.closerThan(eq, reach + profile[group[j]].radius() * GroupFit.scaleOf(ej))) near[m++] = j;
			}
			if (m == 0) continue;
			final double[] f = widened(e, group, profile, kept, window, q, near, m);
			if (f != null && (f[0] != 1 || f[1] != 1)) e[group[q]] = eq.withCoupled(eq.reportedX() * f[0], eq.reportedY() *
				f[1]);
		}
	}

	/**
	 * @param near the members ({@code near[0..m)}) whose information reaches member {@code q}'s pixels
	 * @return the factors by which member {@code q}'s errors along x and y widen, or null where the complement is not
	 *         positive (the one-deep approximation failed: the member keeps its own)
	 */
	private static double[] widened(final Estimate[] e, final int[] group, final EmpiricalProfile[] profile,
		final GroupFit.Kept[] kept, final double[] window, final int q, final int[] near, final int m)
	{
		final int per = GroupFit.PER_PARTICLE;
		// the member's blocks with each neighbour, on the member's pixels (every stride-th of them where they are many:
		// the sums of smooth gradients over a regular sample, times the stride); the member's own block is its fit's
		final double[] cross = new double[m * per * per];
		final GroupFit.Kept mine = kept[q];
		final int count = mine.candidates.count(), stride = Math.max(1, count / SAMPLED);
		final double[] gq = new double[per], gj = new double[per];
		final double[] packed = mine.candidates.packed();
		final boolean[] use = mine.use;
		final Estimate eq = e[group[q]];
		final EmpiricalProfile pq = profile[group[q]];
		final double[] nx = new double[m], ny = new double[m], reach2 = new double[m];
		for (int t = 0; t < m; t++) {
			final Estimate ej = e[group[near[t]]];
			nx[t] = ej.x();
			ny[t] = ej.y();
			final double r = profile[group[near[t]]].radius() * GroupFit.scaleOf(ej);
			reach2[t] = r * r;
		}
		for (int i = 0, o = 0; i < count; i += stride, o += stride * FitPixels.PACKED) {
			if (use != null && !use[i]) continue;
			final double x = packed[o], y = packed[o + 1];
			boolean lit = false; // (the member's gradient, once, where a neighbour's information lies)
			for (int t = 0; t < m; t++) {
				final double dx = x - nx[t], dy = y - ny[t];
				if (!(dx * dx + dy * dy < reach2[t])) continue;
				if (!lit && !(lit = gradient(x, y, eq, pq, gq))) break;
				if (!gradient(x, y, e[group[near[t]]], profile[group[near[t]]], gj)) continue;
				final int c = t * per * per;
				for (int a = 0; a < per; a++)
					for (int b = 0; b < per; b++)
						cross[c + a * per + b] += gq[a] * gj[b];
			}
		}
		final double[][] alone = block(mine.jtj), s = block(mine.jtj);
		for (int c = 0; c < cross.length; c++)
			cross[c] *= stride;
		for (int t = 0; t < m; t++) {
			final double[][] ajjInv = SymmetricSolver.invert(block(kept[near[t]].jtj));
			if (ajjInv == null) continue;
			final int c = t * per * per;
			// s -= c ajj^-1 c^T
			for (int a = 0; a < per; a++)
				for (int b = 0; b < per; b++) {
					double sum = 0;
					for (int u = 0; u < per; u++)
						for (int v = 0; v < per; v++)
							sum += cross[c + a * per + u] * ajjInv[u][v] * cross[c + b * per + v];
					s[a][b] -= sum;
				}
		}
		final double[][] aloneInv = SymmetricSolver.invert(alone), marginal = SymmetricSolver.invert(s);
		if (aloneInv == null || marginal == null || !(marginal[0][0] > 0) || !(marginal[1][1] > 0)) return null;
		// (a complement that is positive is no larger than the member's own information: widened, never narrowed)
		return new double[] { Math.min(MOST, Math.max(1, Math.sqrt(marginal[0][0] / aloneInv[0][0]))), Math.min(MOST,
			Math.max(1, Math.sqrt(marginal[1][1] / aloneInv[1][1]))) };
	}

	/**
	 * The gradient of a particle's light at pixel {@code (x, y)} with respect to its x, y, amplitude and scale, as the
	 * fit's passes compute it ({@link NormalEquations}), into {@code g}.
	 *
	 * @return whether the pixel lies within the particle's profile (else {@code g} is not written)
	 */
	private static boolean gradient(final double x, final double y, final Estimate est, final EmpiricalProfile profile,
		final double[] g)
	{
		return gradient(x, y, est.x(), est.y(), GroupFit.amplitudeOf(est), GroupFit.scaleOf(est), profile, g);
	}

	/** {@link #gradient(double, double, Estimate, EmpiricalProfile, double[])} of a particle at these parameters */
	static boolean gradient(final double x, final double y, final double cx, final double cy, final double a,
		final double sc, final EmpiricalProfile profile, final double[] g)
	{
		final double dx = x - cx, dy = y - cy, r = Math.sqrt(dx * dx + dy * dy), rs = r / sc;
		if (!(rs < profile.radius())) return false;
		final double d = a * profile.slope(rs) / sc, radial = r > 1e-12 ? -d / r : 0;
		g[0] = radial * dx;
		g[1] = radial * dy;
		g[2] = profile.lookup(rs);
		g[3] = -d * rs;
		return true;
	}

	/** @return the member's own 4 x 4 block of a J^T J (a copy) */
	private static double[][] block(final double[][] a) {
		final double[][] out = new double[GroupFit.PER_PARTICLE][GroupFit.PER_PARTICLE];
		for (int i = 0; i < out.length; i++)
			System.arraycopy(a[i], 0, out[i], 0, out.length);
		return out;
	}
}
