package io.github.contacttracker.core;

/**
 * Working state of one particle while a frame is localized: its active area, gradients, and the centres of
 * each pass.
 */
final class ParticleState {
	final Region region;
	final GradientField field;
	/** Integrated intensity above threshold over the active area. */
	final double quality;
	/** Intensity-above-threshold weighted centroid: the fallback of a degenerate first pass. */
	final double centroidX, centroidY;
	final boolean atBorder;
	/** sqrt of the ratio of the principal second moments of the active area (1 for a disc). */
	final double elongation;

	double firstX, firstY;
	double x, y;
	int flags;
	int secondArea;
	int iterations;
	/** The last radial-symmetry solve behind (x, y), for its error propagation; null if none. */
	SolveContext lastSolve;
	/** The first pass's solve. */
	SolveContext firstSolve;
	/** Standard errors set by a method that estimates its own (the joint fit); NaN otherwise. */
	double fitSigmaX = Double.NaN, fitSigmaY = Double.NaN;

	/**
	 * A solve's gradients, which of them were used ({@code used == null}: all), the normal matrix, and the
	 * offset of the gradients' coordinates from the frame's.
	 */
	record SolveContext(GradientField field, boolean[] used, double[] matrix, int originX, int originY) {}

	ParticleState(final Plane plane, final Region region, final double threshold) {
		this.region = region;
		this.field = GradientField.compute(plane, region);
		double q = 0, qx = 0, qy = 0;
		double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
		for (int r = 0; r < region.runCount(); r++) {
			final int yy = region.runY(r);
			for (int xx = region.runStart(r); xx <= region.runEnd(r); xx++) {
				final double v = plane.get(xx, yy) - threshold;
				q += v;
				qx += v * xx;
				qy += v * yy;
				sx += xx;
				sy += yy;
				sxx += (double) xx * xx;
				syy += (double) yy * yy;
				sxy += (double) xx * yy;
			}
		}
		final int n = region.area();
		quality = q;
		// Every pixel is >= threshold, so q > 0 unless all sit exactly on it: then the plain centroid.
		centroidX = q > 0 ? qx / q : sx / n;
		centroidY = q > 0 ? qy / q : sy / n;
		final double cxx = sxx / n - (sx / n) * (sx / n), cyy = syy / n - (sy / n) * (sy / n);
		final double cxy = sxy / n - (sx / n) * (sy / n);
		final double tr = cxx + cyy, det = cxx * cyy - cxy * cxy;
		final double disc = Math.sqrt(Math.max(0, tr * tr / 4 - det));
		final double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
		elongation = l2 > 0 ? Math.sqrt(l1 / l2) : Double.POSITIVE_INFINITY;
		atBorder = field.withoutGradient > 0 || region.minX() == 0 || region.minY() == 0 ||
			region.maxX() == plane.width() - 1 || region.maxY() == plane.height() - 1;
		secondArea = n;
	}

	void set(final int flag) {
		flags |= flag;
	}

	void clear(final int flag) {
		flags &= ~flag;
	}

	/** Whether the first pass was degenerate (the centre is then the centroid). */
	boolean firstDegenerate;

	/**
	 * @return whether the particle's centre describes one particle: not a suspected merge, and its first pass
	 *         solved
	 */
	boolean reliable() {
		return !has(Flag.MERGED) && !firstDegenerate;
	}

	boolean has(final Flag flag) {
		return flag.isSet(flags);
	}

	/** Solves on the pixels marked in {@code use} ({@code null}: all); remembers them for the uncertainty. */
	LineFit.Solution solve(final boolean[] use) {
		final LineFit fit = new LineFit(centroidX, centroidY);
		for (int i = 0; i < field.size; i++)
			if (use == null || use[i]) fit.addPaperWeighted(field.x[i], field.y[i], field.gx[i], field.gy[i]);
		final LineFit.Solution s = fit.solve();
		if (s.ok()) lastSolve = new SolveContext(field, use, fit.matrix(), 0, 0);
		return s;
	}
}
