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

/**
 * The point with the least weighted squared distance to a set of lines: the radial-symmetry centre.
 * <p>
 * Each line passes through a pixel {@code p} along its gradient {@code g}. In direction form, with the unit
 * normal {@code n = (-gy, gx) / |g|}, the minimiser solves {@code (sum w n n^T) c = sum w n n^T p}, a 2x2
 * system. This is the paper's slope-form solution without its singularity at {@code gx = 0}. A near-singular
 * system (all lines nearly parallel, or too few lines) is reported as {@link Status#DEGENERATE}, never divided
 * through.
 * <p>
 * Sums are accumulated relative to a reference point near the lines to keep them well conditioned.
 */
public final class LineFit {

	/** Outcome of a solve. */
	public enum Status {
		OK, DEGENERATE
	}

	/**
	 * A solved centre.
	 *
	 * @param x centre x, or NaN when degenerate
	 * @param y centre y, or NaN when degenerate
	 * @param status whether the system could be solved
	 * @param lines number of lines used
	 */
	public record Solution(double x, double y, Status status, int lines) {
		/** @return whether the centre is valid */
		public boolean ok() {
			return status == Status.OK;
		}
	}

	/** Smallest accepted {@code det / (trace/2)^2}: 0 for parallel lines, 1 for lines in all directions. */
	public static final double MIN_CONDITION = 1e-6;

	private final double refX;
	private final double refY;
	private double mxx, mxy, myy, bx, by;
	private int lines;

	/** @param refX reference point near the lines (for conditioning) */
	public LineFit(final double refX, final double refY) {
		this.refX = refX;
		this.refY = refY;
	}

	/**
	 * Adds the line through (px, py) along (gx, gy) with weight {@code weight}. Zero gradients carry no
	 * direction and are ignored.
	 */
	private void add(final double px, final double py, final double gx, final double gy, final double weight) {
		final double g2 = gx * gx + gy * gy;
		if (g2 == 0 || weight == 0) return;
		final double s = weight / g2;
		final double axx = s * gy * gy, axy = -s * gx * gy, ayy = s * gx * gx;
		final double dx = px - refX, dy = py - refY;
		mxx += axx;
		mxy += axy;
		myy += ayy;
		bx += axx * dx + axy * dy;
		by += axy * dx + ayy * dy;
		lines++;
	}

	/** Adds the line with the paper's weight {@code |g|}. */
	public void addPaperWeighted(final double px, final double py, final double gx, final double gy) {
		add(px, py, gx, gy, Math.sqrt(gx * gx + gy * gy));
	}

	/** @return the weighted normal matrix {mxx, mxy, myy} */
	double[] matrix() {
		return new double[] { mxx, mxy, myy };
	}

	/** @return the least-squares centre, or a degenerate solution */
	public Solution solve() {
		final double det = mxx * myy - mxy * mxy;
		final double halfTrace = 0.5 * (mxx + myy);
		if (lines < 2 || !(halfTrace > 0) || !(det > MIN_CONDITION * halfTrace * halfTrace))
			return new Solution(Double.NaN, Double.NaN, Status.DEGENERATE, lines);
		final double cx = (myy * bx - mxy * by) / det;
		final double cy = (mxx * by - mxy * bx) / det;
		return new Solution(refX + cx, refY + cy, Status.OK, lines);
	}
}
