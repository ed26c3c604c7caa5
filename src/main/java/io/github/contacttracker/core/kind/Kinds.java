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
package io.github.contacttracker.core.kind;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.math.Statistics;

/**
 * The kinds of particle in a movie and a classifier that places any particle among them, immutable.
 * <p>
 * Particles are told apart by the size and the brightness of their bright core ({@link KindFeatures}): each
 * particle is a point {@code (ln coreRadius, ln peak)}, so that sizes and brightnesses compare as ratios. The kinds
 * are the components of a two-dimensional Gaussian mixture fitted to the particles of a few frames:
 * <ul>
 * <li>automatically ({@link #find(Collection)}): 1 to {@value #MAX_KINDS} components, the number of least Bayesian
 * information criterion; then fewer while two of them are not clearly apart (Ashman's D below
 * {@value #MIN_SEPARATION}: one spread-out group, not two); a component of fewer than {@value #MIN_MEMBERS}
 * particles or {@value #MIN_SHARE} of the sample is no kind (a few stray blobs): its members are set aside and the
 * mixture fitted again without them;</li>
 * <li>given ({@link #find(Collection, int)} with a count): that many components, however close; 1 puts every
 * particle in one kind.</li>
 * </ul>
 * Kinds are numbered 1, 2, ... in order of size (core radius; kinds of one size, within 6%, in order of
 * brightness), so that the numbering does not depend on the sample; 0 stands for a particle that cannot be
 * classified (no bright core: see {@link KindFeatures#usable()}). Immutable and serializable: one instance serves
 * every frame and thread, and travels to a distributed job's workers.
 */
public final class Kinds implements Serializable {

	private static final long serialVersionUID = 1L;

	/** Most kinds found automatically. */
	public static final int MAX_KINDS = 4;
	/** Fewest particles of a kind found automatically. */
	public static final int MIN_MEMBERS = 3;
	/** Smallest share of the sample held by a kind found automatically. */
	public static final double MIN_SHARE = 0.02;
	/** Smallest Ashman's D between two kinds found automatically. */
	public static final double MIN_SEPARATION = 2;
	/**
	 * The smallest spread of a kind's {@code ln coreRadius} and {@code ln peak}: 3% in size, 5% in brightness, about
	 * what the median rings and a sub-pixel centre leave between identical particles.
	 */
	static final double[] FLOOR = { 0.03, 0.05 };

	/**
	 * One kind as found in the sample.
	 *
	 * @param kind its number, 1 the smallest
	 * @param count the sample's particles of this kind
	 * @param coreRadius their median core radius (px)
	 * @param peak their median central contrast (grey levels above the background)
	 * @param ringDepth their median dark-ring depth (grey levels below the background)
	 * @param ringRadius their median dark-ring radius (px; NaN if most have none)
	 * @param activeRadius their median active-area radius (px; NaN if not known)
	 * @param profile their median radial profile minus the background, radius 0, 1, 2, ... px
	 */
	public record Kind(int kind, int count, double coreRadius, double peak, double ringDepth, double ringRadius,
		double activeRadius, double[] profile) implements Serializable
	{
		/** Copies the profile. */
		public Kind {
			profile = profile.clone();
		}

		@Override
		public double[] profile() {
			return profile.clone();
		}
	}

	/** null: no usable particle in the sample, every particle is of kind 0. */
	private final GaussianMixture mixture;
	/** Kind number (1-based) of each mixture component. */
	private final int[] number;
	private final List<Kind> kinds;

	private Kinds(final GaussianMixture mixture, final int[] number, final List<Kind> kinds) {
		this.mixture = mixture;
		this.number = number;
		this.kinds = List.copyOf(kinds);
	}

	/** Finds the number of kinds automatically; see the class comment. */
	public static Kinds find(final Collection<KindFeatures> sample) {
		return find(sample, 0);
	}

