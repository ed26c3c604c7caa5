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
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TestImages;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.ContactTracker;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import net.imglib2.type.numeric.integer.UnsignedShortType;

/**
 * Detection by the image against ground truth, on the footage a threshold cannot cut into one component per
 * particle: blurred discs (fluorescent beads, microgels) pushed into overlap, dim 16-bit spots, particles on a ramp
 * and on a background clipped at 0. Each scene is also tracked by the threshold, to show what the image adds.
 */
class ImageDetectionTest {

	/** A blurred disc of radius 5 px (D = 10), blur 1.5 px, 120 grey levels on 30, noise 3 (8 bits). */
	private static Scenes.Frame pair(final double separation, final long seed, final double rampX) {
		final double d = 10;
		final List<Scenes.Truth> t = List.of(new Scenes.Truth(40 - separation * d / 2 + 0.3, 30.2, 120, 5),
			new Scenes.Truth(40 + separation * d / 2 + 0.3, 30.2, 120, 5));
		return new Scenes.Frame(Scenes.noisy(Scenes.render(80, 60, (x, y) -> 30 + rampX * x, t, Scenes.blurredDisc(1,
			0.3), 2), 3, 0, 255, seed), 80, 60, t, d);
	}

	/** @return a pair pushed from two diameters apart by {@code by} diameters over {@code frames} frames */
	private static List<Scenes.Frame> pushed(final int frames, final double by, final long seed, final double rampX) {
		final List<Scenes.Frame> fs = new ArrayList<>();
		for (int t = 0; t < frames; t++)
			fs.add(pair(2.0 - by * t / (frames - 1), seed + t, rampX));
		return fs;
	}

	private static List<ArrayImg<UnsignedByteType, ByteArray>> images(final List<Scenes.Frame> fs) {
		final List<ArrayImg<UnsignedByteType, ByteArray>> imgs = new ArrayList<>();
		for (final Scenes.Frame f : fs)
			imgs.add(TestImages.bytes(f.pixels(), f.width(), f.height()));
		return imgs;
	}

	private static List<Localization> track(final Scenes.Frame f, final double threshold, final double rOut,
		final Detection detection)
	{
		final TrackerParameters p = TrackerParameters.of(threshold, rOut).withDiameter(f.diameter()).withDetection(
			detection);
		return new ContactTracker(p).track(TestImages.bytes(f.pixels(), f.width(), f.height()), 0);
	}

	@ParameterizedTest
	@ValueSource(doubles = { 2, 1.5, 1.2, 1.0, 0.8, 0.7, 0.6 })
	void aPairIsTwoSpotsDownToOverlapWhereTheThresholdMergesIt(final double separation) {
		final Scenes.Frame f = pair(separation, 7, 0);
		final Scenes.Score image = Scenes.score(f, track(f, 90, 11.5, Detection.IMAGE), 5, 0);
		assertEquals(2, image.found(), "two spots: " + image);
		assertEquals(2, image.matched(), image.toString());
		assertTrue(image.worstError() < 0.05, "each within 0.05 px of its particle: " + image);
		if (separation <= 1.2) {
			final Scenes.Score threshold = Scenes.score(f, track(f, 90, 11.5, Detection.THRESHOLD), 5, 0);
			assertTrue(threshold.matched() < 2 || threshold.worstError() > 1, "the threshold merges them: " + threshold);
		}
	}

	/**
	 * A tweezer-like movie: the pair pushed from two diameters apart to 0.96 diameters, on a ramp. By the image, and
	 * by the default, auto, which finds the threshold's areas merged on its sample frames and so detects by the image.
	 */
	@ParameterizedTest
	@org.junit.jupiter.params.provider.EnumSource(value = Detection.class, names = { "IMAGE", "AUTO" })
	void aPairPushedTogetherStaysTwoSpotsInEveryFrame(final Detection detection) {
		final int frames = 24;
		final List<Scenes.Frame> fs = pushed(frames, 1.04, 100, 0.2);
		final List<ArrayImg<UnsignedByteType, ByteArray>> imgs = images(fs);
		final TrackerParameters p = TrackerParameters.of(90, 11.5).withDiameter(10).withDetection(detection);
		final List<FrameResult> res = new StackTracker(p).track(imgs, false);
		if (detection == Detection.AUTO) {
			final DetectionChoice choice = res.get(0).detection();
			assertEquals(Detection.IMAGE, choice.detection(), choice.toString());
			assertTrue(choice.merged() > 0 && choice.said().startsWith("found by their image (auto)"), choice.said());
			final List<FrameResult> byThreshold = new StackTracker(p.withDetection(Detection.THRESHOLD)).track(imgs,
				false);
			int merged = 0;
			for (int t = 0; t < frames; t++)
				if (Scenes.score(fs.get(t), byThreshold.get(t).spots(), 5, 0).found() < 2) merged++;
			assertTrue(merged > 0, "the threshold alone merges the pair in some frames");
		}
		for (int t = 0; t < frames; t++) {
			final Scenes.Score s = Scenes.score(fs.get(t), res.get(t).spots(), 5, 0);
			assertEquals(2, s.found(), "frame " + t + ": " + s);
			assertEquals(0, s.flagged(), "frame " + t + ": " + s);
			assertTrue(s.worstError() < 0.06, "frame " + t + ": " + s);
		}
	}

