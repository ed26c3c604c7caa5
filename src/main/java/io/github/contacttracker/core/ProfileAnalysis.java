package io.github.contacttracker.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;
import net.imglib2.view.Views;

/**
 * Suggests {@code threshold} and {@code r_out} from the radial intensity profile of one isolated particle, the
 * way the paper reads them off its Fig. 2.
 * <ol>
 * <li>Noise: the frame's pixel-noise standard deviation {@code s} ({@link NoiseEstimate}, Immerkaer).</li>
 * <li>Centre: the given point, refined by one radial-symmetry pass ({@link Method#FIRST}) on the particle's
 * active area at half its height above background.</li>
 * <li>Profile: the mean grey level in 1 px wide rings around the centre, out to {@code max_radius}
 * ({@value #AUTO_RADIUS_DIAMETERS} diameters unless given). Background {@code I0}: the median of the pixels in
 * the outer {@value #BACKGROUND_ANNULUS_PERCENT}% of that radius.</li>
 * <li>{@code r_out}: the radius beyond which the profile stays within the noise of the background,
 * {@code |I(r) - I0| <= s} (the reach), plus {@value #R_OUT_MARGIN_PX} px.</li>
 * <li>{@code threshold}: two equal particles at contact (centres one diameter {@code D} apart) add up; the
 * brightest point between them lies on the perpendicular bisector of their centres, at distance
 * {@code r >= D/2} from both, so it is {@code I0 + 2 max(0, max over D/2 <= r <= reach of (I(r) - I0))} (the
 * {@code max(0, ..)} is the background far along the bisector). The threshold is that level plus
 * {@value #THRESHOLD_MARGIN_SIGMAS} {@code s}, so that noise cannot bridge the two active areas either.</li>
 * </ol>
 */
public final class ProfileAnalysis {

	/** Added to the reach for {@code r_out}: half the width of the gradient operator. */
	public static final double R_OUT_MARGIN_PX = 2;
	/** Noise margin of the threshold above the brightest point between two particles, in noise sigmas. */
	public static final double THRESHOLD_MARGIN_SIGMAS = 3;
	/** Default {@code max_radius}, in particle diameters. */
	public static final double AUTO_RADIUS_DIAMETERS = 2.5;
	/** The background is measured in this outer part of {@code max_radius} (percent). */
	public static final int BACKGROUND_ANNULUS_PERCENT = 20;
	/** Fewest pixels accepted in the background annulus. */
	static final int MIN_BACKGROUND_PIXELS = 20;

	/**
	 * What the profile shows.
	 *
	 * @param x refined particle centre x (px, TrackMate convention: pixel (0,0)'s centre is at 0,0)
	 * @param y refined particle centre y (px)
	 * @param refined whether the radial-symmetry refinement found the particle (else the given point is used)
	 * @param diameter the particle diameter given (px)
	 * @param maxRadius radius measured out to (px)
	 * @param radius mean distance of each ring's pixels from the centre (px); ring {@code k} holds the pixels at
	 *        distances in {@code [k - 0.5, k + 0.5)}
	 * @param mean mean grey level of each ring
	 * @param count pixels in each ring
	 * @param background background grey level {@code I0}
	 * @param noise pixel-noise standard deviation {@code s} of the frame
	 * @param peak brightest pixel near the given point
	 * @param reach radius beyond which {@code |I(r) - I0| <= s} (px)
	 * @param rOut suggested {@code r_out}: {@code reach + 2} (px, not rounded)
	 * @param bridge brightest grey level between two such particles at contact
	 * @param threshold suggested threshold: {@code bridge + 3 s} (not rounded)
	 * @param activeRadius radius of the particle's active area at the suggested threshold (px; 0 when even the
	 *        centre is below it)
	 * @param warnings things the user should know, one sentence each (empty when all is well)
	 */
	public record Result(double x, double y, boolean refined, double diameter, double maxRadius, double[] radius,
		double[] mean, int[] count, double background, double noise, double peak, double reach, double rOut,
		double bridge, double threshold, double activeRadius, List<String> warnings)
	{
		public Result {
			warnings = List.copyOf(warnings);
		}
	}

	private ProfileAnalysis() {}

