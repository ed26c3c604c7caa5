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

	/**
	 * Localizes the particles of a 2D frame with a radial profile measured beforehand (for instance over a whole
	 * stack, see {@link ProfileEstimator}); used by the {@code deblend} and {@code fit} methods, ignored by the
	 * others. With {@code profile == null} those methods measure the profile on this frame alone.
	 */
	public <T extends RealType<T>> FrameResult analyse(final RandomAccessibleInterval<T> frame,
		final int frameIndex, final EmpiricalProfile profile)
	{
		return analyse(Plane.of(frame), frameIndex, true, profile);
	}

	/** The whole pipeline on a plane; regions are kept only when asked for. */
	FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions) {
		return analyse(plane, frameIndex, keepRegions, null);
	}

	FrameResult analyse(final Plane plane, final int frameIndex, final boolean keepRegions,
		final EmpiricalProfile profile)
	{
		final List<ParticleState> particles = new ArrayList<>();
		int discarded = 0;
		for (final Region r : ComponentLabeling.label(plane, params.threshold(), params.connectivity())) {
			final ParticleState p = r.area() >= params.minArea() ? new ParticleState(plane, r, params.threshold())
				: null;
			// A component without any gradient line (a flat plateau) holds nothing to localize.
			if (p != null && firstPass(p)) particles.add(p);
			else discarded++;
		}
		final ParticleState[] ps = particles.toArray(new ParticleState[0]);
		flagShapes(particles);
		final Method method = params.method();
		double[][] discs = firstCentres(ps);
		if (method == Method.PAPER) secondPasses(ps, discs);
		else if (method != Method.FIRST) {
			discs = iterate(ps);
			if (method.needsProfile() && ps.length > 0) refineWithProfile(plane, ps, profile);
		}
		final double noise = NoiseEstimate.sigma(plane);
		final List<Localization> spots = new ArrayList<>(ps.length);
		final List<Region> active = new ArrayList<>(), second = new ArrayList<>();
		final int dx = (int) plane.minX(), dy = (int) plane.minY();
		for (int k = 0; k < ps.length; k++) {
			final ParticleState p = ps[k];
			double sx = p.fitSigmaX, sy = p.fitSigmaY;
			if (Double.isNaN(sx) && p.lastSolve != null) {
				final ParticleState.SolveContext c = p.lastSolve;
				final double[] cov = CentreUncertainty.covariancePerUnitNoise(c.field(), c.used(), p.x - c.originX(), p.y -
					c.originY(), c.matrix());
				sx = noise * Math.sqrt(cov[0]);
				sy = noise * Math.sqrt(cov[1]);
			}
			spots.add(new Localization(frameIndex, p.x + dx, p.y + dy, p.firstX + dx, p.firstY + dy,
				p.region.area(), p.secondArea, p.quality, Math.sqrt(p.region.area() / Math.PI), p.flags,
				p.iterations, sx, sy));
			if (keepRegions) {
				active.add(p.region.translate(dx, dy));
				second.add(secondRegion(p.region, k, discs).translate(dx, dy));
			}
		}
		return new FrameResult(spots, active, second, noise, discarded);
	}

	/** Upper bound on the passes of the iterative methods. */
	public static final int MAX_ITERATIONS = 100;
	/** The iterative method stops when no centre moves more than this between passes (px). */
	public static final double TOLERANCE = 1e-4;

	private static double[][] firstCentres(final ParticleState[] ps) {
		final double[][] c = new double[2][ps.length];
		for (int k = 0; k < ps.length; k++) {
			c[0][k] = ps[k].firstX;
			c[1][k] = ps[k].firstY;
		}
		return c;
	}

	/** One second pass for every particle, with discs around {@code centres}; returns the largest move. */
	private double secondPasses(final ParticleState[] ps, final double[][] centres) {
		double move = 0;
		for (int k = 0; k < ps.length; k++) {
			final double x = ps[k].x, y = ps[k].y;
			secondPass(ps[k], k, centres[0], centres[1]);
			move = Math.max(move, Math.hypot(ps[k].x - x, ps[k].y - y));
		}
		return move;
	}

	/**
	 * The iterative method: second passes with discs around the latest centres until they settle.
	 *
	 * @return the disc centres of the last pass
	 */
	private double[][] iterate(final ParticleState[] ps) {
		double[][] centres = firstCentres(ps);
		for (int it = 1; it <= MAX_ITERATIONS; it++) {
			final double move = secondPasses(ps, centres);
			for (final ParticleState p : ps)
				if (p.has(Flag.SECOND_PASS)) p.iterations = it + 1;
			if (move < TOLERANCE) return centres;
			centres = new double[2][ps.length];
			for (int k = 0; k < ps.length; k++) {
				centres[0][k] = ps[k].x;
				centres[1][k] = ps[k].y;
			}
		}
		for (final ParticleState p : ps)
			if (p.has(Flag.SECOND_PASS)) p.set(Flag.NOT_CONVERGED.bit());
		return centres;
	}

	/**
	 * deblend and fit: measure the profile on this frame unless given (twice, the second time around the
	 * refined centres), then refine the centres with it.
	 */
	private void refineWithProfile(final Plane plane, final ParticleState[] ps, final EmpiricalProfile given) {
		final int rounds = given == null ? 2 : 1;
		EmpiricalProfile profile = given;
		for (int round = 0; round < rounds; round++) {
			if (given == null) {
				final ProfileEstimator estimator = ProfileEstimator.forROut(params.rOut());
				final double[] cx = new double[ps.length], cy = new double[ps.length];
				final boolean[] masked = new boolean[ps.length];
				for (int k = 0; k < ps.length; k++) {
					cx[k] = ps[k].x;
					cy[k] = ps[k].y;
					masked[k] = !ps[k].reliable();
				}
				estimator.add(plane, cx, cy, masked);
				try {
					profile = estimator.estimate();
				}
				catch (final IllegalStateException e) {
					for (final ParticleState p : ps)
						p.set(Flag.FELL_BACK.bit()); // keeps the iterative centre
					return;
				}
			}
			final int iterations;
			if (params.method() == Method.DEBLEND) {
				double disc = profile.activeRadius(params.threshold());
				if (disc < 3) disc = medianEquivalentRadius(ps);
				iterations = Deblender.refine(plane, ps, profile, disc);
			}
			else iterations = GroupFit.refine(plane, ps, profile, 2 * params.rOut());
			for (final ParticleState p : ps) {
				p.clear(Flag.SECOND_PASS.bit() | Flag.FELL_BACK.bit() | Flag.NOT_CONVERGED.bit());
				p.iterations = Math.abs(iterations);
				if (iterations < 0) p.set(Flag.NOT_CONVERGED.bit());
			}
		}
	}

	private static double medianEquivalentRadius(final ParticleState[] ps) {
		final double[] r = new double[ps.length];
		for (int k = 0; k < ps.length; k++)
			r[k] = Math.sqrt(ps[k].region.area() / Math.PI);
		Arrays.sort(r);
		return r[r.length / 2];
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
			p.firstDegenerate = true;
			p.set(Flag.DEGENERATE.bit());
		}
		p.x = p.firstX;
		p.y = p.firstY;
		p.iterations = 1;
		p.firstSolve = p.lastSolve;
		return true;
	}

	/**
	 * The paper's second pass: solve again outside the other particles' discs around (cx, cy). Sets the
	 * particle's centre (its first-pass centre when nothing is excluded or the pass falls back) and flags.
	 */
	private void secondPass(final ParticleState p, final int self, final double[] cx, final double[] cy) {
		p.clear(Flag.SECOND_PASS.bit() | Flag.FELL_BACK.bit());
		p.x = p.firstX;
		p.y = p.firstY;
		p.lastSolve = p.firstSolve;
		p.secondArea = p.region.area();
		final int[] near = neighboursReaching(p.region, self, cx, cy);
		if (near.length == 0) return; // nothing to exclude: the first centre is final
		final double r2 = params.rOut() * params.rOut();
		p.secondArea = countOutside(p.region, near, cx, cy, r2);
		if (p.secondArea == p.region.area()) return;
		if (p.secondArea < params.minSecondArea()) {
			p.set(Flag.FELL_BACK.bit());
			return;
		}
		final boolean[] use = new boolean[p.field.size];
		for (int i = 0; i < p.field.size; i++)
			use[i] = outside(p.field.x[i], p.field.y[i], near, cx, cy, r2);
		final LineFit.Solution s = p.solve(use);
		if (!s.ok()) {
			p.lastSolve = p.firstSolve;
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

	/** The second active area of particle {@code self} with discs around {@code discs}, for display. */
	private Region secondRegion(final Region region, final int self, final double[][] discs) {
		if (params.method() == Method.FIRST) return region;
		final double[] cx = discs[0], cy = discs[1];
		final int[] near = neighboursReaching(region, self, cx, cy);
		final double r2 = params.rOut() * params.rOut();
		final RunList runs = new RunList();
		for (int r = 0; r < region.runCount(); r++) {
			final int y = region.runY(r);
			runs.addWhere(y, region.runStart(r), region.runEnd(r), x -> outside(x, y, near, cx, cy, r2));
		}
		return runs.toRegion();
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
