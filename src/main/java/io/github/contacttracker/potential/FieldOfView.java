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
package io.github.contacttracker.potential;

import io.github.contacttracker.core.InvalidInputException;

/**
 * The rectangle the spots were found in, which sets the ideal-gas reference of g(r): for {@code N} particles
 * placed independently and uniformly in a {@code width x height} rectangle, the distance of a pair has the
 * probability density (the rectangle's set covariance integrated over directions)
 *
 * <pre>
 * p(r) = r (2 pi A - 4 r (W + H) + 2 r^2) / A^2,   A = W H,   0 &lt;= r &lt;= min(W, H)
 * </pre>
 *
 * whose integral is {@link #pairFractionWithin(double)}. This is the exact pair-geometry edge correction: the
 * {@code 2 pi r} of an unbounded plane, reduced by the pairs a shell loses where it leaves the rectangle. For
 * g(r) only the size matters; the corner {@code (x0, y0)} places the rectangle among the spots, which matters
 * when spots at its border were left out and the field shrinks to where spots were kept ({@link #inset}). A
 * field given by its size alone has its corner at {@code (0, 0)}; an image's starts half a pixel before its first
 * pixel's centre ({@link #ofImage}). The formula holds up to
 * {@code min(W, H)}; beyond it the shells would leave the field on two opposite sides, and g(r) that far out
 * means little, so it is refused.
 *
 * @param x0 the smallest x of the field, in the spots' units
 * @param y0 the smallest y of the field
 * @param width width, in the spots' units
 * @param height height, in the spots' units
 * @param inferred whether the size was inferred from the spots rather than given
 */
public record FieldOfView(double x0, double y0, double width, double height, boolean inferred) implements
	java.io.Serializable
{

	/** @throws IllegalArgumentException when a side is not a positive finite number */
	public FieldOfView {
		if (!(width > 0) || !(height > 0) || !Double.isFinite(width) || !Double.isFinite(height))
			throw new InvalidInputException("the field of view must have a positive width and height, not " + width +
				" x " + height);
		if (!Double.isFinite(x0) || !Double.isFinite(y0))
			throw new InvalidInputException("the field of view's corner must be finite, not " + x0 + ", " + y0);
	}

	/** A field whose corner is at {@code (0, 0)}. */
	public FieldOfView(final double width, final double height, final boolean inferred) {
		this(0, 0, width, height, inferred);
	}

	/** @return a field of the given size (given by the user, not inferred) */
	public static FieldOfView of(final double width, final double height) {
		return new FieldOfView(width, height, false);
	}

	/**
	 * @param width the image's width in pixels
	 * @param height its height in pixels
	 * @param dx a pixel's width in the spots' units
	 * @param dy a pixel's height
	 * @return the image's field, in the spots' coordinates (pixel {@code (0, 0)}'s centre at {@code (0, 0)})
	 */
	public static FieldOfView ofImage(final int width, final int height, final double dx, final double dy) {
		return new FieldOfView(-0.5 * dx, -0.5 * dy, width * dx, height * dy, false);
	}

	/**
	 * The field inferred from the spots: the bounding box of all spots of all frames, widened on each side by
	 * the expected gap between the last of {@code n} uniform points and the edge ({@code extent / (n - 1)}), so
	 * that the estimate is unbiased for uniform spots. With thousands of spots the widening is negligible; with
	 * few, give the field's size instead.
	 *
	 * @param xs x of every spot
	 * @param ys y of every spot
	 * @return the inferred field
	 * @throws IllegalArgumentException when there are fewer than 2 spots or they all lie on one line
	 */
	public static FieldOfView inferred(final double[] xs, final double[] ys) {
		if (xs.length != ys.length) throw new InvalidInputException(xs.length + " x values but " + ys.length + " y");
		if (xs.length < 2)
			throw new InvalidInputException("cannot infer the field of view from fewer than 2 spots: give its width " +
				"and height");
		double x0 = Double.POSITIVE_INFINITY, x1 = Double.NEGATIVE_INFINITY;
		double y0 = Double.POSITIVE_INFINITY, y1 = Double.NEGATIVE_INFINITY;
		for (int i = 0; i < xs.length; i++) {
			x0 = Math.min(x0, xs[i]);
			x1 = Math.max(x1, xs[i]);
			y0 = Math.min(y0, ys[i]);
			y1 = Math.max(y1, ys[i]);
		}
		return inferred(x0, x1, y0, y1, xs.length);
	}

	/**
	 * @return the field inferred from the spots' extent and number (what a distributed front end aggregates), as
	 *         {@link #inferred(double[], double[])}
	 */
	public static FieldOfView inferred(final double x0, final double x1, final double y0, final double y1,
		final long n)
	{
		if (n < 2)
			throw new InvalidInputException("cannot infer the field of view from fewer than 2 spots: give its width " +
				"and height");
		final double w = (x1 - x0) * (n + 1) / (n - 1), h = (y1 - y0) * (n + 1) / (n - 1);
		if (!(w > 0) || !(h > 0))
			throw new InvalidInputException("cannot infer the field of view: all spots lie on one line; give its " +
				"width and height");
		return new FieldOfView(x0 - (x1 - x0) / (n - 1), y0 - (y1 - y0) / (n - 1), w, h, true);
	}

	/**
	 * @param margin a distance {@code >= 0}
	 * @return the field shrunk by {@code margin} on every side (the same corner rule and inferred state)
	 * @throws IllegalArgumentException when nothing is left
	 */
	public FieldOfView inset(final double margin) {
		if (!(margin >= 0)) throw new InvalidInputException("an inset must be 0 or more, not " + margin);
		if (2 * margin >= Math.min(width, height))
			throw new InvalidInputException(String.format(java.util.Locale.ROOT, "the spots left out at the border " +
				"reach %s into the field of view (%s x %s): no field is left between them", PairCorrelation.num(margin),
				PairCorrelation.num(width), PairCorrelation.num(height)));
		return new FieldOfView(x0 + margin, y0 + margin, width - 2 * margin, height - 2 * margin, inferred);
	}

	/** @return the distance of {@code (x, y)} inside the field to its nearest edge; negative outside */
	public double depth(final double x, final double y) {
		return Math.min(Math.min(x - x0, x0 + width - x), Math.min(y - y0, y0 + height - y));
	}

	/** @return the area */
	public double area() {
		return width * height;
	}

	/** @return the largest distance for which the edge correction is exact: {@code min(width, height)} */
	public double maxDistance() {
		return Math.min(width, height);
	}

	/**
	 * The probability that two independent uniform points of the field lie closer than {@code r}:
	 * {@code (pi A r^2 - 4/3 (W + H) r^3 + r^4 / 2) / A^2}.
	 *
	 * @param r a distance in {@code [0, maxDistance()]}
	 * @return the fraction of pairs closer than {@code r}
	 * @throws IllegalArgumentException outside that range
	 */
	public double pairFractionWithin(final double r) {
		if (!(r >= 0) || r > maxDistance() * (1 + 1e-12))
			throw new InvalidInputException("the edge correction holds for distances up to min(width, height) = " +
				maxDistance() + ", not " + r);
		final double a = area(), r2 = r * r;
		return (Math.PI * a * r2 - 4.0 / 3.0 * (width + height) * r2 * r + 0.5 * r2 * r2) / (a * a);
	}
}
