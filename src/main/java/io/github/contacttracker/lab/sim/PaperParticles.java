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
 * The two particle kinds of the paper's simulations. The paper's profiles are experimental (an interpolated
 * 5.53 um image and a Gaussian-Bessel fit to a 2.06 um image) and not published as numbers, so these are
 * stand-ins with the properties that matter: a "5.53 um-like" short-range profile ({@code R_out <= D}) and a
 * "2.06 um-like" long-range one whose rings reach beyond one diameter. Every tunable number is in the
 * constants block below.
 */
public final class PaperParticles {

	// ---- the tunable numbers, all in one place ------------------------------------------------------------

	/** Grey level below which the profile counts as gone: half a grey level rounds to the background. */
	public static final double REACH_LEVEL = 0.5;
	/** Added to the reach for {@code R_out}: half the width of the 5x3 gradient operator. */
	public static final double R_OUT_MARGIN_PX = 2;

	private static final double SILICA553_DIAMETER_UM = 5.53;
	private static final double SILICA553_PIXEL_NM = 84.7;
	private static final double SILICA553_AMPLITUDE = 120;
	private static final double SILICA553_BESSEL_SCALE = 0.14;
	private static final double SILICA553_SIGMA_PX = 22;
	private static final double SILICA553_BACKGROUND = 60;
	private static final double SILICA553_THRESHOLD_ABOVE_BACKGROUND = 25;
	private static final double SILICA553_NOISE_AMPLITUDE = 5;

	private static final double SILICA206_DIAMETER_UM = 2.06;
	private static final double SILICA206_PIXEL_NM = 37;
	private static final double SILICA206_AMPLITUDE = 100;
	private static final double SILICA206_BESSEL_SCALE = 0.16;
	private static final double SILICA206_SIGMA_PX = 40;
	private static final double SILICA206_BACKGROUND = 80;
	private static final double SILICA206_THRESHOLD_ABOVE_BACKGROUND = 60;
	private static final double SILICA206_NOISE_AMPLITUDE = 5;

	// ---------------------------------------------------------------------------------------------------------

	private static final ParticleType SILICA_553 = preset("silica 5.53 um", SILICA553_DIAMETER_UM, SILICA553_PIXEL_NM,
		new GaussianBesselProfile(SILICA553_AMPLITUDE, SILICA553_BESSEL_SCALE, SILICA553_SIGMA_PX), SILICA553_BACKGROUND,
		SILICA553_THRESHOLD_ABOVE_BACKGROUND, SILICA553_NOISE_AMPLITUDE);

	private static final ParticleType SILICA_206 = preset("silica 2.06 um", SILICA206_DIAMETER_UM, SILICA206_PIXEL_NM,
		new GaussianBesselProfile(SILICA206_AMPLITUDE, SILICA206_BESSEL_SCALE, SILICA206_SIGMA_PX), SILICA206_BACKGROUND,
		SILICA206_THRESHOLD_ABOVE_BACKGROUND, SILICA206_NOISE_AMPLITUDE);

	private PaperParticles() {}

	/**
	 * "5.53 um-like": D = 5.53 um at 84.7 nm/px (65.29 px), short range ({@code R_out <= D}); the paper's
	 * favourable case. Gaussian-Bessel A = 120, k = 0.14 /px, s = 22 px on background 60: a bright core, a
	 * dark ring (-15 grey levels at 27 px) that darkens the bridge between touching particles, a faint outer
	 * ring, back to background within 58 px (so {@code R_out} = 61 px, just inside D as the paper requires).
	 * Uniform noise of amplitude 5, {@code th} = background + 25 (the core, radius 13 px),
	 * {@code R_out = ceil(reach(0.5) + 2)}.
	 *
	 * @return the preset
	 */
	public static ParticleType silica553() {
		return SILICA_553;
	}

	/**
	 * "2.06 um-like": D = 2.06 um at 37 nm/px (55.68 px), long range ({@code R_out > D}): at contact no
	 * undistorted area is left. Gaussian-Bessel A = 100, k = 0.16 /px, s = 40 px on background 80, uniform noise
	 * of amplitude 5, {@code th} = background + 60: above where three overlapping first rings (16 grey levels each)
	 * can reach, so no spurious component appears between particles at any separation;
	 * {@code R_out = ceil(reach(0.5) + 2)}.
	 *
	 * @return the preset
	 */
	public static ParticleType silica206() {
		return SILICA_206;
	}

	private static ParticleType preset(final String name, final double diameterMicrons, final double pixelSizeNm,
		final RadialProfile profile, final double background, final double thresholdAboveBackground,
		final double noiseAmplitude)
	{
		final double rOut = Math.ceil(profile.reach(REACH_LEVEL) + R_OUT_MARGIN_PX);
		return new ParticleType(name, diameterMicrons, pixelSizeNm, profile, background,
			background + thresholdAboveBackground, rOut, NoiseModel.uniform(noiseAmplitude));
	}
}
