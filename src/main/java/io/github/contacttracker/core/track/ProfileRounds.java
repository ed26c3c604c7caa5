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
package io.github.contacttracker.core.track;

import static io.github.contacttracker.core.track.FramePass.pass;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.IntFunction;

import io.github.contacttracker.core.Detection;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.detect.ModelSelection;
import io.github.contacttracker.core.fit.ProfileRefinement;
import io.github.contacttracker.core.fit.Rounds;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindFeatures;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.kind.Kinds;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.profile.ProfileEstimator;
import io.github.contacttracker.core.track.FramePass.Progress;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.parallel.Parallelization;
import net.imglib2.type.numeric.RealType;

/**
 * The rounds of profile and centres on a movie's sample frames, with which the profile methods (deblend, fit) start a
 * movie: iterative centres on the sample frames (fewer of them where they hold more particles than the profile
 * needs), the detection chosen where it is to be, the kinds of particle told apart, the first profile measured on
 * those centres (or on the image's, in a packed field); then profile and centres alternated until the centres stop
 * moving; and, where the last rounds refitted the particles the first ones found, a last pass over the sample frames
 * with the last profile. {@link StackTracker} then refines every other frame with that profile.
 */
final class ProfileRounds {

	private ProfileRounds() {}

	/**
	 * What the rounds on a movie's sample frames end with.
	 *
	 * @param sample the sample frames kept (0-based, ascending)
	 * @param profile the profile of each kind the movie's frames are refined with, or {@code null} when each frame
	 *        measures its own
	 * @param settled whether the rounds settled (or cycled between two fits)
	 * @param round the sample frames' results of the last round, before the movie's flags
	 * @param choice the detection chosen for the movie, or null where it was given
	 * @param misfit the typical fit of the sample frames' spots, where the particles were found by their image, else
	 *        null
	 */
	record Outcome(int[] sample, KindProfiles profile, boolean settled, List<FrameResult> round, DetectionChoice choice,
		Misfit misfit) {}

