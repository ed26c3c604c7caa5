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

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.Locale;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scene;
import io.github.contacttracker.lab.sim.SimulatedStack;

/**
 * Accuracy in a {@link Scene}: many noisy frames of the same scene, tracked as one stack; per scene the error of
 * the distance of every touching pair (mean, spread, against the scene's Cramer-Rao bound), every particle's own
 * bias (along x, y, and the radial and tangential directions from the cluster's centre; the largest is reported),
 * particles lost and extra spots, spots flagged, and the reported standard errors against the observed spread.
 */
public final class SceneStudy {

	/**
	 * One scene's outcome (nm unless said otherwise).
	 *
	 * @param scene the scene's key
	 * @param particle the particles' name
	 * @param images frames simulated
	 * @param meanError mean distance error over all touching pairs and frames
	 * @param worstPairMean the touching pair's mean error of largest magnitude
	 * @param std root mean square of the pairs' standard deviations
	 * @param crb root mean square of the pairs' Cramer-Rao bounds
	 * @param worstStdOverCrb the largest ratio std / CRB over the pairs
	 * @param bias the largest |bias| of any particle along x, y, radial or tangential
	 * @param biasWhere which particle and direction
	 * @param lost truth particles without their own spot, over all frames
	 * @param extra spots matching no particle, over all frames
	 * @param flagged spots with a warning flag, over all frames
	 * @param sigmaRatioMin smallest reported sigma / observed spread, over particles and axes
	 * @param sigmaRatioMax largest
	 * @param clipped pixels clipped at 255 or 0, over all frames
	 * @param wrongKind matched spots of the wrong kind, over all frames: the tracker labels kinds by its own numbers,
	 *        so each true kind is given the label most of its spots have, and a spot counts as wrong when its label
	 *        is not its particle's, or when its particle's kind shares its label with a more numerous kind (kinds
	 *        not told apart)
	 */
	public record Result(String scene, String particle, int images, double meanError, double worstPairMean,
		double std, double crb, double worstStdOverCrb, double bias, String biasWhere, int lost, int extra,
		int flagged, double sigmaRatioMin, double sigmaRatioMax, long clipped, int wrongKind)
	{}

	private final Method method;
	private final int threads;

	/**
	 * @param method the method measured
	 * @param threads worker threads (below 1: all)
	 */
	public SceneStudy(final Method method, final int threads) {
		this.method = method;
		this.threads = threads;
	}

	/** @return the method measured */
	public Method method() {
		return method;
	}

	/**
	 * @param key {@code 5.53}, {@code 2.06} or {@code flat} ({@link Scene#flatTop()})
	 * @return the particle type
	 */
	public static ParticleType particle(final String key) {
		return switch (key.trim()) {
			case "5.53" -> PaperParticles.silica553();
			case "2.06" -> PaperParticles.silica206();
			case "flat" -> Scene.flatTop();
			default -> throw new InvalidInputException("--particle must be 5.53, 2.06 or flat with --scene, not '" + key +
				"'");
		};
	}

	/** Simulates and measures one scene. */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public Result run(final Scene scene, final int images, final long seed) {
		final SimulatedStack<?> stack = scene.simulate(images, seed);
		final TrackerParameters params = TrackerParameters.of(scene.threshold(), scene.type().rOut()).withMethod(
			method);
		final StackTracker tracker = new StackTracker(params);
		final List<FrameResult> results = StackTracker.withThreads(threads, () -> tracker.track((List) stack.frames(),
			false));
		return measure(scene, stack, results);
	}

