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

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.IntFunction;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.lab.sim.DetectionScene;

/**
 * How well a tracker finds and centres the particles of a {@link DetectionScene}, judged against the truth: per band
 * of frames, the particles found (a spot within a quarter of their diameter), the spots without a particle, the share
 * of the spots wholly inside the frame that carry no warning flag, the mean error (bias) and spread of the unflagged
 * centres, and that spread against the Cramer-Rao bound where the scene has one.
 * <p>
 * Spots are matched to particles nearest first, each spot to one particle. A spot left over is <em>false</em> when no
 * particle lies within a quarter of its diameter of it, a <em>duplicate</em> when one does (a particle found twice).
 * Bias and spread are over the matched, unflagged spots wholly inside the frame: the mean error along x, along y and
 * along the line from the nearest other particle (positive: pushed away from it), and the root mean square of the
 * errors about their mean, per axis. The bound is each such particle's own, from the scene's Fisher matrix at its
 * frame's true centres (centres, amplitudes, radial scales and a background plane free), averaged as a mean square.
 */
public final class DetectionStudy {

	/** A tracker as a new user runs it: the movie in, its spots out, with what it chose. */
	@FunctionalInterface
	public interface Tracker {
		/** @return what the tracker found in the scene's movie */
		Tracked track(DetectionScene scene);
	}

	/**
	 * What a tracker found in one movie.
	 *
	 * @param spots per frame, its spots (empty lists where the movie was refused)
	 * @param detection the detection it used ({@code image}, {@code threshold}) and how it was chosen
	 * @param diameter the diameter it measured or was given (px), NaN where none
	 * @param seconds wall-clock time of the whole run, measuring included
	 * @param notice what it said about the run (measured values, a refusal), one line
	 */
	public record Tracked(List<List<Localization>> spots, String detection, double diameter, double seconds,
		String notice)
	{
		/** Copies the lists. */
		public Tracked {
			final List<List<Localization>> copy = new ArrayList<>();
			for (final List<Localization> f : spots)
				copy.add(List.copyOf(f));
			spots = List.copyOf(copy);
		}
	}

	/**
	 * One band's figures, summed over the movies of a scene.
	 *
	 * @param scene the scene's key
	 * @param band the band's name
	 * @param particles true particles, over frames
	 * @param found particles with a spot within a quarter diameter
	 * @param spots spots found
	 * @param falseSpots spots without a particle within a quarter of its diameter
	 * @param falseUnflagged of those, the spots without a warning flag: false spots a user who leaves out the flagged
	 *        ones still keeps
	 * @param duplicates spots left over near a particle already found
	 * @param inside spots wholly inside the frame
	 * @param unflagged of those, the spots without a warning flag
	 * @param measured matched unflagged spots inside the frame: the bias and spread are over these
	 * @param biasX mean error along x (px)
	 * @param biasY mean error along y (px)
	 * @param biasAway mean error along the line from the nearest other particle (px; positive: away from it)
	 * @param spread root mean square error about the mean, per axis (px)
	 * @param bound root mean square Cramer-Rao bound per axis (px), NaN where the scene has none
	 * @param reported root mean square of the standard errors the tracker reported per axis ({@code SIGMA_X},
	 *        {@code SIGMA_Y}; px), over the measured spots that reported one
	 * @param errorOverReported root mean square of each error over its own reported standard error, per axis: 1 where
	 *        the reported errors are what the centres' errors are, above 1 where they understate them
	 * @param mainFlag the warning flag most of the flagged spots inside the frame carry, with how many of them do
	 *        ({@code AT_BORDER 12/14}); empty where none is flagged
	 */
	public record Row(String scene, String band, int particles, int found, int spots, int falseSpots,
		int falseUnflagged, int duplicates, int inside, int unflagged, int measured, double biasX, double biasY,
		double biasAway, double spread, double bound, double reported, double errorOverReported, String mainFlag)
	{

		/** @return the share of particles found */
		public double recall() {
			return particles == 0 ? Double.NaN : found / (double) particles;
		}

		/** @return the share of the spots inside the frame that are unflagged, NaN where there are none */
		public double unflaggedShare() {
			return inside == 0 ? Double.NaN : unflagged / (double) inside;
		}

		/** @return the largest magnitude of the three biases (px), NaN where nothing was measured */
		public double worstBias() {
			return Math.max(Math.abs(biasX), Math.max(Math.abs(biasY), Math.abs(biasAway)));
		}

		/** @return the standard error of a bias: the spread over the root of the centres measured (px) */
		public double biasError() {
			return spread / Math.sqrt(measured);
		}

		/** @return the spread over the bound, NaN where either is unknown */
		public double spreadOverBound() {
			return spread / bound;
		}
	}