	/**
	 * @param frame a 2D frame
	 * @param px x of a point on the particle (px, in the frame's coordinates)
	 * @param py y of a point on the particle (px)
	 * @param diameter particle diameter (px): the centre distance at contact
	 * @param maxRadius radius to measure out to (px); 0 for {@value #AUTO_RADIUS_DIAMETERS} diameters. It is
	 *        clipped to the farthest image corner.
	 * @return the profile and the suggestions
	 * @throws IllegalArgumentException with a one-line message: bad diameter or radius, point outside the frame,
	 *         no background ring inside the image, or no particle brighter than the noise at the point
	 */
	public static <T extends RealType<T>> Result analyse(final RandomAccessibleInterval<T> frame, final double px,
		final double py, final double diameter, final double maxRadius)
	{
		if (!(diameter > 0) || !Double.isFinite(diameter))
			throw new InvalidInputException("diameter must be the particle diameter in pixels (> 0), not " + fmt(
				diameter));
		if (!(maxRadius >= 0) || !Double.isFinite(maxRadius))
			throw new InvalidInputException("max_radius must be >= 0 pixels (0 = automatic), not " + fmt(maxRadius));
		final Plane plane = Plane.of(frame);
		final double lx = px - plane.minX(), ly = py - plane.minY();
		final int w = plane.width(), h = plane.height();
		if (!(lx >= -0.5 && lx < w - 0.5 && ly >= -0.5 && ly < h - 0.5))
			throw new InvalidInputException("point (" + fmt(px) + ", " + fmt(py) + ") is outside the image");

		final double wanted = maxRadius > 0 ? maxRadius : AUTO_RADIUS_DIAMETERS * diameter;
		final double radiusCap = Math.min(wanted, farthestCorner(lx, ly, w, h));
		final double noise = NoiseEstimate.sigma(plane);

		// A first background and peak around the given point, to refine the centre.
		final double background0 = background(plane, lx, ly, radiusCap);
		final double peak = peak(plane, lx, ly, Math.max(2, diameter / 4));
		if (!(peak - background0 > THRESHOLD_MARGIN_SIGMAS * noise))
			throw new InvalidInputException(String.format(Locale.ROOT, "no bright particle at (%s, %s): the " +
				"brightest pixel within %s px is %s, within %s noise sigmas (%s) of the background %s", fmt(px), fmt(py),
				fmt(Math.max(2, diameter / 4)), fmt(peak), fmt(THRESHOLD_MARGIN_SIGMAS), fmt(noise), fmt(background0)));

		final List<String> warnings = new ArrayList<>();
		final Localization spot = refine(frame, px, py, diameter, background0 + 0.5 * (peak - background0));
		final boolean refined = spot != null;
		double cx = lx, cy = ly;
		if (refined) {
			cx = spot.x() - plane.minX();
			cy = spot.y() - plane.minY();
			if (spot.has(Flag.MERGED))
				warnings.add("the particle's active area looks merged with a neighbour's: pick an isolated particle");
		}
		else warnings.add("could not refine the centre; the profile is taken around the point given");

		// The profile around the refined centre.
		final int bins = (int) Math.floor(radiusCap + 0.5) + 1;
		final double[] sum = new double[bins], sumR = new double[bins];
		final int[] count = new int[bins];
		final int x0 = (int) Math.max(0, Math.floor(cx - radiusCap)), x1 = (int) Math.min(w - 1, Math.ceil(cx + radiusCap));
		final int y0 = (int) Math.max(0, Math.floor(cy - radiusCap)), y1 = (int) Math.min(h - 1, Math.ceil(cy + radiusCap));
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				final double r = Math.hypot(x - cx, y - cy);
				final int k = (int) Math.floor(r + 0.5);
				if (r > radiusCap || k >= bins) continue;
				sum[k] += plane.get(x, y);
				sumR[k] += r;
				count[k]++;
			}
		int used = bins;
		while (used > 0 && count[used - 1] == 0)
			used--;
		final double[] radius = new double[used], mean = new double[used];
		final int[] n = Arrays.copyOf(count, used);
		for (int k = 0; k < used; k++) {
			radius[k] = n[k] > 0 ? sumR[k] / n[k] : k;
			mean[k] = n[k] > 0 ? sum[k] / n[k] : Double.NaN;
		}
		final double background = background(plane, cx, cy, radiusCap);

		// Reach: scan inwards from the inner edge of the background ring.
		final double inner = innerBackgroundRadius(radiusCap);
		int last = -1;
		for (int k = 0; k < used; k++)
			if (radius[k] < inner && n[k] > 0) last = k;
		double reach = 0;
		for (int k = last; k >= 0; k--) {
			if (n[k] == 0 || !(Math.abs(mean[k] - background) > noise)) continue;
			if (k == last) {
				reach = radius[k];
				warnings.add(String.format(Locale.ROOT, "the profile has not returned to the background by %s px: " +
					"increase max_radius (r_out is a lower bound)", fmt(inner)));
			}
			else {
				int j = k + 1;
				while (j < last && n[j] == 0)
					j++;
				final double a = Math.abs(mean[k] - background), b = Math.abs(mean[j] - background);
				reach = radius[k] + (radius[j] - radius[k]) * (a - noise) / (a - b);
			}
			break;
		}
		final double rOut = reach + R_OUT_MARGIN_PX;

		// The brightest point between two particles at contact.
		final double half = diameter / 2;
		double brightest = 0; // far along the bisector: the background
		if (half < reach) {
			brightest = Math.max(brightest, interpolate(radius, mean, n, half) - background);
			for (int k = 0; k < used; k++)
				if (n[k] > 0 && radius[k] > half && radius[k] <= reach) brightest = Math.max(brightest, mean[k] -
					background);
		}
		final double bridge = background + 2 * brightest;
		final double threshold = bridge + THRESHOLD_MARGIN_SIGMAS * noise;

