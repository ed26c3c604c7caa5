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

import io.github.contacttracker.core.Flag;

import io.github.contacttracker.core.image.DoublePlane;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.image.RunList;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.GradientField;
import io.github.contacttracker.core.radial.GradientOperator;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.radial.Solve;

/**
 * The {@code deblend} method: each particle is solved by radial symmetry on a disc around its centre (the
 * active area an isolated particle would have), in an image from which the modelled light of every other
 * particle has been subtracted; the centres are refined until they settle. The disc is symmetric about the
 * particle, so neither the neighbours' tails nor a lopsided area bias the lines. Unreliable particles
 * (suspected merges, degenerate) are neither refined nor subtracted: their centre does not describe their light.
 */
final class Deblender {

	/** Stop when no centre moves more than this (px). */
	static final double TOLERANCE = 1e-4;
	static final int MAX_ITERATIONS = 50;

	private Deblender() {}

	/**
	 * Refines the centres of the reliable particles, starting from {@code start}.
	 *
	 * @param discRadius radius of the solving disc (px)
	 * @return the new estimates (the others unchanged) and the number of iterations, negative if the limit was
	 *         reached
	 */
	static ProfileRefinement.Refined refine(final Plane plane, final Particle[] particles, final Estimate[] start,
		final EmpiricalProfile[] profile, final double discRadius)
	{
		final int n = particles.length;
		final Estimate[] e = start.clone();
		final int margin = (int) Math.ceil(discRadius) + GradientOperator.MARGIN + 1;
		final double[] cx = new double[n], cy = new double[n];
		// whether a particle's latest solve gave no centre on its disc (it keeps its previous one, flagged)
		final boolean[] fell = new boolean[n];
		for (int it = 1; it <= MAX_ITERATIONS; it++) {
			for (int k = 0; k < n; k++) {
				cx[k] = e[k].x();
				cy[k] = e[k].y();
			}
			double move = 0;
			for (int k = 0; k < n; k++) {
				final Particle p = particles[k];
				if (!p.reliable()) continue;
				// Local window around the particle, clipped to the frame.
				final int x0 = Math.max(0, (int) Math.floor(cx[k]) - margin), y0 = Math.max(0, (int) Math.floor(cy[k]) -
					margin);
				final int x1 = Math.min(plane.width() - 1, (int) Math.ceil(cx[k]) + margin), y1 = Math.min(plane.height() -
					1, (int) Math.ceil(cy[k]) + margin);
				final int w = x1 - x0 + 1, h = y1 - y0 + 1;
				final double[] data = new double[w * h];
				for (int y = 0; y < h; y++)
					for (int x = 0; x < w; x++)
						data[y * w + x] = plane.get(x0 + x, y0 + y);
				for (int q = 0; q < n; q++) {
					if (q == k || !particles[q].reliable()) continue;
					final double reach = profile[q].radius();
					if (Math.hypot(cx[q] - cx[k], cy[q] - cy[k]) > reach + margin * 1.5) continue;
					for (int y = 0; y < h; y++)
						for (int x = 0; x < w; x++) {
							final double r = Math.hypot(x0 + x - cx[q], y0 + y - cy[q]);
							if (r < reach) data[y * w + x] -= profile[q].lookup(r);
						}
				}
				final DoublePlane local = new DoublePlane(data, w, h);
				final Region disc = disc(cx[k] - x0, cy[k] - y0, discRadius, w, h);
				final GradientField field = GradientField.compute(local, disc);
				final Solve s = Solve.on(field, null, cx[k] - x0, cy[k] - y0, x0, y0);
				// Lines that meet off the disc they were drawn on describe no particle there: a seed on no particle (on
				// a ramp their directions hardly differ, and they meet hundreds of pixels away, where the next
				// iteration's window would be empty). The particle keeps its previous centre, flagged.
				final double jump = s.ok() ? Math.hypot(s.solution().x() - cx[k], s.solution().y() - cy[k]) : Double.NaN;
				fell[k] = !(jump <= discRadius);
				if (fell[k]) continue;
				e[k] = new Estimate(s.solution().x(), s.solution().y(), e[k].flags(), e[k].secondArea(), e[k].iterations(),
					s, e[k].sigmaX(), e[k].sigmaY());
				move = Math.max(move, jump);
			}
			if (move < TOLERANCE) return new ProfileRefinement.Refined(fellBack(e, fell), it);
		}
		// the centres move together, so none of them has settled
		for (int k = 0; k < e.length; k++)
			e[k] = e[k].withFlags(e[k].flags() | Flag.NOT_CONVERGED.bit());
		return new ProfileRefinement.Refined(fellBack(e, fell), -MAX_ITERATIONS);
	}

	/** @return the estimates, those whose latest solve gave no centre on their disc flagged {@code FELL_BACK} */
	private static Estimate[] fellBack(final Estimate[] e, final boolean[] fell) {
		for (int k = 0; k < e.length; k++)
			if (fell[k]) e[k] = e[k].withFlags(e[k].flags() | Flag.FELL_BACK.bit());
		return e;
	}

	/** Pixels whose centres lie within {@code r} of (cx, cy), clipped to a w x h window. */
	static Region disc(final double cx, final double cy, final double r, final int w, final int h) {
		final RunList runs = new RunList();
		final int y0 = Math.max(0, (int) Math.ceil(cy - r)), y1 = Math.min(h - 1, (int) Math.floor(cy + r));
		for (int y = y0; y <= y1; y++) {
			final double half = Math.sqrt(Math.max(0, r * r - (y - cy) * (y - cy)));
			final int a = Math.max(0, (int) Math.ceil(cx - half)), b = Math.min(w - 1, (int) Math.floor(cx + half));
			if (a <= b) runs.add(y, a, b);
		}
		return runs.toRegion();
	}
}
