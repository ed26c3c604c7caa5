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

/**
 * A known pair potential for simulated fluids: the truth that a measured U(r) is compared with. Distances in
 * pixels, energies in units of kT.
 */
public interface PairInteraction {

	/**
	 * @param r centre distance (px)
	 * @return U(r)/kT; {@code +Infinity} where the particles would overlap
	 */
	double energyKt(double r);

	/** @return the distance (px) beyond which U is exactly 0 */
	double range();

	/** @return a short description for reports */
	String describe();
}
