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
package io.github.contacttracker.core.fit;

import io.github.contacttracker.core.math.UnionFind;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.math.SymmetricSolver;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import net.imglib2.parallel.Parallelization;

/**
 * The {@code fit} method: particles closer than {@code 2 r_out} form a group (their significant light
 * overlaps), and each group is fitted jointly by least squares to the pixels within {@code R} (the measured
 * profile's reach) of its members: {@code I(x) = B + sum_k a_k P_k(|x - c_k| / s_k) + F(x)} with the measured
 * profile {@code P_k} of each particle's kind, free centres {@code c_k}, amplitudes {@code a_k}, radial scales
 * {@code s_k} and local background {@code B} (Levenberg-Marquardt; a member of a large group fitted in turn holds it
 * at the profile's: {@link Budget}); {@code F} is the faint light of particles of other groups (all farther than
 * {@code 2 r_out}), held at their current estimates: only its tail reaches the group, where a centre error of
 * a few hundredths of a pixel changes nothing that matters. All the light of every particle is used, which is what the
 * Cramer-Rao bound assumes. Unreliable particles (suspected merges, degenerate) are left as they are and are
 * not modelled.
 * <p>
 * This class holds the groups and the iterations of a fit; a group's pixels are {@link FitPixels}, the passes over
 * them {@link NormalEquations}, and a group too large to fit jointly is fitted member by member by
 * {@link MemberSweeps}, each member's fit one of this class's.
 */
public final class GroupFit {

	static final int MAX_ITERATIONS = 50;
	/**
	 * Groups of up to this many particles are fitted jointly; larger ones member by member ({@link MemberSweeps}). A
	 * compact cluster at contact couples every member to its neighbours so strongly (each image reaching over theirs)
	 * that member by member its centres creep towards the joint solution by a little each sweep; a joint fit solves
	 * the coupling at once, at a cost that grows with the cube of its 4 parameters per member. So clusters of a few
	 * tens are fitted jointly, and a dense field's one large group (a hundred members or more) member by member,
	 * whose cost is linear. The figures: accuracy.md ({@code hex19}, {@code hex37}).
	 */
	static final int MAX_JOINT = 24;
	/**
	 * The floor of the move (px) below which a fit has converged (a tenth of the centres' own errors where that is
	 * larger: {@link #settled}); the step is taken, unevaluated. The
	 * iterations converge at least tenfold per step near the solution (on the bench stack: steps of about 5e-2,
	 * 1e-4, 1e-7 px), so the centres end within about 1e-4 px of the exact least-squares point: a hundredth of a
	 * nanometre at usual pixel sizes, two orders below the Cramer-Rao bound. A tighter tolerance costs a pass over
	 * every pixel per group for nothing measurable.
	 */
	static final double TOLERANCE = 1e-3;
	/**
	 * A chord step (from the J^T J of an earlier point) is evaluated as it is, by the residuals alone, while it is at
	 * most this fraction of the step before it: the iterations still converge fast, and J^T J is not recomputed.
	 */
	static final double CHORD_CONTRACTION = 0.5;

	private GroupFit() {}

