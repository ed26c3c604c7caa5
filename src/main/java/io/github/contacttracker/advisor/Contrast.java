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

import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.detect.ParticleScale;
import io.github.contacttracker.core.image.Illumination;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.Statistics;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * The particles' contrast as a frame shows it, before any value is measured: whether its particles are darker than
 * the background (to be inverted first), and whether it holds any particle at all.
 */
public final class Contrast {

	private Contrast() {}

	/**
	 * How much further below the background its darkest pixel must lie than its brightest above it for a frame
	 * without blobs to compare to be taken for dark particles when nobody said which. The background covers most of a
	 * frame; bright particles reach further above it than their dark rings reach below, and dark particles the other
	 * way round. Twice as far leaves a margin: saturated cores and deep dark rings can bring bright particles' two
	 * reaches near each other, and such footage must not be taken for dark (manual.md gives the figures measured on
	 * real footage).
	 */
	public static final double DARK_RATIO = 2;

	/**
	 * Where the frame has blobs, its brightest pixel reaching more than this many times as far above the background as
	 * its darkest below says bright particles; short of that, the extremes do not tell, and the blobs decide: the
	 * inverted frame's blobs must stand out more than its own. Particles dark inside a bright ring (microgels, beads a
	 * little out of focus) reach 1.3 to 1.6 times as far below as above while they stand apart (a simulated pair with
	 * a core 700 grey levels deep and a ring 350 high, under photon noise); pushed into contact, their rings' light
	 * adds up where they cross, as bright as the cores are dark (1.0 to 1.1 times as far), while their cores still
	 * stand out twice as much as the rings at the particles' scale. Bright particles with deep dark rings stay bright:
	 * the paper authors' 1.avi reaches 1.04 times as far either way, and its rings are no blobs; inverted, its cores
	 * are, and it is taken for dark, as it then is.
	 */
	public static final double DARKER = 1.2;

	/**
	 * @return whether the frame's particles are darker than the background, to be inverted first
	 *         ({@code core.image.Inversion}): its brightest pixel lies no more than {@link #DARKER} times as far above
	 *         the background as its darkest below it, and the inverted frame's blobs stand out more than the frame's
	 *         own ({@link DetectionChoice#otherContrastStronger}, at the scale of the frame's blobs); or, where the
	 *         frame holds no blob, more than {@link #DARK_RATIO} times as far. The levels are read relative to the
	 *         frame's light ({@link Illumination}: a ramp of light across the frame puts its extremes on the ramp),
	 *         the background at their median. The median is the background's level only where the background
	 *         covers most of the frame: bright particles packed edge to edge put it on the particles, with the small
	 *         dark gaps between them far below, and only the blobs tell which are the particles (a simulated
	 *         monolayer of bright discs at an area fraction of 0.6: the median test says dark, the inverted blobs
	 *         stand 1.06 times as high as the frame's; dark spheres in dyed fluid on a confocal slice, 2.3).
	 */
	public static boolean looksDark(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		return looksDark(frame, 0);
	}

	/**
	 * {@link #looksDark(RandomAccessibleInterval)}; where {@code diameter > 0} (someone gave it), the blobs at that
	 * diameter decide alone ({@link DetectionChoice#otherContrastStrongerAt}). The frame's own blobs can be a large
	 * particle's texture and the pieces of its rim, and its extremes the rim's light: a tweezer's bead 62 px across,
	 * dark inside a bright rim that reaches the 8-bit ceiling, lies 1.2 times as far above the background as its
	 * core below, and at its own diameter it stands inverted 15 times as high as anything else in the frame.
	 *
	 * @param diameter the particles' diameter as given (px), or 0 (not given: the frame's blobs')
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public static boolean looksDark(final RandomAccessibleInterval<? extends RealType<?>> frame, final double diameter) {
		final Plane plane = Plane.of((RandomAccessibleInterval) frame);
		if (diameter > 0) return DetectionChoice.otherContrastStrongerAt(plane, inverted(frame), diameter);
		final double[] v = Illumination.residuals(plane);
		final double median = Statistics.quantile(v, 0.5); // sorted by it
		final double below = median - v[0], above = v[v.length - 1] - median;
		if (!(below * DARKER > above)) return false;
		final Plane inverted = inverted(frame);
		double d = ParticleScale.diameter(plane);
		if (!(d > 0)) d = ParticleScale.diameter(inverted);
		// no blob at any scale to compare: the levels alone decide
		return d > 0 ? DetectionChoice.otherContrastStronger(plane, inverted, d) : below > DARK_RATIO * above;
	}

	/** @return the frame inverted ({@code core.image.Inversion}: a copy), as a plane */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	private static Plane inverted(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		return Plane.of((RandomAccessibleInterval) Inversion.of((RandomAccessibleInterval) frame));
	}

	/**
	 * @return whether the frame holds nothing brighter or darker than its noise, as the helper judges it
	 *         ({@link FrameSpots#find}: its brightest pixels stand no more than {@link Margins#THRESHOLD_MARGIN_SIGMAS}
	 *         noise sigmas above its median, and its darkest no more below): a blank frame, such as one before the
	 *         shutter opened or a confocal slice below the coverslip
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public static boolean blank(final RandomAccessibleInterval<? extends RealType<?>> frame) {
		final FrameSpots.Levels levels = FrameSpots.Levels.of(Plane.of((RandomAccessibleInterval) frame));
		return !levels.brighterThanNoise() && !levels.darkerThanNoise();
	}
}
