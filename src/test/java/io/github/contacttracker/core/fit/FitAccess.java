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

import java.util.List;

import io.github.contacttracker.core.image.Censoring;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/** For the tests of the rooms above: the fit's grouping and its fit member by member (package-private in the core). */
public final class FitAccess {

	public static final int MAX_JOINT = GroupFit.MAX_JOINT;
	public static final int MAX_ITERATIONS = GroupFit.MAX_ITERATIONS;
	public static final int MAX_SWEEPS = MemberSweeps.MAX_SWEEPS;

	private FitAccess() {}

	public static List<int[]> groups(final Particle[] ps, final Estimate[] e, final double distance) {
		return GroupFit.groups(ps, e, distance);
	}

	/**
	 * Fits {@code group} member by member in at most {@code sweeps} sweeps, every particle drawn with {@code profile};
	 * returns the new estimates.
	 */
	public static Estimate[] fitInTurn(final Plane plane, final Particle[] ps, final Estimate[] start, final int[] group,
		final EmpiricalProfile profile, final double window, final Censoring censoring, final int sweeps)
	{
		final Estimate[] e = start.clone();
		final EmpiricalProfile[] of = new EmpiricalProfile[ps.length];
		java.util.Arrays.fill(of, profile);
		MemberSweeps.fitInTurn(plane, ps, e, group, of, window, censoring, sweeps);
		return e;
	}
}
