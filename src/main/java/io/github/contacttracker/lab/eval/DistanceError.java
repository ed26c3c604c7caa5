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
package io.github.contacttracker.lab.eval;

import io.github.contacttracker.core.Method;

/**
 * Error statistics of a measured centre-to-centre distance, at one separation, for one method.
 *
 * @param separationOverD true separation in diameters (1 = contact)
 * @param method the method
 * @param images images analysed
 * @param measured images in which both particles of the measured pair were found
 * @param failures images in which a particle of the measured pair was lost (no spot near it, or merged)
 * @param fallbacks images in which a particle of the pair kept its first-pass centre ({@code FELL_BACK})
 * @param meanErrorNm mean of (measured - true) distance (nm): the bias
 * @param stdNm standard deviation of the measured distance (nm)
 * @param meanSigmaNm mean reported standard error of the distance (nm), from the spots' own error estimates
 */
public record DistanceError(double separationOverD, Method method, int images, int measured, int failures,
	int fallbacks, double meanErrorNm, double stdNm, double meanSigmaNm)
{}
