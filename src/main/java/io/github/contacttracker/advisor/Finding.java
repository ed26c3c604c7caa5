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

/**
 * Something the profile helper found that the user should know, with the numbers it is about; the front ends put it
 * into words ({@code report.ProfileReport}). Lengths in pixels, levels in grey levels.
 */
public sealed interface Finding {

	/**
	 * The diameter was not given: it is twice the radius where the particles' own image returns to the background.
	 *
	 * @param diameter the estimate (px)
	 * @param imageRadius where the particles' image ends (px)
	 */
	record DiameterFromImage(double diameter, double imageRadius) implements Finding {}

	/**
	 * The diameter was not given, no two spots sit within the particles' image, and the profile has a plateau: the
	 * diameter is twice the radius at which it falls to half its height, where a blurred sphere's rim lies.
	 *
	 * @param diameter the estimate (px)
	 * @param imageRadius where the particles' image returns to the background (px)
	 */
	record DiameterFromHalfHeight(double diameter, double imageRadius) implements Finding {}

	/**
	 * The diameter was not given: it is a percentile of the spots' nearest-neighbour distances, which is smaller
	 * than the particles' own image.
	 *
	 * @param diameter the estimate (px)
	 * @param percentile the percentile taken
	 * @param spots how many spots the distances are of
	 * @param imageAcross how far across the particles' image reaches (px)
	 */
	record DiameterFromSpacing(double diameter, double percentile, int spots, double imageAcross) implements Finding {}

	/**
	 * Spots so close that two particles of the measured profile would have been one spot where the spots were found
	 * (bright marks burned into the frame, say, such as a timestamp's digits): their distances are left out of the
	 * spacing the diameter is estimated from.
	 *
	 * @param spots how many spots' nearest-neighbour distances were left out
	 * @param closest the shortest distance two such particles stay apart at (px)
	 */
	record SpotsTooClose(int spots, double closest) implements Finding {}

	/** The particle at the point given has an active area that looks merged with a neighbour's. */
	record MergedAtPoint() implements Finding {}

	/**
	 * The particle at the point given is not isolated: its nearest neighbour (or the image's edge) is closer than twice
	 * {@code r_out}, so its own profile holds its neighbours' light and does not return to the background between
	 * them. The profile and the values are the frame's most isolated particles'; the particle's own r_out is kept
	 * only to say why it is not used.
	 *
	 * @param neighbour its nearest neighbour's distance, or the image edge's when that is nearer (px)
	 * @param edge whether {@code neighbour} is the edge's distance (beyond the edge neighbours go unseen)
	 * @param frameROut {@code r_out} of the frame's most isolated particles' profile (px): the one given
	 * @param ownROut {@code r_out} of the particle's own profile (px), disturbed by its neighbours; NaN when it
	 *        could not be measured
	 * @param others how many of the frame's particles are profiled instead
	 */
	record FrameValuesAtPoint(double neighbour, boolean edge, double frameROut, double ownROut, int others)
		implements Finding {}

	/** No spot near the point given: the profile is taken around the point itself. */
	record NotRefined() implements Finding {}

	/**
	 * No particle has its nearest neighbour two diameters away or more.
	 *
	 * @param neighbour the most isolated particle's nearest neighbour distance (px)
	 * @param diameter the diameter the particles were chosen with (px)
	 */
	record NotIsolated(double neighbour, double diameter) implements Finding {}

	/**
	 * The field is so dense that masking every neighbour within {@code wanted} left no background around the
	 * particles profiled: they were masked only within {@code mask}, and their light may show in the profile.
	 *
	 * @param mask how far from each neighbour pixels were masked (px)
	 * @param wanted how far they were to be (px)
	 */
	record NeighboursMaskedCloser(double mask, double wanted) implements Finding {}

	/**
	 * The profile is still off the background where the background is measured: {@code r_out} is a lower bound.
	 *
	 * @param radius where the background annulus starts (px)
	 */
	record NotBackToBackground(double radius) implements Finding {}

	/**
	 * The threshold at contact would take bright spots of the background for particles; it is raised to the middle
	 * of the gap between them and the particles' cores.
	 *
	 * @param atContact the threshold at contact
	 * @param spots the background's spots above it
	 * @param textureTop the highest of them above the background
	 * @param coreBottom the lowest core above the background
	 */
	record BackgroundTexture(double atContact, int spots, double textureTop, double coreBottom) implements Finding {}

	/**
	 * Some active areas have the shape of no single particle; the threshold is raised until they are round.
	 *
	 * @param from the threshold before
	 * @param notRound how many active areas there fail the outline tests
	 * @param areas how many active areas there are there
	 */
	record RaisedUntilRound(double from, int notRound, int areas) implements Finding {}

	/**
	 * Some active areas have the shape of no single particle at any threshold up to half the cores' height: they
	 * will be flagged merged.
	 *
	 * @param notRound how many active areas fail the outline tests at the suggested threshold
	 * @param areas how many active areas there are there
	 * @param ceiling half the cores' height (grey level)
	 */
	record NotRound(int notRound, int areas, double ceiling) implements Finding {}

	/** The suggested threshold is above the particle's centre. */
	record ThresholdAboveCentre() implements Finding {}
}
