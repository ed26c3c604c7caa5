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
package io.github.contacttracker.advisor;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.ComponentLabeling;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.radial.ComponentShape;

/**
 * The particles the profile helper profiles for a diameter, and their pooled profile: the one at a point given
 * when it is isolated, else the frame's most isolated spots ({@link FrameSpots}), their neighbours masked. Holds
 * their centres, how far out the profile is measured, the pooled profile, its reach and where the particles' own
 * image ends ({@link PooledProfile#imageEdge(PooledProfile, double)}).
 *
 * @param centres the profiled particles' centres {@code {x, y}} (px, the plane's coordinates)
 * @param at the centre of the particle at the point given (whether profiled or not), {@code null} without a point
 * @param refined whether the particle at the point was found among the spots (else the point itself is used)
 * @param radiusCap how far out the profile is measured (px)
 * @param pooled the pooled profile
 * @param reach where the profile returns to the background (px)
 * @param imageEdge where the particles' own image ends (px)
 * @param findings what the user should know of the choice and the profile
 */
record ProfiledParticles(List<double[]> centres, double[] at, boolean refined, double radiusCap,
	PooledProfile pooled, double reach, double imageEdge, List<Finding> findings) {

	/** At most this many particles are profiled together. */
	static final int MAX_PARTICLES = 8;

	/** @return the same profile, for the particle at a point: its centre, and what was found of it first */
	ProfiledParticles withAt(final double[] point, final boolean pointRefined, final List<Finding> more) {
		final List<Finding> all = new ArrayList<>(more);
		all.addAll(findings);
		return new ProfiledParticles(centres, point, pointRefined, radiusCap, pooled, reach, imageEdge, all);
	}

	/**
	 * Steps 3-6: picks the particles (the one at {@code point}, else the most isolated), masks their neighbours and
	 * pools their profile, twice (the masks widened to the measured reach the second time).
	 * <p>
	 * A particle at a point is profiled alone only when it is isolated: its nearest neighbour, and the image's edge
	 * (beyond which a neighbour goes unseen), at least twice {@code r_out} away (the reach plus
	 * {@value Margins#R_OUT_MARGIN_PX} px, measured on the frame's most isolated particles or on the particle
	 * alone, whichever is larger), so that no pixel holds the light of both and the neighbours' masks leave its own
	 * pixels. Closer, its profile never returns to the background between it and its neighbours: its own background, noise
	 * and reach would be the neighbours' halos (a reach of twice the true one, masks that swallow the particle
	 * itself), so the profile and the values are the frame's most isolated particles' instead (as without a point),
	 * and said ({@link Finding.FrameValuesAtPoint}).
	 *
	 * @param narrow whether the masks may narrow where they leave no background ({@link PooledProfile#poolNarrowing}):
	 *        for an
	 *        estimated diameter; a given one that leaves none is wrong for the image, and the front ends say so and
	 *        estimate it instead
	 */
	static ProfiledParticles measure(final Plane plane, final FrameSpots s, final double[] point, final double diameter,
		final double maxRadiusGiven, final boolean narrow)
	{
		final List<Localization> spots = s.spots();
		final double[][] xy = s.xy();
		final double wanted = maxRadiusGiven > 0 ? maxRadiusGiven : Margins.AUTO_RADIUS_DIAMETERS * diameter;
		if (point == null) {
			final List<Finding> findings = new ArrayList<>();
			final List<Integer> chosen = mostIsolated(plane, s, diameter, wanted);
			if (chosen.isEmpty()) throw new InvalidInputException("no single particle away from the border found in " +
				"the frame: give a point on one");
			if (s.nn().length > 1 && s.nn()[chosen.get(0)] < 2 * diameter)
				findings.add(new Finding.NotIsolated(s.nn()[chosen.get(0)], diameter));
			return pooledTwice(plane, s, centresOf(xy, chosen), diameter, wanted, narrow, findings);
		}
		final List<Finding> findings = new ArrayList<>();
		// the particle at the point: the spot nearest to it, if near enough
		final int nearest = nearest(xy, point);
		final int best = nearest >= 0 && distance(xy[nearest], point) <= Math.max(s.near(), diameter / 2) ? nearest : -1;
		final double[] own;
		if (best >= 0) {
			own = xy[best];
			if (spots.get(best).has(Flag.MERGED) && outlineMerged(plane, s.level(), own)) findings.add(
				new Finding.MergedAtPoint());
		}
		else {
			own = point;
			findings.add(new Finding.NotRefined());
		}
		double neighbour = Double.POSITIVE_INFINITY;
		for (int k = 0; k < xy.length; k++)
			if (k != best) neighbour = Math.min(neighbour, distance(xy[k], own));
		// beyond the image's edge a neighbour goes unseen: the edge counts as one
		final double edge = Math.min(Math.min(own[0], plane.width() - 1 - own[0]), Math.min(own[1], plane.height() - 1 -
			own[1]));
		final boolean byEdge = edge < neighbour;
		neighbour = Math.min(neighbour, edge);
		final List<Integer> frame = mostIsolated(plane, s, diameter, wanted);
		ProfiledParticles m = null;
		if (!frame.isEmpty()) {
			try {
				m = pooledTwice(plane, s, centresOf(xy, frame), diameter, wanted, narrow, new ArrayList<>());
			}
			catch (final InvalidInputException e) {
				m = null; // the frame's particles have no background: the particle is measured alone
			}
		}
		ProfiledParticles alone = null;
		final List<Finding> ownFindings = new ArrayList<>();
		try {
			alone = pooledTwice(plane, s, List.of(own), diameter, wanted, narrow, ownFindings);
		}
		catch (final InvalidInputException e) {
			if (m == null) throw best >= 0 ? e : noParticleAt(plane, point, xy, nearest);
		}
		// r_out as the frame gives it or as the particle alone does, whichever reaches further
		final double rOut = Math.max(m == null ? 0 : m.reach(), alone == null ? 0 : alone.reach()) +
			Margins.R_OUT_MARGIN_PX;
		if (m != null && (alone == null || neighbour < 2 * rOut)) {
			findings.add(new Finding.FrameValuesAtPoint(neighbour, byEdge, m.reach() + Margins.R_OUT_MARGIN_PX,
				alone == null ? Double.NaN : alone.reach() + Margins.R_OUT_MARGIN_PX, m.centres().size()));
			return m.withAt(own, best >= 0, findings);
		}
		return alone.withAt(own, best >= 0, findings);
	}

	/**
	 * Whether the active area at {@code level} that holds the pixel nearest {@code at} has the outline of several
	 * particles ({@link ComponentShape#outlineMerged}: elongated, or with a bay). The spot finder also flags an
	 * area whose gradient lines miss one another, as a saturated core's flat top makes them: a particle larger or
	 * brighter than the rest, not merged, and no reason to send the user to another.
	 */
	private static boolean outlineMerged(final Plane plane, final double level, final double[] at) {
		final int x = (int) Math.round(at[0]), y = (int) Math.round(at[1]);
		for (final Region r : ComponentLabeling.label(plane, level, Connectivity.EIGHT))
			for (int k = 0; k < r.runCount(); k++)
				if (r.runY(k) == y && r.runStart(k) <= x && x <= r.runEnd(k)) return ComponentShape.of(r).outlineMerged(
					false);
		return false;
	}

	/**
	 * @return each pixel's whether it lies in an active area at {@code level} whose outline is one particle's (not
	 *         {@link ComponentShape#outlineMerged})
	 */
	private static boolean[] roundAreas(final Plane plane, final double level) {
		final int w = plane.width();
		final boolean[] round = new boolean[w * plane.height()];
		for (final Region r : ComponentLabeling.label(plane, level, Connectivity.EIGHT)) {
			if (ComponentShape.of(r).outlineMerged(false)) continue;
			for (int k = 0; k < r.runCount(); k++)
				java.util.Arrays.fill(round, r.runY(k) * w + r.runStart(k), r.runY(k) * w + r.runEnd(k) + 1, true);
		}
		return round;
	}

	/** @return the index of the pixel nearest {@code at} (plane coordinates) */
	private static int pixel(final Plane plane, final double[] at) {
		final int x = Math.max(0, Math.min(plane.width() - 1, (int) Math.round(at[0])));
		final int y = Math.max(0, Math.min(plane.height() - 1, (int) Math.round(at[1])));
		return y * plane.width() + x;
	}

	/**
	 * The spots to profile when no point is given: the ones with the largest distances to their nearest neighbours,
	 * none merged, degenerate or near the border, at most {@value #MAX_PARTICLES}, down to half the
	 * first one's distance (or {@code wanted}). Where that leaves none and every area away from the border has one
	 * particle's outline ({@link #outlineMerged}), a spot flagged merged counts too, as it does at a point: the flags
	 * then come from the gradient lines alone, not from any outline. On compressed video, whose codec smooths the
	 * noise between neighbouring pixels away, the frame's noise (read from those neighbours) is a seventh of its true
	 * value or less, and a lone particle's gradient lines, which the noise still tilts, miss one another by more than
	 * so little noise explains (an optical trap's single bead at low signal: a round area, no bay, its lines 2 px
	 * apart, every frame refused). Where some area's outline is merged (particles of both contrasts in several focal
	 * planes, whose rings and cores part into fragments), the areas are no particles to profile.
	 */
	private static List<Integer> mostIsolated(final Plane plane, final FrameSpots s, final double diameter,
		final double wanted)
	{
		final List<Integer> chosen = mostIsolated(plane, s, diameter, wanted, null);
		if (!chosen.isEmpty()) return chosen;
		final boolean[] round = roundAreas(plane, s.level());
		for (int k = 0; k < s.xy().length; k++) {
			final Localization spot = s.spots().get(k);
			if (!spot.has(Flag.AT_BORDER) && !spot.has(Flag.DEGENERATE) && !round[pixel(plane, s.xy()[k])]) return chosen;
		}
		return mostIsolated(plane, s, diameter, wanted, round);
	}

	/**
	 * @param round null, or each pixel's whether its active area at the spots' level has one particle's outline: a
	 *        spot flagged merged on such an area counts
	 */
	private static List<Integer> mostIsolated(final Plane plane, final FrameSpots s, final double diameter,
		final double wanted, final boolean[] round)
	{
		final int w = plane.width(), h = plane.height();
		final double[][] xy = s.xy();
		final double[] nn = s.nn();
		final Integer[] order = new Integer[xy.length];
		for (int k = 0; k < order.length; k++)
			order[k] = k;
		Arrays.sort(order, Comparator.comparingDouble(k -> -nn[k]));
		final List<Integer> chosen = new ArrayList<>();
		for (final int k : order) {
			final Localization spot = s.spots().get(k);
			if (spot.has(Flag.AT_BORDER) || spot.has(Flag.DEGENERATE)) continue;
			if (spot.has(Flag.MERGED) && (round == null || !round[pixel(plane, xy[k])])) continue;
			if (xy[k][0] < diameter / 2 || xy[k][1] < diameter / 2 || xy[k][0] > w - 1 - diameter / 2 || xy[k][1] > h - 1 -
				diameter / 2) continue;
			if (!chosen.isEmpty() && nn[k] < Math.min(wanted, 0.5 * nn[chosen.get(0)])) break;
			chosen.add(k);
			if (chosen.size() == MAX_PARTICLES) break;
		}
		return chosen;
	}

	private static List<double[]> centresOf(final double[][] xy, final List<Integer> chosen) {
		final List<double[]> centres = new ArrayList<>();
		for (final int k : chosen)
			centres.add(xy[k]);
		return centres;
	}

	/**
	 * Pools the profile of {@code centres} (the first one's window sets how far out), masking the other spots within
	 * a diameter, then again within the measured reach plus the margin.
	 */
	private static ProfiledParticles pooledTwice(final Plane plane, final FrameSpots s, final List<double[]> centres,
		final double diameter, final double wanted, final boolean narrow,
		final List<Finding> findings)
	{
		final double radiusCap = Math.min(wanted, farthestCorner(centres.get(0)[0], centres.get(0)[1], plane.width(),
			plane.height()));
		final double narrowest = narrow ? diameter / 2 : Double.POSITIVE_INFINITY;
		PooledProfile pooled = PooledProfile.poolNarrowing(plane, centres, s.xy(), diameter, radiusCap, narrowest,
			null);
		double reach = PooledProfile.reach(pooled, radiusCap, null);
		pooled = PooledProfile.poolNarrowing(plane, centres, s.xy(), Math.max(diameter, reach +
			Margins.R_OUT_MARGIN_PX), radiusCap, narrowest, findings);
		reach = PooledProfile.reach(pooled, radiusCap, findings);
		return new ProfiledParticles(pooled.centres(), null, true, radiusCap, pooled, reach, PooledProfile.imageEdge(pooled,
			reach), findings);
	}

	private static double farthestCorner(final double x, final double y, final int w, final int h) {
		final double dx = Math.max(x, w - 1 - x), dy = Math.max(y, h - 1 - y);
		return Math.hypot(dx, dy);
	}

	/**
	 * @return the refusal of a point that is on no particle found, naming the nearest spot ({@code nearest}, -1 if
	 *         none; the frame's own measurement failed too, so there is nothing to give instead), in the image's
	 *         coordinates
	 */
	private static InvalidInputException noParticleAt(final Plane plane, final double[] point, final double[][] xy,
		final int nearest)
	{
		final double ox = plane.minX(), oy = plane.minY();
		return new InvalidInputException(String.format(java.util.Locale.ROOT, "no particle found at (%.0f, %.0f)%s: " +
			"give a point on a particle", point[0] + ox, point[1] + oy, nearest < 0 ? "" : String.format(
				java.util.Locale.ROOT, " (the nearest spot is at (%.1f, %.1f), %.1f px away)", xy[nearest][0] + ox,
				xy[nearest][1] + oy, distance(xy[nearest], point))));
	}

	/** @return the index of the point of {@code xy} nearest to {@code at} (the first of equals), -1 if none */
	private static int nearest(final double[][] xy, final double[] at) {
		int nearest = -1;
		double d = Double.POSITIVE_INFINITY;
		for (int k = 0; k < xy.length; k++) {
			final double e = distance(xy[k], at);
			if (e < d) {
				d = e;
				nearest = k;
			}
		}
		return nearest;
	}

	private static double distance(final double[] a, final double[] b) {
		return Math.hypot(a[0] - b[0], a[1] - b[1]);
	}
}
