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
package io.github.contacttracker.lab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.lab.eval.DetectionStudy;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.lab.sim.DetectionScenes;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Detection as a new user meets it, on the detection study's scenes, small and few: what the tracker meets today,
 * held so that it does not get worse (each test also says the figures of the study's report). What it does not meet
 * yet is in that report.
 */
class DetectionScenesTest {

	private static DetectionStudy study(final DetectionScene scene) {
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, new NewUserTracker(2).track(scene));
		return study;
	}

	/**
	 * A blurred pair swept from 2 D to 0.5 D in 10 frames. At 1 D and more apart (7 frames) both particles are found
	 * in every frame, no spot is false, at least 9 in 10 spots are unflagged, and their centres are within 0.05 px of
	 * the truth (the study's 3 movies of 40 frames: 0.002 px) with a spread within twice the bound (there: 1.06).
	 */
	@Test
	void pairSweepApartIsFoundAndCentred() {
		final DetectionStudy study = study(DetectionScenes.pairSweep(10, 21));
		final DetectionStudy.Row apart = study.bands().get(0);
		assertEquals(">= 1 D", apart.band());
		assertEquals(14, apart.particles());
		assertEquals(1.0, apart.recall(), "recall");
		assertEquals(0, apart.falseSpots(), "false spots");
		assertEquals(0, apart.duplicates(), "duplicates");
		assertTrue(apart.unflaggedShare() >= 0.9, "unflagged " + apart.unflaggedShare() + ", mostly " + apart
			.mainFlag());
		assertTrue(apart.worstBias() < 0.05, "bias " + apart.worstBias() + " px");
		assertTrue(apart.spreadOverBound() < 2, "spread / CRB " + apart.spreadOverBound());
	}

	/**
	 * The same pair pushed on into overlap, 40 frames from 2 D to 0.5 D as a tweezer pair is: below contact too, both
	 * particles are found in every frame, unflagged, within 0.02 px of the truth (the study's 5 movies: every
	 * particle found, one false spot in 400, bias under 0.006 px, spread 1.04-1.09 x CRB).
	 */
	@Test
	void pairSweepIntoOverlapIsFoundAndCentred() {
		final DetectionStudy study = study(DetectionScenes.pairSweep(40, 21));
		for (final String name : new String[] { "0.75-1 D", "0.5-0.75 D" }) {
			final DetectionStudy.Row b = band(study, name);
			assertEquals(1.0, b.recall(), name + ": recall");
			assertEquals(0, b.falseSpots() + b.duplicates(), name + ": false spots and duplicates");
			assertTrue(b.unflaggedShare() >= 0.9, name + ": unflagged " + b.unflaggedShare() + ", mostly " + b
				.mainFlag());
			assertTrue(b.worstBias() < 0.02, name + ": bias " + b.worstBias() + " px");
			assertTrue(b.spreadOverBound() < 1.5, name + ": spread / CRB " + b.spreadOverBound());
		}
	}

	/**
	 * A tweezer pair of particles dark inside a bright ring, on a 16-bit ramp of light, with photon noise, pushed from
	 * 2 D to 0.5 D in 40 frames, tracked with no value given: taken for dark particles; down to 0.54 D both found in
	 * every frame, none flagged, each frame's mean error under 0.2 px; to 0.75 D unbiased within 0.05 px and spread
	 * within 1.5 times the bound (the study's
	 * 5 movies: 0.94-0.99 x CRB). Taken for bright, as they were on the ramp's levels, 2 spots were found in 40 frames.
	 * Not yet: at 0.5 D this movie (and one of the study's five) gets one spot between the two, unflagged.
	 */
	@Test
	void aRingPairOnARampIsFoundAndCentred() {
		final DetectionStudy study = study(DetectionScenes.ringPair(40, 21));
		int frames = 0;
		for (final DetectionStudy.Row r : study.labels()) {
			if (Double.parseDouble(r.band()) < 0.53) continue;
			frames++;
			assertEquals(2, r.found(), r.band() + " D: found");
			assertEquals(0, r.falseSpots() + r.duplicates(), r.band() + " D: false spots and duplicates");
			assertEquals(1.0, r.unflaggedShare(), r.band() + " D: unflagged, else " + r.mainFlag());
			assertTrue(r.worstBias() < 0.2, r.band() + " D: error " + r.worstBias() + " px");
		}
		assertEquals(39, frames);
		for (final String name : new String[] { ">= 1 D", "0.75-1 D" }) {
			final DetectionStudy.Row b = band(study, name);
			assertTrue(b.worstBias() < 0.05, name + ": bias " + b.worstBias() + " px");
			assertTrue(b.spreadOverBound() < 1.5, name + ": spread / CRB " + b.spreadOverBound());
		}
	}

	/**
	 * The study's first movie of the pair pushed into overlap (seed 1000): at 0.885 D the image's seeds and the fit's
	 * split put a third member between the two particles, and the joint fit took its light to nothing (amplitude 0, its
	 * centre drifting 50 to 100 px off) with the pair's two members on their particles. That left the fit's normal
	 * matrix singular, and the three kept their seeds, flagged FELL_BACK: one false spot, three flagged. The vanished
	 * member is now left out and the pair fitted again: every particle found, no false spot, none flagged.
	 */
	@Test
	void aMemberTheFitTakesToNothingIsLeftOut() {
		final DetectionStudy study = study(DetectionScenes.pairSweep(40, 1000));
		for (final DetectionStudy.Row b : study.bands()) {
			assertEquals(1.0, b.recall(), b.band() + ": recall");
			assertEquals(0, b.falseSpots() + b.duplicates(), b.band() + ": false spots and duplicates");
			assertEquals(1.0, b.unflaggedShare(), b.band() + ": unflagged, else mostly " + b.mainFlag());
		}
	}

	private static DetectionStudy.Row band(final DetectionStudy study, final String name) {
		for (final DetectionStudy.Row r : study.bands())
			if (r.band().equals(name)) return r;
		throw new AssertionError("no band " + name + " in " + study.bands());
	}

	/**
	 * The fit of a faint spot settles well within its iterations: at a peak signal to noise of 3 to 5 its residual sum
	 * of squares is shallow and bent within a step, and the steps, accepted for any drop, crossed its valley from side
	 * to side until the iterations ran out (a fifth of the dim scene's fits ended so, flagged NOT_CONVERGED). With the
	 * damping raised where a step drops the residuals by far less than foretold, and the fit settled at a tenth of
	 * the centres' own errors, none does.
	 */
	@Test
	void theFitsOfFaintSpotsSettle() {
		final DetectionScene scene = DetectionScenes.dim(3, 32);
		int spots = 0, capped = 0;
		for (final java.util.List<io.github.contacttracker.core.Localization> frame : new NewUserTracker(2).track(scene)
			.spots())
			for (final io.github.contacttracker.core.Localization l : frame) {
				spots++;
				if (l.iterations() > io.github.contacttracker.core.fit.FitAccess.MAX_ITERATIONS) capped++;
			}
		assertTrue(spots > 80, spots + " spots");
		assertEquals(0, capped, capped + " of " + spots + " fits ran out of iterations");
	}

	/**
	 * Dim 16-bit spots at SNR 3-5 (5 frames): nearly all found, the touching ones too (the partner of a touching pair
	 * dips towards the brighter one by less than a seed's prominence, and is added from the residuals where its light
	 * is significant), at most 3 false spots, 95% unflagged or more (the fits of faint spots settle, and a centre that
	 * a faint profile moves by a fraction of its error round to round is not flagged), and the unflagged centres
	 * unbiased within 0.1 px along x and y with a spread within 1.5 times the bound.
	 */
	@Test
	void dimSpotsAreFoundAndCentredToTheBound() {
		final DetectionStudy study = study(DetectionScenes.dim(5, 31));
		final DetectionStudy.Row all = study.total(), alone = band(study, DetectionScenes.ALONE), touching = band(study,
			DetectionScenes.TOUCHING);
		assertTrue(alone.recall() >= 0.93, "recall alone " + alone.recall());
		assertTrue(touching.recall() >= 0.8, "recall touching " + touching.recall());
		assertTrue(all.falseSpots() <= 3, all.falseSpots() + " false spots");
		assertTrue(all.unflaggedShare() >= 0.95, "unflagged " + all.unflaggedShare() + ", mostly " + all.mainFlag());
		assertTrue(Math.abs(all.biasX()) < 0.1 && Math.abs(all.biasY()) < 0.1, "bias " + all.biasX() + ", " + all
			.biasY());
		assertTrue(all.spreadOverBound() < 1.5, "spread / CRB " + all.spreadOverBound());
	}

	/**
	 * Dark spheres on a bright background (2 frames): every particle found, none false, none flagged; those alone
	 * unbiased within 0.01 px and spread within 1.5 times the bound (the study: 0.001 px, 1.12); those touching
	 * too (the study: 0.001 px, 1.02).
	 */
	@Test
	void darkSpheresAreAllFound() {
		final DetectionStudy study = study(DetectionScenes.dark(2, 32));
		final DetectionStudy.Row all = study.total(), alone = band(study, DetectionScenes.ALONE), touching = band(study,
			DetectionScenes.TOUCHING);
		assertEquals(1.0, all.recall(), "recall");
		assertEquals(0, all.falseSpots() + all.duplicates(), "false spots and duplicates");
		assertEquals(1.0, all.unflaggedShare(), "unflagged");
		assertTrue(alone.worstBias() < 0.01, "bias alone " + alone.worstBias());
		assertTrue(alone.spreadOverBound() < 1.5, "spread / CRB alone " + alone.spreadOverBound());
		assertTrue(touching.worstBias() < 0.01, "bias touching " + touching.worstBias());
		assertTrue(touching.spreadOverBound() < 1.5, "spread / CRB touching " + touching.spreadOverBound());
	}

	/**
	 * Bright spheres on a background clipped at 0 (5 frames): every particle alone is found, unflagged, unbiased
	 * within 0.01 px (the study: 0.002 px); at least 9 in 10 of those touching in pairs and chains are found (the
	 * study: all of them), unbiased within 0.01 px too (here 0.002 px; with the background measured from the pixels
	 * above the floor alone, 0.016 px, pulled towards each other; the study: 0.031 px).
	 */
	@Test
	void particlesOnAClippedBackgroundAreFound() {
		final DetectionStudy study = study(DetectionScenes.clipped(5, 33));
		final DetectionStudy.Row alone = band(study, DetectionScenes.ALONE), touching = band(study,
			DetectionScenes.TOUCHING);
		assertEquals(1.0, alone.recall(), "recall alone");
		assertEquals(0, alone.falseSpots() + alone.duplicates(), "false spots alone");
		assertEquals(1.0, alone.unflaggedShare(), "unflagged alone");
		assertTrue(alone.worstBias() < 0.01, "bias alone " + alone.worstBias());
		assertTrue(touching.recall() >= 0.9, "recall touching " + touching.recall());
		assertTrue(touching.worstBias() < 0.01, "bias touching " + touching.worstBias());
	}

	/**
	 * Packed monolayers of 255 bright blurred discs (D 14 px, area fraction 0.6, none alone), 2 frames each, tracked
	 * with no value given, two layouts (the second one where the image's seeds miss particles in packed patches, which
	 * the fit must add from their residual peaks a neighbour's distance from the members): at least 99% of the
	 * particles are found, under 1% of the spots are false, at least 95% of the spots inside the frame are unflagged,
	 * and their centres are unbiased within 0.005 px and spread by less than 0.035 px (the study's 5 movies: 99.6%
	 * found, 0.2% false, 97.7% unflagged, bias under 0.001 px, spread 0.023 px).
	 */
	@Test
	void aPackedMonolayerIsFoundAndCentred() {
		assertPackedMonolayersFoundAndCentred(1, 5001);
	}

	/**
	 * Packed monolayers of 255 bright blurred discs (the study's {@code dense}, 2 frames each) at these seeds, tracked
	 * with no value given: at least 99% of the particles found, under 1% of the spots false, at least 95% of the spots
	 * inside the frame unflagged, their centres unbiased within 0.005 px and spread by less than 0.035 px, and their
	 * reported errors their errors within a fifth: each member is fitted in turn, its neighbours held, and its error
	 * widened by theirs (the fit's own errors alone understated the study's by a third: error / σ 1.33).
	 */
	private static void assertPackedMonolayersFoundAndCentred(final long... seeds) {
		final DetectionStudy study = new DetectionStudy();
		final NewUserTracker tracker = new NewUserTracker(2);
		for (final long seed : seeds) {
			final DetectionScene scene = DetectionScenes.dense(2, seed);
			study.add(scene, tracker.track(scene));
		}
		final DetectionStudy.Row all = study.total();
		assertFoundAndCentred(all);
		assertTrue(all.errorOverReported() > 0.8 && all.errorOverReported() < 1.2, "error / reported error " + all
			.errorOverReported());
	}

	/**
	 * At least 99% of the particles found, under 1% of the spots false or duplicate, at least 95% of the spots inside
	 * the frame unflagged, their centres unbiased within 0.005 px and spread by less than 0.035 px.
	 */
	private static void assertFoundAndCentred(final DetectionStudy.Row all) {
		assertTrue(all.recall() >= 0.99, "recall " + all.recall());
		assertTrue(all.falseSpots() + all.duplicates() <= 0.01 * all.particles(), all.falseSpots() + " false spots, " +
			all.duplicates() + " duplicates");
		assertTrue(all.unflaggedShare() >= 0.95, "unflagged " + all.unflaggedShare() + ", mostly " + all.mainFlag());
		assertTrue(all.worstBias() < 0.005, "bias " + all.worstBias() + " px");
		assertTrue(all.spread() < 0.035, "spread " + all.spread() + " px");
	}

	/**
	 * Two more layouts of the same packed monolayer, where the threshold's areas look single though each holds several
	 * particles (in the first, more than half of them: they would start the profile; in the second, the few areas a
	 * frame has teach its own profile): a profile taught by them is too wide, the image's seeds fitted with it pin at
	 * its scale's limits, and the run found 47% and 14% of the particles, every spot flagged. The rounds start from
	 * the image's centres instead, and each frame's own profile takes over: as in the other layouts, at least 99% of
	 * the particles found, under 1% of the spots false, at least 95% of those inside the frame unflagged.
	 */
	@Test
	void aPackedMonolayerWhoseAreasLookSingleIsFoundToo() {
		assertPackedMonolayersFoundAndCentred(2001, 2003);
	}

	/**
	 * A packed monolayer of two sizes (the study's {@code dense-bidisperse}: 1,578 discs of D 10 and 14 px at an area
	 * fraction of 0.7, none alone, 512 x 512 px), two frames tracked with no value given: at least 99% of the
	 * particles found, under 1% of the spots false or duplicate, at least 95% of the spots inside the frame unflagged,
	 * their centres unbiased within 0.005 px and spread by less than 0.035 px. Each round of the model's moves refits
	 * the frame from the fit before; from their first passes, the members that had not settled in one fit's sweeps
	 * started over in the next, and this layout (the study's second movie) had 92.9% of its spots unflagged (98.1%
	 * now; the study's 5 movies: 89% to 96%, now 96% to 98%).
	 */
	@Test
	void aPackedMonolayerOfTwoSizesIsFoundAndCentred() {
		final DetectionStudy study = new DetectionStudy();
		final DetectionScene scene = DetectionScenes.denseBidisperse(2, 6001);
		study.add(scene, new NewUserTracker(2).track(scene));
		assertFoundAndCentred(study.total());
	}

	/**
	 * A confocal slice of a dense packing of many sizes, a fifth of the gaps between them clipped at 0, with {@code --r-out
	 * 7} given (the helper's 4 falls short of the largest particles' light: accuracy.md): 99% of the particles found,
	 * at least 80% of the spots unflagged (today 99.1% and 86%), at most 3 false spots, spread under 0.5 px. The pixels at
	 * and near 0 are fitted through the mean of the noise clipped there; left out within 3 noise sigma of 0, the rule
	 * before, the rounds of profile and centres did not settle and every spot was flagged {@code NOT_CONVERGED}.
	 */
	@Test
	void aConfocalPackingClippedAtZeroSettles() {
		final DetectionScene scene = DetectionScenes.densePolydisperse(1, 8001);
		final DetectionStudy study = new DetectionStudy();
		study.add(scene, new NewUserTracker(2).given(TrackingSettings.R_OUT, 7.0).track(scene));
		final DetectionStudy.Row all = study.total();
		// a fifth of the gaps between the particles (2.3% of the frame: below the 5% that makes a background clipped,
		// so the floor is linked with the frame's noise)
		assertTrue(scene.clipped() > 0.02 * scene.width() * scene.height(), scene.clipped() + " pixels at 0");
		assertTrue(all.recall() >= 0.99, "recall " + all.recall());
		assertTrue(all.unflaggedShare() >= 0.8, "unflagged " + all.unflaggedShare() + ", mostly " + all.mainFlag());
		assertTrue(all.falseSpots() <= 3, all.falseSpots() + " false spots");
		assertTrue(all.spread() < 0.5, "spread " + all.spread() + " px");
	}

	/**
	 * A pair that stands apart in the first frame, in a movie whose threshold the helper cannot measure (it lies above
	 * every pixel where the pair overlaps and clips): the helper's rim diameter is kept, and the notice says the helper
	 * measured the rim, not that it measured nothing.
	 */
	@Test
	void theNoticeSaysWhatTheHelperMeasuredWhereItsRimIsKept() {
		final DetectionScene scene = DetectionScenes.pairSweep(40, 1000);
		final MeasuredSettings.Result m = MeasuredSettings.of("pair.tif", t -> frame(scene, t), scene.frames().size(),
			true, SettingValues.defaults(), Set.of(), FrontEnd.COMMAND_LINE);
		assertTrue(m.notice().contains(": the profile helper measured the particles' rim but no threshold (its " +
			"threshold "), m.notice());
		assertTrue(Math.abs(m.settings().diameter() - 12) < 0.05 * 12, m.notice());
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static RandomAccessibleInterval<? extends RealType<?>> frame(final DetectionScene scene, final int t) {
		return (RandomAccessibleInterval) scene.frames().get(t);
	}
}