	/**
	 * Refines the centres of the reliable particles, starting from {@code start}, group by group. Groups are
	 * independent work: each is fitted with the other groups' light held at their estimates in {@code start}, so the
	 * groups of one frame are spread over the caller's threads ({@link Parallelization#getTaskExecutor()}, the
	 * imglib2 idiom) and the result does not depend on their number or order.
	 *
	 * @param profile each particle's profile (its kind's), same order as the particles
	 * @return the new estimates, each with the iterations of its group's fit or, fitted member by member, its own over
	 *         the sweeps (the others unchanged; the members of a
	 *         group that could not be fitted, too few pixels left or a singular system, keep theirs flagged
	 *         {@code FELL_BACK}) and the largest number of iterations a group needed, negative if a group hit the limit
	 */
	static ProfileRefinement.Refined refine(final Plane plane, final Particle[] particles, final Estimate[] start,
		final EmpiricalProfile[] profile, final double groupDistance, final double window, final Censoring censoring)
	{
		final List<int[]> groups = groups(particles, start, groupDistance);
		final Function<int[], Fitted> fit = group -> {
			// this group's own copy of the estimates: its members move in it, every other particle stays at its start
			final Estimate[] own = start.clone();
			final int it = group.length <= MAX_JOINT ? fitJointly(plane, particles, own, group, profile, window,
				censoring) : MemberSweeps.fitInTurn(plane, particles, own, group, profile, window, censoring,
				MemberSweeps.MAX_SWEEPS);
			final Estimate[] members = new Estimate[group.length];
			for (int q = 0; q < group.length; q++)
				members[q] = own[group[q]];
			return new Fitted(members, it);
		};
		final List<Fitted> fitted;
		if (groups.size() > 1) fitted = Parallelization.getTaskExecutor().forEachApply(groups, fit);
		else {
			fitted = new ArrayList<>(groups.size());
			for (final int[] group : groups)
				fitted.add(fit.apply(group));
		}
		final Estimate[] e = start.clone();
		int worst = 0;
		for (int g = 0; g < groups.size(); g++) {
			final int[] group = groups.get(g);
			final Fitted f = fitted.get(g);
			final int it = f.iterations();
			for (int q = 0; q < group.length; q++) // (a group fitted member by member: each member's own, see MemberSweeps)
				e[group[q]] = group.length <= MAX_JOINT ? f.members()[q].withIterations(Math.abs(it)) : f.members()[q];
			if (it < 0) worst = Math.min(worst, it);
			else if (worst >= 0) worst = Math.max(worst, it);
		}
		return new ProfileRefinement.Refined(e, worst);
	}

	/** A group's fitted members (in the group's order) and the iterations its fit took ({@link #refine}). */
	private record Fitted(Estimate[] members, int iterations) {}

	/**
	 * One joint fit of the group; its members keep their estimates flagged {@code FELL_BACK} if it cannot be made, and
	 * are flagged {@code NOT_CONVERGED} if it reaches {@value #MAX_ITERATIONS} iterations; a member whose fit is
	 * {@link #absurd} keeps its start, flagged {@code FELL_BACK}.
	 */
	private static int fitJointly(final Plane plane, final Particle[] particles, final Estimate[] e, final int[] group,
		final EmpiricalProfile[] profile, final double window, final Censoring censoring)
	{
		final Estimate[] start = new Estimate[group.length];
		for (int q = 0; q < group.length; q++)
			start[q] = e[group[q]];
		final int it = fitGroup(plane, particles, e, group, profile, window, censoring, JOINT, null,
			new NormalEquations(censoring));
		// flagged here, per group: a group that hit the limit says nothing of the frame's other groups
		final int flag = it == 0 ? Flag.FELL_BACK.bit() : it < 0 ? Flag.NOT_CONVERGED.bit() : 0;
		for (int q = 0; q < group.length; q++) {
			final int k = group[q];
			if (flag != 0) e[k] = e[k].withFlags(e[k].flags() | flag);
			else if (absurd(e[k])) e[k] = start[q].withFlags(e[k].flags() | Flag.FELL_BACK.bit());
		}
		return it;
	}

	/**
	 * @return whether a jointly fitted member is no particle of its kind: an amplitude not above zero, or a radial
	 *         scale pressed against a limit of its range. (A member cut by the frame's edge may rightly end far from
	 *         its start, the first pass's centre of the part in view, so the slide that marks a failed member fitted
	 *         in turn does not serve here.)
	 */
	private static boolean absurd(final Estimate fitted) {
		final double scale = fitted.scale();
		return !(fitted.amplitude() > 0) || !(scale > MIN_SCALE * 1.001 && scale < MAX_SCALE * 0.999);
	}

	/**
	 * @return the move (px) below which a centre counts as settled: {@link #TOLERANCE}, or a tenth of its standard
	 *         error where that is larger. On real footage the imperfect model leaves the iterations circling within a
	 *         few thousandths of a pixel (pixels enter and leave a window, a censoring choice flips), far below the
	 *         centres' errors (hundredths to tenths of a pixel); a tenth of the error changes nothing measurable.
	 */
	public static double settled(final double sigmaX, final double sigmaY) {
		final double s = Math.max(sigmaX, sigmaY);
		return Double.isFinite(s) ? Math.max(TOLERANCE, SETTLED_SIGMA * s) : TOLERANCE;
	}

	/** The fraction of a centre's standard error below which a move counts as settled. */
	static final double SETTLED_SIGMA = 0.1;