	/**
	 * The rounds on a movie's sample frames, the frames shared among the threads of the caller's task executor.
	 *
	 * @param given the tracker of the movie's frames, as the settings give it
	 * @param sample the sample frames (0-based, ascending); fewer are kept where they hold more particles than the
	 *        profile needs
	 * @param frame supplies frame {@code t} (thread-safe; the sample frames are read once a round)
	 * @param progress the run's passes over a frame, whose total the rounds correct as they go
	 * @return the profile, the sample frames kept and their last round's results
	 */
	static <T extends RealType<T>> Outcome measure(final ContactTracker given, int[] sample,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final Progress progress,
		final BooleanSupplier cancelled)
	{
		final TrackerParameters params = given.parameters();
		// A dense field needs fewer frames for as many particles (the rounds' cost follows the frames): how many is
		// estimated from the iterative centres of two sample frames, the first and the middle one, and only the frames
		// kept are then run (the profile's error falls with the particles it is measured on, not with the frames).
		// (the iterative start from the threshold's components: seeds of the image that are no particles, such as the
		// fringes where bright-field halos meet, are told apart by the profile, which is not known yet)
		final ContactTracker iterativeTracker = new ContactTracker(params.withMethod(Method.ITERATIVE).withDetection(
			Detection.THRESHOLD));
		final int[] probe = sample.length <= 2 ? FramePass.range(sample.length) : new int[] { 0, sample.length / 2 };
		final List<FrameResult> probed = pass(iterativeTracker, null, at(sample, probe), frame,
			false, progress, cancelled);
		final int[] keep = fewer(sample.length, RoundResults.usable(probed) / (double) probe.length);
		final FrameResult[] done = new FrameResult[sample.length]; // by position among the sample frames
		for (int i = 0; i < probe.length; i++)
			done[probe[i]] = probed.get(i);
		final int[] rest = java.util.stream.IntStream.of(keep).filter(p -> done[p] == null).toArray();
		final List<FrameResult> others = pass(iterativeTracker, null, at(sample, rest), frame, false, progress,
			cancelled);
		for (int i = 0; i < rest.length; i++)
			done[rest[i]] = others.get(i);
		List<FrameResult> iterative = new ArrayList<>(keep.length);
		for (final int p : keep)
			iterative.add(done[p]);
		progress.total -= sample.length - probe.length - rest.length; // iterative frames not run
		progress.total -= sample.length - keep.length; // the first round's frames
		sample = at(sample, keep);
		// the detection, where it is to be chosen: from the threshold's components on these frames
		final DetectionChoice choice = params.choosesDetection() ? choose(iterative, frame.apply(sample[0]), params)
			: null;
		final ContactTracker tracker = withChoice(given, choice);
		final boolean detects = tracker.parameters().detectsByImage();
		// Where the image detects and most of the threshold's areas are not single particles (a packed field, where they
		// hold several particles each: 12% to 20% of them single on simulated dense monolayers), the first centres are
		// the image's, each sample frame fitted with a profile of its own: a profile measured around the areas' centres
		// would start the rounds so far from the particles' that they settle elsewhere, or not at all (a fifth of the
		// particles found, every one flagged; with the image's start all found, 0.03 px off). Where most areas are
		// single particles (touching beads, spheres parted by dark rims, a pair that merges only when pushed close:
		// 65% to 100% on public and simulated footage), they start it: they flag their merges, which a frame's own
		// profile learns as one wide particle (a simulated pair whose last quarter merged: its closest frame lost).
		Start start = start(tracker, params, sample, iterative, detects && RoundResults.usableShare(iterative) <
			IMAGE_START, frame, progress, cancelled);
		// Areas that look single but hold several particles each (a packed field that no outline tells apart) teach a
		// profile too wide for the particles: the image's seeds, fitted with it, pin at its scale's limits and most are
		// left out (a simulated monolayer of blurred discs: 72 spots for 510 particles, every one flagged). The rounds
		// start again from the image's centres, each frame's profile its own.
		if (detects && !start.fromImage() && mostLeftOut(start.round())) {
			progress.total += sample.length; // (the first round again)
			start = start(tracker, params, sample, iterative, true, frame, progress, cancelled);
		}
		final Kinds kinds = start.kinds();
		Measured used = start.used();
		List<FrameResult> previous = start.previous(), round = start.round();
		// where the threshold's areas taught no profile (dim spots below the threshold: it kept none of them), this
		// round's spots, found by the image with each frame's own profile, teach it; the rounds go on from there (with
		// no centre to compare, the first verdict would otherwise find nothing moving and call it settled)
		if (used == null && detects && !FrameResult.allSpots(round).isEmpty()) {
			progress.total += sample.length;
			previous = round;
			used = profile(round, null, sample, frame, params.profileReach(), kinds);
			round = pass(tracker, profiles(used), sample, frame, false, progress, cancelled);
		}
		final Rounds rounds = new Rounds();
		Rounds.Verdict verdict = rounds.next(RoundResults.moves(previous, round));
		double lastStep = Double.POSITIVE_INFINITY;
		final RoundResults.Unsettled unsettled = new RoundResults.Unsettled();
		boolean refitted = false;
		for (int r = 1; r < ProfileRefinement.PROFILE_ROUNDS && verdict == Rounds.Verdict.GOING_ON; r++) {
			progress.total += sample.length;
			previous = round;
			final Measured before = used;
			final Measured full = before == null ? null : new Measured(before.profiles(), null);
			// (the rounds that refitted the same particles: see RoundResults.Unsettled)
			final List<FrameResult> teaching = refitted ? unsettled.keptOut(round) : round;
			used = profile(teaching, r == 1 ? full : before, sample, frame, params.profileReach(), kinds);
			double step = change(used, before);
			if (r > 1 && !(step < lastStep)) {
				used = profile(teaching, full, sample, frame, params.profileReach(), kinds);
				step = change(used, before);
			}
			lastStep = step;
			final boolean refit = r >= SETTLED_MEMBERS && tracker.parameters().detectsByImage();
			round = pass(tracker, profiles(used), sample, frame, false, progress, cancelled, refit ? previous : null);
			refitted |= refit;
			verdict = rounds.next(RoundResults.moves(previous, round));
		}
		if (verdict == Rounds.Verdict.GOING_ON) verdict = rounds.atLimit(); // (the rounds' limit)
		// no fixed point within the rounds, or rounds that stalled far from one: every centre rests on a profile that
		// was still moving. Settled: the
		// profile of the last round is the fixed point's (to within the tolerance), and the sample frames were just
		// refined with that very profile: without regions to keep, their results are the final ones. Cycling: so
		// is the profile, but a few centres of the sample frames went back and forth between two fits; they are flagged.
		final boolean settled = verdict == Rounds.Verdict.SETTLED || verdict == Rounds.Verdict.CYCLING;
		// Where the last rounds refitted the particles the first ones found, those particles were decided on an early
		// profile: the sample frames are found once more with the last one, as every other frame is (a pair pushed into
		// overlap is told apart only by a profile close to its own), each spot that a nearby one of the rounds' saw
		// still moving flagged as that one was (where the frame's particles are the rounds').
		if (refitted) {
			progress.total += sample.length;
			final List<FrameResult> found = pass(tracker, profiles(used), sample, frame, false, progress, cancelled);
			round = verdict == Rounds.Verdict.CYCLING ? RoundResults.carried(round, RoundResults.stillMoving(round,
				rounds), found, params.diameter() / 4) : found;
		}
		else if (verdict == Rounds.Verdict.CYCLING) round = RoundResults.stillMovingFlagged(round, rounds);
		return new Outcome(sample, profiles(used), settled, round, choice, tracker.parameters().detectsByImage()
			? Misfit.of(round) : null);
	}

