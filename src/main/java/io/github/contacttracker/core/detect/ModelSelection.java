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

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.fit.ProfileRefinement;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.kind.KindProfiles;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;
import io.github.contacttracker.core.radial.Refinement;

/**
 * Which particles a frame holds, decided by the fit: seeds from the image ({@link ImageDetection}), the profile
 * fit of them all, then moves that change the model where the data ask for it, until none does (at most
 * {@value #ROUNDS} rounds):
 * <ul>
 * <li><b>remove</b> a member the fit does not need: one whose fitted amplitude is not positive (no particle of its
 * kind: a bright fringe between dark-ringed particles), one that sits on another member (within a quarter
 * diameter: both fitted one particle), and one whose light lowers the residual sum of squares by less than
 * {@value #SIGNIFICANCE}&sup2; noise variances (the likelihood ratio of the model with and without it, at the
 * others' fitted values: a bump of noise), and a weak one whose own light (the residuals with its light added back,
 * its fitted neighbours' taken out) does not match its profile ({@link ProfileMatch#MATCH}: a fringe where halos
 * meet);</li>
 * <li><b>add</b> a particle where the residuals, band-passed as the frame was, hold a peak that stands out as the
 * seeds did, twice as high ({@link #ADD_LEVEL}, {@link ImageDetection#PROMINENCE}, in units of the band-passed
 * residuals' noise, the larger of the pixel noise's and the residuals' own robust spread, so that a model that
 * does not match the particles everywhere adds nothing) farther than a quarter diameter from every member: a
 * particle the seeds missed, such as the second of a pair closer than the filter resolves, which the fit of one
 * member leaves as a peak beside it;</li>
 * <li><b>split</b> a member beside which such a peak stands nearer than a diameter: the member held two particles, and
 * its two children are seeded along the peak's direction. Where the profiles are known and the member is fitted no
 * wider than its kind, a peak at least {@value #NEIGHBOUR_APART} diameters from it is a neighbour the seeds missed: it
 * adds a particle where it stands out as an added particle's must, and never splits the member.</li>
 * </ul>
 * After a move, every particle is seeded again at its fitted centre (an added one at its residual peak) and the frame
 * fitted again with the same profiles. A particle's significance, the square root of that drop of the residual sum of
 * squares in noise units, ranks the spots (their {@code QUALITY}).
 */
public final class ModelSelection {

	/**
	 * The threshold's components teach a frame's profile when at least this many, and this share of them, are one
	 * particle each (not suspected merges): else the seeds of the image do.
	 */
	static final int MIN_BOOTSTRAP = 1;
	/** See {@link #MIN_BOOTSTRAP}. */
	static final double HEALTHY = 0.8;
	/**
	 * A frame's own profile replaces one the threshold's areas taught, where that left most seeds out, only if it
	 * leaves out at most this share as many seeds as it keeps particles ({@link #track}).
	 */
	static final double OWN_LEFT_OUT = 0.05;

	/**
	 * With the profiles measured beforehand on the movie's particles (their amplitude 1 stands for a typical one), a
	 * member fainter than this is no particle of theirs: the texture of a compressed video's background and the
	 * fringes of a defocused bead's rings are fitted at a few hundredths of a particle, well above the pixel noise
	 * that a compressed video smooths away, and held the fit of the real particle beside them from settling.
	 */
	public static final double FAINT = 0.1;