	/** Groups of reliable particles closer than {@code distance} (transitively), at centres {@code e}. */
	static List<int[]> groups(final Particle[] ps, final Estimate[] e, final double distance) {
		final int n = ps.length;
		final int[] parent = UnionFind.singletons(n);
		for (int i = 0; i < n; i++)
			for (int j = i + 1; j < n; j++)
				if (ps[i].reliable() && ps[j].reliable() && e[i].closerThan(e[j], distance))
					UnionFind.union(parent, i, j);
		final List<int[]> groups = new ArrayList<>();
		for (int r = 0; r < n; r++) {
			if (UnionFind.find(parent, r) != r || !ps[r].reliable()) continue;
			int size = 0;
			for (int i = 0; i < n; i++)
				if (UnionFind.find(parent, i) == r) size++;
			final int[] g = new int[size];
			int f = 0;
			for (int i = 0; i < n; i++)
				if (UnionFind.find(parent, i) == r) g[f++] = i;
			groups.add(g);
		}
		return groups;
	}

	static boolean contains(final int[] group, final int k) {
		for (final int g : group)
			if (g == k) return true;
		return false;
	}


	/** Parameters per particle: x, y, amplitude, radial scale. */
	static final int PER_PARTICLE = 4;
	/** Background terms per group: B, bx, by (a plane). */
	static final int BACKGROUND = 3;
	/** Radial scales outside this range are not accepted as steps (a particle of another kind entirely). */
	static final double MIN_SCALE = 0.5, MAX_SCALE = 2;

	static double amplitudeOf(final Estimate e) {
		return Double.isFinite(e.amplitude()) ? e.amplitude() : 1;
	}

	static double scaleOf(final Estimate e) {
		return e.scale() > 0 ? e.scale() : 1;
	}

