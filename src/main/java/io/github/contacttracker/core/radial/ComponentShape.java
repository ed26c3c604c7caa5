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

import java.util.Arrays;

import io.github.contacttracker.core.image.Region;

/**
 * Is an active area one particle or several? Decided by shape alone, never by size, because on real movies
 * particles in and slightly out of focus have active areas of very different sizes (70 and 200 px).
 * <p>
 * The geometry: the active area of one radially symmetric particle is a disc ({@code I(r) >= th} with {@code I}
 * decreasing in {@code r}), or an annulus when a defocused particle's centre is darker than its bright ring; with
 * its holes filled it is a disc either way, and a disc is convex. Several particles whose active areas merged are
 * the union of discs (lobes) joined by bridges: that set is not convex. Where two lobes meet the outline has a
 * waist, and the convex hull spans a "bay" over it whose depth is about the smaller lobe's radius minus half the
 * width of the waist (the whole radius for two discs that just touch; still 0.4 of it for two equal discs that
 * overlap by 20% of their diameter). Pixel noise only notches a disc's outline by a pixel or so. So the measure
 * is the <b>depth of the deepest bay</b>: the largest distance, from the convex hull's edge, of a pixel that lies
 * inside the hull of the hole-filled active area but not in it.
 * <ul>
 * <li>Digital discs are digitally convex: every pixel centre inside the hull of their pixel centres belongs to
 * them, so a noise-free disc of any size has depth 0, and a noisy one about 1 px.</li>
 * <li>Two equal lobes that overlap heavily have a shallow waist but are elongated (the ratio of the principal
 * second moments); three lobes in a triangle are not elongated but have three deep bays. The two measures are
 * complementary; a cut disc at the image border is elongated but convex, so there only the bays count.</li>
 * </ul>
 */
public final class ComponentShape {

	/** Above this elongation (sqrt of the principal second moments' ratio; 1 for a disc) a component is merged. */
	static final double MERGE_ELONGATION = 1.5;
	/** A bay at least this deep (px) marks a merge, however small the component... */
	static final double MERGE_MIN_DEPTH_PX = 2.5;
	/** ...and at least this fraction of the component's equivalent radius {@code sqrt(area / pi)}. */
	static final double MERGE_DEPTH_FRACTION = 0.2;
	/**
	 * Above this fraction of the equivalent radius (and of the particle diameter, when known), the gradient lines'
	 * RMS distance from the centre (beyond what pixel noise explains) marks a merge.
	 */
	static final double MERGE_RESIDUAL_FRACTION = 0.1;

	/** sqrt of the ratio of the principal second moments of the active area (1 for a disc). */
	final double elongation;
	/** Depth (px) of the deepest bay of the hole-filled active area below its convex hull. */
	final double bayDepth;
	/**
	 * How far (px) the first pass's gradient lines pass from its centre, root mean square with the pass's weights
	 * {@code |g|}: about 0 for one radially symmetric particle, about a third of the distance between two merged
	 * particles (NaN when the first pass was degenerate).
	 */
	final double symmetryResidual;
	/** The part of {@link #symmetryResidual} that pixel noise explains (px), for noise of 1 grey level. */
	final double noiseResidualPerSigma;
	/** Pixels of the active area with its holes filled. */
	final int filledArea;
	/** Pixel centres inside the convex hull of the filled active area's pixel centres (edges included). */
	final int hullArea;

	private ComponentShape(final double elongation, final double[] residual, final double bayDepth,
		final int filledArea, final int hullArea)
	{
		this.elongation = elongation;
		this.symmetryResidual = residual[0];
		this.noiseResidualPerSigma = residual[1];
		this.bayDepth = bayDepth;
		this.filledArea = filledArea;
		this.hullArea = hullArea;
	}

	/** @return the depth a bay must reach to mark a component of equivalent radius {@code sqrt(area / pi)} */
	static double mergeDepth(final int area) {
		return Math.max(MERGE_MIN_DEPTH_PX, MERGE_DEPTH_FRACTION * Math.sqrt(area / Math.PI));
	}

