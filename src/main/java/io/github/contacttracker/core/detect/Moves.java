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

import java.util.Arrays;

import io.github.contacttracker.core.radial.Estimate;

/**
 * The seeds of {@link ModelSelection}'s next round: kept members' centres, children of split members, added particles.
 */
final class Moves {
	double[] x, y;
	/** a kept member's fit, which its next fit starts from (null: a new seed, fitted from its first pass) */
	Estimate[] warm;
	int n;

	Moves(final int capacity) {
		x = new double[Math.max(1, capacity)];
		y = new double[x.length];
		warm = new Estimate[x.length];
	}

	void add(final double px, final double py) {
		add(px, py, null);
	}

	void add(final double px, final double py, final Estimate fitted) {
		if (n == x.length) {
			x = Arrays.copyOf(x, 2 * n);
			y = Arrays.copyOf(y, 2 * n);
			warm = Arrays.copyOf(warm, 2 * n);
		}
		x[n] = px;
		y[n] = py;
		warm[n++] = fitted;
	}

	/** Replaces the seed at (ox, oy), if there, by two; adds both otherwise. */
	void replace(final double ox, final double oy, final double x1, final double y1, final double x2,
		final double y2)
	{
		for (int i = 0; i < n; i++)
			if (x[i] == ox && y[i] == oy) {
				x[i] = x1;
				y[i] = y1;
				warm[i] = null;
				add(x2, y2);
				return;
			}
		add(x1, y1);
		add(x2, y2);
	}

	boolean near(final double px, final double py, final double within) {
		for (int i = 0; i < n; i++)
			if (MemberTests.dist(x[i] - px, y[i] - py) < within) return true;
		return false;
	}

	int size() {
		return n;
	}

	double[] x() {
		return Arrays.copyOf(x, n);
	}

	double[] y() {
		return Arrays.copyOf(y, n);
	}

	Estimate[] warm() {
		return Arrays.copyOf(warm, n);
	}
}
