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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Plane;
import net.imglib2.img.array.ArrayImgs;

/** The pooling of the profile helper where no particle has background around it. */
class PooledProfileTest {

	/**
	 * A frame smaller than a particle's background annulus, with a diameter of 0 (the masks start at 0 and may narrow
	 * to 0): the helper refuses in one line at once. It used to narrow a mask of 0 for ever (a 104x32 frame found by
	 * the fuzz never answered).
	 */
	@Test
	void noBackgroundWithAZeroMaskIsRefusedNotNarrowedForEver() {
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(new byte[64], 8, 8));
		final List<double[]> centres = List.of(new double[] { 4, 4 });
		final double[][] spots = { { 4, 4 } };
		assertTimeoutPreemptively(Duration.ofSeconds(10), () -> assertThrows(InvalidInputException.class,
			() -> PooledProfile.poolNarrowing(plane, centres, spots, 0, 20, 0, null)));
	}
}