	/**
	 * How the rounds start: the centres they start from ({@code previous}: the threshold's iterative ones, or where
	 * {@code fromImage} the image's, each sample frame fitted with a profile of its own), the kinds, the first
	 * profile measured around those centres ({@code used}) and the first round found with it.
	 */
	private record Start(boolean fromImage, Kinds kinds, Measured used, List<FrameResult> previous,
		List<FrameResult> round) {}

	/**
	 * @param threshold the sample frames' iterative centres, from the threshold's areas
	 * @param imageStart whether the image's centres start the profile instead
	 * @return the start of the rounds on the sample frames
	 */
	private static <T extends RealType<T>> Start start(final ContactTracker tracker, final TrackerParameters params,
		final int[] sample, final List<FrameResult> threshold, final boolean imageStart,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final Progress progress,
		final BooleanSupplier cancelled)
	{
		List<FrameResult> iterative = threshold;
		if (imageStart) {
			progress.total += sample.length;
			iterative = pass(tracker, null, sample, frame, false, progress, cancelled);
		}
		// the kinds of particle, told apart on the same frames; the profile of each is measured on its particles
		Kinds kinds = null;
		if (params.kinds() != 1) {
			// each frame read and its spots measured once (frames shared among the threads), to find the kinds and to
			// place each spot
			final List<FrameResult> measured = iterative;
			final int[] frames = sample;
			final List<KindFeatures[]> features = Parallelization.getTaskExecutor().forEachApply(FramePass.positions(
				frames.length), i -> KindFeatures.measure(Plane.of(frame.apply(frames[i])), measured.get(i).spots(),
					params.rOut()));
			final List<KindFeatures> found = new ArrayList<>();
			for (int i = 0; i < sample.length; i++) {
				final List<Localization> spots = iterative.get(i).spots();
				final KindFeatures[] f = features.get(i);
				for (int k = 0; k < f.length; k++) // merges too: a kind may be all merges at a low threshold
					if (!spots.get(k).has(Flag.DEGENERATE)) found.add(f[k]);
			}
			kinds = KindProfiles.tellApart(found, params.kinds());
			if (kinds != null) iterative = withKinds(iterative, features, kinds);
		}
		// The profile is measured around estimated centres, and in a configuration that never changes (every frame
		// the same cluster) it absorbs part of their error; so profile and centres are alternated on the sample
		// frames until the centres stop moving (the joint least-squares fixed point, to a tenth of the centres' errors).
		// The first round's profile, on the iterative centres, only starts the rounds: it is measured on every other
		// sample frame (a start needs no more: the rounds after it converge to the same fixed point), the later
		// ones on them all. The third and later rounds' profiles are chord steps from the second's least squares (see
		// ProfileEstimator). Not from the first's: it rests on the iterative centres without fitted amplitudes and
		// scales, too far from the later rows for a step from it to land near the exact profile.
		// A chord step converges only while the rows stay near those of its normal matrix: one that moves the profile
		// no less than the round before did is replaced by the full least squares (where the rows change much, as
		// with particles cut by the edge, chord steps can grow round after round and the centres run off).
		final List<FrameResult> previous = iterative;
		// (the image's: on every sample frame, each fitted with its own profile, some of which may not have settled)
		final int every = imageStart ? 1 : 2;
		final int[] starting = new int[(sample.length + every - 1) / every];
		for (int i = 0; i < starting.length; i++)
			starting[i] = every * i;
		final Frames first = new Frames(sample, previous).at(starting);
		Measured used = profile(first.results(), null, first.indices(), frame, params.profileReach(), kinds);
		// a kind none of whose particles can teach a profile (all merged where the threshold joined touching
		// particles, as it does a pair pushed together): one profile for them all, not none
		if (used == null && kinds != null) {
			kinds = null;
			used = profile(first.results(), null, first.indices(), frame, params.profileReach(), null);
		}
		return new Start(imageStart, kinds, used, previous, pass(tracker, profiles(used), sample, frame, false, progress,
			cancelled));
	}