	/**
	 * Fits one group, replacing its members' estimates in {@code e} on success; returns the iterations (0: not
	 * fitted, where a member that {@link #VANISHED vanished} gets the amplitude it was fitted, its start otherwise
	 * kept). The pixels fitted lie within {@code window} (px, times each member's scale) of a member: out to
	 * {@code r_out}, where a particle's image has returned to the background, not to the profile's full reach
	 * (1.5 {@code r_out}), whose faint tail carries almost no information on the centre but more than doubles the
	 * pixels. The model itself
	 * keeps the full reach: every member's and neighbour's tail is in the light of the pixels fitted. Where the
	 * pixel type clips, the pixels used are those the {@code censoring} rule keeps at the model's current
	 * parameters: chosen again when the fit has settled, and the fit continued, until the choice stays put.
	 */
	static int fitGroup(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile[] profile, final double window, final Censoring censoring, final Budget budget,
		final Kept kept, final NormalEquations passes)
	{
		final int n = group.length, np = PER_PARTICLE * n + BACKGROUND;
		final FitPixels candidates;
		final Nearby nearby = kept == null ? null : kept.nearby;
		if (kept != null && kept.candidates != null) candidates = kept.candidates.relit(ps, e, group, profile,
			kept.lit, nearby, kept.rows());
		else {
			candidates = FitPixels.gather(plane, ps, e, group, profile, window, censoring, nearby);
			if (kept != null) kept.lit = candidates.litAt(ps, e, group, profile, nearby);
		}
		if (kept != null) kept.candidates = candidates;
		if (candidates.count() <= np) return 0;
		final EmpiricalProfile[] members = new EmpiricalProfile[n];
		for (int q = 0; q < n; q++)
			members[q] = profile[group[q]];
		final double[] p = new double[np];
		for (int q = 0; q < n; q++) {
			final Estimate s = e[group[q]];
			p[PER_PARTICLE * q] = s.x();
			p[PER_PARTICLE * q + 1] = s.y();
			p[PER_PARTICLE * q + 2] = amplitudeOf(s);
			p[PER_PARTICLE * q + 3] = scaleOf(s);
		}
		p[np - BACKGROUND] = members[0].background(); // (every kind's profile has the same background)
		// held at the profile's: a background clipped at the floor (no pixel the fit may use shows it), and a member
		// fitted in turn (see Budget#heldBackground)
		final boolean heldBackground = budget.heldBackground() || censoring.backgroundClipped();
		final boolean frozen = kept != null && kept.use != null;
		final boolean[] use = frozen ? kept.use : censoring.active() ? new boolean[candidates.count()] : null;
		if (kept != null) kept.use = use;
		final double[][] jtj = new double[np][np];
		final double[] jtr = new double[np];
		// A later sweep: the member's J^T J from its previous fit, on these very pixels, serves its first step. Its
		// neighbours' light, which moved, is a constant of its model and leaves J alone; its own parameters moved
		// little since (the background plane, linear, enters J^T J not at all). The step is then a chord step, from
		// a residual pass instead of a J^T J pass: the last sweeps refit most members for a step below their tolerance.
		final double[][] previous = kept != null && (frozen || use == null) ? kept.jtj : null;
		if (kept != null) kept.jtj = null;
		// per member, the residuals' variance where its centre's information lies (see accumulate): every pass at p
		// sums it, so that the standard errors always come from it, whichever pass the fit ends on
		final double[] startNoise = new double[PER_PARTICLE * n];
		final Start start = firstPass(candidates, use, frozen, previous, kept, passes, p, n, members, jtj, jtr, startNoise,
			censoring, heldBackground);
		final Evaluated initial = start.initial();
		double rss = start.rss();
		FitPixels pixels = start.pixels();
		if (pixels.count() <= np) return 0;
		if (heldBackground) hold(jtj, jtr, np);
		final double tolerance = Double.isNaN(budget.tolerance()) ? ownTolerance(jtj, rss, pixels.count(), n) : budget
			.tolerance();
		int selections = frozen ? budget.selections() : 1;
		// The members whose moves decide that the fit has settled: not one whose active area the frame's edge cuts
		// (unless all are), which with most of it outside may never settle: what is left of its image constrains its
		// centre too little, so it can slide out of the frame and hold its whole group for all its iterations.
		final boolean[] holds = new boolean[n];
		boolean anyInside = false;
		for (int q = 0; q < n; q++)
			anyInside |= holds[q] = !ps[group[q]].atBorder();
		if (!anyInside) java.util.Arrays.fill(holds, true);
		double mu = 1e-3;
		int it = 1;
		boolean converged = false;
		// Whether J^T J was computed at p. A step is evaluated by the residuals alone (a third of the cost of J^T J);
		// once accepted, the next step comes from the previous J^T J with the new J^T r (a chord step): near the
		// solution J^T J hardly changes, so that step is as good, and when it is below the tolerance the fit has
		// settled. A chord step at most CHORD_CONTRACTION of the one before is evaluated as it is (the iteration is
		// contracting, so J^T J is still close); a longer one, or one that fails, has J^T J computed at p first.
		boolean hessianAtP = previous == null;
		// the residuals' variances of the latest pass at p; the model on the pixels at the latest pass's point, for the
		// re-choice of the pixels (where they are chosen)
		final boolean choosing = use != null && !frozen;
		final Latest latest = new Latest(startNoise, choosing ? candidates.count() : -1, initial, np);
		// the latest accepted step's largest centre move (px), and the steps accepted since J^T J was computed
		double lastMove = Double.POSITIVE_INFINITY;
		int sinceHessian = previous == null ? 0 : 1;
		// the iterations' work arrays, allocated once per fit: the damped system's factor and its step, the trial point
		// and its J^T r
		final double[] factor = new double[np * np], work = new double[np], step = new double[np];
		final double[] trial = new double[np], tr = new double[np];
		for (; it <= budget.iterations(); it++) {
			if (heldBackground) hold(jtj, jtr, np);
			if (!SymmetricSolver.factor(jtj, mu, np, factor)) break;
			SymmetricSolver.solveFactored(factor, np, jtr, work, step);
			boolean allowed = true;
			for (int i = 0; i < np; i++)
				trial[i] = p[i] + step[i];
			for (int q = 0; q < n; q++) {
				final double sc = trial[PER_PARTICLE * q + 3];
				if (!(sc >= MIN_SCALE && sc <= MAX_SCALE)) allowed = false;
			}
			double move = 0;
			for (int q = 0; q < n; q++)
				if (holds[q]) move = Math.max(move, Math.hypot(step[PER_PARTICLE * q], step[PER_PARTICLE * q + 1]));
			if (allowed && move < tolerance) {
				// Settled: the step is taken without evaluating the model there (a pass over every pixel, a third of
				// the fit's time); J^T J and the residuals at p serve the uncertainties as well. Where the pixel type
				// clips, the pixels are chosen again at the settled model, and if the choice changed the fit goes on.
				System.arraycopy(trial, 0, p, 0, np);
				// chosen at the point of the latest residual pass, whose model is known on the pixels in use (the
				// settled point is within the tolerance of it)
				final Evaluated evaluated = latest.evaluated;
				if (use != null && selections < budget.selections() && (evaluated == null ? FitPixels.select(candidates, p, n,
					members, censoring, use, null, null) : FitPixels.select(candidates, evaluated.p(), n, members, censoring,
						use, evaluated.pixels(), evaluated.models()))) {
					selections++;
					final FitPixels chosen = heldBackground ? candidates.subsetToPass(use) : candidates.subset(use);
					if (chosen.count() <= np) break;
					pixels = chosen;
					rss = passes.accumulate(pixels, p, n, members, jtj, jtr, latest.clearedNoise(), latest.models);
					latest.take(pixels, p);
					hessianAtP = true;
					sinceHessian = 0;
					mu = 1e-3;
					continue;
				}
				converged = true;
				// the uncertainties want J^T J near the solution: after a run of chord steps it is that of a point
				// several steps back, so it is computed once more here (with the residuals' variances)
				if (sinceHessian > 1) {
					rss = passes.accumulate(pixels, p, n, members, jtj, jtr, latest.clearedNoise(), null);
					latest.takeNoise();
				}
				break;
			}
			// a step from J^T J at p, or a chord step that shrinks fast, is evaluated
			if (hessianAtP || allowed && move <= CHORD_CONTRACTION * lastMove) {
				double trialRss = Double.POSITIVE_INFINITY;
				if (allowed) {
					trialRss = passes.accumulate(pixels, trial, n, members, null, tr, latest.clearedNoise(),
						latest.models);
				}
				if (trialRss <= rss) {
					final double gain = (rss - trialRss) / predictedDrop(jtj, jtr, step, np);
					System.arraycopy(trial, 0, p, 0, np);
					System.arraycopy(tr, 0, jtr, 0, np);
					hessianAtP = false;
					latest.take(pixels, trial);
					rss = trialRss;
					// a step that lowered the residuals as the linear model foretold: less damping; one that lowered them
					// by far less (the model bends within the step: the profile's table, a faint particle's shallow
					// minimum), more, else the steps cross the valley from side to side for every iteration they have
					mu = gain < POOR_GAIN ? mu * 10 : Math.max(mu / 10, 1e-9);
					lastMove = move;
					sinceHessian++;
					continue;
				}
			}
			if (!hessianAtP) { // a chord step that does not shrink fast, or that failed: J^T J at p, and the step again
				rss = passes.accumulate(pixels, p, n, members, jtj, jtr, latest.clearedNoise(), latest.models);
				latest.take(pixels, p);
				hessianAtP = true;
				sinceHessian = 0;
			}
			else mu *= 10;
		}
		return store(e, group, p, jtj, jtr, heldBackground, kept, pixels, members, rss, latest.noise, converged ? it
			: -it);
	}