	/** At most this many rounds of moves and refits. */
	public static final int ROUNDS = 3;
	/** A member must lower the residual sum of squares by this many noise standard deviations, squared. */
	public static final double SIGNIFICANCE = 5;
	/**
	 * A residual peak adds a particle at this many times the band-passed residuals' noise: twice a seed's level, so
	 * that a particle once added is not removed again by the next round (a missed particle leaves a residual peak of
	 * its whole height; a profile that is still being measured leaves ripples near every particle).
	 */
	public static final double ADD_LEVEL = 2 * ImageDetection.LEVEL;
	/**
	 * A fainter residual peak, at least {@link #FAINT_LEVEL} high, adds a particle only this many
	 * diameters or more from every kept member, where its light is as significant as a kept member's must be
	 * ({@value #SIGNIFICANCE}) and matches a profile: the partner of a dim pair that touches, whose dip towards the
	 * brighter one is shallower than a seed's prominence. Nearer, such a peak is the ripple a profile leaves on a
	 * bright particle.
	 */
	static final double FAINT_APART = 0.75;
	/**
	 * A residual peak this many diameters or more from the nearest member, where the profiles are known and that
	 * member is fitted no wider than its kind ({@link #WIDE}), adds a particle rather than splitting the member: in a
	 * packed field a particle the seeds missed sits a diameter from its neighbours, and its light pulls each towards it
	 * until its peak lies nearer than a diameter (a monolayer of blurred discs at contact: 0.83 to 0.96 diameters). Split,
	 * the member's children landed between particles; the missed particle's three neighbours were 0.3 to 1 px off, and
	 * unflagged. A member that holds two particles is fitted wider, and its peaks, beyond both particles, lie at 0.7 to 1
	 * diameter from it (a blurred pair at 0.85 diameters, fitted as one at scale 1.24 to 1.33). A peak there that does not
	 * stand out as an added particle's must splits nothing either: split, a member of its kind's width beside the frame's
	 * edge left a child 3 px from any particle, unflagged.
	 */
	static final double NEIGHBOUR_APART = 0.75;
	/**
	 * The least height of a residual peak that may add a particle, in units of the band-passed residuals' noise:
	 * below a seed's level ({@link ImageDetection#LEVEL}), since a faint peak adds a particle only where the
	 * significance of its light ({@value #SIGNIFICANCE}, the matched filter's measure, which the band-pass only
	 * approximates) says so. A dim particle at a peak signal to noise of 3 has a significance near 6.5, and a
	 * band-passed height near 5 half the time.
	 */
	static final double FAINT_LEVEL = 4;
	/**
	 * Faint peaks add particles only where the model matches the particles about as closely as the noise allows: the
	 * band-passed residuals' spread near the particles at most this many times the noise's. Where the profile's misfit
	 * is larger (real footage of bright particles: 6 to 100 times on public fluorescent and monolayer movies), its
	 * ripples and the specks between the particles stand out as faint peaks as a dim particle would.
	 */
	static final double FAINT_MISFIT = 1.5;

	private ModelSelection() {}

	/**
	 * The particles of a frame, their estimates and significance.
	 *
	 * @param particles the particles, seeded by the image and kept by the fit
	 * @param outcome their refinement, same order
	 * @param significance each particle's significance (noise units; NaN where not measured)
	 * @param removed seeds the fit did not need
	 */
	public record Result(Particle[] particles, Refinement.Outcome outcome, double[] significance, int removed) {}

	/**
	 * @param plane the frame
	 * @param params the parameters ({@link TrackerParameters#diameter()} {@code > 0})
	 * @param refinement the profile method ({@link ProfileRefinement#FIT} or {@link ProfileRefinement#DEBLEND})
	 * @param given the profiles measured beforehand, or {@code null} (measured on this frame)
	 * @param noise the frame's pixel noise (grey levels)
	 */
	public static Result track(final Plane plane, final TrackerParameters params, final ProfileRefinement refinement,
		final KindProfiles given, final double noise)
	{
		return track(plane, params, refinement, given, noise, null);
	}

	/**
	 * @param bootstrap without profiles given: the particles the threshold's components give, whose fit measures the
	 *        profiles that tell the image's seeds apart (a seed is kept where the frame matches a profile); null, or
	 *        a fit of them that measures no profile: the frame's own profile is measured on every seed
	 */
	public static Result track(final Plane plane, final TrackerParameters params, final ProfileRefinement refinement,
		final KindProfiles given, final double noise, final java.util.function.Supplier<Particle[]> bootstrap)
	{
		final Pixels pixels = new Pixels(plane, params.diameter());
		if (given == null && bootstrap != null) {
			final Particle[] first = bootstrap.get();
			int reliable = 0;
			for (final Particle p : first)
				if (p.reliable()) reliable++;
			// only components that are particles teach the profile: most of them one particle each
			if (reliable >= MIN_BOOTSTRAP && reliable >= HEALTHY * first.length) {
				final KindProfiles measured = refinement.fit(plane, first, params, null, noise).profiles();
				if (measured != null) {
					final Result taught = select(plane, pixels, params, refinement, measured, noise, null, null);
					if (!(taught.removed() > taught.particles().length)) return taught;
					// Most seeds left out: the areas that taught the profile were no single particles (in a packed
					// field, areas of several that no outline tells apart teach a profile too wide, and the seeds'
					// fits pin at its scale's limits: 42 particles kept of 253 seeds on a simulated monolayer of
					// blurred discs). The frame's own profile, measured on every seed, is tried too; it stands where
					// it keeps more particles and leaves out almost no seed, as on a field of particles (that
					// monolayer: 259 kept, 3 left out). Seeds on a textured background fit no one profile: there
					// it leaves out a tenth to nine tenths of them (DeepTrack's focal planes), and the areas' stands.
					final Result own = ownProfile(plane, pixels, params, refinement, noise);
					return own.particles().length > taught.particles().length && own.removed() <= OWN_LEFT_OUT * own
						.particles().length ? own : taught;
				}
			}
		}
		return given != null ? select(plane, pixels, params, refinement, given, noise, null, null) : ownProfile(plane,
			pixels, params, refinement, noise);
	}

