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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.ImageAccess;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.track.TrackAccess;

/**
 * {@link FitPixels#gather}, read by row spans, against its definition pixel by pixel; and the primitive-array fast
 * paths of {@link Plane} it and the first pass rest on ({@link Plane#read}, the 8-bit threshold scan) against the
 * general ones.
 */
class FitPixelsTest {

	private static final int W = 150, H = 120;

	/** Five particles (one below another, so that light reaches a group from above and below), clipped bright cores and a dark floor, so that censoring leaves pixels out. */
	private static Plane frame() {
		final double[] img = TestImages.withUniformNoise(TestImages.render(W, H, 12, TestImages.gaussian(260, 5),
			new double[] { 40.3, 44.1 }, new double[] { 58.9, 47.2 }, new double[] { 110.2, 30.4 }, new double[] { 95.6,
				95.1 }, new double[] { 60.4, 101.3 }), 14, 5);
		return Plane.of(TestImages.bytes(img, W, H));
	}

	private static EmpiricalProfile profile() {
		// a long faint tail: every group's pixels get the light of the others
		final double[] c = new double[45];
		for (int j = 0; j < c.length; j++)
			c[j] = 240 * Math.exp(-j * j / 50.0) - 10 * Math.exp(-(j - 12) * (j - 12) / 6.0) + 8 * Math.exp(-j / 15.0);
		return ProfileAccess.profile(1, c, 12, 1000);
	}