	/** Sums of one band: counts, then the errors' sums and sums of squares, and the bound's mean square. */
	private static final class Tally {
		int particles, found, spots, falseSpots, falseUnflagged, duplicates, inside, unflagged, measured, bounded, sigmas;
		double sx, sy, sa, sxx, syy, bound2, sigma2, z2;
		/** Per flag, the flagged spots inside the frame that carry it. */
		final int[] flags = new int[Flag.values().length];

		void add(final Tally t) {
			particles += t.particles;
			found += t.found;
			spots += t.spots;
			falseSpots += t.falseSpots;
			falseUnflagged += t.falseUnflagged;
			duplicates += t.duplicates;
			inside += t.inside;
			unflagged += t.unflagged;
			measured += t.measured;
			bounded += t.bounded;
			sx += t.sx;
			sy += t.sy;
			sa += t.sa;
			sxx += t.sxx;
			syy += t.syy;
			bound2 += t.bound2;
			sigmas += t.sigmas;
			sigma2 += t.sigma2;
			z2 += t.z2;
			for (int f = 0; f < flags.length; f++)
				flags[f] += t.flags[f];
		}

		String mainFlag() {
			int best = -1;
			for (int f = 0; f < flags.length; f++)
				if (flags[f] > 0 && (best < 0 || flags[f] > flags[best])) best = f;
			return best < 0 ? "" : Flag.values()[best].name() + " " + flags[best] + "/" + (inside - unflagged);
		}

		Row row(final String scene, final String band) {
			final double n = measured;
			final double bx = sx / n, by = sy / n;
			final double spread = n < 2 ? Double.NaN : Math.sqrt(Math.max(0, (sxx - n * bx * bx + syy - n * by * by) / (2 *
				(n - 1))));
			return new Row(scene, band, particles, found, spots, falseSpots, falseUnflagged, duplicates, inside, unflagged,
				measured, bx, by, sa / n, spread, bounded == 0 ? Double.NaN : Math.sqrt(bound2 / bounded), sigmas == 0 ? Double.NaN : Math
					.sqrt(sigma2 / sigmas), sigmas == 0 ? Double.NaN : Math.sqrt(z2 / sigmas), mainFlag());
		}
	}

	private final Map<String, Tally> bands = new LinkedHashMap<>();
	private final Map<Double, Tally> labels = new TreeMap<>();
	private String key;

	/**
	 * Adds one tracked movie of a scene to the sums (every movie of a study is of the same scene).
	 *
	 * @param scene the movie with its truth
	 * @param tracked what the tracker found in it
	 */
	public void add(final DetectionScene scene, final Tracked tracked) {
		if (key != null && !key.equals(scene.key())) throw new IllegalArgumentException("a study of " + key +
			" given a movie of " + scene.key());
		key = scene.key();
		if (scene.scene().particles().isEmpty()) throw new IllegalArgumentException("a scene without particles");
		SceneCramerRao bound = null;
		for (int t = 0; t < scene.frames().size(); t++) {
			final double label = scene.labels()[t];
			// a layout moved as a whole keeps its bound (it barely depends on the sub-pixel offset): computed once
			if (scene.boundKnown() && (bound == null || !Double.isNaN(label))) bound = new SceneCramerRao(scene.scene(),
				scene.truth().get(t), scene.width(), scene.height(), true, SceneCramerRao.saturation(scene.bitDepth()));
			final int frame = t;
			final Tally byLabel = Double.isNaN(label) ? null : labels.computeIfAbsent(Math.round(label * 1e6) / 1e6,
				l -> new Tally());
			final List<Localization> spots = t < tracked.spots().size() ? tracked.spots().get(t) : List.of();
			frame(scene, t, spots, bound, k -> bands.computeIfAbsent(scene.band(frame, k), b -> new Tally()));
			if (byLabel != null) frame(scene, t, spots, bound, k -> byLabel);
		}
	}

