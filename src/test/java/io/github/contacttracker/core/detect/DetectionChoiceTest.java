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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/** What {@link Detection#AUTO} chooses, and that where it keeps the threshold the run is the threshold's. */
class DetectionChoiceTest {

	/** 16 blurred discs 10 px across, well apart, on a flat background with noise. */
	private static Scenes.Frame apart(final long seed) {
		final List<Scenes.Truth> t = new ArrayList<>();
		for (int i = 0; i < 4; i++)
			for (int j = 0; j < 4; j++)
				t.add(new Scenes.Truth(16 + 24 * i + 0.1 * j, 16 + 24 * j + 0.07 * i, 120, 5));
		return new Scenes.Frame(Scenes.noisy(Scenes.render(104, 104, (x, y) -> 30, t, Scenes.blurredDisc(1, 0.3), 2), 3,
			0, 255, seed), 104, 104, t, 10);
	}

	@Test
	void whereEveryAreaIsOneParticleTheThresholdIsKeptAndTheSpotsAreItsOwn() {
		final List<ArrayImg<UnsignedByteType, ByteArray>> imgs = new ArrayList<>();
		for (int t = 0; t < 3; t++) {
			final Scenes.Frame f = apart(40 + t);
			imgs.add(TestImages.bytes(f.pixels(), f.width(), f.height()));
		}
		final TrackerParameters p = TrackerParameters.of(90, 11.5).withDiameter(10);
		assertEquals(Detection.AUTO, p.detection(), "the default");
		final List<FrameResult> auto = new StackTracker(p).track(imgs, false);
		final List<FrameResult> threshold = new StackTracker(p.withDetection(Detection.THRESHOLD)).track(imgs, false);
		assertEquals(Detection.THRESHOLD, auto.get(0).detection().detection());
		assertEquals(0, auto.get(0).detection().merged());
		assertEquals("", auto.get(0).detection().said(), "nothing to say: the run is the threshold's");
		assertEquals(StackTracker.spots(threshold), StackTracker.spots(auto));
		assertEquals(48, StackTracker.spots(auto).size());
	}

	/**
	 * A threshold area flagged merged on a frame whose seeds at the particles' scale are hundreds (a texture): the
	 * threshold is kept, and said why. Fewer seeds than that: by the image.
	 */
	@Test
	void seedsThatAreTextureKeepTheThreshold() {
		final int w = 200, h = 200;
		final Random r = new Random(3);
		final List<Scenes.Truth> specks = new ArrayList<>();
		for (int i = 0; i < 400; i++)
			specks.add(new Scenes.Truth(r.nextDouble() * w, r.nextDouble() * h, 40 + 40 * r.nextDouble(), 1.5));
		final Plane texture = Plane.of(TestImages.bytes(Scenes.noisy(Scenes.render(w, h, (x, y) -> 60, specks, Scenes
			.blurredDisc(1, 0.5), 2), 1, 0, 255, 5), w, h));
		final List<List<Localization>> one = List.of(List.of(spot(Flag.MERGED.bit())));
		final DetectionChoice onTexture = DetectionChoice.choose(one, 0, texture, 6);
		assertTrue(onTexture.seeds() > DetectionChoice.SEEDS_PER_PARTICLE, "seeds: " + onTexture.seeds());
		assertEquals(Detection.THRESHOLD, onTexture.detection());
		assertTrue(onTexture.said().contains("the background's texture"), onTexture.said());
		// the same seeds where the threshold kept no particle at all (many dim spots below it): nothing to weigh them
		// against, and only the image can find any
		final DetectionChoice noneKept = DetectionChoice.choose(List.of(List.of()), 40, texture, 6);
		assertEquals(Detection.IMAGE, noneKept.detection(), noneKept.said());
		final Scenes.Frame f = apart(7);
		final Plane particles = Plane.of(TestImages.bytes(f.pixels(), f.width(), f.height()));
		final List<List<Localization>> sixteen = new ArrayList<>();
		final List<Localization> spots = new ArrayList<>();
		for (int k = 0; k < 16; k++)
			spots.add(spot(k == 0 ? Flag.MERGED.bit() : 0));
		sixteen.add(spots);
		assertEquals(Detection.IMAGE, DetectionChoice.choose(sixteen, 0, particles, 10).detection());
		assertEquals(Detection.THRESHOLD, DetectionChoice.choose(List.of(spots.subList(1, 16)), 15, particles, 10)
			.detection(), "no merged area, no more areas discarded than kept: the threshold");
		final DetectionChoice crumbs = DetectionChoice.choose(List.of(spots.subList(1, 16)), 16, particles, 10);
		assertEquals(Detection.IMAGE, crumbs.detection(), "more areas discarded than kept: the image");
		assertTrue(crumbs.said().contains("discarded more areas than it kept (16 against 15 spots"), crumbs.said());
	}

	/**
	 * A packed field that a threshold joins into one area: the image's seeds, one a particle, outnumber the threshold's
	 * one spot more than {@link DetectionChoice#SEEDS_PER_PARTICLE} times, yet they are the particles its area holds,
	 * not texture: by the image.
	 */
	@Test
	void seedsOfAPackedFieldTheThresholdJoinsAreNotTakenForTexture() {
		final List<Scenes.Truth> t = new ArrayList<>();
		for (int i = 0; i < 12; i++)
			for (int j = 0; j < 12; j++)
				t.add(new Scenes.Truth(12 + 11 * i + (j % 2) * 5.5, 12 + 9.5 * j, 120, 5));
		final int w = 152, h = 130;
		final Plane packed = Plane.of(TestImages.bytes(Scenes.noisy(Scenes.render(w, h, (x, y) -> 30, t, Scenes
			.blurredDisc(1, 0.3), 2), 3, 0, 255, 11), w, h));
		final Localization joined = new Localization(0, 76, 65, 76, 65, 144 * 79, 144 * 79, 1, 60, Flag.MERGED.bit(), 3,
			0.01, 0.01, Double.NaN, Double.NaN, 0);
		final DetectionChoice choice = DetectionChoice.choose(List.of(List.of(joined)), 0, packed, 10);
		assertTrue(choice.seeds() > DetectionChoice.SEEDS_PER_PARTICLE, "seeds: " + choice.seeds());
		assertEquals(Detection.IMAGE, choice.detection(), choice.said());
		assertTrue(choice.firstSpots() >= 100, "the area holds " + choice.firstSpots() + " particles");
	}

	/** Bright particles: their own contrast is the stronger; the same frame inverted (dark particles): the other. */
	@Test
	void theOtherContrastIsSeenWhereTheParticlesAreDark() {
		final Scenes.Frame f = apart(9);
		final double[] inverted = f.pixels().clone();
		for (int i = 0; i < inverted.length; i++)
			inverted[i] = 255 - inverted[i];
		final Plane bright = Plane.of(TestImages.bytes(f.pixels(), f.width(), f.height()));
		final Plane dark = Plane.of(TestImages.bytes(inverted, f.width(), f.height()));
		assertFalse(DetectionChoice.otherContrastStronger(bright, dark, 10));
		assertTrue(DetectionChoice.otherContrastStronger(dark, bright, 10));
		assertFalse(DetectionChoice.otherContrastStronger(dark, bright, 1e6), "no filter wider than the frame");
	}

	private static Localization spot(final int flags) {
		return new Localization(0, 10, 10, 10, 10, 80, 80, 1, 5, flags, 3, 0.01, 0.01, Double.NaN, Double.NaN, 0);
	}
}