	/**
	 * From this round of profile and centres on, a frame found by its image refits the particles of the round before
	 * instead of finding them again ({@link ModelSelection#refit}). Its particles are found by the first two rounds, on
	 * the start's profile and on the first measured on the movie; in a packed field one particle added or removed moves
	 * its neighbours' centres by more than their tolerance, and rounds which found them anew never settled (a dense
	 * monolayer of blurred discs: the count changing by 4 to 11 each round, the median move stalled at 8 to 14
	 * tolerances, every spot flagged). Removing in these rounds what the fit does not need cascaded there (each
	 * removal moving the neighbours of the next) and never settled either; a particle the fit would remove is kept
	 * out of the profile instead ({@link RoundResults.Unsettled}).
	 */
	static final int SETTLED_MEMBERS = 2;

	/** @return whether the image's seeds left out on these frames outnumber the spots found */
	private static boolean mostLeftOut(final List<FrameResult> round) {
		long spots = 0, left = 0;
		for (final FrameResult r : round) {
			spots += r.spots().size();
			left += r.discarded();
		}
		return left > spots;
	}

	/** Below this share of single-particle areas among the threshold's, the image's centres start the profile. */
	static final double IMAGE_START = 0.5;

	/** @return {@code tracker}, with the detection {@code choice} chose (as it is where none was chosen) */
	static ContactTracker withChoice(final ContactTracker tracker, final DetectionChoice choice) {
		return choice == null ? tracker : new ContactTracker(tracker.parameters().withDetection(choice.detection()));
	}

	/** @return the detection {@link Detection#AUTO} chooses from the threshold's first pass on the sample frames */
	private static <T extends RealType<T>> DetectionChoice choose(final List<FrameResult> firstPass,
		final RandomAccessibleInterval<T> first, final TrackerParameters params)
	{
		final List<List<Localization>> spots = new ArrayList<>(firstPass.size());
		int discarded = 0;
		for (final FrameResult r : firstPass) {
			spots.add(r.spots());
			discarded += r.discarded();
		}
		return DetectionChoice.choose(spots, discarded, Plane.of(first), params.diameter());
	}

	/** @return the elements of {@code array} at {@code positions}, in that order */
	private static int[] at(final int[] array, final int[] positions) {
		final int[] out = new int[positions.length];
		for (int i = 0; i < positions.length; i++)
			out[i] = array[positions[i]];
		return out;
	}

	/** Frames (their indices in the stack) and their results, in the same order. */
	private record Frames(int[] indices, List<FrameResult> results) {
		/** @return the frames at {@code positions} (of this list), in that order */
		Frames at(final int[] positions) {
			final List<FrameResult> out = new ArrayList<>(positions.length);
			for (final int p : positions)
				out.add(results.get(p));
			return new Frames(ProfileRounds.at(indices, positions), out);
		}
	}

	/**
	 * Enough particles for the profile: past {@value #PROFILE_PARTICLES} usable particles the profile's spline is
	 * as well determined as the centres need (the bench stack's 15 frames hold 180), and more frames only multiply
	 * the cost of the profile rounds.
	 *
	 * @param n the sample frames
	 * @param perFrame usable particles a frame (as the profile counts them: {@link RoundResults#usable})
	 * @return the positions among the {@code n} sample frames (evenly spread) of the frames kept
	 */
	private static int[] fewer(final int n, final double perFrame) {
		final double particles = perFrame * n;
		final int m = particles <= PROFILE_PARTICLES ? n : (int) Math.max(1, Math.min(n, Math.ceil(PROFILE_PARTICLES /
			perFrame)));
		final int[] kept = new int[m];
		for (int i = 0; i < m; i++)
			kept[i] = (int) ((long) i * n / m);
		return kept;
	}

