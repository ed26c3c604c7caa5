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

import java.util.Random;

import org.junit.jupiter.api.Test;

import net.imglib2.img.array.ArrayImgs;

import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileAccess;

/**
 * The least-squares pass of {@link GroupFit} ({@link NormalEquations}) against the least squares' definition, for
 * groups of one, two and three members, of one kind and of two.
 */
class NormalEquationsTest {

	/**
	 * A ringed profile (bright core, dark ring) reaching 30 px, and noisy particles at {@code (x, y)} pairs on a plane
	 * with others' light.
	 */
	private static FitPixels pixels(final EmpiricalProfile profile, final double... centres) {
		final Random random = new Random(11);
		final int w = 70, h = 64, n = w * h;
		final int[] xs = new int[n], ys = new int[n];
		final double[] values = new double[n], fixed = new double[n];
		for (int y = 0, i = 0; y < h; y++)
			for (int x = 0; x < w; x++, i++) {
				xs[i] = x;
				ys[i] = y;
				fixed[i] = 0.01 * x;
				values[i] = 40 + 0.05 * x + fixed[i] + 3 * random.nextGaussian();
				for (int c = 0; c < centres.length; c += 2)
					values[i] += 1.1 * profile.value(Math.hypot(x - centres[c], y - centres[c + 1]) / 0.97);
			}
		return new FitPixels(xs, ys, values, fixed, n, 0.5 * (w - 1), 0.5 * (h - 1), 0.5 * (w - 1));
	}

	private static EmpiricalProfile ringed() {
		return ringed(120, 14);
	}

	/** A ringed profile of central height {@code peak} and dark ring at {@code ring} px (another kind of particle). */
	private static EmpiricalProfile ringed(final double peak, final double ring) {
		final double[] c = new double[29];
		for (int j = 0; j < c.length; j++)
			c[j] = peak * Math.exp(-j * j / 60.0) - 25 * Math.exp(-(j - ring) * (j - ring) / 8.0);
		return ProfileAccess.profile(1, c, 40, 1000);
	}

	/**
	 * The model of the fit at parameters {@code p} on pixel {@code i}, from its definition: background plane, other
	 * groups' light, and each member's light {@code a_q P_q(|x - c_q| / s_q)} by the profile's own lookup.
	 */
	private static double model(final FitPixels px, final int i, final double[] p, final EmpiricalProfile[] profile) {
		final int n = profile.length, b0 = 4 * n;
		double m = p[b0] + p[b0 + 1] * px.u()[i] + p[b0 + 2] * px.v()[i] + px.fixed()[i];
		for (int q = 0; q < n; q++)
			m += p[4 * q + 2] * profile[q].lookup(Math.hypot(px.x()[i] - p[4 * q], px.y()[i] - p[4 * q + 1]) / p[4 * q +
				3]);
		return m;
	}

	/**
	 * The one pass against the least squares' definition: residuals and models exactly, J^T r and J^T J against
	 * those of a Jacobian by central differences of the model (the pass differentiates the profile's spline, the
	 * differences its table: they agree to a few 1e-4 of the largest entry).
	 */
	private static void assertMatchesDefinition(final FitPixels px, final double[] p,
		final EmpiricalProfile[] profile)
	{
		assertMatchesDefinition(px, p, profile, null);
	}