	/**
	 * @param sample the particles of a few frames (a few hundred particles, and at least {@value #MIN_MEMBERS} of
	 *        the rarest kind, serve well); particles without a bright core are left out
	 * @param count the number of kinds, or 0 to find it automatically
	 * @return the kinds
	 * @throws InvalidInputException if {@code count} is negative
	 */
	public static Kinds find(final Collection<KindFeatures> sample, final int count) {
		if (count < 0) throw new InvalidInputException("the number of kinds must be 0 (automatic) or more, not " + count);
		final List<KindFeatures> usable = new ArrayList<>();
		for (final KindFeatures f : sample)
			if (f.usable()) usable.add(f);
		final int n = usable.size();
		if (n == 0) return new Kinds(null, new int[0], List.of());
		final double[] x = new double[n], y = new double[n];
		for (int i = 0; i < n; i++) {
			x[i] = Math.log(usable.get(i).coreRadius());
			y[i] = Math.log(usable.get(i).peak());
		}
		final GaussianMixture m = count > 0 ? given(x, y, Math.min(count, n)) : automatic(x, y);
		return of(m, usable, x, y);
	}

	/** {@code count} components, or fewer if so many cannot be fitted (fewer distinct points). */
	private static GaussianMixture given(final double[] x, final double[] y, final int count) {
		for (int k = count; k > 1; k--) {
			final GaussianMixture m = GaussianMixture.fit(x, y, k, FLOOR);
			if (m != null) return m;
		}
		return GaussianMixture.fit(x, y, 1, FLOOR);
	}

	/** Most rounds of setting aside the members of too small a component (stray blobs, not a kind). */
	static final int MAX_OUTLIER_ROUNDS = 5;

	/**
	 * The mixture of least BIC, then fewer components while two are not clearly apart; the members of a component
	 * too small to be a kind (a few stray blobs: a halo, two particles merged) are set aside and the mixture fitted
	 * again without them, so that they neither take a kind's place nor spread one.
	 */
	private static GaussianMixture automatic(final double[] allX, final double[] allY) {
		double[] x = allX, y = allY;
		GaussianMixture m = null;
		for (int round = 0; round <= MAX_OUTLIER_ROUNDS; round++) {
			final int n = x.length;
			final int minMembers = Math.max(MIN_MEMBERS, (int) Math.ceil(MIN_SHARE * n));
			m = separated(x, y, Math.max(1, Math.min(MAX_KINDS, n / minMembers)));
			final int[] members = new int[m.k];
			for (int i = 0; i < n; i++)
				members[m.component(x[i], y[i])]++;
			int kept = 0;
			for (int i = 0; i < n; i++)
				if (members[m.component(x[i], y[i])] >= minMembers) kept++;
			if (kept == n || kept < minMembers) return m;
			final double[] keptX = new double[kept], keptY = new double[kept];
			for (int i = 0, j = 0; i < n; i++)
				if (members[m.component(x[i], y[i])] >= minMembers) {
					keptX[j] = x[i];
					keptY[j++] = y[i];
				}
			x = keptX;
			y = keptY;
		}
		return m;
	}

	/** The mixture of least BIC among 1 to {@code most} components, then fewer while two are not clearly apart. */
	private static GaussianMixture separated(final double[] x, final double[] y, final int most) {
		final int n = x.length;
		final GaussianMixture[] fits = new GaussianMixture[most + 1];
		int best = 1;
		for (int k = 1; k <= most; k++) {
			fits[k] = GaussianMixture.fit(x, y, k, FLOOR);
			if (fits[k] != null && fits[k].bic(n) < fits[best].bic(n)) best = k;
		}
		for (int k = best; k > 1; k--)
			if (fits[k] != null && apart(fits[k])) return fits[k];
		return fits[1];
	}

	/**
	 * Whether every two components are clearly apart: well separated for their spreads, and unlike enough in size or
	 * brightness to need profiles of their own ({@link #MIN_SIZE_RATIO}, {@link #MIN_BRIGHTNESS_RATIO}).
	 */
	private static boolean apart(final GaussianMixture m) {
		for (int a = 0; a < m.k; a++)
			for (int b = a + 1; b < m.k; b++)
				if (m.separation(a, b) < MIN_SEPARATION || Math.abs(m.mean[a][0] - m.mean[b][0]) < Math.log(
					MIN_SIZE_RATIO) && Math.abs(m.mean[a][1] - m.mean[b][1]) < Math.log(MIN_BRIGHTNESS_RATIO)) return false;
		return true;
	}