	/** The profile rounds use frames holding about this many particles, if the sample frames hold more. */
	static final int PROFILE_PARTICLES = 300;

	/**
	 * The profiles of a round and the linearisation of their least squares (null: the next round is measured in
	 * full).
	 */
	private record Measured(KindProfiles profiles, ProfileEstimator.Linearisation linearisation) {}

	private static KindProfiles profiles(final Measured m) {
		return m == null ? null : m.profiles();
	}

	/** @return how far the profiles moved from {@code before} to {@code after} (infinite if either is missing) */
	private static double change(final Measured after, final Measured before) {
		return after == null || before == null || after.linearisation() == null || before.linearisation() == null
			? Double.POSITIVE_INFINITY : after.linearisation().change(before.linearisation());
	}

	/**
	 * Measures the radial profile of each kind on frames {@code indices} (with their results, in the same order, each
	 * spot of its {@link Localization#kind() kind}), the frames shared among the threads; null (each frame then
	 * measures its own) when they hold too few usable pixels. The profiles the results were refined with, if any,
	 * choose the pixels left out near clip levels, and the new ones are a chord step from their least squares.
	 */
	private static <T extends RealType<T>> Measured profile(final List<FrameResult> results,
		final Measured fitted, final int[] indices,
		final IntFunction<? extends RandomAccessibleInterval<T>> frame, final double reach, final Kinds kinds)
	{
		final int count = kinds == null ? 1 : kinds.count();
		// One estimator per frame, merged in frame order: the sums, and so the results, do not depend on the
		// number of threads.
		final List<Localization> all = FrameResult.allSpots(results);
		final double[][] norms = ProfileEstimator.norms(all, positions(all, kinds), count);
		final KindProfiles fittedWith = profiles(fitted);
		final EmpiricalProfile[] before = fittedWith == null ? null : new EmpiricalProfile[count];
		if (before != null) for (int c = 0; c < count; c++)
			before[c] = fittedWith.profile(c);
		final ProfileEstimator.Linearisation from = fitted == null ? null : fitted.linearisation();
		final List<ProfileEstimator> parts = Parallelization.getTaskExecutor().forEachApply(FramePass.positions(
			indices.length), i -> {
				final ProfileEstimator part = new ProfileEstimator(reach, count, from);
				final List<Localization> spots = results.get(i).spots();
				part.add(frame.apply(indices[i]), spots, positions(spots, kinds), norms[0], norms[1], before, results.get(
					i).noiseSigma());
				return part;
			});
		final ProfileEstimator sum = parts.get(0);
		for (int i = 1; i < parts.size(); i++)
			sum.merge(parts.get(i));
		try {
			final ProfileEstimator.Solution solved = sum.solve();
			final EmpiricalProfile[] measured = solved.profiles();
			return new Measured(kinds == null ? KindProfiles.one(measured[0]) : KindProfiles.of(kinds, measured), solved
				.linearisation());
		}
		catch (final IllegalStateException e) {
			return null;
		}
	}

	/** @return the position of each spot's kind among the kinds' profiles ({@link KindProfiles#position}) */
	private static int[] positions(final List<Localization> spots, final Kinds kinds) {
		final int[] at = new int[spots.size()];
		for (int k = 0; k < at.length; k++)
			at[k] = KindProfiles.position(kinds, spots.get(k).kind());
		return at;
	}

	/** @return the results, each spot labelled with its kind ({@code features}: the spots', frame by frame) */
	private static List<FrameResult> withKinds(final List<FrameResult> results, final List<KindFeatures[]> features,
		final Kinds kinds)
	{
		final List<FrameResult> out = new ArrayList<>(results.size());
		for (int i = 0; i < results.size(); i++) {
			final List<Localization> spots = results.get(i).spots();
			final int[] kind = KindProfiles.kindsOf(kinds, features.get(i));
			final List<Localization> labelled = new ArrayList<>(spots.size());
			for (int k = 0; k < kind.length; k++)
				labelled.add(spots.get(k).withKind(kind[k]));
			out.add(results.get(i).withSpots(labelled));
		}
		return out;
	}
}
