package io.github.contacttracker.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Localizes the particles of one 2D frame with the close-contact radial-symmetry method of Yucel and
 * Okumusoglu (J. Phys.: Condens. Matter 29, 465101, 2017):
 * <ol>
 * <li>active areas: pixels {@code >= threshold}, labelled into components; components smaller than
 * {@code min_area} are dropped as noise;</li>
 * <li>first pass: each particle's radial-symmetry centre on its whole active area;</li>
 * <li>effective discs of radius {@code r_out} around the first centres;</li>
 * <li>second pass: each particle's centre again on its active area minus the other particles' discs.</li>
 * </ol>
 * Stateless and thread-safe: one instance can serve many threads.
 */
public final class ContactTracker {

	/** Above this elongation of its active area a component is flagged as a suspected merge. */
	public static final double MERGE_ELONGATION = 1.5;
	/** Above this multiple of the frame's median active area a component is flagged as a suspected merge. */
	public static final double MERGE_AREA_RATIO = 1.8;

	private final TrackerParameters params;

	public ContactTracker(final TrackerParameters params) {
		if (params == null) throw new IllegalArgumentException("parameters must be given");
		this.params = params;
	}

	/** @return the parameters */
	public TrackerParameters parameters() {
		return params;
	}

	/**
	 * Localizes the particles of a 2D frame.
	 *
	 * @param frame the frame; positions are returned in its coordinates (its interval minimum included)
	 * @param frameIndex the frame index written into the spots
	 * @return the spots, in raster order of their active areas' first pixels
	 * @throws IllegalArgumentException if the frame is not 2D or holds NaN or infinite pixels
	 */
	public <T extends RealType<T>> List<Localization> track(final RandomAccessibleInterval<T> frame,
		final int frameIndex)
	{
		return analyse(Plane.of(frame), frameIndex, false).spots();
	}

	/**
	 * Localizes the particles of a 2D frame and keeps each spot's active and second active areas.
	 *
	 * @see #track(RandomAccessibleInterval, int)
	 */
	public <T extends RealType<T>> FrameResult analyse(final RandomAccessibleInterval<T> frame,
		final int frameIndex)
	{
		return analyse(Plane.of(frame), frameIndex, true);
	}