	/** Compares tracked frames with the truth. */
	public static Result measure(final Scene scene, final SimulatedStack<?> stack, final List<FrameResult> results) {
		final ParticleType type = scene.type();
		final double nm = type.pixelSizeNm();
		final int n = scene.particles().size();
		final List<int[]> pairs = stack.measuredPairs();
		final double[][] pairSum = new double[pairs.size()][3]; // count, sum, sum of squares
		final double[][] pos = new double[n][7]; // count, sum dx, sum dy, sum dx2, sum dy2, sum sigmaX, sum sigmaY
		int lost = 0, extra = 0, flagged = 0;
		final int[] truthKind = scene.kinds();
		final Map<Integer, Map<Integer, Integer>> labels = new TreeMap<>();
		final double maxMatch = 0.4 * type.diameterPx();
		for (int t = 0; t < results.size(); t++) {
			final List<double[]> truth = stack.truth().get(t);
			final List<Localization> spots = results.get(t).spots();
			final Localization[] match = new Localization[n];
			final boolean[] used = new boolean[spots.size()];
			for (int k = 0; k < n; k++) {
				int best = -1;
				double bestD = maxMatch;
				for (int s = 0; s < spots.size(); s++) {
					final double d = Math.hypot(spots.get(s).x() - truth.get(k)[0], spots.get(s).y() - truth.get(k)[1]);
					if (d <= bestD) {
						bestD = d;
						best = s;
					}
				}
				if (best < 0 || used[best]) lost++;
				else {
					used[best] = true;
					match[k] = spots.get(best);
				}
			}
			for (int s = 0; s < spots.size(); s++) {
				if (!used[s]) extra++;
				if (spots.get(s).isFlagged()) flagged++;
			}
			for (int k = 0; k < n; k++) {
				if (match[k] == null) continue;
				labels.computeIfAbsent(truthKind[k], kind -> new TreeMap<>()).merge(match[k].kind(), 1, Integer::sum);
				final double dx = match[k].x() - truth.get(k)[0], dy = match[k].y() - truth.get(k)[1];
				final double[] p = pos[k];
				p[0]++;
				p[1] += dx;
				p[2] += dy;
				p[3] += dx * dx;
				p[4] += dy * dy;
				p[5] += match[k].sigmaX();
				p[6] += match[k].sigmaY();
			}
			for (int q = 0; q < pairs.size(); q++) {
				final int i = pairs.get(q)[0], j = pairs.get(q)[1];
				if (match[i] == null || match[j] == null) continue;
				final double e = Math.hypot(match[i].x() - match[j].x(), match[i].y() - match[j].y()) - Math.hypot(truth.get(
					i)[0] - truth.get(j)[0], truth.get(i)[1] - truth.get(j)[1]);
				pairSum[q][0]++;
				pairSum[q][1] += e * nm;
				pairSum[q][2] += e * e * nm * nm;
			}
		}
		// the bound, at the first frame's configuration (it barely depends on the sub-pixel offset)
		final List<double[]> c0 = stack.truth().get(0);
		final SceneCramerRao bound = new SceneCramerRao(scene, c0, stack.width(), stack.height(), true);
		double total = 0, count = 0, worst = 0, varSum = 0, crbSum = 0, worstRatio = 0;
		for (int q = 0; q < pairs.size(); q++) {
			final double m = pairSum[q][0];
			if (m < 2) continue;
			final double mean = pairSum[q][1] / m;
			final double var = Math.max(0, (pairSum[q][2] - m * mean * mean) / (m - 1));
			final double crb = bound.distance(c0, pairs.get(q)[0], pairs.get(q)[1]) * nm;
			total += pairSum[q][1];
			count += m;
			if (Math.abs(mean) > Math.abs(worst)) worst = mean;
			varSum += var;
			crbSum += crb * crb;
			worstRatio = Math.max(worstRatio, Math.sqrt(var) / crb);
		}
		final int np = Math.max(1, pairs.size());
		// the cluster's centre: radial and tangential directions of each particle
		double gx = 0, gy = 0;
		for (final double[] c : c0) {
			gx += c[0] / n;
			gy += c[1] / n;
		}
		double bias = 0, ratioMin = Double.POSITIVE_INFINITY, ratioMax = 0;
		String where = "";
		final String[] axes = { "x", "y", "radial", "tangential" };
		for (int k = 0; k < n; k++) {
			final double[] p = pos[k];
			if (p[0] < 2) continue;
			final double bx = p[1] / p[0], by = p[2] / p[0];
			double ux = c0.get(k)[0] - gx, uy = c0.get(k)[1] - gy;
			final double len = Math.hypot(ux, uy);
			if (len > 1e-6) {
				ux /= len;
				uy /= len;
			}
			else {
				ux = 1;
				uy = 0;
			}
			final double[] b = { bx, by, bx * ux + by * uy, -bx * uy + by * ux };
			for (int a = 0; a < 4; a++)
				if (Math.abs(b[a] * nm) > Math.abs(bias)) {
					bias = b[a] * nm;
					where = "particle " + k + (scene.profiles().size() > 1 ? " (kind " + (truthKind[k] + 1) + ")" : "") +
						" " + axes[a];
				}
			final double sdx = Math.sqrt(Math.max(0, (p[3] - p[0] * bx * bx) / (p[0] - 1)));
			final double sdy = Math.sqrt(Math.max(0, (p[4] - p[0] * by * by) / (p[0] - 1)));
			final double rx = p[5] / p[0] / sdx, ry = p[6] / p[0] / sdy;
			ratioMin = Math.min(ratioMin, Math.min(rx, ry));
			ratioMax = Math.max(ratioMax, Math.max(rx, ry));
		}
		return new Result(scene.key(), type.name(), results.size(), count > 0 ? total / count : Double.NaN, worst, Math
			.sqrt(varSum / np), Math.sqrt(crbSum / np), worstRatio, bias, where, lost, extra, flagged, ratioMin, ratioMax,
			stack.clippedPixels(), wrongKind(labels));
	}

