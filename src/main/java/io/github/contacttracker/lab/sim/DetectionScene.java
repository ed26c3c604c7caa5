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

import net.imglib2.img.array.ArrayImg;

/**
 * A movie rendered for the study of detection, as a new user meets one: frames whose particles are known exactly,
 * and what the study needs to judge a tracker on them. Each frame may carry a label (a tweezer pair's separation over
 * the diameter) and belongs to a band (the labels grouped, or the whole scene), over which the study sums.
 *
 * @param key the scene's name ({@code pair-sweep}, {@code dim}, ...)
 * @param description what the scene shows, in one line, for reports
 * @param scene the particles' kinds, sizes and brightness, the background and the noise; its particles are those
 *        of every frame, in the order of {@code truth}'s centres
 * @param bitDepth 8 or 16
 * @param frames the movie's frames
 * @param truth per frame, every particle's true centre (px, {@link Scene#particles()}'s order)
 * @param labels per frame, a number that sorts it (a pair's separation over the diameter), NaN where none
 * @param bands per frame, the band it is summed in
 * @param groups per particle, the band it is summed in instead (alone, touching), or empty: the frame's band
 * @param boundKnown whether the scene's Cramer-Rao bound is meaningful (no background clipped by the camera; on
 *        16 bits the scene's light is rendered without the camera's offset, which carries no information)
 * @param clipped pixels clipped at 0 or the bit depth's top, over every frame
 */
public record DetectionScene(String key, String description, Scene scene, int bitDepth, List<ArrayImg<?, ?>> frames,
	List<List<double[]>> truth, double[] labels, List<String> bands, List<String> groups, boolean boundKnown,
	long clipped)
{

	/** Copies the lists; one truth, label and band per frame. */
	public DetectionScene {
		frames = List.copyOf(frames);
		truth = List.copyOf(truth);
		bands = List.copyOf(bands);
		groups = List.copyOf(groups);
		if (!groups.isEmpty() && groups.size() != scene.particles().size()) throw new IllegalArgumentException(
			groups.size() + " groups for " + scene.particles().size() + " particles");
		labels = labels.clone();
		if (truth.size() != frames.size() || labels.length != frames.size() || bands.size() != frames.size())
			throw new IllegalArgumentException("one truth, label and band per frame: " + frames.size() + " frames, " +
				truth.size() + " truths, " + labels.length + " labels, " + bands.size() + " bands");
		for (final List<double[]> t : truth)
			if (t.size() != scene.particles().size()) throw new IllegalArgumentException("a frame holds " + t.size() +
				" particles, the scene " + scene.particles().size());
	}

	/** @return the band particle {@code k} of frame {@code t} is summed in: its group's, or else the frame's */
	public String band(final int t, final int k) {
		return groups.isEmpty() ? bands.get(t) : groups.get(k);
	}

	/** @return the frames' width (px) */
	public int width() {
		return (int) frames.get(0).dimension(0);
	}

	/** @return the frames' height (px) */
	public int height() {
		return (int) frames.get(0).dimension(1);
	}

	/** @return particle {@code k}'s true diameter (px): the type's times its scale */
	public double diameter(final int k) {
		return scene.type().diameterPx() * scene.particles().get(k).scale();
	}

	/** @return the pixel size (nm) */
	public double pixelSizeNm() {
		return scene.type().pixelSizeNm();
	}
}