	/** Where a fit starts: its pixels, the residual sum of squares at its start and the model there (where chosen). */
	private record Start(FitPixels pixels, double rss, Evaluated initial) {}

	/**
	 * A fit's first pass at its start {@code p}: J^T J (or a later sweep's, kept), J^T r and the residuals' variances
	 * into {@code jtj}, {@code jtr} and {@code startNoise}; where the pixel type clips, the pixels chosen from the
	 * model it computes ({@code use}, {@code kept}). With the background {@code held}, its rows and columns of J^T J are
	 * not made here (the caller holds them).
	 */
	private static Start firstPass(final FitPixels candidates, final boolean[] use, final boolean frozen,
		final double[][] previous, final Kept kept, final NormalEquations passes, final double[] p, final int n,
		final EmpiricalProfile[] members, final double[][] jtj, final double[] jtr, final double[] startNoise,
		final Censoring censoring, final boolean held)
	{
		final int np = p.length;
		Evaluated initial = null;
		double rss;
		FitPixels pixels = candidates;
		if (frozen) {
			pixels = candidates.subset(use);
			if (pixels != candidates) { // kept from now on: only the pixels chosen are lit again and passed over
				kept.candidates = pixels = pixels.asCandidates();
				kept.use = new boolean[pixels.count()];
				java.util.Arrays.fill(kept.use, true);
			}
		}
		if (previous != null) {
			for (int a = 0; a < np; a++)
				System.arraycopy(previous[a], 0, jtj[a], 0, np);
			rss = passes.accumulate(pixels, p, n, members, null, jtr, startNoise, null);
		}
		else if (frozen) rss = passes.accumulate(pixels, p, n, members, jtj, jtr, startNoise, null);
		else if (use == null || FitPixels.allUsable(candidates, p, n, members, censoring, use))
			rss = passes.accumulate(candidates, p, n, members, jtj, jtr, startNoise, null);
		else {
			// The first pass over every candidate chooses the pixels from the model it computes, and the pixels left
			// out are then taken out of its sums (a pass over them alone): one pass, not a choice and a pass.
			final double[] models = new double[candidates.count()];
			rss = passes.accumulate(candidates, p, n, members, jtj, jtr, startNoise, models);
			initial = new Evaluated(candidates, p.clone(), models);
			final boolean[] out = new boolean[use.length];
			for (int i = 0; i < use.length; i++) {
				use[i] = censoring.usable(models[i]);
				out[i] = !use[i];
			}
			pixels = held ? candidates.subsetToPass(use) : candidates.subset(use);
			if (pixels != candidates) {
				final double[][] outJtj = new double[np][np];
				final double[] outJtr = new double[np], outNoise = new double[startNoise.length];
				rss -= passes.accumulate(held ? candidates.subsetToPass(out) : candidates.subset(out), p, n, members, outJtj,
					outJtr, outNoise, null);
				for (int i = 0; i < startNoise.length; i++)
					startNoise[i] -= outNoise[i];
				for (int a = 0; a < np; a++) {
					jtr[a] -= outJtr[a];
					for (int b = 0; b < np; b++)
						jtj[a][b] -= outJtj[a][b];
				}
			}
		}
		return new Start(pixels, rss, initial);
	}

