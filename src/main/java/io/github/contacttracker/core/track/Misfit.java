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
package io.github.contacttracker.core.track;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.math.Statistics;

/**
 * Spots found by the image whose light the measured profile does not describe: flagged {@code MERGED}.
 * <p>
 * For a particle the model describes, a centre's standard error falls as one over the square root of its
 * significance (how much its light lowers the residuals, in noise units: its {@code QUALITY} under detection by the
 * image), so their product is about the same for every particle, whatever its brightness (it grows with the
 * particle's size, not by more than about two between the kinds of one movie). A spot whose product is
 * {@value #TIMES} times the typical one (the median over the unflagged spots of the movie's sample frames) holds
 * light that one particle of the profile cannot make: two particles closer than the filter told apart, fitted as one
 * between them (on a simulated pair pushed into overlap, 10 to 24 times), or debris. Left unflagged, such a spot is a
 * wrong centre nothing marks. The typical product is the whole sample's, not each kind's: spots that all hold merged
 * pairs can make a kind of their own. On the footage of other laboratories tracked by the image, 0 to 1.3% of the
 * unflagged spots pass that mark (measured: 7 of 593 touching fluorescent beads, 8 of 2440 bright-field spheres).
 *
 * @param typical the typical product, NaN where the sample held fewer than {@value #MIN_SPOTS} unflagged spots (no
 *        spot is then flagged)
 */
record Misfit(double typical) implements Serializable {

	private static final long serialVersionUID = 1L;

	/** How many times the typical product a spot's must exceed to be flagged. */
	static final double TIMES = 5;

	/** Fewest unflagged spots on the sample frames for their median to be the typical product. */
	static final int MIN_SPOTS = 10;

	/** @return the typical product of the sample frames' unflagged spots */
	static Misfit of(final List<FrameResult> sample) {
		final List<Double> p = new ArrayList<>();
		for (final FrameResult r : sample)
			for (final Localization l : r.spots()) {
				final double x = product(l);
				if (!l.isFlagged() && Double.isFinite(x)) p.add(x);
			}
		if (p.size() < MIN_SPOTS) return new Misfit(Double.NaN);
		final double[] v = new double[p.size()];
		for (int i = 0; i < v.length; i++)
			v[i] = p.get(i);
		return new Misfit(Statistics.median(v));
	}

	/** @return the results, each spot whose product exceeds {@value #TIMES} times the typical one flagged */
	List<FrameResult> flagged(final List<FrameResult> results) {
		final List<FrameResult> out = new ArrayList<>(results.size());
		for (final FrameResult r : results) {
			final List<Localization> spots = new ArrayList<>(r.spots().size());
			for (final Localization l : r.spots())
				spots.add(misfit(l) ? l.withFlags(l.flags() | Flag.MERGED.bit()) : l);
			out.add(r.withSpots(spots));
		}
		return out;
	}

	/** @return whether a spot's product exceeds {@value #TIMES} times the typical one */
	boolean misfit(final Localization l) {
		return product(l) > TIMES * typical; // NaN: not tested
	}

	/** @return a spot's centre error (the larger of x and y) times the square root of its significance; NaN if unknown */
	static double product(final Localization l) {
		final double s = Math.max(l.settlingSigmaX(), l.settlingSigmaY()), q = l.quality();
		return s > 0 && q > 0 && Double.isFinite(s) && Double.isFinite(q) ? s * Math.sqrt(q) : Double.NaN;
	}
}
