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
 * One radial-symmetry solve and what its error propagation needs: the gradients, which of them were used
 * ({@code used == null}: all), the normal matrix, and the offset of the gradients' coordinates from the frame's.
 *
 * @param solution the solved centre, in the gradients' coordinates plus the origin
 */
public record Solve(LineFit.Solution solution, GradientField field, boolean[] used, double[] matrix, int originX,
	int originY)
{
	/** Solves on {@code field}'s lines marked in {@code use} ({@code null}: all), with the paper's weights. */
	static Solve on(final GradientField field, final boolean[] use, final double refX, final double refY) {
		return on(field, use, refX, refY, 0, 0);
	}

	/**
	 * As {@link #on(GradientField, boolean[], double, double)} for a field computed on a window whose pixel
	 * (0, 0) is the frame's {@code (originX, originY)}; the solution is returned in frame coordinates.
	 */
	public static Solve on(final GradientField field, final boolean[] use, final double refX, final double refY,
		final int originX, final int originY)
	{
		final LineFit fit = new LineFit(refX, refY);
		for (int i = 0; i < field.size; i++)
			if (use == null || use[i]) fit.addPaperWeighted(field.x[i], field.y[i], field.gx[i], field.gy[i]);
		final LineFit.Solution s = fit.solve();
		final LineFit.Solution inFrame = s.ok() && (originX != 0 || originY != 0) ? new LineFit.Solution(s.x() +
			originX, s.y() + originY, s.status(), s.lines()) : s;
		return new Solve(inFrame, field, use, s.ok() ? fit.matrix() : null, originX, originY);
	}

	/** @return whether the solve succeeded */
	public boolean ok() {
		return solution.ok();
	}
}