	/**
	 * The end of a fit at {@code p}: J^T J inverted for the centres' standard errors (from each member's residuals'
	 * {@code noise}, see {@link NormalEquations#accumulate}) and the members' estimates replaced in {@code e}; returns
	 * {@code iterations}. A singular J^T J replaces none (a member that {@link #VANISHED vanished} gets the amplitude it
	 * was fitted) and returns 0.
	 */
	private static int store(final Estimate[] e, final int[] group, final double[] p, final double[][] jtj,
		final double[] jtr, final boolean heldBackground, final Kept kept, final FitPixels fitted,
		final EmpiricalProfile[] members, final double rss, final double[] noise, final int iterations)
	{
		final int pixels = fitted.count();
		final int n = group.length, np = p.length;
		if (heldBackground) hold(jtj, jtr, np);
		final double[][] inv = SymmetricSolver.invert(jtj);
		if (inv == null) {
			// a member whose light the fit took to nothing leaves J^T J singular: said, so that it can be left out
			final boolean[] gone = vanished(p, n);
			for (int q = 0; q < n && gone != null; q++)
				if (gone[q]) e[group[q]] = e[group[q]].withAmplitude(Math.min(0, p[PER_PARTICLE * q + 2]));
			return 0;
		}
		if (kept != null) kept.jtj = jtj;
		final double dof = pixels / (double) (pixels - np), s2 = rss / (pixels - np);
		// the errors to report: the residuals' variance corrected for what the fit took up of the noise (the fit's own
		// errors, below, stay the scale its iterations and rounds settle by)
		final double[] leverage = Leverage.factors(fitted.packed(), pixels, p, n, members, inv, heldBackground, dof);
		for (int q = 0; q < n; q++) {
			final Estimate old = e[group[q]];
			final int b = PER_PARTICLE * q;
			final double vx = noise[b] > 0 ? dof * noise[b + 1] / noise[b] : s2;
			final double vy = noise[b + 2] > 0 ? dof * noise[b + 3] / noise[b + 2] : s2;
			final double sx = Math.sqrt(vx * inv[b][b]), sy = Math.sqrt(vy * inv[b + 1][b + 1]);
			final double fx = leverage[2 * q], fy = leverage[2 * q + 1];
			e[group[q]] = new Estimate(p[b], p[b + 1], old.flags(), old.secondArea(), old.iterations(), old.solve(), sx,
				sy, p[b + 2], p[b + 3], fx > 1 ? sx * fx : Double.NaN, fy > 1 ? sy * fy : Double.NaN);
		}
		return iterations;
	}

