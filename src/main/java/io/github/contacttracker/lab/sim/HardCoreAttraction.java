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

import java.util.Locale;

/**
 * Hard spheres with a short-range attraction, the kind of potential depletion or van der Waals forces give:
 * {@code U = +inf} for {@code r < contact}, {@code U/kT = -depth exp(-(r - contact) / decay)} beyond, cut to 0 at
 * {@code contact + CUTOFF_DECAYS * decay} (where it is below {@code 3e-4 depth}; the cut potential is the truth).
 *
 * @param contact centre distance at contact (px), the particle diameter
 * @param depthKt well depth at contact, in kT (0 for plain hard spheres)
 * @param decay decay length of the attraction (px)
 */
public record HardCoreAttraction(double contact, double depthKt, double decay) implements PairInteraction {

	/** Decay lengths after which the attraction is cut. */
	public static final double CUTOFF_DECAYS = 8;

	/** @throws IllegalArgumentException for a non-positive contact or decay, or a negative depth */
	public HardCoreAttraction {
		if (!(contact > 0) || !(decay > 0) || !(depthKt >= 0) || !Double.isFinite(contact + decay + depthKt))
			throw new IllegalArgumentException("hard core + attraction needs contact > 0, decay > 0 and depth >= 0, not " +
				contact + ", " + decay + ", " + depthKt);
	}

	@Override
	public double energyKt(final double r) {
		if (r < contact) return Double.POSITIVE_INFINITY;
		if (r >= range()) return 0;
		return -depthKt * Math.exp(-(r - contact) / decay);
	}

	@Override
	public double range() {
		return contact + CUTOFF_DECAYS * decay;
	}

	@Override
	public String describe() {
		return String.format(Locale.ROOT, "hard core at %.2f px + attraction %.2f kT exp(-(r - %.2f px) / %.2f px)",
			contact, depthKt, contact, decay);
	}
}