	/**
	 * The moves of {@link #track} from the image's seeds with the frame's own profile. Where the highest seeds stand
	 * apart, {@code 1 / }{@link ImageDetection#RELATIVE} times as high as every other, the profile is measured on
	 * them alone, and every seed is fitted with it as with a profile given (a seed that it matches at less than
	 * {@link #FAINT} of its amplitude is no particle of it): in a tweezer's small field of view a particle a third of
	 * the frame across stands among bumps of the background (its uneven illumination, dust) that the band-pass at
	 * its scale leaves 15 to 40 times lower, which the noise does not part from particles, and whose reach, cut by the
	 * frame's edge, masked every pixel the profile could be measured on (an optical-tweezer stack of one bead 62 px
	 * across in 184 x 181 px: no spot fitted, every one flagged). Else, and where that profile cannot be measured,
	 * the profile is measured on every seed.
	 */
	private static Result ownProfile(final Plane plane, final Pixels pixels, final TrackerParameters params,
		final ProfileRefinement refinement, final double noise)
	{
		final double d = params.diameter();
		final Peaks seeds = ImageDetection.seeds(pixels.bandPassed(), pixels.w, pixels.h, d, noise);
		final int strong = seeds.standingApart(1 / ImageDetection.RELATIVE);
		if (strong < seeds.count()) {
			final Particle[] teaching = Seeded.at(plane, Arrays.copyOf(seeds.x(), strong), Arrays.copyOf(seeds.y(),
				strong), d).particles();
			final KindProfiles measured = refinement.fit(plane, teaching, params, null, noise).profiles();
			if (measured != null) return select(plane, pixels, params, refinement, measured, noise, null, null);
		}
		return select(plane, pixels, params, refinement, null, noise, null, null);
	}

	/**
	 * The particles at {@code (x, y)} (the frame's local coordinates), fitted with the profiles given, each with its
	 * significance; none added, split or removed. A movie's profile rounds refit the particles an earlier round found,
	 * so that the centres they compare round to round are those of the same particles (see the stack tracker).
	 */
	public static Result refit(final Plane plane, final TrackerParameters params, final ProfileRefinement refinement,
		final KindProfiles given, final double noise, final double[] x, final double[] y)
	{
		return select(plane, new Pixels(plane, params.diameter()), params, refinement, given, noise, x, y);
	}