	/** @return {@code n} Gaussian spots of sigma 1 px, 50 grey levels high, placed at random in 200 x 200 px */
	private static List<Scenes.Truth> dimSpots(final int n, final long seed) {
		final List<Scenes.Truth> t = new ArrayList<>();
		final Random r = new Random(seed);
		for (int i = 0; i < n; i++)
			t.add(new Scenes.Truth(5 + r.nextDouble() * 190, 5 + r.nextDouble() * 190, 50, 1));
		return t;
	}

	/**
	 * A background with a texture of its own at the particles' scale, as a compressed video's blocks and a
	 * microscope's specks give it: smoothed noise whose pixel-to-pixel steps are small, so the pixel noise measured is
	 * small and the texture's bumps stand out of the band-passed frame as seeds do, and, fitted, lower the residuals
	 * by more than a member must. The band-passed frame away from the particles is spread five times as widely as the
	 * pixel noise makes it, and so is a bump's significance: a member must be that much more significant. Every
	 * particle is found and no bump (without the texture's factor: 38 spots on bumps besides the 36 particles).
	 */
	@Test
	void theBumpsOfATexturedBackgroundAreNoParticles() {
		final int w = 200, h = 200;
		final List<Scenes.Truth> t = new ArrayList<>();
		final Random r = new Random(11);
		for (int i = 0; i < 6; i++)
			for (int j = 0; j < 6; j++)
				t.add(new Scenes.Truth(18 + 33 * i + 6 * r.nextDouble(), 18 + 33 * j + 6 * r.nextDouble(), 24, 1));
		final double[] texture = smoothedNoise(w, h, 1.5, 12);
		final double[] img = Scenes.noisy(Scenes.render(w, h, (x, y) -> 50 + 1.5 * texture[y * w + x], t, Scenes
			.blurredDisc(0, 1.3), 6), 0.7, 0, 255, 13);
		final Scenes.Frame f = new Scenes.Frame(img, w, h, t, 6);
		final TrackerParameters p = TrackerParameters.of(80, 5).withDiameter(6).withDetection(Detection.IMAGE);
		final Scenes.Score s = Scenes.score(f, new ContactTracker(p).track(TestImages.bytes(img, w, h), 0), 2, 0);
		assertTrue(s.recall() >= 0.97, "recall: " + s);
		assertEquals(0, s.spurious(), s.toString());
	}

