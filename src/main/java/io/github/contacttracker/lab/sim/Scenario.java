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
package io.github.contacttracker.lab.sim;

import java.util.List;

/**
 * The paper's two simulation geometries (its Fig. 3). In both, particles 0 and 1 are the measured pair, 0 on
 * the left, 1 on the right, on a horizontal line through {@code (cx, cy)} and symmetric about it; their centre
 * distance is {@code r = separationOverD * D}.
 */
public enum Scenario {

	/** Two particles: indices 0 (left) and 1 (right). */
	PAIR(2),

	/**
	 * Three particles, starting at contact as an equilateral triangle of side D. The middle particle (index 2)
	 * stays fixed at {@code (cx, cy - D sqrt(3) / 2)}, above the pair (y grows downwards); the measured pair
	 * (0 and 1) moves apart symmetrically about {@code (cx, cy)}. At {@code r = D} all three distances are D.
	 */
	TRIPLE(3);

	private final int particleCount;

	Scenario(final int particleCount) {
		this.particleCount = particleCount;
	}

	/** @return the number of particles */
	public int particleCount() {
		return particleCount;
	}

	/** @return the indices of the measured pair, {@code {0, 1}} (a fresh array) */
	public int[] measuredPair() {
		return new int[] { 0, 1 };
	}

	/**
	 * @param separationOverD measured centre distance in diameters ({@code r / D}; 1 = contact)
	 * @param diameterPx particle diameter D (px)
	 * @param cx x of the measured pair's midpoint (px)
	 * @param cy y of the measured pair's midpoint (px)
	 * @return the centres {@code {x, y}} (px), in index order
	 */
	public List<double[]> centres(final double separationOverD, final double diameterPx, final double cx,
		final double cy)
	{
		if (!(separationOverD > 0) || !Double.isFinite(separationOverD) || !(diameterPx > 0)
			|| !Double.isFinite(diameterPx))
			throw new IllegalArgumentException("separation and diameter must be positive, not " + separationOverD
				+ " D and " + diameterPx + " px");
		final double half = 0.5 * separationOverD * diameterPx;
		final double[] left = { cx - half, cy };
		final double[] right = { cx + half, cy };
		return switch (this) {
			case PAIR -> List.of(left, right);
			case TRIPLE -> List.of(left, right, new double[] { cx, cy - diameterPx * Math.sqrt(3) / 2 });
		};
	}
}