	/**
	 * The moves of {@link #track} from the image's seeds, or ({@code x} and {@code y} not null, profiles given) the
	 * particles at {@code (x, y)} fitted, each with its significance, no move made.
	 */
	private static Result select(final Plane plane, final Pixels pixels, final TrackerParameters params,
		final ProfileRefinement refinement, final KindProfiles given, final double noise, final double[] x,
		final double[] y)
	{
		final boolean grow = x == null;
		final double d = params.diameter();
		final int w = pixels.w, h = pixels.h;
		final float[] data = pixels.data;
		final ImageDetection.Scale scale = pixels.scale;
		// the seeds from the band-passed frame that the moves below use too
		final Peaks seeds = grow ? ImageDetection.seeds(pixels.bandPassed(), w, h, d, noise) : Peaks.NONE;
		final double least = ImageDetection.RELATIVE * seeds.typicalHeight();
		final double strong = ProfileMatch.STRONG * ProfileMatch.typicalMatching(seeds, data, w, h, given, noise);
		// with the profiles known, no seed is fitted where the profile matches it at less than a faint particle's
		// amplitude (a textured background's bumps: fitted, they would cost more than the particles). Whether a weak
		// seed is a particle at all is judged after the fit, on its own light (see the removal below): the frame
		// around a seed holds its neighbours' light too, which in a packed field spoils its match with any single
		// profile (on a monolayer of blurred discs at contact, a match on the frame kept 114 of 255 seeds).
		final Moves start = new Moves(grow ? seeds.count() : x.length);
		int removed = 0;
		if (!grow) for (int i = 0; i < x.length; i++)
			start.add(x[i], y[i]);
		else for (int i = 0; i < seeds.count(); i++)
			if (given == null || !(ProfileMatch.amplitudeAny(data, w, h, seeds.x()[i], seeds.y()[i], given) < FAINT)) start
				.add(seeds.x()[i], seeds.y()[i]);
			else removed++;
		// where each particle was seeded (see the moves: a member cut by the edge is seeded there again)
		Seeded seeded = Seeded.at(plane, start.x(), start.y(), d);
		ProfileRefinement.Fitted fitted = refinement.fit(plane, seeded.particles(), params, given, noise, false);
		final KindProfiles profiles = fitted.profiles();
		double[] significance = new double[seeded.particles().length];
		Arrays.fill(significance, Double.NaN);
		if (profiles == null) return new Result(seeded.particles(), fitted.outcome(), significance, removed);
		// members removed whose light the fit needed: particles cut by the frame's edge (see unmodelled)
		final java.util.List<Unmodelled> unmodelled = new java.util.ArrayList<>();
		for (int round = 0; round <= ROUNDS; round++) {
			final Estimate[] e = fitted.outcome().estimates();
			final int[] kinds = fitted.outcome().kinds() != null ? fitted.outcome().kinds() : new int[e.length];
			final EmpiricalProfile[] of = profiles.byParticle(kinds);
			final float[] residual = data.clone();
			for (int k = 0; k < e.length; k++)
				if (DrawnModel.drawn(e[k])) DrawnModel.draw(residual, w, h, e[k], of[k], -1);
			significance = new double[e.length];
			for (int k = 0; k < e.length; k++)
				significance[k] = DrawnModel.drawn(e[k]) ? MemberTests.significance(residual, w, h, e[k], of[k], noise)
					: MemberTests.undrawn(residual, w, h, e[k], of[k], noise);
			if (round == ROUNDS || !grow) break;
			// remove
			final float[] framed = pixels.bandPassed();
			final double[] match = new double[e.length];
			for (int k = 0; k < e.length; k++)
				match[k] = !ProfileMatch.weak(framed, w, h, e[k].x(), e[k].y(), strong) ? 1 : DrawnModel.drawn(e[k]) ? ProfileMatch
					.shapeOwn(residual, w, h, e[k], of[k], noise) : ProfileMatch.matched(data, w, h, e[k].x(), e[k].y(),
						of[k], noise);
			// (on a background textured at the particles' scale, a member must stand out of the texture's bumps)
			final double texture = BackgroundTexture.factor(framed, w, h, e, of, ImageDetection.unit(scale.noise(noise),
				framed), seeds.typicalHeight());
			final boolean[] keep = new boolean[e.length];
			// (a member whose own fit is no particle of its kind: its scale pressed against a limit, or its light not
			// matching its profile)
			final boolean[] misfit = new boolean[e.length];
			int kept = 0;
			for (int k = 0; k < e.length; k++) {
				misfit[k] = e[k].scale() <= PINNED_LOW || pinned(e[k]) || match[k] < ProfileMatch.MATCH;
				keep[k] = !(e[k].amplitude() <= (given != null ? FAINT : 0)) && !misfit[k] && !(significance[k] <
					SIGNIFICANCE * texture);
				for (int j = 0; j < k && keep[k]; j++)
					if (keep[j] && e[j].closerThan(e[k], d / 4)) {
						// two members on one particle: the weaker goes
						if (e[k].amplitude() > e[j].amplitude()) keep[j] = false;
						else keep[k] = false;
					}
			}
			MemberTests.overlapTest(data, w, h, e, of, keep, significance, d, noise);
			// (removed for its own fit, not because another member draws its light)
			for (int k = 0; k < e.length; k++)
				if (misfit[k] && DrawnModel.drawn(e[k]) && e[k].has(Flag.AT_BORDER) && significance[k] >=
					SIGNIFICANCE * texture) unmodelled.add(new Unmodelled(e[k].x(), e[k].y(), of[k].radius() * e[k].scale()));
			for (final boolean b : keep)
				if (b) kept++;
			// split and add
			final float[] bp = BandPass.of(residual, w, h, scale.sigma(), scale.halfWidth());
			final double noiseUnit = ImageDetection.unit(scale.noise(noise), bp);
			final double unit = Math.max(noiseUnit, DrawnModel.robustSpread(bp, DrawnModel.near(w, h, e, of)));
			// faint peaks add particles only where the model matches them as closely as the noise allows; the
			// residuals' noise there counts what misfit is left
			final boolean faintAdds = unit <= FAINT_MISFIT * noiseUnit;
			final double residualNoise = noise * unit / noiseUnit;
			final Peaks more = Peaks.find(bp, w, h, 0, Math.max((faintAdds ? FAINT_LEVEL : ADD_LEVEL) * unit, least),
				ImageDetection.PROMINENCE * unit);
			final Moves moves = new Moves(e.length + 2 * more.count() + e.length);
			// a kept member's seed for the next round: its fitted centre, or, where the frame's edge cuts it, where it
			// was seeded (what is left of its image hardly tells its centre from its scale, and the fit leaves it
			// anywhere along that valley: seeded again at its fitted centre, it slid further each round, 2 to 5 px
			// off the frame on a packed monolayer, until it no longer matched its profile and was removed, its light
			// left to pull its neighbours); its fit starts from where this one ended, unless cut (ProfileRefinement#fit)
			final double[] nextX = new double[e.length], nextY = new double[e.length];
			final Estimate[] nextStart = new Estimate[e.length];
			for (int k = 0; k < e.length; k++) {
				final boolean cut = e[k].has(Flag.AT_BORDER);
				nextX[k] = cut ? seeded.x()[k] : e[k].x();
				nextY[k] = cut ? seeded.y()[k] : e[k].y();
				nextStart[k] = cut ? null : e[k];
			}
			final boolean[] split = new boolean[e.length];
			for (int k = 0; k < e.length; k++)
				if (keep[k] && round == 0 && (given == null || e[k].scale() >= WIDE) && significance[k] >= SIGNIFICANCE &&
					split(pixels.bandPassed(), w, h, e, k, d, PAIR, moves)) split[k] = true;
				else if (keep[k]) moves.add(nextX[k], nextY[k], nextStart[k]);
				else if (pinned(e[k]) && significance[k] >= SIGNIFICANCE) {
					// a blob too large for one particle of its kind: two if it is elongated, else kept as it is
					if (split(pixels.bandPassed(), w, h, e, k, d, 0.125, moves)) split[k] = true;
					else moves.add(e[k].x(), e[k].y());
				}
			for (int p = 0; p < more.count(); p++) {
				final double px = more.x()[p], py = more.y()[p];
				int nearest = -1;
				double dn = Double.POSITIVE_INFINITY;
				for (int k = 0; k < e.length; k++) {
					final double dk = MemberTests.dist(e[k].x() - px, e[k].y() - py);
					if (keep[k] && dk < dn) {
						dn = dk;
						nearest = k;
					}
				}
				if (dn < d / 4 || moves.near(px, py, d / 4)) continue; // on a member, or on one just added
				if (more.height()[p] < ADD_LEVEL * unit) {
					// a faint peak (found only where faintAdds): a particle of its own where its light, at its best
					// amplitude, lowers the residuals as much as a kept member's must, and its shape is a particle's
					if ((nearest < 0 || dn >= FAINT_APART * d) && MemberTests.undrawnAny(residual, w, h, px, py, profiles,
						residualNoise) >= SIGNIFICANCE && ProfileMatch.shapeAny(residual, w, h, px, py, profiles,
							residualNoise) >= ProfileMatch.MATCH) moves.add(px, py);
					continue;
				}
				// (a peak a neighbour's distance from a member of its kind's width: a particle the seeds missed)
				final boolean apart = nearest < 0 || dn >= d || given != null && dn >= NEIGHBOUR_APART * d && !(e[nearest]
					.scale() >= WIDE);
				if (apart && (more.height()[p] >= strong || ProfileMatch.matchedAny(data, w, h, px, py, profiles,
					noise) >= ProfileMatch.MATCH)) moves.add(px, py);
				else if (!apart && !split[nearest]) {
					// a peak beside a member: the member held two particles; it splits along the peak's direction
					split[nearest] = true;
					moves.replace(nextX[nearest], nextY[nearest], e[nearest].x() + 0.5 * (px - e[nearest].x()),
						e[nearest].y() + 0.5 * (py - e[nearest].y()), e[nearest].x() - 0.5 * (px - e[nearest].x()),
						e[nearest].y() - 0.5 * (py - e[nearest].y()));
				}
			}
			int splits = 0;
			for (final boolean b : split)
				if (b) splits++;
			final int added = moves.size() - kept;
			if (kept == e.length && added == 0 && splits == 0) break;
			removed += Math.max(0, e.length - moves.size());
			seeded = Seeded.at(plane, moves.x(), moves.y(), moves.warm(), d);
			fitted = refinement.fit(plane, seeded.particles(), params, profiles, noise, seeded.warm());
		}
		return new Result(seeded.particles(), flagNear(unmodelled, fitted.outcome(), profiles, d), significance,
			removed);
	}

