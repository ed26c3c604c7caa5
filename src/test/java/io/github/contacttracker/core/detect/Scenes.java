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
package io.github.contacttracker.core.detect;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.DoubleUnaryOperator;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileEstimator;

/**
 * Simulated frames with ground truth for detection by the image: the kinds of footage a threshold cannot cut into
 * one component per particle (blurred pairs pushed into overlap, small touching particles, dense monolayers with no
 * isolated particle, dim spots, dark particles on a bright background, ramps and clipped backgrounds), and the score
 * of a tracker's spots against the truth.
 */
final class Scenes {

	private Scenes() {}

	/** One particle of a scene: centre (px), amplitude (grey levels; negative: darker than the background), size. */
	record Truth(double x, double y, double amplitude, double size) {}

	/** A frame and its particles. */
	record Frame(double[] pixels, int width, int height, List<Truth> truth, double diameter) {}

	/**
	 * The image of a blurred sphere of radius {@code size} (px): a disc seen through a Gaussian blur of {@code blur}
	 * px, as fluorescent beads and microgels look; {@code size} 0 gives a Gaussian spot of width {@code blur}.
	 */
	static DoubleUnaryOperator blurredDisc(final double size, final double blur) {
		if (size <= 0) return r -> Math.exp(-r * r / (2 * blur * blur));
		return r -> 0.5 * erfc((r - size) / (Math.sqrt(2) * blur));
	}

	/** A bright core in a dark ring, as bright-field colloids look: a Gaussian core minus a ring at {@code size}. */
	static DoubleUnaryOperator ringed(final double size, final double blur) {
		return r -> Math.exp(-r * r / (2 * blur * blur)) - 0.5 * Math.exp(-(r - size) * (r - size) / (2 * blur * blur));
	}

	/**
	 * Renders the particles ({@code profile} of r / size... times amplitude) on {@code background(x, y)}, 4x4
	 * sub-samples a pixel, each particle out to {@code reach} px times its size.
	 */
	static double[] render(final int w, final int h, final Background background, final List<Truth> particles,
		final java.util.function.DoubleUnaryOperator unitProfile, final double reach)
	{
		final double[] img = new double[w * h];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				img[y * w + x] = background.at(x, y);
		final int ss = 4;
		for (final Truth t : particles) {
			final double R = reach * t.size;
			for (int y = Math.max(0, (int) Math.floor(t.y - R)); y <= Math.min(h - 1, (int) Math.ceil(t.y + R)); y++)
				for (int x = Math.max(0, (int) Math.floor(t.x - R)); x <= Math.min(w - 1, (int) Math.ceil(t.x + R)); x++) {
					double sum = 0;
					for (int sy = 0; sy < ss; sy++)
						for (int sx = 0; sx < ss; sx++) {
							final double px = x - 0.5 + (sx + 0.5) / ss, py = y - 0.5 + (sy + 0.5) / ss;
							sum += unitProfile.applyAsDouble(Math.hypot(px - t.x, py - t.y) / t.size);
						}
					img[y * w + x] += t.amplitude * sum / (ss * ss);
				}
		}
		return img;
	}

	/** A background grey level at each pixel. */
	@FunctionalInterface
	interface Background {
		double at(int x, int y);
	}

	/** @return the image with Gaussian noise of standard deviation {@code sigma}, clipped to {@code [lo, hi]} */
	static double[] noisy(final double[] img, final double sigma, final double lo, final double hi, final long seed) {
		final Random r = new Random(seed);
		final double[] out = new double[img.length];
		for (int i = 0; i < img.length; i++)
			out[i] = Math.max(lo, Math.min(hi, Math.round(img[i] + sigma * r.nextGaussian())));
		return out;
	}

	/** @return a hexagonal-ish random packing: {@code n} discs of the given radii, no overlap, by random sequential adding */
	static List<double[]> packing(final int w, final int h, final double[] radii, final double fraction, final double gap,
		final long seed)
	{
		final Random r = new Random(seed);
		final List<double[]> out = new ArrayList<>();
		double area = 0;
		int tries = 0;
		while (area < fraction * w * h && tries < 2_000_000) {
			tries++;
			final double rad = radii[r.nextInt(radii.length)];
			final double x = r.nextDouble() * w, y = r.nextDouble() * h;
			boolean free = true;
			for (final double[] p : out)
				if (Math.hypot(p[0] - x, p[1] - y) < p[2] + rad + gap) {
					free = false;
					break;
				}
			if (free) {
				out.add(new double[] { x, y, rad });
				area += Math.PI * rad * rad;
			}
		}
		return out;
	}