	/** The whole pipeline on a plane; regions are kept only when asked for. */
	FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions) {
		final List<ParticleState> particles = new ArrayList<>();
		int discarded = 0;
		for (final Region r : ComponentLabeling.label(plane, params.threshold(), params.connectivity())) {
			final ParticleState p = r.area() >= params.minArea() ? new ParticleState(plane, r, params.threshold())
				: null;
			// A component without any gradient line (a flat plateau) holds nothing to localize.
			if (p != null && firstPass(p)) particles.add(p);
			else discarded++;
		}
		final int n = particles.size();
		if (params.method() != Method.FIRST) {
			final double[] cx = new double[n], cy = new double[n];
			for (int k = 0; k < n; k++) {
				cx[k] = particles.get(k).firstX;
				cy[k] = particles.get(k).firstY;
			}
			for (int k = 0; k < n; k++)
				secondPass(particles.get(k), k, cx, cy);
		}
		flagShapes(particles);
		final double noise = NoiseEstimate.sigma(plane);
		final List<Localization> spots = new ArrayList<>(n);
		final List<Region> active = new ArrayList<>(), second = new ArrayList<>();
		final int dx = (int) plane.minX(), dy = (int) plane.minY();
		for (int k = 0; k < n; k++) {
			final ParticleState p = particles.get(k);
			double sx = Double.NaN, sy = Double.NaN;
			if (p.matrix != null) {
				final double[] cov = CentreUncertainty.covariancePerUnitNoise(p.field, p.used, p.x, p.y, p.matrix);
				sx = noise * Math.sqrt(cov[0]);
				sy = noise * Math.sqrt(cov[1]);
			}
			spots.add(new Localization(frameIndex, p.x + dx, p.y + dy, p.firstX + dx, p.firstY + dy,
				p.region.area(), p.secondArea, p.quality, Math.sqrt(p.region.area() / Math.PI), p.flags,
				p.iterations, sx, sy));
			if (keepRegions) {
				active.add(p.region.translate(dx, dy));
				second.add(secondRegion(p.region, k, particles).translate(dx, dy));
			}
		}
		return new FrameResult(spots, active, second, noise, discarded);
	}

	/** @return false when the particle has no gradient line at all */
	private static boolean firstPass(final ParticleState p) {
		final LineFit.Solution s = p.solve(null);
		if (s.lines() == 0) return false;
		if (s.ok()) {
			p.firstX = s.x();
			p.firstY = s.y();
		}
		else {
			p.firstX = p.centroidX;
			p.firstY = p.centroidY;
			p.set(Flag.DEGENERATE.bit());
		}
		p.x = p.firstX;
		p.y = p.firstY;
		p.iterations = 1;
		return true;
	}

	/** The paper's second pass: solve again outside the other particles' discs around (cx, cy). */
	private void secondPass(final ParticleState p, final int self, final double[] cx, final double[] cy) {
		final int[] near = neighboursReaching(p.region, self, cx, cy);
		if (near.length == 0) return; // nothing to exclude: the first centre is final
		final double r2 = params.rOut() * params.rOut();
		p.secondArea = countOutside(p.region, near, cx, cy, r2);
		if (p.secondArea == p.region.area()) return;
		final boolean[] use = new boolean[p.field.size];
		for (int i = 0; i < p.field.size; i++)
			use[i] = outside(p.field.x[i], p.field.y[i], near, cx, cy, r2);
		if (p.secondArea < params.minSecondArea()) {
			p.set(Flag.FELL_BACK.bit());
			return;
		}
		final LineFit.Solution s = p.solve(use);
		if (!s.ok()) {
			p.set(Flag.FELL_BACK.bit() | Flag.DEGENERATE.bit());
			return;
		}
		p.x = s.x();
		p.y = s.y();
		p.iterations = 2;
		p.set(Flag.SECOND_PASS.bit());
	}

	/** @return indices of the other particles whose disc can reach the region's bounding box */
	private int[] neighboursReaching(final Region region, final int self, final double[] cx, final double[] cy) {
		final double r = params.rOut();
		int[] out = new int[4];
		int n = 0;
		for (int h = 0; h < cx.length; h++) {
			if (h == self) continue;
			final double dx = Math.max(0, Math.max(region.minX() - cx[h], cx[h] - region.maxX()));
			final double dy = Math.max(0, Math.max(region.minY() - cy[h], cy[h] - region.maxY()));
			if (dx * dx + dy * dy <= r * r) {
				if (n == out.length) out = Arrays.copyOf(out, 2 * n);
				out[n++] = h;
			}
		}
		return Arrays.copyOf(out, n);
	}

	private static boolean outside(final int x, final int y, final int[] near, final double[] cx,
		final double[] cy, final double r2)
	{
		for (final int h : near) {
			final double dx = x - cx[h], dy = y - cy[h];
			if (dx * dx + dy * dy <= r2) return false;
		}
		return true;
	}

	private static int countOutside(final Region region, final int[] near, final double[] cx, final double[] cy,
		final double r2)
	{
		int count = 0;
		for (int r = 0; r < region.runCount(); r++)
			for (int x = region.runStart(r); x <= region.runEnd(r); x++)
				if (outside(x, region.runY(r), near, cx, cy, r2)) count++;
		return count;
	}

	/** The second active area of particle {@code self} as a region, for display. */
	private Region secondRegion(final Region region, final int self, final List<ParticleState> particles) {
		if (params.method() == Method.FIRST) return region;
		final int n = particles.size();
		final double[] cx = new double[n], cy = new double[n];
		for (int k = 0; k < n; k++) {
			cx[k] = particles.get(k).firstX;
			cy[k] = particles.get(k).firstY;
		}
		final int[] near = neighboursReaching(region, self, cx, cy);
		final double r2 = params.rOut() * params.rOut();
		final RunList runs = new RunList();
		for (int r = 0; r < region.runCount(); r++) {
			final int y = region.runY(r);
			int start = -1;
			for (int x = region.runStart(r); x <= region.runEnd(r); x++) {
				if (outside(x, y, near, cx, cy, r2)) {
					if (start < 0) start = x;
				}
				else if (start >= 0) {
					runs.add(y, start, x - 1);
					start = -1;
				}
			}
			if (start >= 0) runs.add(y, start, region.runEnd(r));
		}
		return new Region(Arrays.copyOf(runs.y, runs.size), Arrays.copyOf(runs.x0, runs.size),
			Arrays.copyOf(runs.x1, runs.size));
	}

	/** Flags spots at the border and components that look like several particles merged. */
	private static void flagShapes(final List<ParticleState> particles) {
		final int n = particles.size();
		double medianArea = Double.NaN;
		if (n >= 3) {
			final int[] areas = new int[n];
			for (int k = 0; k < n; k++)
				areas[k] = particles.get(k).region.area();
			Arrays.sort(areas);
			medianArea = n % 2 == 1 ? areas[n / 2] : 0.5 * (areas[n / 2 - 1] + areas[n / 2]);
		}
		for (final ParticleState p : particles) {
			if (p.atBorder) p.set(Flag.AT_BORDER.bit());
			final boolean elongated = !p.atBorder && p.elongation > MERGE_ELONGATION;
			final boolean large = p.region.area() > MERGE_AREA_RATIO * medianArea;
			if (elongated || large) p.set(Flag.MERGED.bit());
		}
	}
}
