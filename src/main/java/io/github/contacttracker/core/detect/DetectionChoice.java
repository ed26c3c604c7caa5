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

import java.io.Serializable;
import java.util.List;
import java.util.Locale;
import java.util.function.ToDoubleFunction;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;

/**
 * The detection {@link Detection#AUTO} chooses for a movie, from the threshold's first pass on its sample frames
 * (the iterative centres the profile methods start from anyway) and the image's seeds on the first of them.
 * <p>
 * By the image where the threshold joins particles: a component {@link Flag#MERGED} (too large for one particle of
 * the diameter) on any sample frame. A single one is enough: a tweezer pair pushed into contact, or a few touching
 * doublets among isolated beads, are exactly where a threshold's centre lies between two particles. Also where the
 * threshold discards more components than it keeps (smaller than {@code min_area}, or without a gradient): a level
 * that cuts the particles into crumbs loses them, and nothing in its spots says so. By the threshold otherwise: each
 * component is one particle, and the image would find the same ones at several times the cost.
 * <p>
 * Also by the threshold where the image's seeds outnumber the threshold's particles (one an area, as many as a merged
 * area holds) more than {@value #SEEDS_PER_PARTICLE} times: seeds on that scale are the texture of the background (a mottled or compressed
 * bright field, particles whose diameter was measured on their core or ring), not particles, and fitting hundreds of
 * them costs minutes a frame for nothing the threshold does not find. Bright-field particles with rings give a few
 * seeds each, dense fields of touching particles a few per component; a texture gives hundreds per particle. Not
 * where the threshold keeps no particle on the first frame: nothing then tells a texture from particles below the
 * threshold (160 dim spots, none above it, would be taken for texture and no spot found), and only the image can
 * find any.
 *
 * @param detection the detection chosen ({@link Detection#IMAGE} or {@link Detection#THRESHOLD})
 * @param merged the threshold's components flagged {@code MERGED} on the sample frames
 * @param spots the threshold's spots on the sample frames
 * @param discarded the threshold's components discarded on the sample frames
 * @param frames the sample frames
 * @param seeds the image's seeds on the first sample frame
 * @param firstSpots the particles the threshold's spots hold on the first sample frame: one a spot, as many as fit in
 *        its area for a spot flagged {@code MERGED}
 */