	/** The score of spots against the truth. */
	record Score(int truth, int found, int matched, int spurious, int flagged, double meanDx, double meanDy,
		double rmsError, double worstError, List<Localization> unmatchedSpots, List<Truth> missed)
	{
		double recall() {
			return matched / (double) truth;
		}

		double unflagged() {
			return found == 0 ? 0 : 1 - flagged / (double) found;
		}

		@Override
		public String toString() {
			return String.format("truth %d found %d matched %d spurious %d flagged %d | bias (%.4f, %.4f) rms %.4f worst %.3f",
				truth, found, matched, spurious, flagged, meanDx, meanDy, rmsError, worstError);
		}
	}

	/**
	 * Matches each true particle inside the frame (its centre at least {@code inset} px from every edge) to the nearest
	 * spot within {@code within} px, each spot used once (nearest pairs first); spots nearer than {@code inset} to an
	 * edge whose particle is not counted are ignored.
	 */
	static Score score(final Frame f, final List<Localization> spots, final double within, final double inset) {
		final List<Truth> inside = new ArrayList<>();
		for (final Truth t : f.truth())
			if (t.x >= inset && t.y >= inset && t.x <= f.width() - 1 - inset && t.y <= f.height() - 1 - inset) inside.add(t);
		final List<double[]> pairs = new ArrayList<>();
		for (int i = 0; i < inside.size(); i++)
			for (int j = 0; j < spots.size(); j++) {
				final double d = Math.hypot(inside.get(i).x - spots.get(j).x(), inside.get(i).y - spots.get(j).y());
				if (d <= within) pairs.add(new double[] { d, i, j });
			}
		pairs.sort((a, b) -> Double.compare(a[0], b[0]));
		final boolean[] tUsed = new boolean[inside.size()], sUsed = new boolean[spots.size()];
		int matched = 0, flagged = 0;
		double sx = 0, sy = 0, s2 = 0, worst = 0;
		for (final double[] p : pairs) {
			final int i = (int) p[1], j = (int) p[2];
			if (tUsed[i] || sUsed[j]) continue;
			tUsed[i] = sUsed[j] = true;
			matched++;
			final Localization l = spots.get(j);
			final double dx = l.x() - inside.get(i).x, dy = l.y() - inside.get(i).y;
			sx += dx;
			sy += dy;
			s2 += dx * dx + dy * dy;
			worst = Math.max(worst, Math.hypot(dx, dy));
		}
		int spurious = 0, counted = 0;
		final List<Localization> unmatched = new ArrayList<>();
		for (int j = 0; j < spots.size(); j++) {
			final Localization l = spots.get(j);
			final boolean nearEdge = l.x() < inset || l.y() < inset || l.x() > f.width() - 1 - inset || l.y() > f.height() -
				1 - inset;
			if (!sUsed[j] && nearEdge) continue;
			counted++;
			if (warned(l)) flagged++;
			if (!sUsed[j]) {
				spurious++;
				unmatched.add(l);
			}
		}
		final List<Truth> missed = new ArrayList<>();
		for (int i = 0; i < inside.size(); i++)
			if (!tUsed[i]) missed.add(inside.get(i));
		return new Score(inside.size(), counted, matched, spurious, flagged, matched == 0 ? 0 : sx / matched, matched == 0
			? 0 : sy / matched, matched == 0 ? 0 : Math.sqrt(s2 / matched), worst, unmatched, missed);
	}

	/** @return whether a spot carries a warning flag */
	static boolean warned(final Localization l) {
		for (final Flag f : Flag.decode(l.flags()))
			if (f.isWarning()) return true;
		return false;
	}

	/** erfc by Abramowitz and Stegun 7.1.26 (error below 1.5e-7). */
	static double erfc(final double x) {
		final double z = Math.abs(x);
		final double t = 1 / (1 + 0.3275911 * z);
		final double y = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t *
			1.061405429)))) * Math.exp(-z * z);
		return x >= 0 ? y : 2 - y;
	}

	/** @return the profile measured on the frame at the particles' true centres, out to {@code reach} px */
	static EmpiricalProfile measured(final Plane plane, final List<Truth> truth, final double reach) {
		final int n = truth.size();
		final double[] x = new double[n], y = new double[n], ones = new double[n];
		for (int k = 0; k < n; k++) {
			x[k] = truth.get(k).x();
			y[k] = truth.get(k).y();
			ones[k] = 1;
		}
		final ProfileEstimator estimator = new ProfileEstimator(reach, 1, null);
		estimator.add(plane, x, y, ones, ones, new boolean[n], null);
		return estimator.solve().profiles()[0];
	}
}
