package io.github.contacttracker.eval;

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