	/**
	 * A member removed for its own fit (its shape, or its scale pressed against a limit) although its light lowered the
	 * residuals as a particle's must: one cut by the frame's edge, whose
	 * fit what is left of its image does not determine (its scale and its centre along the edge's normal slide
	 * together, 2 to 5 px off the frame at 1.3 to 2 times its scale on a packed monolayer), so that its light no longer
	 * matches its profile. That light stays in the frame, drawn by no member, and pulls the members it reaches (their
	 * centres 0.2 to 1.9 px off on that monolayer).
	 *
	 * @param reach how far its light reached (px)
	 */
	private record Unmodelled(double x, double y, double reach) {}

	/**
	 * @return the outcome with every member that the light of an {@link Unmodelled} one reaches flagged
	 *         {@code UNMODELLED_NEIGHBOUR} (unless cut by the edge itself); one that a later round found again (a
	 *         member within a quarter diameter) reaches none
	 */
	private static Refinement.Outcome flagNear(final java.util.List<Unmodelled> unmodelled,
		final Refinement.Outcome outcome, final KindProfiles profiles, final double d)
	{
		if (unmodelled.isEmpty()) return outcome;
		final Estimate[] e = outcome.estimates().clone();
		final EmpiricalProfile[] of = profiles.byParticle(outcome.kinds() != null ? outcome.kinds() : new int[e.length]);
		for (final Unmodelled u : unmodelled) {
			boolean foundAgain = false;
			for (final Estimate m : e)
				foundAgain |= MemberTests.dist(m.x() - u.x(), m.y() - u.y()) < d / 4;
			if (foundAgain) continue;
			for (int k = 0; k < e.length; k++)
				if (!e[k].has(Flag.AT_BORDER) && MemberTests.dist(e[k].x() - u.x(), e[k].y() - u.y()) < u.reach() +
					of[k].radius() * (e[k].scale() > 0 ? e[k].scale() : 1)) e[k] = e[k].withFlags(e[k].flags() |
						Flag.UNMODELLED_NEIGHBOUR.bit());
		}
		return new Refinement.Outcome(e, outcome.discs(), outcome.kinds());
	}

