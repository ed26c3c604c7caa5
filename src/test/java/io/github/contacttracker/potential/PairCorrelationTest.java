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
package io.github.contacttracker.potential;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class PairCorrelationTest {

	@Test
	void pairFractionOfASquareMatchesTheKnownClosedForm() {
		// two uniform points of the unit square are closer than 1 with probability pi - 13/6
		assertEquals(Math.PI - 13.0 / 6, FieldOfView.of(1, 1).pairFractionWithin(1), 1e-12);
		assertEquals(0, FieldOfView.of(3, 2).pairFractionWithin(0), 0);
		// small r: the unbounded-plane value pi r^2 / A, less the edge term 4/3 (W + H) r^3 / A^2, plus r^4 / 2A^2
		assertEquals(Math.PI * 1e-6 / 6 - 4.0 / 3 * 5 * 1e-9 / 36 + 0.5e-12 / 36, FieldOfView.of(3, 2)
			.pairFractionWithin(1e-3), 1e-20);
	}

	@Test
	void pairFractionAgreesWithSampledPairsOfARectangle() {
		final FieldOfView f = FieldOfView.of(30, 20);
		final SplittableRandom random = new SplittableRandom(5);
		final int n = 400_000;
		final double[] radii = { 2, 8, 15, 20 };
		final int[] within = new int[radii.length];
		for (int i = 0; i < n; i++) {
			final double d = Math.hypot(random.nextDouble(30) - random.nextDouble(30), random.nextDouble(20) - random
				.nextDouble(20));
			for (int k = 0; k < radii.length; k++)
				if (d < radii[k]) within[k]++;
		}
		for (int k = 0; k < radii.length; k++) {
			final double p = f.pairFractionWithin(radii[k]);
			final double sigma = Math.sqrt(p * (1 - p) / n);
			assertEquals(p, within[k] / (double) n, 4 * sigma, "r = " + radii[k]);
		}
	}

	@Test
	void countsAndNormalisationAreExactOnAKnownTriangle() {
		// one frame, a 3-4-5 triangle: one pair in each of the bins [3,4), [4,5), [5,6)
		final SpotSet spots = SpotSet.ofPositions(List.of(List.of(new double[] { 1, 1 }, new double[] { 4, 1 },
			new double[] { 1, 5 })), 1);
		final FieldOfView f = FieldOfView.of(10, 8);
		final PairCorrelation.Result r = PairCorrelation.compute(spots, f, 1, 6);
		assertEquals(6, r.bins().size());
		assertEquals(3, r.framePairs(), 0);
		assertEquals(3, r.pairs());
		for (int k = 0; k < 6; k++) {
			final PairCorrelation.Bin b = r.bins().get(k);
			assertEquals(k + 0.5, b.r(), 1e-12);
			final double expected = 3 * (f.pairFractionWithin(k + 1) - f.pairFractionWithin(k));
			assertEquals(expected, b.expected(), 1e-12);
			assertEquals(k >= 3 ? 1 : 0, b.pairs());
			assertEquals(b.pairs() / expected, b.g(), 1e-12);
			if (k >= 3) {
				assertEquals(Math.log(expected), r.u(k), 1e-12);
				assertEquals(1, b.uError(), 0);
			}
			else {
				assertTrue(Double.isNaN(r.u(k)));
				assertTrue(Double.isNaN(b.uError()));
			}
		}
	}

	@Test
	void pairsOfDifferentFramesAreNotCounted() {
		final SpotSet spots = SpotSet.ofPositions(List.of(List.of(new double[] { 1, 1 }), List.of(new double[] { 1,
			2 })), 1);
		assertThrows(IllegalArgumentException.class, () -> PairCorrelation.compute(spots, FieldOfView.of(5, 5), 1, 3));
	}

	/**
	 * Uniform random points: g = 1 within the counting statistics in every bin, up to r = the field's smaller side,
	 * where most shells lie outside the field: the edge correction is what makes this hold (without it g would
	 * drop to about 0.2 at the last bin).
	 */
	@Test
	void uniformPointsGiveGOfOneUpToTheEdge() {
		final double w = 30, h = 20;
		final SplittableRandom random = new SplittableRandom(11);
		final List<List<double[]>> frames = new ArrayList<>();
		for (int f = 0; f < 400; f++) {
			final List<double[]> spots = new ArrayList<>();
			final int n = 30 + random.nextInt(21); // the number of spots varies from frame to frame
			for (int i = 0; i < n; i++)
				spots.add(new double[] { 7 + random.nextDouble(w), -3 + random.nextDouble(h) }); // anywhere: only the size matters
			frames.add(spots);
		}
		final PairCorrelation.Result r = PairCorrelation.compute(SpotSet.ofPositions(frames, 1), FieldOfView.of(w, h),
			0.5, 20);
		assertEquals(40, r.bins().size());
		double chi2 = 0;
		for (final PairCorrelation.Bin b : r.bins()) {
			final double z = (b.pairs() - b.expected()) / Math.sqrt(b.expected());
			assertTrue(Math.abs(z) < 4, "bin at " + b.r() + ": g = " + b.g() + ", z = " + z);
			chi2 += z * z;
		}
		assertTrue(chi2 / r.bins().size() < 1.6, "chi2 per bin " + chi2 / r.bins().size());
		// the outermost bins, dominated by the edge: g = 1 within 5%, where the unbounded-plane reference is far off
		final PairCorrelation.Bin last = r.bins().get(39);
		assertEquals(1, last.g(), 0.05);
		final double plane = r.framePairs() * Math.PI * (last.rHigh() * last.rHigh() - last.rLow() * last.rLow()) / (w *
			h);
		assertTrue(last.pairs() / plane < 0.3, "without the edge correction g would be " + last.pairs() / plane);
	}

	@Test
	void inferredFieldGivesGOfOneForUniformPoints() {
		final SplittableRandom random = new SplittableRandom(2);
		final List<List<double[]>> frames = new ArrayList<>();
		for (int f = 0; f < 300; f++) {
			final List<double[]> spots = new ArrayList<>();
			for (int i = 0; i < 40; i++)
				spots.add(new double[] { random.nextDouble(50), random.nextDouble(40) });
			frames.add(spots);
		}
		final SpotSet set = SpotSet.ofPositions(frames, 1);
		final FieldOfView f = FieldOfView.inferred(set.allX(), set.allY());
		assertTrue(f.inferred());
		assertEquals(50, f.width(), 0.05);
		assertEquals(40, f.height(), 0.05);
		final PairCorrelation.Result r = PairCorrelation.compute(set, f, 2, 40);
		for (final PairCorrelation.Bin b : r.bins())
			assertEquals(1, b.g(), 4 / Math.sqrt(b.expected()), "bin at " + b.r());
	}

	@Test
	void zeroRangeSetsTheMeanOfUToZeroThere() {
		final SpotSet spots = SpotSet.ofPositions(List.of(List.of(new double[] { 0, 0 }, new double[] { 1.5, 0 },
			new double[] { 0, 2.5 }, new double[] { 3.5, 0 })), 1);
		final PairCorrelation.Result raw = PairCorrelation.compute(spots, FieldOfView.of(10, 10), 1, 5);
		final PairCorrelation.Result z = raw.withZero(2, 4);
		long pairs = 0;
		double expected = 0;
		for (final PairCorrelation.Bin b : raw.bins())
			if (b.r() >= 2 && b.r() <= 4) {
				pairs += b.pairs();
				expected += b.expected();
			}
		assertEquals(-Math.log(pairs / expected), z.uZero(), 1e-12);
		for (int i = 0; i < raw.bins().size(); i++)
			if (raw.bins().get(i).pairs() > 0) assertEquals(raw.u(i) - z.uZero(), z.u(i), 1e-12);
		assertEquals(raw.bins().get(1).g(), z.bins().get(1).g(), 0); // g is left as measured
		final IllegalArgumentException none = assertThrows(IllegalArgumentException.class, () -> raw.withZero(7, 9));
		assertTrue(none.getMessage().contains("holds no bin centre"), none.getMessage());
		assertTrue(assertThrows(IllegalArgumentException.class, () -> raw.withZero(0.2, 0.8)).getMessage().contains(
			"no pair in the zero range"));
	}

	@Test
	void badBinsAndRangesAreRefusedWithTheReason() {
		final SpotSet spots = SpotSet.ofPositions(List.of(List.of(new double[] { 0, 0 }, new double[] { 1, 1 })), 1);
		final FieldOfView f = FieldOfView.of(10, 6);
		assertTrue(assertThrows(IllegalArgumentException.class, () -> PairCorrelation.compute(spots, f, 0, 5))
			.getMessage().contains("bin width"));
		assertTrue(assertThrows(IllegalArgumentException.class, () -> PairCorrelation.compute(spots, f, 1, 0.5))
			.getMessage().contains("at least one bin"));
		final String tooFar = assertThrows(IllegalArgumentException.class, () -> PairCorrelation.compute(spots, f, 1,
			7)).getMessage();
		assertTrue(tooFar.contains("r_max 7 exceeds the smaller side") && tooFar.contains("6"), tooFar);
		assertThrows(IllegalArgumentException.class, () -> FieldOfView.of(0, 3));
	}

	/**
	 * An ideal gas whose spots near the border are flagged there, as the tracker flags particles whose active area
	 * the border cuts (all within 4 units of an edge, half of those 4 to 6 units in) and left out: g = 1 within its
	 * errors in every bin, with the field given and with it inferred, because the area shrinks with the counts.
	 * Counting the same spots against the whole field gives g well above 1 (the density the reference assumes is
	 * too low), which is what the shrinking corrects.
	 */
	@Test
	void idealGasWithBorderSpotsLeftOutGivesGOfOne() {
		final double w = 100, h = 80;
		final SplittableRandom random = new SplittableRandom(40);
		final List<Double> xs = new ArrayList<>(), ys = new ArrayList<>(), frames = new ArrayList<>(), border =
			new ArrayList<>();
		for (int f = 0; f < 300; f++)
			for (int i = 0; i < 60; i++) {
				final double x = random.nextDouble(w), y = random.nextDouble(h);
				final double depth = Math.min(Math.min(x, w - x), Math.min(y, h - y));
				xs.add(x);
				ys.add(y);
				frames.add((double) f);
				border.add(depth < 4 || depth < 6 && random.nextBoolean() ? 1.0 : 0.0);
			}
		final java.util.Map<String, double[]> columns = new java.util.LinkedHashMap<>();
		columns.put(SpotSet.X, xs.stream().mapToDouble(Double::doubleValue).toArray());
		columns.put(SpotSet.Y, ys.stream().mapToDouble(Double::doubleValue).toArray());
		columns.put(SpotSet.FRAME, frames.stream().mapToDouble(Double::doubleValue).toArray());
		columns.put(SpotSet.BORDER_FLAG, border.stream().mapToDouble(Double::doubleValue).toArray());
		final SpotSet set = SpotSet.fromColumns(columns, SpotSet.Selection.DEFAULT);
		final long flagged = border.stream().filter(b -> b != 0).count();
		assertEquals(flagged, set.flaggedLeftOut());

		for (final FieldOfView field : List.of(FieldOfView.of(w, h), set.inferredField())) {
			final PairCorrelation.Result r = PairCorrelation.compute(set, field, 1, 30);
			// the border reaches as deep as the deepest flagged spot: just under 6
			assertEquals(6, r.borderReach(), 0.1, "reach with " + field);
			assertEquals(w - 2 * r.borderReach(), r.field().width(), 0.15);
			assertEquals(h - 2 * r.borderReach(), r.field().height(), 0.15);
			// every spot is used, flagged, or as near the border as flagged ones
			assertEquals(xs.size(), r.spots() + set.flaggedLeftOut() + r.nearBorderLeftOut());
			assertTrue(r.nearBorderLeftOut() > 0);
			double chi2 = 0;
			for (final PairCorrelation.Bin b : r.bins()) {
				final double z = (b.pairs() - b.expected()) / Math.sqrt(b.expected());
				assertTrue(Math.abs(z) < 4, field + ": bin at " + b.r() + ": g = " + b.g() + ", z = " + z);
				chi2 += z * z;
			}
			assertTrue(chi2 / r.bins().size() < 1.6, field + ": chi2 per bin " + chi2 / r.bins().size());
			// over all bins together: 1 within 1% (the total's own error is about 0.3%)
			long pairs = 0;
			double expected = 0;
			for (final PairCorrelation.Bin b : r.bins()) {
				pairs += b.pairs();
				expected += b.expected();
			}
			assertEquals(1, pairs / expected, 0.01, field.toString());
		}

		// the spots kept, counted against the whole field: g far from 1, what the shrinking corrects
		final SpotSet kept = SpotSet.fromColumns(columnsWithout(columns, SpotSet.BORDER_FLAG, border),
			new SpotSet.Selection(0, false));
		final PairCorrelation.Result whole = PairCorrelation.compute(kept, FieldOfView.of(w, h), 1, 30);
		assertTrue(whole.bins().get(5).g() > 1.15, "whole-field g " + whole.bins().get(5).g());
	}

	/** @return the columns with the rows flagged in {@code flag} removed, and that column dropped */
	private static java.util.Map<String, double[]> columnsWithout(final java.util.Map<String, double[]> columns,
		final String flag, final List<Double> flags)
	{
		final java.util.Map<String, double[]> out = new java.util.LinkedHashMap<>();
		for (final var e : columns.entrySet()) {
			if (e.getKey().equals(flag)) continue;
			final double[] v = e.getValue();
			final double[] kept = new double[(int) flags.stream().filter(b -> b == 0).count()];
			for (int i = 0, k = 0; i < v.length; i++)
				if (flags.get(i) == 0) kept[k++] = v[i];
			out.put(e.getKey(), kept);
		}
		return out;
	}
}