	/**
	 * @param atBorder whether the component is cut by the image border (then elongation does not count)
	 * @param noise the frame's pixel-noise standard deviation (grey levels)
	 * @param alone whether no neighbour's light reaches the component: a neighbour's light tilts the gradient lines
	 *        of a single particle too (long-range profiles at contact), so the symmetry residual counts only alone
	 * @param diameter the particles' diameter (px; 0 when not known)
	 * @return whether the component looks like several particles
	 */
	public boolean merged(final boolean atBorder, final double noise, final boolean alone, final double diameter) {
		return outlineMerged(atBorder) || alone && excessResidual(noise) > residualLimit(diameter);
	}

	/**
	 * @param atBorder whether the component is cut by the image border (then elongation does not count)
	 * @return whether the outline alone is that of several particles: elongated, or with a bay as deep as a waist
	 */
	public boolean outlineMerged(final boolean atBorder) {
		return !atBorder && elongation > MERGE_ELONGATION || bayDepth >= mergeDepth(filledArea);
	}

	/**
	 * How far the gradient lines may pass from the centre (beyond noise) in one particle: a tenth of the
	 * equivalent radius, and of the diameter when it is known. Two merged particles' lines meet at two points at
	 * least a diameter {@code D} apart: their RMS distance from the joint centre is {@code D sqrt(f (1 - f) / 2)}
	 * for a share {@code f} of the gradient weight in the smaller one, above {@code 0.1 D} for any {@code f >= 2%}.
	 * A real particle's lines do not meet in one point either (an imperfect lens, illumination from a slight angle,
	 * JPEG blocks): on the bright-field movie of the paper's authors single cores of radius 4.7 to 8.3 px have
	 * residuals of 0.3 to 1.3 px, up to 0.17 of their radius, for particles about 32-34 px apart at contact. The
	 * radius alone would flag them; the diameter, which two merged particles' lines must span, does not.
	 */
	double residualLimit(final double diameter) {
		return MERGE_RESIDUAL_FRACTION * Math.max(Math.sqrt(filledArea / Math.PI), diameter);
	}

	/** @return the symmetry residual beyond what noise explains (px; 0 when unknown) */
	double excessResidual(final double noise) {
		if (!Double.isFinite(symmetryResidual)) return 0;
		final double n = noise * noiseResidualPerSigma;
		return Math.sqrt(Math.max(0, symmetryResidual * symmetryResidual - n * n));
	}

	/** Measures a region's outline only (no symmetry residual). */
	public static ComponentShape of(final Region region) {
		return of(region, null, Double.NaN, Double.NaN);
	}

	/**
	 * Measures a region and how well its gradient lines meet at the first pass's centre ({@code cx, cy}; NaN
	 * when there is none).
	 */
	static ComponentShape of(final Region region, final GradientField field, final double cx, final double cy) {
		return new ComponentShape(elongation(region), residual(field, cx, cy), 0, 0, 0).withBays(region);
	}

	/**
	 * Weighted RMS distance of the gradient lines from (cx, cy), weights |g| as in the first pass; and the RMS
	 * distance pixel noise of 1 grey level alone would cause. The 5x3 operators sum 12 pixels each, so noise
	 * {@code s} moves each gradient component by {@code sqrt(12) s}; turned by the angle {@code sqrt(12) s / |g|}
	 * (at most a random direction: mean squared sine 1/2), the line through a pixel at distance {@code rho} from
	 * the centre passes {@code rho} times that sine from it.
	 */
	private static double[] residual(final GradientField field, final double cx, final double cy) {
		if (field == null || !Double.isFinite(cx) || !Double.isFinite(cy)) return new double[] { Double.NaN, 0 };
		double sw = 0, swd = 0, swn = 0;
		for (int i = 0; i < field.size; i++) {
			final double gx = field.gx[i], gy = field.gy[i], g = Math.sqrt(gx * gx + gy * gy); // (hypot: 4x slower)
			if (g == 0) continue;
			// distance of c from the line through p along g: |g x (c - p)| / |g|
			final double px = cx - field.x[i], py = cy - field.y[i];
			final double d = (gx * py - gy * px) / g;
			sw += g;
			swd += g * d * d;
			swn += g * (px * px + py * py) * Math.min(0.5, 12 / (g * g));
		}
		return sw > 0 ? new double[] { Math.sqrt(swd / sw), Math.sqrt(swn / sw) } : new double[] { Double.NaN, 0 };
	}