	/**
	 * @param labels per true kind, how many of its spots got each label
	 * @return the spots of the wrong kind ({@link Result#wrongKind()})
	 */
	static int wrongKind(final Map<Integer, Map<Integer, Integer>> labels) {
		// each true kind's label: the one most of its spots have; the most numerous kinds choose first
		final List<int[]> kinds = new ArrayList<>(); // true kind, its label, spots with it, all its spots
		for (final Map.Entry<Integer, Map<Integer, Integer>> e : labels.entrySet()) {
			int label = 0, most = -1, all = 0;
			for (final Map.Entry<Integer, Integer> l : e.getValue().entrySet()) {
				all += l.getValue();
				if (l.getValue() > most) {
					most = l.getValue();
					label = l.getKey();
				}
			}
			kinds.add(new int[] { e.getKey(), label, most, all });
		}
		kinds.sort((a, b) -> Integer.compare(b[3], a[3]));
		final Set<Integer> taken = new HashSet<>();
		int wrong = 0;
		for (final int[] k : kinds)
			wrong += taken.add(k[1]) ? k[3] - k[2] : k[3];
		return wrong;
	}

	/** The table's header, as {@link #print} writes it. */
	public static void printHeader(final PrintStream out) {
		out.println("  scene      | mean err  worst pair   std (nm) | CRB (nm) | std/CRB (worst pair) | position bias (nm)" +
			"              | lost extra flagged | reported sigma / spread | clipped px | wrong kind");
	}

	/** One row. */
	public static void print(final PrintStream out, final Result r) {
		out.printf(Locale.ROOT, "  %-10s | %8.2f %11.2f %10.2f | %8.2f | %20.2f | %6.2f %-23s | %4d %5d %7d | %10.2f to %-10.2f | %10d | %d%n",
			r.scene(), r.meanError(), r.worstPairMean(), r.std(), r.crb(), r.worstStdOverCrb(), r.bias(), r.biasWhere(),
			r.lost(), r.extra(), r.flagged(), r.sigmaRatioMin(), r.sigmaRatioMax(), r.clipped(), r.wrongKind());
	}

	/** The CSV header matching {@link #csv}. */
	public static final String CSV_HEADER = "particle,scene,method,images,mean_error_nm,worst_pair_mean_nm,std_nm,crb_nm," +
		"worst_std_over_crb,position_bias_nm,bias_where,lost,extra,flagged,sigma_ratio_min,sigma_ratio_max,clipped,wrong_kind\n";

	/** One CSV line. */
	public String csv(final Result r) {
		return String.format(Locale.ROOT, "%s,%s,%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%d,%d,%d,%.4f,%.4f,%d,%d%n", r
			.particle(), r.scene(), method.key(), r.images(), r.meanError(), r.worstPairMean(), r.std(), r.crb(), r
				.worstStdOverCrb(), r.bias(), r.biasWhere(), r.lost(), r.extra(), r.flagged(), r.sigmaRatioMin(), r
					.sigmaRatioMax(), r.clipped(), r.wrongKind());
	}