	/**
	 * Adds frame {@code t}'s spots to the tallies: each particle to its own, each spot to its particle's (or, where it
	 * found none, to that of the particle nearest to it).
	 */
	private static void frame(final DetectionScene scene, final int t, final List<Localization> spots,
		final SceneCramerRao bound, final IntFunction<Tally> tallyOf)
	{
		final List<double[]> truth = scene.truth().get(t);
		final int n = truth.size(), m = spots.size();
		// every particle-spot pair within a quarter diameter, nearest first
		final List<double[]> close = new ArrayList<>();
		final int[] nearest = new int[m];
		for (int s = 0; s < m; s++) {
			double best = Double.POSITIVE_INFINITY;
			for (int k = 0; k < n; k++) {
				final double dist = Math.hypot(spots.get(s).x() - truth.get(k)[0], spots.get(s).y() - truth.get(k)[1]);
				if (dist <= scene.diameter(k) / 4) close.add(new double[] { dist, k, s });
				if (dist < best) {
					best = dist;
					nearest[s] = k;
				}
			}
		}
		close.sort((a, b) -> Double.compare(a[0], b[0]));
		final int[] spotOf = new int[n], particleOf = new int[m];
		Arrays.fill(spotOf, -1);
		Arrays.fill(particleOf, -1);
		final boolean[] near = new boolean[m];
		for (final double[] c : close) {
			final int k = (int) c[1], s = (int) c[2];
			near[s] = true;
			if (spotOf[k] < 0 && particleOf[s] < 0) {
				spotOf[k] = s;
				particleOf[s] = k;
			}
		}
		for (int k = 0; k < n; k++) {
			final Tally tally = tallyOf.apply(k);
			tally.particles++;
			if (spotOf[k] >= 0) tally.found++;
		}
		final double typical = scene.scene().type().diameterPx();
		final int w = scene.width(), h = scene.height();
		for (int s = 0; s < m; s++) {
			final Localization l = spots.get(s);
			final int k = particleOf[s];
			final Tally tally = tallyOf.apply(k >= 0 ? k : nearest[s]);
			tally.spots++;
			if (k < 0) {
				if (near[s]) tally.duplicates++;
				else {
					tally.falseSpots++;
					if (!l.isFlagged()) tally.falseUnflagged++;
				}
			}
			final double r = (k < 0 ? typical : scene.diameter(k)) / 2;
			final boolean inside = l.x() - r >= -0.5 && l.x() + r <= w - 0.5 && l.y() - r >= -0.5 && l.y() + r <= h - 0.5;
			if (!inside) continue;
			tally.inside++;
			if (l.isFlagged()) {
				for (final Flag f : Flag.values())
					if (f.isWarning() && l.has(f)) tally.flags[f.ordinal()]++;
				continue;
			}
			tally.unflagged++;
			if (k < 0) continue;
			final double dx = l.x() - truth.get(k)[0], dy = l.y() - truth.get(k)[1];
			tally.measured++;
			tally.sx += dx;
			tally.sy += dy;
			tally.sxx += dx * dx;
			tally.syy += dy * dy;
			tally.sa += away(truth, k, dx, dy);
			if (l.sigmaX() > 0 && l.sigmaY() > 0) { // (NaN: none reported)
				tally.sigmas++;
				tally.sigma2 += 0.5 * (l.sigmaX() * l.sigmaX() + l.sigmaY() * l.sigmaY());
				tally.z2 += 0.5 * (dx * dx / (l.sigmaX() * l.sigmaX()) + dy * dy / (l.sigmaY() * l.sigmaY()));
			}
			if (bound != null) {
				final double bx = bound.position(k, 0), by = bound.position(k, 1);
				if (Double.isFinite(bx) && Double.isFinite(by)) {
					tally.bound2 += 0.5 * (bx * bx + by * by);
					tally.bounded++;
				}
			}
		}
	}

	/** @return the error's part along the line from particle {@code k}'s nearest other particle to it */
	private static double away(final List<double[]> truth, final int k, final double dx, final double dy) {
		double best = Double.POSITIVE_INFINITY, ux = 0, uy = 0;
		final double[] c = truth.get(k);
		for (int j = 0; j < truth.size(); j++) {
			if (j == k) continue;
			final double vx = c[0] - truth.get(j)[0], vy = c[1] - truth.get(j)[1], d = Math.hypot(vx, vy);
			if (d < best && d > 0) {
				best = d;
				ux = vx / d;
				uy = vy / d;
			}
		}
		return dx * ux + dy * uy;
	}

	/** @return one row per band, in the order the bands first came */
	public List<Row> bands() {
		final List<Row> rows = new ArrayList<>();
		for (final Map.Entry<String, Tally> e : bands.entrySet())
			rows.add(e.getValue().row(key, e.getKey()));
		return rows;
	}

	/** @return one row per frame label (a pair's separation over the diameter), largest first; none without labels */
	public List<Row> labels() {
		final List<Row> rows = new ArrayList<>();
		for (final Map.Entry<Double, Tally> e : labels.entrySet())
			rows.add(0, e.getValue().row(key, String.format(java.util.Locale.ROOT, "%.3f", e.getKey())));
		return rows;
	}

	/** @return the row of every band together */
	public Row total() {
		final Tally all = new Tally();
		for (final Tally t : bands.values())
			all.add(t);
		return all.row(key, "all");
	}

	/**
	 * @param rows the rows of every frame label, largest first ({@link #labels()})
	 * @return the largest label (separation over the diameter) at which a particle was missed or a false spot found,
	 *         NaN where none was
	 */
	public static double failsAt(final List<Row> rows) {
		for (final Row r : rows)
			if (r.found() < r.particles() || r.falseSpots() > 0) return Double.parseDouble(r.band());
		return Double.NaN;
	}
}
