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
package io.github.contacttracker.core.radial;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.image.Region;

/**
 * One particle of a frame as the first pass leaves it, immutable: its active area, the gradients on it, its shape,
 * and its first-pass {@link Estimate}. Every {@link Refinement} starts from these and returns new estimates.
 */
public final class Particle {

	private final Region region;
	private final GradientField field;
	private final double quality;
	/** Intensity-above-threshold weighted centroid: the fallback of a degenerate first pass. */
	private final double centroidX, centroidY;
	private final boolean atBorder;
	private final ComponentShape shape;
	private final Estimate first;

	private Particle(final Region region, final GradientField field, final double quality, final double centroidX,
		final double centroidY, final boolean atBorder, final ComponentShape shape, final Estimate first)
	{
		this.region = region;
		this.field = field;
		this.quality = quality;
		this.centroidX = centroidX;
		this.centroidY = centroidY;
		this.atBorder = atBorder;
		this.shape = shape;
		this.first = first;
	}

	/**
	 * Measures a component and runs the first pass on it.
	 *
	 * @return the particle, or {@code null} when its active area holds no gradient line (a flat plateau: nothing
	 *         to localize)
	 */
	public static Particle firstPass(final Plane plane, final Region region, final double threshold) {
		final GradientField field = GradientField.compute(plane, region);
		double q = 0, qx = 0, qy = 0;
		double sx = 0, sy = 0;
		final byte[] bytes = plane.unsignedBytes(); // 8-bit pixels straight from the array (the same values)
		for (int r = 0; r < region.runCount(); r++) {
			final int yy = region.runY(r), row = yy * plane.width();
			for (int xx = region.runStart(r); xx <= region.runEnd(r); xx++) {
				final double v = (bytes != null ? bytes[row + xx] & 0xff : plane.get(xx, yy)) - threshold;
				q += v;
				qx += v * xx;
				qy += v * yy;
				sx += xx;
				sy += yy;
			}
		}
		final int n = region.area();
		// Every pixel is >= threshold, so q > 0 unless all sit exactly on it: then the plain centroid.
		final double centroidX = q > 0 ? qx / q : sx / n;
		final double centroidY = q > 0 ? qy / q : sy / n;
		final boolean atBorder = field.withoutGradient > 0 || region.minX() == 0 || region.minY() == 0 ||
			region.maxX() == plane.width() - 1 || region.maxY() == plane.height() - 1;

		final Solve solve = Solve.on(field, null, centroidX, centroidY);
		if (solve.solution().lines() == 0) return null;
		final Estimate first = solve.solution().ok() ? Estimate.first(solve.solution().x(), solve.solution().y(), 0, n,
			solve) : Estimate.first(centroidX, centroidY, Flag.DEGENERATE.bit(), n, null);
		final ComponentShape shape = solve.solution().ok() ? ComponentShape.of(region, field, solve.solution().x(), solve
			.solution().y()) : ComponentShape.of(region);
		return new Particle(region, field, q, centroidX, centroidY, atBorder, shape, first);
	}

	/**
	 * A particle found by its image ({@code core.detect}): the first pass on {@code region}, the pixels around a
	 * seed that lie nearer to it than to any other seed, with the pixels' excess over the region's least value as
	 * the centroid's weights. Where the gradient lines give no centre, the seed is the first centre (it is a
	 * particle's peak at sub-pixel precision, not a guess, so the particle stays reliable and is fitted).
	 *
	 * @param atBorder whether the particle lies so near the frame's edge that its image is cut
	 * @return the particle, or {@code null} when the region is empty
	 */
	public static Particle atSeed(final Plane plane, final Region region, final double seedX, final double seedY,
		final boolean atBorder)
	{
		if (region.area() == 0) return null;
		double base = Double.POSITIVE_INFINITY;
		for (int r = 0; r < region.runCount(); r++)
			for (int xx = region.runStart(r); xx <= region.runEnd(r); xx++)
				base = Math.min(base, plane.get(xx, region.runY(r)));
		final GradientField field = GradientField.compute(plane, region);
		double q = 0, qx = 0, qy = 0;
		for (int r = 0; r < region.runCount(); r++) {
			final int yy = region.runY(r);
			for (int xx = region.runStart(r); xx <= region.runEnd(r); xx++) {
				final double v = plane.get(xx, yy) - base;
				q += v;
				qx += v * xx;
				qy += v * yy;
			}
		}
		final Solve solve = Solve.on(field, null, seedX, seedY);
		final boolean solved = solve.solution().lines() > 0 && solve.solution().ok() && Math.hypot(solve.solution()
			.x() - seedX, solve.solution().y() - seedY) <= Math.sqrt(region.area() / Math.PI);
		final Estimate first = solved ? Estimate.first(solve.solution().x(), solve.solution().y(), 0, region.area(),
			solve) : Estimate.first(seedX, seedY, 0, region.area(), null);
		final ComponentShape shape = ComponentShape.of(region);
		return new Particle(region, field, q, q > 0 ? qx / q : seedX, q > 0 ? qy / q : seedY, atBorder, shape, first);
	}

	/** @return this particle with {@code flags} (border, merge) added to its first-pass estimate */
	public Particle withShapeFlags(final int flags) {
		return new Particle(region, field, quality, centroidX, centroidY, atBorder, shape, first.withFlags(
			first.flags() | flags));
	}

	/** @return the active area */
	public Region region() {
		return region;
	}

	/** @return the gradients on the active area */
	GradientField field() {
		return field;
	}

	/** @return the integrated intensity above threshold over the active area */
	public double quality() {
		return quality;
	}

	/** @return whether the active area touches the image's border or holds pixels without a gradient */
	public boolean atBorder() {
		return atBorder;
	}

	/** @return the active area's shape: one disc, or several merged ({@link ComponentShape}) */
	public ComponentShape shape() {
		return shape;
	}

	/**
	 * @return the first pass on the whole active area (its flags include the shape flags once
	 *         {@link #withShapeFlags})
	 */
	public Estimate first() {
		return first;
	}

	/** Whether the first pass was degenerate (the centre is then the centroid). */
	boolean firstDegenerate() {
		return Flag.DEGENERATE.isSet(first.flags());
	}

	/**
	 * @return whether the particle's centre describes one particle: not a suspected merge, and its first pass
	 *         solved. Unreliable particles are neither refined by the profile methods nor modelled as neighbours.
	 */
	public boolean reliable() {
		return !Flag.MERGED.isSet(first.flags()) && !firstDegenerate();
	}

	/** Solves on the gradient lines marked in {@code use} ({@code null}: all), referenced at the centroid. */
	Solve solve(final boolean[] use) {
		return Solve.on(field, use, centroidX, centroidY);
	}
}