	/**
	 * Runs every scene for every particle type and prints the table.
	 *
	 * @param types the particle types (e.g. {@link #particle} of a key)
	 * @param scenes comma-separated scene keys ({@link #sceneKeys})
	 * @param images frames per scene
	 * @return the table's rows, in order (as CSV: {@link #CSV_HEADER}, then {@link #csv} of each)
	 */
	public List<Result> report(final PrintStream out, final List<ParticleType> types, final String scenes,
		final int images)
	{
		final List<Kinds> sets = new ArrayList<>();
		for (final ParticleType t : types)
			sets.add(new Kinds(t.name(), List.of(t)));
		return reportKinds(out, sets, scenes, images);
	}

	/**
	 * The kinds of particle of one source (a movie's, or a single type): each kind alone in every plain scene, and
	 * all of them together in the {@link Scene#MIXED_KEYS mixed} ones.
	 *
	 * @param name the source's name: the mixed scenes' particles are called after it
	 * @param types its kinds, at least one
	 */
	public record Kinds(String name, List<ParticleType> types) {

		/** Copies the list. */
		public Kinds {
			types = List.copyOf(types);
		}
	}

	/**
	 * Runs every plain scene for every kind of every source, then the mixed scenes of each source of two kinds or
	 * more (a source of one kind has none: said so), and prints the tables.
	 *
	 * @param sets the sources and their kinds
	 * @param scenes comma-separated scene keys ({@link #sceneKeys}), plain or {@link Scene#MIXED_KEYS mixed}
	 * @param images frames per scene
	 * @return the table's rows, in order
	 */
	public List<Result> reportKinds(final PrintStream out, final List<Kinds> sets, final String scenes,
		final int images)
	{
		final List<String> keys = new ArrayList<>(), mixed = new ArrayList<>();
		for (final String k : sceneKeys(scenes))
			(Scene.MIXED_KEYS.contains(k.toLowerCase(Locale.ROOT)) ? mixed : keys).add(k);
		final ParticleType any = sets.get(0).types().get(0);
		for (final String k : keys)
			Scene.of(k, any); // unknown names fail before any work
		final List<Result> rows = new ArrayList<>();
		for (final Kinds set : sets) {
			for (final ParticleType type : set.types()) {
				if (keys.isEmpty()) break;
				heading(out, type, images);
				long seed = 11;
				for (final String k : keys)
					rows.add(printed(out, run(Scene.of(k, type), images, seed++)));
			}
			if (mixed.isEmpty()) continue;
			if (set.types().size() < 2) {
				out.printf(Locale.ROOT, "%n%s: one kind, no mixed scene%n", set.name());
				continue;
			}
			final String name = mixedName(set);
			heading(out, Scene.mixed(mixed.get(0), name, set.types()).type(), images);
			long seed = 31;
			for (final String k : mixed)
				rows.add(printed(out, run(Scene.mixed(k, name, set.types()), images, seed++)));
		}
		return rows;
	}

	/** @return the name of a source's mixed scenes' particles */
	public static String mixedName(final Kinds set) {
		return set.name() + ", kinds 1 to " + set.types().size() + " mixed";
	}

	private void heading(final PrintStream out, final ParticleType type, final int images) {
		out.printf(Locale.ROOT, "%n%s (D = %.1f px at %.1f nm/px), r_out %.0f px, method %s, %d images per scene, " +
			"at contact%n", type.name(), type.diameterPx(), type.pixelSizeNm(), type.rOut(), method.key(), images);
		printHeader(out);
	}

	private static Result printed(final PrintStream out, final Result r) {
		print(out, r);
		return r;
	}

	/** @return the scenes named in a comma-separated list ({@code all}: every one) */
	public static List<String> sceneKeys(final String text) {
		if (text.trim().equals("all")) return Scene.KEYS;
		final List<String> keys = new ArrayList<>();
		for (final String k : text.split(","))
			keys.add(k.trim());
		return keys;
	}
}