	private ComponentShape withBays(final Region region) {
		if (region.area() == 0) return this;
		// bitmap of the bounding box with a 1 px frame, so that the outside is connected
		final int x0 = region.minX() - 1, y0 = region.minY() - 1;
		final int w = region.maxX() - x0 + 2, h = region.maxY() - y0 + 2;
		final byte[] map = new byte[w * h]; // 0 free, 1 region, 2 outside
		for (int r = 0; r < region.runCount(); r++) {
			final int row = (region.runY(r) - y0) * w - x0;
			Arrays.fill(map, row + region.runStart(r), row + region.runEnd(r) + 1, (byte) 1);
		}
		// the outside: free pixels 4-connected to the frame; the rest (holes included) is the filled area. The frame
		// is free all round, so it is outside, and the search runs over the inner pixels only, seeded next to the
		// frame: no bounds to test. A plain int queue (every pixel enters at most once; no boxing: this runs for
		// every component).
		final int[] queue = new int[w * h];
		int tail = 0;
		for (int x = 0; x < w; x++)
			map[x] = map[(h - 1) * w + x] = 2;
		for (int y = 1; y < h - 1; y++)
			map[y * w] = map[y * w + w - 1] = 2;
		for (int x = 1; x < w - 1; x++) {
			tail = enqueueFree(map, queue, tail, w + x);
			tail = enqueueFree(map, queue, tail, (h - 2) * w + x);
		}
		for (int y = 1; y < h - 1; y++) {
			tail = enqueueFree(map, queue, tail, y * w + 1);
			tail = enqueueFree(map, queue, tail, y * w + w - 2);
		}
		for (int head = 0; head < tail; head++) {
			final int i = queue[head];
			tail = enqueueFree(map, queue, tail, i - 1);
			tail = enqueueFree(map, queue, tail, i + 1);
			tail = enqueueFree(map, queue, tail, i - w);
			tail = enqueueFree(map, queue, tail, i + w);
		}
		// each row's first and last filled pixel: enough for the convex hull
		final int rows = h - 2;
		final long[] pts = new long[2 * rows];
		int n = 0, filled = 0;
		for (int y = 1; y <= rows; y++) {
			int first = -1, last = -1;
			for (int x = 1; x < w - 1; x++)
				if (map[y * w + x] != 2) {
					if (first < 0) first = x;
					last = x;
					filled++;
				}
			if (first < 0) continue;
			pts[n++] = pack(first, y);
			if (last != first) pts[n++] = pack(last, y);
		}
		final long[] hull = hull(Arrays.copyOf(pts, n));
		if (hull.length < 3) return new ComponentShape(elongation, residualPair(), 0, filled, filled);
		// lattice points inside the hull, row by row; the depth of those outside the filled area
		double depth = 0;
		int inside = 0;
		final int m = hull.length;
		// the hull's extent on every row, edge by edge (each edge visits only the rows it spans)
		final double[] lows = new double[rows + 1], highs = new double[rows + 1];
		Arrays.fill(lows, Double.POSITIVE_INFINITY);
		Arrays.fill(highs, Double.NEGATIVE_INFINITY);
		for (int e = 0; e < m; e++) {
			final long a = hull[e], b = hull[(e + 1) % m];
			final int ay = py(a), by = py(b);
			for (int y = Math.max(1, Math.min(ay, by)); y <= Math.min(rows, Math.max(ay, by)); y++) {
				if (ay == by) {
					lows[y] = Math.min(lows[y], Math.min(px(a), px(b)));
					highs[y] = Math.max(highs[y], Math.max(px(a), px(b)));
				}
				else {
					final double x = px(a) + (double) (px(b) - px(a)) * (y - ay) / (by - ay);
					lows[y] = Math.min(lows[y], x);
					highs[y] = Math.max(highs[y], x);
				}
			}
		}
		for (int y = 1; y <= rows; y++) {
			final double lo = lows[y], hi = highs[y];
			if (lo > hi) continue;
			for (int x = (int) Math.ceil(lo - 1e-9); x <= (int) Math.floor(hi + 1e-9); x++) {
				inside++;
				if (map[y * w + x] != 2) continue;
				double d = Double.POSITIVE_INFINITY;
				for (int e = 0; e < m; e++)
					d = Math.min(d, distanceToLine(hull[e], hull[(e + 1) % m], x, y));
				depth = Math.max(depth, d);
			}
		}
		return new ComponentShape(elongation, residualPair(), depth, filled, inside);
	}