		double activeRadius = 0;
		int previous = -1;
		for (int k = 0; k < used; k++) {
			if (n[k] == 0) continue;
			if (mean[k] < threshold) {
				if (previous >= 0) activeRadius = radius[previous] + (radius[k] - radius[previous]) * (mean[previous] -
					threshold) / (mean[previous] - mean[k]);
				break;
			}
			activeRadius = radius[k];
			previous = k;
		}
		if (activeRadius == 0)
			warnings.add("the suggested threshold is above the particle's centre: at contact no threshold separates " +
				"two such particles (the profile is too long-ranged for the method)");
		if (rOut > diameter)
			warnings.add(String.format(Locale.ROOT, "r_out (%s px) is larger than the diameter (%s px): at contact " +
				"little undistorted active area is left for the second pass (the paper needs r_out <= D)", fmt(rOut), fmt(
					diameter)));
		return new Result(cx + plane.minX(), cy + plane.minY(), refined, diameter, radiusCap, radius, mean, n,
			background, noise, peak, reach, rOut, bridge, threshold, activeRadius, warnings);
	}

	/** Radial-symmetry centre of the particle nearest the point, or null. */
	private static <T extends RealType<T>> Localization refine(final RandomAccessibleInterval<T> frame,
		final double px, final double py, final double diameter, final double threshold)
	{
		final long[] min = new long[2], max = new long[2];
		final double[] p = { px, py };
		for (int d = 0; d < 2; d++) {
			min[d] = Math.max(frame.min(d), (long) Math.floor(p[d] - diameter));
			max[d] = Math.min(frame.max(d), (long) Math.ceil(p[d] + diameter));
		}
		final TrackerParameters params = new TrackerParameters(threshold, Math.max(1, diameter / 2), 5,
			Connectivity.EIGHT, TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.FIRST);
		Localization best = null;
		double bestDistance = diameter / 2;
		for (final Localization s : new ContactTracker(params).track(Views.interval(frame, min, max), 0)) {
			final double d = Math.hypot(s.x() - px, s.y() - py);
			if (d <= bestDistance) {
				best = s;
				bestDistance = d;
			}
		}
		return best;
	}

	private static double innerBackgroundRadius(final double radiusCap) {
		return radiusCap * (1 - BACKGROUND_ANNULUS_PERCENT / 100.0);
	}

	/** Median of the pixels in the outer ring of {@code radiusCap} around (cx, cy). */
	private static double background(final Plane plane, final double cx, final double cy, final double radiusCap) {
		final double inner = innerBackgroundRadius(radiusCap);
		final int w = plane.width(), h = plane.height();
		final int x0 = (int) Math.max(0, Math.floor(cx - radiusCap)), x1 = (int) Math.min(w - 1, Math.ceil(cx + radiusCap));
		final int y0 = (int) Math.max(0, Math.floor(cy - radiusCap)), y1 = (int) Math.min(h - 1, Math.ceil(cy + radiusCap));
		double[] values = new double[1024];
		int n = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				final double r = Math.hypot(x - cx, y - cy);
				if (r < inner || r > radiusCap) continue;
				if (n == values.length) values = Arrays.copyOf(values, 2 * n);
				values[n++] = plane.get(x, y);
			}
		if (n < MIN_BACKGROUND_PIXELS)
			throw new InvalidInputException(String.format(Locale.ROOT, "only %d pixels lie between %s and %s px " +
				"from the particle inside the image: too few to measure the background; use a larger image or " +
				"max_radius", n, fmt(inner), fmt(radiusCap)));
		Arrays.sort(values, 0, n);
		return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
	}

	private static double peak(final Plane plane, final double cx, final double cy, final double within) {
		double peak = Double.NEGATIVE_INFINITY;
		final int x0 = (int) Math.max(0, Math.floor(cx - within)), x1 = (int) Math.min(plane.width() - 1, Math.ceil(cx +
			within));
		final int y0 = (int) Math.max(0, Math.floor(cy - within)), y1 = (int) Math.min(plane.height() - 1, Math.ceil(
			cy + within));
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				if (Math.hypot(x - cx, y - cy) <= within) peak = Math.max(peak, plane.get(x, y));
		return peak;
	}

	/** Linear interpolation of the ring means at radius {@code r}. */
	private static double interpolate(final double[] radius, final double[] mean, final int[] n, final double r) {
		int below = -1, above = -1;
		for (int k = 0; k < radius.length; k++) {
			if (n[k] == 0) continue;
			if (radius[k] <= r) below = k;
			else if (above < 0) above = k;
		}
		if (below < 0) return mean[above];
		if (above < 0) return mean[below];
		return mean[below] + (mean[above] - mean[below]) * (r - radius[below]) / (radius[above] - radius[below]);
	}

	private static double farthestCorner(final double x, final double y, final int w, final int h) {
		final double dx = Math.max(x, w - 1 - x), dy = Math.max(y, h - 1 - y);
		return Math.hypot(dx, dy);
	}

	private static String fmt(final double v) {
		if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
		return String.format(Locale.ROOT, "%.4g", v);
	}
}