public record DetectionChoice(Detection detection, int merged, int spots, int discarded, int frames, int seeds,
	int firstSpots)
	implements Serializable
{

	private static final long serialVersionUID = 1L;

	/** How many times higher the other contrast's peaks must stand to be taken for the particles' (see below). */
	public static final double OTHER_CONTRAST = 1.5;

	/** Seeds per threshold particle beyond which the seeds are taken for texture (see the class comment). */
	public static final int SEEDS_PER_PARTICLE = 50;

	/**
	 * @param firstPass the threshold's first-pass (iterative) results of the sample frames, the first one's first
	 * @param discarded the components the threshold discarded on those frames
	 * @param first the first sample frame, as the tracker sees it
	 * @param diameter the particles' diameter (px, {@code > 0}), the image's filter scale
	 * @return the choice
	 */
	public static DetectionChoice choose(final List<List<Localization>> firstPass, final int discarded,
		final Plane first, final double diameter)
	{
		int merged = 0, spots = 0;
		for (final List<Localization> frame : firstPass) {
			spots += frame.size();
			for (final Localization l : frame)
				if (l.has(Flag.MERGED)) merged++;
		}
		final int firstSpots = firstPass.isEmpty() ? 0 : held(firstPass.get(0), diameter);
		final int frames = firstPass.size();
		if (merged == 0 && discarded <= spots || !fits(first, diameter)) return new DetectionChoice(
			Detection.THRESHOLD, 0, spots, 0, frames, -1, firstSpots);
		final int seeds = ImageDetection.seeds(first, diameter, NoiseEstimate.sigma(first)).count();
		final boolean texture = firstSpots > 0 && seeds > SEEDS_PER_PARTICLE * firstSpots;
		return new DetectionChoice(texture ? Detection.THRESHOLD : Detection.IMAGE, merged, spots, discarded, frames,
			seeds, firstSpots);
	}

	/**
	 * @return the particles the threshold's areas hold: one per area, and as many as its area holds discs of the
	 *         diameter for one flagged {@code MERGED} (a packed field above a threshold is one area of hundreds of
	 *         particles, whose seeds are particles, not texture)
	 */
	private static int held(final List<Localization> spots, final double diameter) {
		final double disc = Math.PI / 4 * diameter * diameter;
		long held = 0;
		for (final Localization l : spots)
			held += l.has(Flag.MERGED) && disc > 0 ? Math.max(1, Math.round(l.activeArea() / disc)) : 1;
		return (int) Math.min(Integer.MAX_VALUE, held);
	}

	/**
	 * Whether a frame's particles look like the other contrast: the strong peaks of the inverted frame, band-passed at
	 * the particles' scale, stand more than {@value #OTHER_CONTRAST} times as high as the frame's own. Where the
	 * threshold cannot be measured because it lies above every pixel, that tells two fields apart: bright particles packed without a dark gap (the image
	 * finds them), and dark cores in bright rings taken for bright particles, whose rings the image would track (the
	 * bright-field movie inverted, or dark particles not said to be dark). The margin is for dense packings, whose
	 * gaps are blobs of the other contrast too: measured, the inverted frame's peaks stand 0.6 times as high as the
	 * frame's on a monolayer of bright spheres and 1.3 times on a dense confocal packing, against 2.0 to 3.0 on dark
	 * cores in bright rings (bright-field movies of silica spheres inverted, a dim optically trapped particle); the
	 * manual's real-footage section names the public footage.
	 *
	 * @param frame the frame as the tracker would see it
	 * @param inverted the frame inverted
	 * @param diameter the particles' diameter (px, {@code > 0})
	 */
	public static boolean otherContrastStronger(final Plane frame, final Plane inverted, final double diameter) {
		return stronger(frame, inverted, diameter, Peaks::typicalHeight);
	}

	/**
	 * {@link #otherContrastStronger} at a diameter someone gave, not one read from the frame's blobs: the peaks that
	 * stand apart ({@link Peaks#standingHeight}, {@code 1 / }{@link ImageDetection#RELATIVE} times as high as every
	 * other) are the particles where some do. A tweezer's bead a third of the frame across, dark inside a bright rim
	 * with a textured core, filtered at its own diameter (62 px in 184 x 181), stands inverted 15 times as high as
	 * every other peak (50.8 against 3.4 and less), and not at all in the frame itself, whose highest peaks are pieces
	 * of its rim (15 to 17.5); the quantile of the inverted frame's nine seeds lay between the bead and the highest
	 * bump (12.9), and the bead was tracked as bright: no spot in 401 frames.
	 */
	public static boolean otherContrastStrongerAt(final Plane frame, final Plane inverted, final double diameter) {
		return stronger(frame, inverted, diameter, p -> p.standingHeight(1 / ImageDetection.RELATIVE));
	}

	/**
	 * @param height the height of a frame's particles among its seeds at {@code diameter}
	 * @return whether the inverted frame's particles stand {@link #OTHER_CONTRAST} times as high as the frame's own
	 */
	private static boolean stronger(final Plane frame, final Plane inverted, final double diameter,
		final ToDoubleFunction<Peaks> height)
	{
		if (!fits(frame, diameter)) return false;
		final double own = height.applyAsDouble(ImageDetection.seeds(frame, diameter, NoiseEstimate.sigma(frame)));
		final double other = height.applyAsDouble(ImageDetection.seeds(inverted, diameter, NoiseEstimate.sigma(
			inverted)));
		return other > OTHER_CONTRAST * own;
	}

	/**
	 * @return whether particles of that diameter fit in the frame (its diagonal): a wider one is refused by the tracker
	 *         itself, and no seeds are sought with a filter wider than the frame
	 */
	private static boolean fits(final Plane frame, final double diameter) {
		return diameter > 0 && diameter <= Math.hypot(frame.width(), frame.height());
	}

	/**
	 * @return what was chosen and why, for a run's summary: empty where the threshold was kept because its components
	 *         are single particles (the run is then the threshold's, as before the choice)
	 */
	public String said() {
		if (merged == 0 && discarded == 0) return "";
		final String on = String.format(Locale.ROOT, "%d sample frame%s", frames, frames == 1 ? "" : "s");
		final String why = merged > 0 ? String.format(Locale.ROOT, "the threshold joined touching particles into one " +
			"area (%d of its %d spots on %s merged)", merged, spots, on) : String.format(Locale.ROOT, "the threshold " +
				"discarded more areas than it kept (%d against %d spots on %s)", discarded, spots, on);
		if (detection == Detection.IMAGE) return "found by their image (auto): " + why;
		return String.format(Locale.ROOT, "found by the threshold (auto), though %s: the image's %d seeds on the " +
			"first frame, against the threshold's %d particle%s, are the background's texture", why, seeds, firstSpots,
			firstSpots == 1 ? "" : "s");
	}
}