	/**
	 * @return whether a member's fitted scale is pressed against the fit's upper limit: a blob of two particles
	 *         fitted as one (pressed against the lower one: no particle of its kind, removed)
	 */
	private static boolean pinned(final Estimate e) {
		return e.scale() >= PINNED_HIGH && e.amplitude() > 0;
	}

	/**
	 * The scales from which a member counts as pressed against the fit's range (0.5 to 2): near the top,
	 * {@link #pinned}; near the bottom, no particle of its kind (removed).
	 */
	static final double PINNED_HIGH = 1.9, PINNED_LOW = 0.52;

	/**
	 * A member on a blob elongated by at least this many diameters ({@link #split}: the spread along its long axis
	 * exceeds that across it as two particles this far from their middle would make it) is tried as two in the next
	 * round (once): a pair closer than the filter resolves, fitted as one particle between them, as it is where no
	 * other particle teaches the profile. The next round's fit keeps both only where each is needed (the removal
	 * tests).
	 */
	static final double PAIR = 0.25;
	/**
	 * With the profiles measured beforehand, only a member fitted at least this much wider than its kind is tried
	 * as two ({@link #PAIR}): the halos of bright-field particles make a single particle's own pixels elongated
	 * where a neighbour cuts them on one side. Where the frame teaches its own profile, a merged pair teaches it as
	 * one wide particle (fitted at scale 1), and the elongation alone decides.
	 */
	static final double WIDE = 1.2;

