package io.github.contacttracker.core;

/**
 * The pixels of a group's fit: positions, values, other groups' light, their coordinates {@code u, v} in the
 * background plane's frame (origin and unit of the group's box) and the plane's block of J^T J, computed once
 * for every iteration.
 * <p>
 * Also where they come from ({@link #gather}) and which of them a fit uses where the pixel type clips
 * ({@link #select}): the pixels of {@link GroupFit}'s least squares, whose passes are {@link NormalEquations}.
 */
record FitPixels(int[] x, int[] y, double[] value, double[] fixed, int count, double[] u, double[] v,
	double[] backgroundBlock, int[] candidates)
{

	FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double mx, final double my, final double unit)
	{
		this(x, y, value, fixed, count, planeCoordinate(x, count, mx, unit), planeCoordinate(y, count, my, unit),
			null);
	}

	/** @return the index among the candidates of pixel {@code j} (a subset's; the candidates' own: j) */
	int candidate(final int j) {
		return candidates == null ? j : candidates[j];
	}

	private FitPixels(final int[] x, final int[] y, final double[] value, final double[] fixed, final int count,
		final double[] u, final double[] v, final int[] candidates)
	{
		this(x, y, value, fixed, count, u, v, backgroundBlock(u, v, count), candidates);
	}

	/** The background plane's block of J^T J, {1, u, v} x {1, u, v} row by row: the same at every step. */
	private static double[] backgroundBlock(final double[] u, final double[] v, final int count) {
		double su = 0, sv = 0, suu = 0, suv = 0, svv = 0;
		for (int i = 0; i < count; i++) {
			su += u[i];
			sv += v[i];
			suu += u[i] * u[i];
			suv += u[i] * v[i];
			svv += v[i] * v[i];
		}
		return new double[] { count, su, sv, su, suu, suv, sv, suv, svv };
	}

	/** @return the pixels marked in {@code keep}, in the same order (these pixels if all are) */
	FitPixels subset(final boolean[] keep) {
		int m = 0;
		for (int i = 0; i < count; i++)
			if (keep[i]) m++;
		if (m == count) return this;
		final int[] sx = new int[m], sy = new int[m];
		final double[] sv = new double[m], sf = new double[m], su = new double[m], sw = new double[m];
		final int[] from = new int[m];
		for (int i = 0, j = 0; i < count; i++) {
			if (!keep[i]) continue;
			from[j] = candidate(i);
			sx[j] = x[i];
			sy[j] = y[i];
			sv[j] = value[i];
			sf[j] = fixed[i];
			su[j] = u[i];
			sw[j++] = v[i];
		}
		return new FitPixels(sx, sy, sv, sf, m, su, sw, from);
	}

	private static double[] planeCoordinate(final int[] c, final int count, final double origin, final double unit) {
		final double[] out = new double[count];
		for (int i = 0; i < count; i++)
			out[i] = (c[i] - origin) / unit;
		return out;
	}

	/**
	 * The pixels a group's fit may use: within each member's window (at its starting centre and scale), not clipped,
	 * with the light of the reliable particles outside the group at their current centres, amplitudes and scales.
	 * (Apart from the fit's loop, so that the compiler sees small methods, each with its own pixel loop.)
	 */
	static FitPixels gather(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile profile, final double window, final Censoring censoring)
	{
		final double R = profile.radius(), W = Math.min(R, window);
		// The pixels: within each member's window (at its starting centre and scale), not clipped.
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (final int k : group) {
			final double reach = W * GroupFit.scaleOf(e[k]);
			x0 = Math.min(x0, (int) Math.floor(e[k].x() - reach));
			x1 = Math.max(x1, (int) Math.ceil(e[k].x() + reach));
			y0 = Math.min(y0, (int) Math.floor(e[k].y() - reach));
			y1 = Math.max(y1, (int) Math.ceil(e[k].y() + reach));
		}
		x0 = Math.max(0, x0);
		y0 = Math.max(0, y0);
		x1 = Math.min(plane.width() - 1, x1);
		y1 = Math.min(plane.height() - 1, y1);
		final double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1), unit = Math.max(1, 0.5 * (x1 - x0));
		int count = 0;
		final int cap = (x1 - x0 + 1) * (y1 - y0 + 1);
		final int[] px = new int[cap], py = new int[cap];
		final double[] pv = new double[cap];
		final int n = group.length;
		final double[] gx = new double[n], gy = new double[n], reach2 = new double[n];
		for (int q = 0; q < n; q++) {
			final Estimate m = e[group[q]];
			final double reach = W * GroupFit.scaleOf(m);
			gx[q] = m.x();
			gy[q] = m.y();
			reach2[q] = reach * reach;
		}
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				boolean inside = false;
				for (int q = 0; q < n && !inside; q++) {
					final double dx = x - gx[q], dy = y - gy[q];
					inside = dx * dx + dy * dy < reach2[q];
				}
				if (!inside) continue;
				final double v = plane.get(x, y);
				if (censoring.clipped(v)) continue; // censored: its true value is unknown
				px[count] = x;
				py[count] = y;
				pv[count++] = v;
			}
		// The light of reliable particles outside the group, at their current centres, amplitudes and scales.
		final double[] fixed = new double[count];
		for (int k = 0; k < ps.length; k++) {
			if (!ps[k].reliable() || GroupFit.contains(group, k)) continue;
			final double kx = e[k].x(), ky = e[k].y(), ks = GroupFit.scaleOf(e[k]), ka = GroupFit.amplitudeOf(e[k]);
			final double reach = R * ks;
			if (kx < x0 - reach || kx > x1 + reach || ky < y0 - reach || ky > y1 + reach) continue;
			for (int i = 0; i < count; i++) {
				final double dx = px[i] - kx, dy = py[i] - ky, d2 = dx * dx + dy * dy;
				if (d2 < reach * reach) fixed[i] += ka * profile.lookup(Math.sqrt(d2) / ks);
			}
		}
		return new FitPixels(px, py, pv, fixed, count, mx, my, unit);
	}

	/**
	 * Marks every candidate used and returns true if cheap bounds on the model show that all are usable; else returns
	 * false and leaves {@code use} unchanged (the caller chooses from the model itself).
	 */
	static boolean allUsable(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring, final boolean[] use)
	{
		if (!withinBounds(candidates, p, n, profile, censoring)) return false;
		java.util.Arrays.fill(use, true);
		return true;
	}

	/**
	 * Marks in {@code use} the candidates whose model value at parameters {@code p} the censoring rule keeps. Where
	 * the model at {@code p} is already known, on the pixels {@code known} (a subset of the candidates; {@code
	 * knownModels} in its order) from the fit's latest pass, only the other candidates are evaluated; both null: none
	 * known.
	 *
	 * @return whether any mark changed
	 */
	static boolean select(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring, final boolean[] use, final FitPixels known,
		final double[] knownModels)
	{
		final int b0 = GroupFit.PER_PARTICLE * n;
		boolean changed = false;
		// usually no model value comes near a clip level (a shortcut where the model is not known already)
		if (known == null && withinBounds(candidates, p, n, profile, censoring)) {
			for (int i = 0; i < candidates.count(); i++) {
				changed |= !use[i];
				use[i] = true;
			}
			return changed;
		}
		final double[] models = new double[candidates.count()];
		java.util.Arrays.fill(models, Double.NaN);
		if (known != null) for (int j = 0; j < known.count(); j++)
			models[known.candidate(j)] = knownModels[j];
		for (int i = 0; i < candidates.count(); i++) {
			if (!Double.isNaN(models[i])) {
				final boolean usable = censoring.usable(models[i]);
				changed |= usable != use[i];
				use[i] = usable;
				continue;
			}
			double model = p[b0] + p[b0 + 1] * candidates.u()[i] + p[b0 + 2] * candidates.v()[i] + candidates.fixed()[i];
			for (int q = 0; q < n; q++) {
				final int b = GroupFit.PER_PARTICLE * q;
				final double dx = candidates.x()[i] - p[b], dy = candidates.y()[i] - p[b + 1];
				model += p[b + 2] * profile.lookup(Math.sqrt(dx * dx + dy * dy) / p[b + 3]);
			}
			final boolean usable = censoring.usable(model);
			changed |= usable != use[i];
			use[i] = usable;
		}
		return changed;
	}

	/**
	 * @return whether bounds on the model over all candidates, cheap to get (no root, no lookup), lie where the
	 *         censoring rule keeps every pixel: background plane and other groups' light at their extremes, each
	 *         member's light between its amplitude times the profile's least and greatest values (or 0)
	 */
	private static boolean withinBounds(final FitPixels candidates, final double[] p, final int n,
		final EmpiricalProfile profile, final Censoring censoring)
	{
		final int b0 = GroupFit.PER_PARTICLE * n;
		double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
		for (int i = 0; i < candidates.count(); i++) {
			final double plane = p[b0] + p[b0 + 1] * candidates.u()[i] + p[b0 + 2] * candidates.v()[i] + candidates
				.fixed()[i];
			lo = Math.min(lo, plane);
			hi = Math.max(hi, plane);
		}
		for (int q = 0; q < n; q++) {
			lo += profile.leastLight(p[GroupFit.PER_PARTICLE * q + 2]);
			hi += profile.greatestLight(p[GroupFit.PER_PARTICLE * q + 2]);
		}
		return censoring.usableBetween(lo, hi);
	}
}
