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

import java.util.Arrays;
import java.util.List;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;

/**
 * The particle diameter the profile is measured with, and that profile: the diameter given, or estimated from the
 * frame. Colloids at contact sit one diameter apart, so the spots' spacing bounds it; where the particles' own image
 * ends (the outer edge of a dark ring, else the reach) bounds it too. The smaller of the two is taken. Where no two
 * spots sit within the particles' image, none touch, and the image's rim gives it: the dark ring's outer edge, or,
 * for a profile with a plateau, its half height ({@link PooledProfile#rim}). The finding says which.
 *
 * @param diameter the diameter (px) the profile was measured with
 * @param estimated whether it was estimated
 * @param measured the profile measured with it
 */
record DiameterEstimate(double diameter, boolean estimated, ProfiledParticles measured) {

	/** Percentile of the nearest-neighbour distances taken as the diameter when it is not given. */
	static final double DIAMETER_PERCENTILE = 10;

	/**
	 * The provisional diameter (to measure the profile on) is at most this many times the spots' median radius at
	 * half height: a Gaussian particle's image ends about 2.5 half-height radii out, a bright-field particle's further,
	 * its dark ring lying outside a narrow bright core; six leaves a margin above both.
	 */
	static final double PROVISIONAL_CORE_RADII = 6;

	/**
	 * Step 2 and the profile (steps 3-6): the diameter given; or where the particles' own image ends, unless the
	 * spots sit closer than that. It is measured on a profile taken out to a provisional diameter: the spots'
	 * spacing, but no more than {@link #PROVISIONAL_CORE_RADII} times their half-height radius
	 * (isolated particles sit far apart: their spacing would take the profile far out, over the background's texture
	 * and every neighbour), and measured again at the estimate.
	 */
	static DiameterEstimate sizeAndMeasure(final Plane plane, final FrameSpots s, final double[] at,
		final double diameterGiven, final double maxRadiusGiven, final List<Finding> findings)
	{
		if (diameterGiven != 0) {
			final ProfiledParticles m = ProfiledParticles.measure(plane, s, at, diameterGiven, maxRadiusGiven, false);
			findings.addAll(m.findings());
			return new DiameterEstimate(diameterGiven, false, m);
		}
		double[] spacing = s.nn().clone();
		double fromSpots = spacing.length >= 2 ? Statistics.quantile(spacing.clone(),
			DIAMETER_PERCENTILE / 100) : Double.NaN;
		final double[] radii = new double[s.spots().size()];
		for (int k = 0; k < radii.length; k++)
			radii[k] = Math.sqrt(s.spots().get(k).activeArea() / Math.PI);
		final double fromCores = PROVISIONAL_CORE_RADII * Statistics.quantile(radii, 0.5);
		double provisional = Double.isFinite(fromSpots) ? Math.min(fromSpots, fromCores) : fromCores;
		ProfiledParticles m = ProfiledParticles.measure(plane, s, at, provisional, maxRadiusGiven, true);
		// Two particles of this profile closer than 'closest' would have been one spot where the spots were found; spots
		// that close are not both such particles (bright marks burned into the frame: a timestamp's digits 6 px apart
		// among particles 20-50 px across gave a diameter of 5.6 px and a threshold above every pixel). Their distances
		// are left out of the spacing, and the profile measured again. Not when no two spots are left: in a field with
		// no background between the particles (a lattice at contact) the profile holds the neighbours' light, and two
		// of it would never stay apart.
		if (fromSpots > 0 && !apart(m, fromSpots, s.level())) {
			final double closest = closestApart(m, fromSpots, s.level());
			final double[] kept = Arrays.stream(spacing).filter(d -> d >= closest).toArray();
			if (kept.length >= 2) {
				findings.add(new Finding.SpotsTooClose(spacing.length - kept.length, closest));
				final int all = spacing.length;
				spacing = kept;
				fromSpots = Statistics.quantile(kept.clone(), DIAMETER_PERCENTILE / 100);
				provisional = Math.min(fromSpots, fromCores);
				m = ProfiledParticles.measure(plane, s, at, provisional, maxRadiusGiven, true);
				// most spots that close, and none of the others alone: no few marks beside the particles (a timestamp's
				// 12 digits leave 5 particles standing apart), but a level that does not part the particles into one
				// spot each, and the spots left are no sample of them (a dense bidisperse monolayer: 1,472 of 1,486 spots
				// within 14.3 px of another, the profile then measured on 4 particles, r_out 19 px for particles 10 and
				// 14 px across, and half the particles lost)
				if (kept.length < all - kept.length && m.findings().stream().anyMatch(
					f -> f instanceof Finding.NotIsolated)) throw new InvalidInputException((all - kept.length) + " of the " +
						all + " spots at the level " + HelperFormat.fmt(s.level()) + " lie closer to another than two " +
						"particles of their profile can (" + HelperFormat.fmt(closest) + " px), and no other stands alone: " +
						"that level does not part these particles into one spot each; give their diameter");
			}
		}
		final double own = 2 * m.imageEdge();
		final boolean fromImage = !(fromSpots < own);
		// no two spots within the particles' image: none touch, and the image shows the rim (a ring's edge, or the
		// half height of a plateau); else the spots that touch show it
		final double rim = fromImage ? PooledProfile.rim(m.pooled(), m.reach()) : Double.NaN;
		final double diameter = fromImage ? 2 * rim : fromSpots;
		if (Math.abs(diameter - provisional) > 0.01 * provisional) m = ProfiledParticles.measure(plane, s, at, diameter,
			maxRadiusGiven, true);
		findings.add(!fromImage ? new Finding.DiameterFromSpacing(diameter, DIAMETER_PERCENTILE, spacing.length, own)
			: rim < own / 2 ? new Finding.DiameterFromHalfHeight(diameter, own / 2) : new Finding.DiameterFromImage(
				diameter, own / 2));
		findings.addAll(m.findings());
		return new DiameterEstimate(diameter, true, m);
	}

	/**
	 * @return whether two particles of {@code m}'s profile {@code distance} apart (and three in a triangle) stay apart
	 *         at {@code level}: the brightest point between them lies below it
	 */
	private static boolean apart(final ProfiledParticles m, final double distance, final double level) {
		return m.pooled().background() + ThresholdRules.brightestBetween(m.pooled(), distance, m.reach()) < level;
	}

	/**
	 * @return the shortest distance (to {@value ThresholdRules#BRIDGE_STEP_PX} px, above {@code from}, at which they
	 *         are not) at which particles of {@code m}'s profile stay {@link #apart} at {@code level}; beyond twice the
	 *         profile's reach if they never do within it
	 */
	private static double closestApart(final ProfiledParticles m, final double from, final double level) {
		double lo = from, hi = 2 * m.reach() + 1;
		if (!apart(m, hi, level)) return hi;
		while (hi - lo > ThresholdRules.BRIDGE_STEP_PX) {
			final double mid = (lo + hi) / 2;
			if (apart(m, mid, level)) hi = mid;
			else lo = mid;
		}
		return hi;
	}
}