	/**
	 * A frame's pixels (read only: every use copies what it changes) and its band-pass at the particles' scale, made
	 * once when first asked: the seeds, the profile's own measurement and the moves of every {@link #select} of the
	 * frame share them.
	 */
	private static final class Pixels {

		final float[] data;
		final int w, h;
		final ImageDetection.Scale scale;
		private float[] bandPassed;

		Pixels(final Plane plane, final double diameter) {
			data = BandPass.pixels(plane);
			w = plane.width();
			h = plane.height();
			scale = ImageDetection.Scale.of(diameter);
		}

		float[] bandPassed() {
			if (bandPassed == null) bandPassed = BandPass.of(data, w, h, scale.sigma(), scale.halfWidth());
			return bandPassed;
		}
	}

	/**
	 * Splits a member on an elongated blob: the second moments of the band-passed frame's positive part within a
	 * diameter of it and nearer to it than to any other member; where the long axis exceeds the short one by a spread
	 * of at least {@code apart} diameters, two seeds at {@code c +- u sqrt(l1 - l2)} (two equal particles a distance
	 * {@code s} apart add {@code (s/2)^2} to the variance along their axis).
	 *
	 * @return whether it was split (its two seeds added to {@code moves})
	 */
	static boolean split(final float[] bp, final int w, final int h, final Estimate[] members, final int member,
		final double d, final double apart, final Moves moves)
	{
		final Estimate e = members[member];
		final double cx = e.x(), cy = e.y();
		// the member's own pixels: those nearer to it than to any other drawn member within two diameters
		final int[] others = new int[members.length];
		int count = 0;
		for (int j = 0; j < members.length; j++)
			if (j != member && DrawnModel.drawn(members[j]) && members[j].closerThan(e, 2 * d)) others[count++] = j;
		final int x0 = Math.max(0, (int) Math.floor(cx - d)), x1 = Math.min(w - 1, (int) Math.ceil(cx + d));
		final int y0 = Math.max(0, (int) Math.floor(cy - d)), y1 = Math.min(h - 1, (int) Math.ceil(cy + d));
		double s = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++) {
				final double v = bp[y * w + x];
				final double own = MemberTests.dist(x - cx, y - cy);
				if (!(v > 0) || own > d || nearerToAnother(members, others, count, x, y, own)) continue;
				s += v;
				sx += v * x;
				sy += v * y;
				sxx += v * x * x;
				syy += v * y * y;
				sxy += v * x * y;
			}
		if (!(s > 0)) return false;
		final double mx = sx / s, my = sy / s;
		final double vxx = sxx / s - mx * mx, vyy = syy / s - my * my, vxy = sxy / s - mx * my;
		final double tr = vxx + vyy, det = vxx * vyy - vxy * vxy, disc = Math.sqrt(Math.max(0, tr * tr / 4 - det));
		final double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
		final double half = Math.sqrt(Math.max(0, l1 - l2));
		if (half < apart * d) return false;
		double ux = vxy, uy = l1 - vxx;
		if (MemberTests.dist(ux, uy) < 1e-12) {
			ux = vxx >= vyy ? 1 : 0;
			uy = vxx >= vyy ? 0 : 1;
		}
		final double norm = MemberTests.dist(ux, uy);
		ux /= norm;
		uy /= norm;
		moves.add(mx + half * ux, my + half * uy);
		moves.add(mx - half * ux, my - half * uy);
		return true;
	}



	/** @return whether pixel (x, y), {@code own} px from the member, lies nearer to one of the {@code others} */
	private static boolean nearerToAnother(final Estimate[] members, final int[] others, final int count, final int x,
		final int y, final double own)
	{
		for (int i = 0; i < count; i++)
			if (MemberTests.dist(x - members[others[i]].x(), y - members[others[i]].y()) < own) return true;
		return false;
	}
}
