package io.github.contacttracker.core;

/**
 * One radial-symmetry solve and what its error propagation needs: the gradients, which of them were used
 * ({@code used == null}: all), the normal matrix, and the offset of the gradients' coordinates from the frame's.
 *
 * @param solution the solved centre, in the gradients' coordinates plus the origin
 */
record Solve(LineFit.Solution solution, GradientField field, boolean[] used, double[] matrix, int originX,
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
	static Solve on(final GradientField field, final boolean[] use, final double refX, final double refY,
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
	boolean ok() {
		return solution.ok();
	}
}