	/** Marks pixel {@code i} outside and queues it if it is free; returns the queue's new length. */
	private static int enqueueFree(final byte[] map, final int[] queue, final int tail, final int i) {
		if (map[i] != 0) return tail;
		map[i] = 2;
		queue[tail] = i;
		return tail + 1;
	}

	private double[] residualPair() {
		return new double[] { symmetryResidual, noiseResidualPerSigma };
	}

	private static long pack(final int x, final int y) {
		return ((long) x << 32) | (y & 0xffffffffL);
	}

	private static int px(final long p) {
		return (int) (p >> 32);
	}

	private static int py(final long p) {
		return (int) p;
	}

	/** Distance of (x, y) from the line through a and b. */
	private static double distanceToLine(final long a, final long b, final int x, final int y) {
		final double dx = px(b) - px(a), dy = py(b) - py(a);
		return Math.abs(dx * (y - py(a)) - dy * (x - px(a))) / Math.sqrt(dx * dx + dy * dy); // integers: exact squares
	}

	/** Convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped. */
	private static long[] hull(final long[] points) {
		final long[] keys = points.clone();
		Arrays.sort(keys); // by x, then y (x sits in the high bits, y >= 0)
		final int n = keys.length;
		if (n < 3) return keys;
		final long[] h = new long[2 * n];
		int k = 0;
		for (int i = 0; i < n; i++) {
			while (k >= 2 && cross(h[k - 2], h[k - 1], keys[i]) <= 0)
				k--;
			h[k++] = keys[i];
		}
		for (int i = n - 2, t = k + 1; i >= 0; i--) {
			while (k >= t && cross(h[k - 2], h[k - 1], keys[i]) <= 0)
				k--;
			h[k++] = keys[i];
		}
		return Arrays.copyOf(h, k - 1);
	}

	private static long cross(final long o, final long a, final long b) {
		return (long) (px(a) - px(o)) * (py(b) - py(o)) - (long) (py(a) - py(o)) * (px(b) - px(o));
	}

	/** sqrt of the ratio of the principal second moments (infinite for a line). */
	private static double elongation(final Region region) {
		double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
		for (int r = 0; r < region.runCount(); r++) {
			final int yy = region.runY(r);
			for (int xx = region.runStart(r); xx <= region.runEnd(r); xx++) {
				sx += xx;
				sy += yy;
				sxx += (double) xx * xx;
				syy += (double) yy * yy;
				sxy += (double) xx * yy;
			}
		}
		final int n = region.area();
		final double cxx = sxx / n - (sx / n) * (sx / n), cyy = syy / n - (sy / n) * (sy / n);
		final double cxy = sxy / n - (sx / n) * (sy / n);
		final double tr = cxx + cyy, det = cxx * cyy - cxy * cxy;
		final double disc = Math.sqrt(Math.max(0, tr * tr / 4 - det));
		final double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
		return l2 > 0 ? Math.sqrt(l1 / l2) : Double.POSITIVE_INFINITY;
	}
}