	/**
	 * A member of a joint fit whose amplitude ends below this (a hundredth of its profile's particle) while the fit's
	 * J^T J is singular has vanished: the fit put no light there, and its centre and scale, which then shape nothing,
	 * drift (a third seed between two particles of a pair at 0.885 diameters ended 50 to 100 px away, the pair's two
	 * members each within 0.03 px of its particle). The group is not fitted ({@code FELL_BACK}, every member at its
	 * start), but a vanished member's start carries the amplitude it was fitted (0 or below): the detection by the
	 * image leaves it out, and the others are fitted again without it.
	 */
	static final double VANISHED = 0.01;

	/**
	 * @return per member whether it {@link #VANISHED vanished} (amplitude below {@value #VANISHED}), or null where none
	 *         or every one did
	 */
	private static boolean[] vanished(final double[] p, final int n) {
		final boolean[] gone = new boolean[n];
		int count = 0;
		for (int q = 0; q < n; q++)
			if (gone[q] = !(p[PER_PARTICLE * q + 2] > VANISHED)) count++;
		return count > 0 && count < n ? gone : null;
	}

	/**
	 * An accepted step that lowered the residual sum of squares by less than this fraction of what the linearised
	 * model foretold raises the damping (tenfold), as one that failed does.
	 */
	static final double POOR_GAIN = 0.25;

	/**
	 * @return the drop of the residual sum of squares the linearised model foretells for {@code step}:
	 *         {@code 2 step . J^T r - step . J^T J step} (positive for a step of the damped system)
	 */
	private static double predictedDrop(final double[][] jtj, final double[] jtr, final double[] step, final int np) {
		double drop = 0;
		for (int a = 0; a < np; a++) {
			double h = 0;
			for (int b = 0; b < np; b++)
				h += jtj[a][b] * step[b];
			drop += step[a] * (2 * jtr[a] - h);
		}
		return drop;
	}

	/**
	 * Holds the background terms (the last {@value #BACKGROUND} parameters) where they are: their rows and columns of
	 * {@code J^T J} those of the identity, their {@code J^T r} zero, so that a step leaves them and their variance is
	 * no part of the others'.
	 */
	private static void hold(final double[][] jtj, final double[] jtr, final int np) {
		for (int b = np - BACKGROUND; b < np; b++) {
			for (int a = 0; a < np; a++)
				jtj[a][b] = jtj[b][a] = 0;
			jtj[b][b] = 1;
			jtr[b] = 0;
		}
	}

	/** @return the move below which the centres of a fit whose first J^T J and residuals are these have settled */
	private static double ownTolerance(final double[][] jtj, final double rss, final int pixels, final int n) {
		final int np = PER_PARTICLE * n + BACKGROUND;
		final double[][] inv = SymmetricSolver.invert(jtj);
		if (inv == null) return TOLERANCE;
		final double s2 = rss / (pixels - np);
		double tolerance = Double.POSITIVE_INFINITY;
		for (int q = 0; q < n; q++) {
			final int b = PER_PARTICLE * q;
			tolerance = Math.min(tolerance, settled(Math.sqrt(s2 * inv[b][b]), Math.sqrt(s2 * inv[b + 1][b + 1])));
		}
		return tolerance;
	}

	/**
	 * The latest pass at the fit's point: the residuals' variances and, where the fit chooses its pixels, the model on
	 * them. Each in two arrays, this pass's and the one the next pass writes into ({@link #clearedNoise}, {@link
	 * #models}), swapped when that pass's point is taken ({@link #take}): the iterations allocate nothing.
	 */
	private static final class Latest {
		/** the residuals' variances of the latest pass taken */
		double[] noise;
		/** the latest pass's point, the pixels and the model on them (null: not known, or not needed) */
		Evaluated evaluated;
		/** where the next pass writes the model (null: the model is not needed) */
		double[] models;
		private double[] spareNoise;
		private final double[] at;

		/** @param capacity the most pixels a pass may cover, negative where the model is not needed */
		Latest(final double[] noise, final int capacity, final Evaluated initial, final int parameters) {
			this.noise = noise;
			spareNoise = new double[noise.length];
			evaluated = capacity < 0 ? null : initial;
			models = capacity < 0 ? null : new double[capacity];
			at = new double[parameters];
		}

		/** @return the array the next pass sums the residuals' variances into, zeroed */
		double[] clearedNoise() {
			java.util.Arrays.fill(spareNoise, 0);
			return spareNoise;
		}