	/**
	 * The definition: every pixel of the members' bounding box within a member's window, row by row, unclipped; the
	 * other reliable particles' light summed over all pixels.
	 */
	private static FitPixels reference(final Plane plane, final Particle[] ps, final Estimate[] e, final int[] group,
		final EmpiricalProfile profile, final double window, final Censoring censoring)
	{
		final double W2 = Math.min(profile.radius(), window);
		int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
		for (final int k : group) {
			final double reach = W2 * GroupFit.scaleOf(e[k]);
			x0 = Math.min(x0, (int) Math.floor(e[k].x() - reach));
			x1 = Math.max(x1, (int) Math.ceil(e[k].x() + reach));
			y0 = Math.min(y0, (int) Math.floor(e[k].y() - reach));
			y1 = Math.max(y1, (int) Math.ceil(e[k].y() + reach));
		}
		x0 = Math.max(0, x0);
		y0 = Math.max(0, y0);
		x1 = Math.min(plane.width() - 1, x1);
		y1 = Math.min(plane.height() - 1, y1);
		final List<int[]> kept = new ArrayList<>();
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				boolean inside = false;
				for (final int k : group) {
					final double reach = W2 * GroupFit.scaleOf(e[k]), dx = x - e[k].x(), dy = y - e[k].y();
					inside |= dx * dx + dy * dy < reach * reach;
				}
				if (inside && !censoring.clipped(plane.get(x, y))) kept.add(new int[] { x, y });
			}
		final int n = kept.size();
		final int[] xs = new int[n], ys = new int[n];
		final double[] values = new double[n], fixed = new double[n];
		for (int i = 0; i < n; i++) {
			xs[i] = kept.get(i)[0];
			ys[i] = kept.get(i)[1];
			values[i] = plane.get(xs[i], ys[i]);
			for (int k = 0; k < ps.length; k++) {
				if (!ps[k].reliable() || GroupFit.contains(group, k)) continue;
				final double ks = GroupFit.scaleOf(e[k]), reach = profile.radius() * ks;
				final double dx = xs[i] - e[k].x(), dy = ys[i] - e[k].y(), d2 = dx * dx + dy * dy;
				if (d2 < reach * reach) fixed[i] += GroupFit.amplitudeOf(e[k]) * profile.lookup(Math.sqrt(d2) / ks);
			}
		}
		return new FitPixels(xs, ys, values, fixed, n, 0.5 * (x0 + x1), 0.5 * (y0 + y1), Math.max(1, 0.5 * (x1 - x0)));
	}

	@Test
	void gatherByRowSpansIsTheDefinitionPixelByPixel() {
		final Plane plane = frame();
		final Particle[] ps = TrackAccess.particles(plane, TrackerParameters.of(120, 15));
		assertEquals(5, ps.length);
		final EmpiricalProfile profile = profile();
		final Censoring censoring = Censoring.of(plane, 4);
		final Random random = new Random(3);
		int compared = 0;
		for (int trial = 0; trial < 40; trial++) {
			// centres off the pixel grid, windows of several sizes and scales, groups of one to five
			final Estimate[] e = new Estimate[ps.length];
			for (int k = 0; k < ps.length; k++) {
				final Estimate f = ps[k].first();
				e[k] = new Estimate(f.x() + random.nextGaussian(), f.y() + random.nextGaussian(), 0, 0, 1, null, Double.NaN,
					Double.NaN, 0.8 + 0.4 * random.nextDouble(), 0.7 + 0.6 * random.nextDouble());
			}
			final int size = 1 + trial % ps.length;
			final int[] group = new int[size];
			for (int q = 0; q < size; q++)
				group[q] = (trial + q) % ps.length;
			final double window = 5 + 30 * random.nextDouble();
			final FitPixels got = FitPixels.gather(plane, ps, e, group, alike(profile, ps.length), window, censoring);
			final FitPixels want = reference(plane, ps, e, group, profile, window, censoring);
			assertEquals(want.count(), got.count(), "trial " + trial);
			assertArrayEquals(java.util.Arrays.copyOf(want.x(), want.count()), java.util.Arrays.copyOf(got.x(), got
				.count()));
			assertArrayEquals(java.util.Arrays.copyOf(want.y(), want.count()), java.util.Arrays.copyOf(got.y(), got
				.count()));
			for (int i = 0; i < want.count(); i++) {
				assertEquals(want.value()[i], got.value()[i], 0);
				// (the loop multiplies by 1 / (scale * step) where the definition divides: the last bit may differ)
				assertEquals(want.fixed()[i], got.fixed()[i], 1e-12 * Math.max(1, Math.abs(want.fixed()[i])),
					"other groups' light, pixel " + i);
				assertEquals(want.u()[i], got.u()[i], 0);
				assertEquals(want.v()[i], got.v()[i], 0);
			}
			assertArrayEquals(want.backgroundBlock(), got.backgroundBlock(), 0);
			assertArrayEquals(want.extent(), got.extent(), 1e-12); // (its last two: the extremes of that light)
			compared += got.count();
		}
		assertTrue(compared > 20_000, "pixels compared: " + compared);
	}

	/**
	 * A member's kept pixels may be none (every candidate chosen out near the clip levels): lit again after its
	 * neighbours moved, it has none, and no light (it is then not fitted), rather than an internal error.
	 */
	@Test
	void noPixelsKeptAreLitAgainAsNone() {
		final Plane plane = frame();
		final Particle[] ps = TrackAccess.particles(plane, TrackerParameters.of(120, 15));
		final EmpiricalProfile[] profiles = alike(profile(), ps.length);
		final Estimate[] e = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++)
			e[k] = ps[k].first();
		final int[] group = { 0 };
		final FitPixels gathered = FitPixels.gather(plane, ps, e, group, profiles, 20, Censoring.of(plane, 4));
		final FitPixels.Lit lit = gathered.litAt(ps, e, group, profiles, null);
		assertTrue(lit.which().length > 0, "neighbours light the member's pixels");
		final FitPixels none = gathered.subset(new boolean[gathered.count()]).asCandidates();
		assertEquals(0, none.count());
		for (int k = 1; k < ps.length; k++) // every neighbour moved
			e[k] = new Estimate(e[k].x() + 0.5, e[k].y(), 0, 0, 1, null, Double.NaN, Double.NaN, 1, 1);
		final FitPixels relit = none.relit(ps, e, group, profiles, lit, null, RowRuns.of(none.x(), none.y(), 0));
		assertEquals(0, relit.count());
		assertEquals(0, relit.fixed().length);
	}

	@Test
	void clippedPixelsAreLeftOut() {
		final Plane plane = frame();
		final Particle[] ps = TrackAccess.particles(plane, TrackerParameters.of(120, 15));
		final EmpiricalProfile profile = profile();
		final Estimate[] e = new Estimate[ps.length];
		for (int k = 0; k < ps.length; k++)
			e[k] = ps[k].first();
		final FitPixels got = FitPixels.gather(plane, ps, e, new int[] { 0, 1 }, alike(profile, ps.length), 20,
			Censoring.of(plane, 4));
		int clippedInWindow = 0;
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				final double dx = x - e[0].x(), dy = y - e[0].y();
				if (dx * dx + dy * dy < 400 && (plane.get(x, y) == 255 || plane.get(x, y) == 0)) clippedInWindow++;
			}
		assertTrue(clippedInWindow > 0, "the test frame clips within the window");
		for (int i = 0; i < got.count(); i++)
			assertTrue(got.value()[i] > 0 && got.value()[i] < 255, "pixel " + i + " = " + got.value()[i]);
	}

	@Test
	void readGivesWhatGetGivesOnEveryPixelType() {
		final double[] img = TestImages.withUniformNoise(TestImages.render(37, 23, 20, TestImages.gaussian(150, 4),
			new double[] { 15.2, 11.7 }), 9, 2);
		for (int i = 0; i < img.length; i++)
			img[i] = Math.round(img[i]);
		for (final Plane plane : new Plane[] { Plane.of(TestImages.bytes(img, 37, 23)), Plane.of(TestImages.shorts(img,
			37, 23)), Plane.of(TestImages.floats(img, 37, 23)), ImageAccess.generic(TestImages.bytes(img, 37, 23)) }) {
			final double[] out = new double[120];
			for (int y = 0; y + 3 < 23; y += 5) {
				java.util.Arrays.fill(out, -1);
				plane.read(3, 30, y, y + 3, out, 2); // 28 x 4 pixels, row after row
				assertEquals(-1, out[1], 0, "nothing before the offset");
				for (int yy = y; yy <= y + 3; yy++)
					for (int x = 3; x <= 30; x++)
						assertEquals(plane.get(x, yy), out[2 + 28 * (yy - y) + x - 3], 0, plane.getClass().getSimpleName() + " (" +
							x + ", " + yy + ")");
				assertEquals(-1, out[2 + 4 * 28], 0, "nothing after the rectangle");
			}
		}
	}

	/** @return {@code profile} for each of {@code n} particles (one kind) */
	static EmpiricalProfile[] alike(final EmpiricalProfile profile, final int n) {
		final EmpiricalProfile[] out = new EmpiricalProfile[n];
		java.util.Arrays.fill(out, profile);
		return out;
	}
}