	/**
	 * Kinds found automatically differ at least this much in core radius, or {@link #MIN_BRIGHTNESS_RATIO} in
	 * brightness. Less is what a particle's surroundings do to its measured profile: in a simulated cluster of seven
	 * alike particles the one surrounded on all sides became a kind of its own, and its profile, measured on
	 * surrounded particles alone, never settled. The fit's free radial scale and amplitude cover such differences.
	 */
	public static final double MIN_SIZE_RATIO = 1.15;
	/** See {@link #MIN_SIZE_RATIO}. */
	public static final double MIN_BRIGHTNESS_RATIO = 1.3;

	/** Numbers the components by size and describes each kind from its members in the sample. */
	private static Kinds of(final GaussianMixture m, final List<KindFeatures> usable, final double[] x,
		final double[] y)
	{
		final Integer[] bySize = new Integer[m.k];
		for (int c = 0; c < m.k; c++)
			bySize[c] = c;
		Arrays.sort(bySize, (a, b) -> Double.compare(m.mean[a][0], m.mean[b][0]));
		// kinds of one size (within twice the size floor) in order of brightness, so that their numbers too do not
		// depend on the sample
		for (int r = 1; r < m.k; r++) {
			final int a = bySize[r - 1], b = bySize[r];
			if (m.mean[b][0] - m.mean[a][0] < 2 * FLOOR[0] && m.mean[b][1] < m.mean[a][1]) {
				bySize[r - 1] = b;
				bySize[r] = a;
			}
		}
		final int[] number = new int[m.k];
		for (int r = 0; r < m.k; r++)
			number[bySize[r]] = r + 1;
		final List<List<KindFeatures>> members = new ArrayList<>();
		for (int c = 0; c < m.k; c++)
			members.add(new ArrayList<>());
		for (int i = 0; i < x.length; i++)
			members.get(number[m.component(x[i], y[i])] - 1).add(usable.get(i));
		final List<Kind> kinds = new ArrayList<>();
		for (int r = 0; r < m.k; r++)
			kinds.add(describe(r + 1, members.get(r)));
		return new Kinds(m, number, kinds);
	}

	private static Kind describe(final int kind, final List<KindFeatures> members) {
		final int n = members.size();
		final double[][] profiles = new double[n][];
		int rings = 0;
		for (int i = 0; i < n; i++) {
			profiles[i] = members.get(i).profile();
			rings = Math.max(rings, profiles[i].length);
		}
		final double[] profile = new double[rings];
		for (int r = 0; r < rings; r++) {
			final double[] at = new double[n];
			for (int i = 0; i < n; i++)
				at[i] = r < profiles[i].length ? profiles[i][r] : Double.NaN;
			profile[r] = median(at);
		}
		return new Kind(kind, n, median(members.stream().mapToDouble(KindFeatures::coreRadius).toArray()), median(
			members.stream().mapToDouble(KindFeatures::peak).toArray()), median(members.stream().mapToDouble(
				KindFeatures::ringDepth).toArray()), median(members.stream().mapToDouble(KindFeatures::ringRadius)
					.toArray()), median(members.stream().mapToDouble(KindFeatures::activeRadius).toArray()), profile);
	}

	/** The median of the values that are not NaN; NaN if fewer than half of them are numbers. */
	private static double median(final double[] values) {
		int numbers = 0;
		for (final double d : values)
			if (!Double.isNaN(d)) numbers++;
		return 2 * numbers < values.length ? Double.NaN : Statistics.median(values);
	}

	/** @return the number of kinds (0 when the sample held no usable particle) */
	public int count() {
		return kinds.size();
	}

	/**
	 * @param f a particle of any frame
	 * @return its kind, 1 to {@link #count()}: the kind most likely to hold it; 0 if it has no bright core (or no
	 *         kind was found)
	 */
	public int kindOf(final KindFeatures f) {
		if (mixture == null || !f.usable()) return 0;
		return number[mixture.component(Math.log(f.coreRadius()), Math.log(f.peak()))];
	}

	/** @return the kinds, in order of their numbers, as found in the sample: for reports */
	public List<Kind> describe() {
		return kinds;
	}
}