	/**
	 * As {@link #assertMatchesDefinition(FitPixels, double[], EmpiricalProfile[])}, the floor linked by {@code link}
	 * (null: not): the residuals against the link's mean of the model, the Jacobian that of the mean (by central
	 * differences of it).
	 */
	private static void assertMatchesDefinition(final FitPixels px, final double[] p,
		final EmpiricalProfile[] profile, final Censoring link)
	{
		final int n = profile.length, np = p.length;
		final double[][] jtj = new double[np][np];
		final double[] jtr = new double[np], models = new double[px.count()];
		final double rss = new NormalEquations(link).accumulate(px, p, n, profile, jtj, jtr, new double[4 * n],
			models);
		final double[][] wantJtj = new double[np][np];
		final double[] wantJtr = new double[np], g = new double[np];
		double wantRss = 0;
		int linked = 0;
		for (int i = 0; i < px.count(); i++) {
			final double m = model(px, i, p, profile), r = px.value()[i] - mean(link, m);
			if (link != null && m < link.linkTop()) linked++;
			assertEquals(m, models[i], 1e-9 * Math.abs(m), "model at pixel " + i);
			wantRss += r * r;
			for (int a = 0; a < np; a++) {
				final double h = 1e-5 * Math.max(1, Math.abs(p[a]));
				final double[] up = p.clone(), down = p.clone();
				up[a] += h;
				down[a] -= h;
				g[a] = (mean(link, model(px, i, up, profile)) - mean(link, model(px, i, down, profile))) / (2 * h);
			}
			for (int a = 0; a < np; a++) {
				wantJtr[a] += g[a] * r;
				for (int b = 0; b < np; b++)
					wantJtj[a][b] += g[a] * g[b];
			}
		}
		assertEquals(wantRss, rss, 1e-9 * wantRss);
		// each entry on its own scale: J^T J's by its diagonal (a correlation), J^T r's by the residuals' norm
		for (int a = 0; a < np; a++) {
			assertEquals(wantJtr[a], jtr[a], 1e-3 * Math.sqrt(wantJtj[a][a] * wantRss), "J^T r, parameter " + a);
			for (int b = 0; b < np; b++)
				assertEquals(wantJtj[a][b], jtj[a][b], 1e-3 * Math.sqrt(wantJtj[a][a] * wantJtj[b][b]), "J^T J, " + a +
					", " + b);
		}
		if (link != null) assertTrue(linked > px.count() / 10 && linked < px.count(), linked + " of " + px.count() +
			" pixels linked: the test must mix both");
	}

	/** @return the model through the link, or the model itself where none */
	private static double mean(final Censoring link, final double model) {
		return link == null || model >= link.linkTop() ? model : link.mean(model);
	}

	/**
	 * The floor linked (here with a noise of 8 grey levels, so that the link reaches 48.5 grey levels, above the
	 * background of 40, below the particles' cores): the passes of a group of one and of two against the definition
	 * of least squares through the link, the background plane's rows and its own block included.
	 */
	@Test
	void linkedFloorMatchesTheDefinition() {
		final byte[] frame = new byte[100];
		java.util.Arrays.fill(frame, (byte) 50);
		final Censoring link = Censoring.of(Plane.of(ArrayImgs.unsignedBytes(frame, 10, 10)), 8);
		assertTrue(link.linked());
		final EmpiricalProfile profile = ringed();
		assertMatchesDefinition(pixels(profile, 34.3, 31.8), new double[] { 34.1, 32.0, 1.05, 0.98, 39, 0.4, -0.2 },
			new EmpiricalProfile[] { profile }, link);
		assertMatchesDefinition(pixels(profile, 24.3, 31.8, 44.1, 30.2), new double[] { 24.1, 32.0, 1.05, 0.98, 44.3,
			30.1, 0.95, 1.02, 39, 0.4, -0.2 }, new EmpiricalProfile[] { profile, profile }, link);
	}

	@Test
	void oneMember() {
		final EmpiricalProfile profile = ringed();
		assertMatchesDefinition(pixels(profile, 34.3, 31.8), new double[] { 34.1, 32.0, 1.05, 0.98, 39, 0.4, -0.2 },
			new EmpiricalProfile[] { profile });
	}

