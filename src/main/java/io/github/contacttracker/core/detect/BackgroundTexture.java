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

import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;

/**
 * The texture of a frame's background at the particles' scale, where it is more than the pixel noise makes it: how
 * much more significant than the noise alone asks a member must be to be a particle ({@link #factor}).
 */
final class BackgroundTexture {

	/**
	 * Where the band-passed frame away from the particles is spread at least this many times as widely as the pixel
	 * noise makes it, the background has a texture of its own.
	 */
	static final double TEXTURE = 1.5;
	/** The texture is measured only where at least this share of the frame lies away from the particles. */
	static final double CLEAR = 0.1;
	/**
	 * A member whose band-passed peak is at least this share of the particles' typical peak stands out as a particle
	 * (its surroundings are not the background's); a texture whose seeds' level reaches this share of it is not told
	 * apart.
	 */
	static final double PARTICLE = 0.5;

	private BackgroundTexture() {}

	/**
	 * How many times as widely the background spreads a member's significance as the pixel noise does: the
	 * band-passed frame's spread away from the members that stand out as particles, over the spread the pixel noise
	 * gives it ({@code noiseUnit}), where that is at least {@value #TEXTURE}; else 1. A member's significance is its
	 * light's drop of the residuals in pixel-noise units, as a matched filter at the particles' scale measures it; the
	 * band-pass is one at that scale too, so on a background whose texture spreads the band-passed frame f times as
	 * widely as white noise would, a bump of it has a significance f times as large as a bump of the noise, and a
	 * member must be f times as significant to be told from it. A compressed video's blocks and a background's
	 * specks are such a texture, and their bumps pass as seeds whose fit lowers the residuals by more than a member
	 * must (DeepTrack's vesicles: the band-passed background spread 5 to 6 times as widely as the noise makes it, the
	 * members on its bumps of significance 14 to 20 against the vesicles' 90 to 120; judged against the texture, 492
	 * of about 5,700 spots flagged became 118, and 251 vesicles more were found). On white noise the spread is the
	 * noise's, and nothing changes.
	 * <p>
	 * A spread as wide as a tenth of the particles' typical peak ({@value #PARTICLE} of it over a seed's
	 * {@link ImageDetection#LEVEL}) is not the background's: it is their own light where no member has reached it
	 * yet (a packed monolayer whose first fit holds a few hundred of its 2,300 particles: half their typical peak),
	 * or a background as textured as the particles are bright (DeepTrack's bacteria), and is left as it is.
	 *
	 * @param bp the frame band-passed at the particles' scale
	 * @param e the members
	 * @param of each member's profile
	 * @param noiseUnit the band-passed frame's spread that the pixel noise makes
	 * @param typical the particles' typical band-passed peak ({@link Peaks#typicalHeight})
	 * @return that factor, 1 where the background is as smooth as the noise, or too little of it is clear of the
	 *         particles to tell (a packed field), or its spread is the particles' own
	 */
	static double factor(final float[] bp, final int w, final int h, final Estimate[] e, final EmpiricalProfile[] of,
		final double noiseUnit, final double typical)
	{
		// away from the members that stand out as particles do: the fainter ones are what is measured
		final Estimate[] bright = new Estimate[e.length];
		final EmpiricalProfile[] theirs = new EmpiricalProfile[e.length];
		int b = 0;
		for (int k = 0; k < e.length; k++)
			if (!ProfileMatch.weak(bp, w, h, e[k].x(), e[k].y(), PARTICLE * typical)) {
				bright[b] = e[k];
				theirs[b++] = of[k];
			}
		final boolean[] clear = DrawnModel.near(w, h, Arrays.copyOf(bright, b), Arrays.copyOf(theirs, b));
		int count = 0;
		for (int i = 0; i < clear.length; i++) {
			clear[i] = !clear[i];
			if (clear[i]) count++;
		}
		if (count < CLEAR * clear.length) return 1;
		final double spread = DrawnModel.robustSpread(bp, clear);
		return spread >= TEXTURE * noiseUnit && ImageDetection.LEVEL * spread <= PARTICLE * typical ? spread / noiseUnit
			: 1;
	}
}