		/** The variances of the pass just made are the latest (the model, if any, stays that of the one before). */
		void takeNoise() {
			final double[] taken = spareNoise;
			spareNoise = noise;
			noise = taken;
		}

		/** The pass just made, on {@code pixels} at {@code p}, is the latest. */
		void take(final FitPixels pixels, final double[] p) {
			takeNoise();
			if (models == null) return;
			final double[] freed = evaluated != null && evaluated.models() != null && evaluated.models().length >= models
				.length ? evaluated.models() : new double[models.length];
			System.arraycopy(p, 0, at, 0, at.length);
			evaluated = new Evaluated(pixels, at, models);
			models = freed;
		}
	}

	/**
	 * A member's pixels kept from one sweep to the next: its candidates (their positions and values; the neighbours'
	 * light is computed afresh) and, where the pixel type clips, the choice of them its first fit ended with. Chosen
	 * afresh every sweep, a few pixels at the margin of the clip levels would flip in and out as the neighbours move,
	 * each flip a small jump of the least squares, and the sweeps would circle instead of settling.
	 */
	static final class Kept {
		FitPixels candidates;
		boolean[] use;
		/** the estimates the candidates' light of other particles was drawn at ({@link FitPixels#relit}) */
		FitPixels.Lit lit;
		/** the frame's particles by their current centres, kept current by the sweeps (null: every one scanned) */
		Nearby nearby;
		/** J^T J of the member's latest fit, on the kept pixels (null: none) */
		double[][] jtj;
		/** the candidates' rows, and the candidates' x they were found from (the same pixels while that is) */
		private RowRuns rows;
		private int[] rowsOf;

		/** @return the kept candidates' {@link RowRuns}, found once for each choice of them */
		RowRuns rows() {
			if (rowsOf != candidates.x()) {
				rows = RowRuns.of(candidates.x(), candidates.y(), candidates.count());
				rowsOf = candidates.x();
			}
			return rows;
		}
	}

	/** The model on a fit's pixels at parameters {@code p}, as a pass over them computed it. */
	private record Evaluated(FitPixels pixels, double[] p, double[] models) {}

	/** The usable pixels are chosen at most this many times per fit (one pixel could flip back and forth). */
	static final int MAX_SELECTIONS = 5;

	/**
	 * What a fit may spend: iterations, the step (px) below which it has converged ({@link #OWN_ERROR}: a tenth of
	 * the centres' own errors), and how many times it may choose its pixels where the pixel type clips; and whether
	 * its background is held at the profile's instead of fitted as a local plane. A joint fit's window reaches past
	 * its group into the background around it, which determines the plane. A member fitted in turn in a dense field
	 * sees little but its own and its neighbours' light: there a local plane is not determined apart from the
	 * member's amplitude, scale and centre (a tilt of the plane under a particle shifts its fitted centre), and held
	 * free it biased the centres of a packed monolayer of blurred discs 3 times beyond their error (fitted with the
	 * exact profile, the median error 0.08 px against 0.026 px held).
	 */
	record Budget(int iterations, double tolerance, int selections, boolean heldBackground) {}

	/**
	 * A budget's tolerance that stands for {@link #settled a tenth of the fitted centres' own standard errors}, as
	 * the first J^T J and residuals give them (one noise variance for all pixels).
	 */
	static final double OWN_ERROR = Double.NaN;

	/**
	 * A joint fit's budget: settled where no centre moves by more than a tenth of its own error, and never below
	 * {@link #TOLERANCE} ({@link #OWN_ERROR}). A bright particle's error is a hundredth of a pixel or less, so its fit
	 * settles at {@link #TOLERANCE}; a faint one's is a few tenths, and a thousandth of a pixel asks of its shallow
	 * least squares more than the noise lets it give within the iterations. A member fitted in turn gets
	 * {@value MemberSweeps#ITERATIONS_PER_SWEEP} iterations a sweep (the sweeps are its outer iterations), in the
	 * first sweep the tolerance of its own error ({@link #OWN_ERROR}) and up to {@value #MAX_SELECTIONS} choices of
	 * pixels, which it then keeps ({@link Kept}); in the later sweeps the tolerance of its latest error
	 * ({@link #settled}).
	 */
	static final Budget JOINT = new Budget(MAX_ITERATIONS, OWN_ERROR, MAX_SELECTIONS, false);
}