	/** @return white noise smoothed by a Gaussian of {@code sigma} px, scaled to a standard deviation of 1 */
	private static double[] smoothedNoise(final int w, final int h, final double sigma, final long seed) {
		final Random r = new Random(seed);
		final double[] white = new double[w * h], rows = new double[w * h], out = new double[w * h];
		for (int i = 0; i < white.length; i++)
			white[i] = r.nextGaussian();
		final int k = (int) Math.ceil(3 * sigma);
		final double[] g = new double[2 * k + 1];
		for (int i = -k; i <= k; i++)
			g[i + k] = Math.exp(-i * i / (2 * sigma * sigma));
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				for (int i = -k; i <= k; i++)
					rows[y * w + x] += g[i + k] * white[y * w + Math.floorMod(x + i, w)];
		double sum2 = 0;
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				for (int i = -k; i <= k; i++)
					out[y * w + x] += g[i + k] * rows[Math.floorMod(y + i, h) * w + x];
				sum2 += out[y * w + x] * out[y * w + x];
			}
		final double sd = Math.sqrt(sum2 / out.length);
		for (int i = 0; i < out.length; i++)
			out[i] /= sd;
		return out;
	}

	/** @return the spots on 500 grey levels with noise 10 (a peak SNR of 5), 16-bit */
	private static double[] dimFrame(final List<Scenes.Truth> t, final long seed) {
		return Scenes.noisy(Scenes.render(200, 200, (x, y) -> 500, t, Scenes.blurredDisc(0, 1), 5), 10, 0, 65535, seed);
	}

	@Test
	void dimSpotsAreFoundWhereTheThresholdFindsNone() {
		final List<Scenes.Truth> t = dimSpots(60, 3);
		final double[] img = dimFrame(t, 9);
		final Scenes.Frame f = new Scenes.Frame(img, 200, 200, t, 4);
		final TrackerParameters p = TrackerParameters.of(525, 6).withDiameter(4);
		final Scenes.Score image = Scenes.score(f, new ContactTracker(p.withDetection(Detection.IMAGE)).track(TestImages
			.shorts(img, 200, 200), 0), 2, 0);
		final Scenes.Score threshold = Scenes.score(f, new ContactTracker(p.withDetection(Detection.THRESHOLD)).track(
			TestImages.shorts(img, 200, 200), 0), 2, 0);
		assertTrue(image.recall() >= 0.95, "recall: " + image);
		assertEquals(0, image.spurious(), image.toString());
		assertTrue(threshold.recall() < 0.1, "the threshold: " + threshold);
	}

	/**
	 * A movie of dim spots whose threshold keeps none of its areas: the threshold's first pass teaches no profile, so
	 * the spots the image finds teach the movie's, and no frame is left to measure its own (less precise).
	 */
	@Test
	void dimSpotsTeachTheMoviesProfileWhereTheThresholdKeepsNone() {
		final List<Scenes.Truth> t = dimSpots(40, 5);
		final List<Scenes.Frame> fs = new ArrayList<>();
		final List<ArrayImg<UnsignedShortType, ShortArray>> imgs = new ArrayList<>();
		for (int k = 0; k < 3; k++) {
			final double[] img = dimFrame(t, 20 + k);
			fs.add(new Scenes.Frame(img, 200, 200, t, 4));
			imgs.add(TestImages.shorts(img, 200, 200));
		}
		final TrackerParameters p = TrackerParameters.of(525, 6).withDiameter(4).withDetection(Detection.IMAGE);
		final List<FrameResult> res = new StackTracker(p).track(imgs, false);
		for (int k = 0; k < fs.size(); k++) {
			assertFalse(res.get(k).ownProfile(), "frame " + k + " measured its own profile");
			final Scenes.Score s = Scenes.score(fs.get(k), res.get(k).spots(), 2, 0);
			assertTrue(s.recall() >= 0.85, "frame " + k + ": " + s);
			assertEquals(0, s.spurious(), "frame " + k + ": " + s);
		}
	}

	@Test
	void aRampAndABackgroundClippedAtZeroDoNotDecideWhichParticlesAreFound() {
		final List<Scenes.Truth> t = new ArrayList<>();
		final Random r = new Random(4);
		for (int i = 0; i < 25; i++)
			t.add(new Scenes.Truth(10 + r.nextDouble() * 180, 10 + r.nextDouble() * 180, 60 + 60 * r.nextDouble(), 4));
		final Scenes.Frame ramp = new Scenes.Frame(Scenes.noisy(Scenes.render(200, 200, (x, y) -> 10 + 0.5 * x, t,
			Scenes.blurredDisc(1, 0.3), 2), 3, 0, 255, 12), 200, 200, t, 8);
		final Scenes.Score onRamp = Scenes.score(ramp, track(ramp, 100, 10, Detection.IMAGE), 4, 0);
		assertTrue(onRamp.matched() >= 24, "on a ramp: " + onRamp);
		assertEquals(0, onRamp.spurious(), onRamp.toString());
		final Scenes.Frame clipped = new Scenes.Frame(Scenes.noisy(Scenes.render(200, 200, (x, y) -> 0, t, Scenes
			.blurredDisc(1, 0.3), 2), 3, 0, 255, 13), 200, 200, t, 8);
		final Scenes.Score atZero = Scenes.score(clipped, track(clipped, 30, 10, Detection.IMAGE), 4, 0);
		assertTrue(atZero.matched() >= 23, "clipped at 0: " + atZero);
		assertTrue(atZero.spurious() <= 1, atZero.toString());
	}

	/**
	 * Confocal slices with the detector's offset subtracted: the background at 0, half its pixels clipped there. The fit
	 * holds its background at the profile's (no pixel it may use shows it) and is not given up: every particle found by either detection is
	 * fitted, unflagged, within 0.05 px of its true centre rms (the first pass's centres were kept before, all flagged
	 * FELL_BACK).
	 */
	/**
	 * The same kind of movie pushed on to half a diameter, tracked with a diameter 30% too large (as the profile helper
	 * measures on blurred particles): where the image cannot tell the pair apart it gives one spot between them, and
	 * that spot is flagged (its light is not one particle's: {@code Misfit}), never a wrong centre left
	 * unmarked. Every frame is two right spots or flagged spots only.
	 */
	@Test
	void aPairTheImageCannotSplitIsFlaggedNotLeftWrong() {
		final int frames = 24;
		final List<Scenes.Frame> fs = pushed(frames, 1.5, 300, 0);
		final List<ArrayImg<UnsignedByteType, ByteArray>> imgs = images(fs);
		final TrackerParameters p = TrackerParameters.of(90, 11.5).withDiameter(13).withDetection(Detection.IMAGE);
		final List<FrameResult> res = new StackTracker(p).track(imgs, false);
		int right = 0, markedOnly = 0;
		for (int t = 0; t < frames; t++) {
			final Scenes.Score s = Scenes.score(fs.get(t), res.get(t).spots(), 5, 0);
			final boolean twoRight = s.found() == 2 && s.matched() == 2 && s.flagged() == 0 && s.worstError() < 0.1;
			assertTrue(twoRight || s.found() > 0 && s.flagged() == s.found(), "frame " + t + ": " + s);
			if (twoRight) right++;
			else markedOnly++;
		}
		assertTrue(right >= frames / 2, "apart, the pair is two right spots: " + right + " of " + frames);
		assertTrue(markedOnly > 0, "the scene reaches where the image cannot split the pair");
	}

	@Test
	void aBackgroundClippedAtZeroIsFittedNotGivenUp() {
		final List<Scenes.Truth> t = new ArrayList<>();
		final Random r = new Random(6);
		while (t.size() < 20) {
			final double x = 12 + r.nextDouble() * 176, y = 12 + r.nextDouble() * 176;
			if (t.stream().allMatch(o -> Math.hypot(o.x() - x, o.y() - y) > 16)) t.add(new Scenes.Truth(x, y, 100, 4));
		}
		final Scenes.Frame f = new Scenes.Frame(Scenes.noisy(Scenes.render(200, 200, (x, y) -> 0, t, Scenes.blurredDisc(1,
			0.3), 2), 3, 0, 255, 21), 200, 200, t, 8);
		for (final Detection detection : Detection.values()) {
			final Scenes.Score s = Scenes.score(f, track(f, 30, 8, detection), 4, 0);
			assertEquals(20, s.matched(), detection + ": " + s);
			assertEquals(0, s.flagged(), detection + ": " + s);
			assertTrue(s.rmsError() < 0.05 && s.worstError() < 0.12, detection + ": " + s);
		}
	}

	/**
	 * Dark-core particles in a bright ring (microgels, defocused beads; D = 10 px) pushed from two diameters apart to
	 * half a diameter, one frame each: two spots, unflagged, each within 0.12 px of its particle (measured: 0.02-0.05 px
	 * down to 0.6 diameters, 0.09 at 0.5, where the rings overlap the cores).
	 */
	@ParameterizedTest
	@ValueSource(doubles = { 2, 1.2, 1.0, 0.8, 0.7, 0.6, 0.5 })
	void aRingedPairIsTwoSpotsDownToHalfADiameter(final double separation) {
		final double d = 10;
		final List<Scenes.Truth> t = List.of(new Scenes.Truth(40 - separation * d / 2 + 0.3, 30.2, 100, 5),
			new Scenes.Truth(40 + separation * d / 2 + 0.3, 30.2, 100, 5));
		final Scenes.Frame f = new Scenes.Frame(Scenes.noisy(Scenes.render(80, 60, (x, y) -> 100 + 0.2 * x, t, Scenes
			.ringed(1, 0.35), 3), 3, 0, 255, 7), 80, 60, t, d);
		final Scenes.Score s = Scenes.score(f, track(f, 160, 11.5, Detection.IMAGE), 5, 0);
		assertEquals(2, s.found(), s.toString());
		assertEquals(2, s.matched(), s.toString());
		assertEquals(0, s.flagged(), s.toString());
		assertTrue(s.worstError() < 0.12, s.toString());
	}
}
