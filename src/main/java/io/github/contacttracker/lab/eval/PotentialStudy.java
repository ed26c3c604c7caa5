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
package io.github.contacttracker.lab.eval;

import java.util.List;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.potential.FieldOfView;
import io.github.contacttracker.potential.PairCorrelation;
import io.github.contacttracker.potential.SpotSet;
import io.github.contacttracker.lab.sim.FluidMovie;
import io.github.contacttracker.lab.sim.HardCoreAttraction;
import io.github.contacttracker.lab.sim.PairInteraction;
import io.github.contacttracker.lab.sim.ParticleType;

/**
 * The pair potential measured end to end: a simulated fluid with a known U(r) ({@link FluidMovie}), tracked,
 * analysed as a user would ({@link PairCorrelation}: flagged spots left out, field of view inferred, U set to 0
 * where the true potential is 0), and compared with the truth. Distances in particle diameters.
 *
 * @param type the particles
 * @param interaction the true potential (px)
 * @param particles particles in the frame
 * @param size frame width and height (px)
 * @param frames frames
 * @param sweepsBetween Monte Carlo sweeps between frames
 * @param seed the seed
 * @param bin bin width (diameters)
 * @param rMax largest distance (diameters)
 * @param zeroFrom U is set to 0 over [zeroFrom, rMax] (diameters)
 */
public record PotentialStudy(ParticleType type, PairInteraction interaction, int particles, int size, int frames,
	int sweepsBetween, long seed, double bin, double rMax, double zeroFrom)
{

	/**
	 * The demo's fluid: hard spheres with a 2 kT attraction decaying over 0.1 D, 10 particles in a 512 x 512 frame
	 * (area fraction 0.09 for the 2.06 um-like, 0.13 for the 5.53 um-like particles), 20 sweeps between frames;
	 * bins of 0.025 D up to 3 D, U = 0 over [2 D, 3 D] (the attraction is below 1e-4 kT there).
	 *
	 * @param type the particles
	 * @param frames frames
	 * @return the study
	 */
	public static PotentialStudy demo(final ParticleType type, final int frames) {
		final double d = type.diameterPx();
		return new PotentialStudy(type, new HardCoreAttraction(d, 2, 0.1 * d), 10, 512, frames, 20, 14, 0.025, 3, 2);
	}

	/** @return the movie */
	public FluidMovie simulate() {
		return FluidMovie.simulate(type, interaction, particles, size, size, frames, sweepsBetween, seed);
	}

	/** @return the spots of every frame, tracked with {@code method} and the type's threshold and r_out */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public List<Localization> track(final FluidMovie movie, final Method method, final int threads) {
		final StackTracker tracker = new StackTracker(TrackerParameters.of(type.threshold(), type.rOut()).withMethod(
			method));
		final List<FrameResult> r = StackTracker.withThreads(threads, () -> tracker.track((List) movie.frames(),
			false));
		return StackTracker.spots(r);
	}

	/** @return U(r) from tracked spots, flagged ones left out, field inferred, in diameters */
	public PairCorrelation.Result measure(final List<Localization> spots) {
		final SpotSet set = SpotSet.ofLocalizations(spots, SpotSet.Selection.DEFAULT, false, 1 / type.diameterPx());
		return analyse(set, FieldOfView.inferred(set.allX(), set.allY()));
	}

	/** @return U(r) from the true centres, with the frame as the field of view, in diameters */
	public PairCorrelation.Result measureTruth(final FluidMovie movie) {
		final double d = type.diameterPx();
		return analyse(SpotSet.ofPositions(movie.truth(), 1 / d), FieldOfView.of(size / d, size / d));
	}

	/**
	 * @return U(r) from the true centres of the particles whose spots {@link #measure} keeps (each kept spot's nearest
	 *         true centre in its frame), in the field inferred from those spots: the same configurations and field as
	 *         the tracked U, so that the two differ by the tracking errors alone
	 */
	public PairCorrelation.Result measureTruthOf(final FluidMovie movie, final List<Localization> spots) {
		final List<List<double[]>> kept = new java.util.ArrayList<>();
		for (int t = 0; t < movie.truth().size(); t++)
			kept.add(new java.util.ArrayList<>());
		for (final Localization l : spots) {
			if (l.isFlagged()) continue;
			double[] nearest = null;
			double best = Double.POSITIVE_INFINITY;
			for (final double[] c : movie.truth().get(l.frame())) {
				final double d = Math.hypot(c[0] - l.x(), c[1] - l.y());
				if (d < best) {
					best = d;
					nearest = c;
				}
			}
			if (nearest != null) kept.get(l.frame()).add(nearest);
		}
		final SpotSet tracked = SpotSet.ofLocalizations(spots, SpotSet.Selection.DEFAULT, false, 1 / type.diameterPx());
		return analyse(SpotSet.ofPositions(kept, 1 / type.diameterPx()), FieldOfView.inferred(tracked.allX(), tracked
			.allY()));
	}

	private PairCorrelation.Result analyse(final SpotSet set, final FieldOfView field) {
		return PairCorrelation.compute(set, field, bin, rMax).withZero(zeroFrom, rMax);
	}

	/** @return the true U(r)/kT at {@code r} diameters */
	public double trueU(final double rOverD) {
		return interaction.energyKt(rOverD * type.diameterPx());
	}

	/**
	 * How a measured U(r) compares with the truth over the bins with centres in [from, to] where the truth is
	 * finite and the bin is not empty.
	 *
	 * @param bins bins compared
	 * @param chi2PerBin mean of {@code ((U - U_true) / U_err)^2}: about 1 when U is right within its error bars
	 * @param maxAbsZ largest {@code |U - U_true| / U_err}
	 * @param pairsInsideCore pairs counted in bins entirely below contact (the truth has none)
	 */
	public record Comparison(int bins, double chi2PerBin, double maxAbsZ, long pairsInsideCore) {}

	/** @return the comparison of {@code r} with the truth over bin centres in [from, to] (diameters) */
	public Comparison compare(final PairCorrelation.Result r, final double from, final double to) {
		int n = 0;
		double chi2 = 0, maxZ = 0;
		long inside = 0;
		for (int i = 0; i < r.bins().size(); i++) {
			final PairCorrelation.Bin b = r.bins().get(i);
			if (b.rHigh() <= 1) inside += b.pairs();
			final double truth = trueU(b.r());
			if (b.r() < from || b.r() > to || !Double.isFinite(truth) || b.pairs() == 0 || b.rLow() < 1) continue;
			final double z = (r.u(i) - truth) / b.uError();
			chi2 += z * z;
			maxZ = Math.max(maxZ, Math.abs(z));
			n++;
		}
		return new Comparison(n, n > 0 ? chi2 / n : Double.NaN, maxZ, inside);
	}
}