	/**
	 * The pass of a group of one ({@code accumulateOne}) gives what the pass of every group size gives for the same
	 * member to the last bit: the member's sums taken out of a group of two whose other member lies out of reach of
	 * every pixel (its terms are never added), the noise weights and the models included, with J^T J and without.
	 */
	@Test
	void oneMembersOwnPassIsTheGeneralOne() {
		final EmpiricalProfile profile = ringed();
		final FitPixels px = pixels(profile, 34.3, 31.8);
		final double[] one = { 34.1, 32.0, 1.05, 0.98, 39, 0.4, -0.2 };
		final double[] two = { 34.1, 32.0, 1.05, 0.98, 500, 500, 1, 1, 39, 0.4, -0.2 };
		final double[][] jtj1 = new double[7][7], jtj2 = new double[11][11];
		final double[] jtr1 = new double[7], jtr2 = new double[11], noise1 = new double[4], noise2 = new double[8];
		final double[] models1 = new double[px.count()], models2 = new double[px.count()];
		final double rss1 = new NormalEquations().accumulate(px, one, 1, new EmpiricalProfile[] { profile }, jtj1, jtr1,
			noise1, models1);
		final double rss2 = new NormalEquations().accumulate(px, two, 2, new EmpiricalProfile[] { profile, profile }, jtj2,
			jtr2, noise2, models2);
		assertEquals(rss2, rss1, 0);
		assertArrayEquals(models2, models1, 0);
		assertArrayEquals(java.util.Arrays.copyOf(noise2, 4), noise1, 0);
		// parameter a of the group of one is parameter at[a] of the group of two
		final int[] at = { 0, 1, 2, 3, 8, 9, 10 };
		for (int a = 0; a < 7; a++) {
			assertEquals(jtr2[at[a]], jtr1[a], 0, "J^T r, parameter " + a);
			for (int b = 0; b < 7; b++)
				assertEquals(jtj2[at[a]][at[b]], jtj1[a][b], 0, "J^T J, " + a + ", " + b);
		}
		assertTrue(jtj1[0][0] > 0 && noise1[1] > 0, "the member's terms were added");
		// the residual pass (no J^T J), adding to noise sums already there, as a fit's passes do
		final double[] more1 = { 1.5, 2.5, 3.5, 4.5 }, more2 = { 1.5, 2.5, 3.5, 4.5, 0, 0, 0, 0 };
		one[0] += 0.03;
		two[0] += 0.03;
		assertEquals(new NormalEquations().accumulate(px, two, 2, new EmpiricalProfile[] { profile, profile }, null, jtr2,
			more2, null), new NormalEquations().accumulate(px, one, 1, new EmpiricalProfile[] { profile }, null, jtr1, more1,
				null), 0);
		assertArrayEquals(java.util.Arrays.copyOf(more2, 4), more1, 0);
		for (int a = 0; a < 7; a++)
			assertEquals(jtr2[at[a]], jtr1[a], 0, "J^T r of the residual pass, parameter " + a);
	}

	/**
	 * Two members of unlike kinds (profiles), near enough for shared pixels and far enough for pixels out of one
	 * member's reach (the profiles reach 30 px).
	 */
	@Test
	void twoMembersOfTwoKinds() {
		final EmpiricalProfile profile = ringed();
		final FitPixels px = pixels(profile, 24.3, 31.8, 47.6, 30.1);
		final double[] p = { 24.1, 32.0, 1.05, 0.98, 47.9, 30.0, 0.9, 1.04, 39, 0.4, -0.2 };
		int onlyOne = 0;
		for (int i = 0; i < px.count(); i++)
			if ((Math.hypot(px.x()[i] - p[0], px.y()[i] - p[1]) < 30 * p[3]) != (Math.hypot(px.x()[i] - p[4], px.y()[i] -
				p[5]) < 30 * p[7])) onlyOne++;
		assertTrue(onlyOne > 500, "pixels within reach of one member only: " + onlyOne);
		assertMatchesDefinition(px, p, new EmpiricalProfile[] { profile, ringed(90, 11) });
	}

	@Test
	void threeMembers() {
		final EmpiricalProfile profile = ringed();
		assertMatchesDefinition(pixels(profile, 20.2, 20.7, 41.1, 22.4, 30.6, 40.9), new double[] { 20.0, 20.5, 1.1, 1.0,
			41.3, 22.2, 0.95, 1.02, 30.4, 41.0, 1.0, 0.97, 40, 0.3, 0.1 }, new EmpiricalProfile[] { profile, profile,
				ringed(90, 11) });
	}
}
