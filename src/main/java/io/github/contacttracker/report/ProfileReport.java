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
package io.github.contacttracker.report;

import static io.github.contacttracker.advisor.HelperFormat.fmt;
import static io.github.contacttracker.advisor.HelperFormat.fmt2;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.advisor.Finding;
import io.github.contacttracker.advisor.Margins;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.kind.Kinds;

/**
 * The profile helper's result ({@link ProfileAnalysis.Result}) in words: the lines that explain its numbers and a
 * sentence for each {@link Finding}. One text for the command line's {@code profile}, Fiji's <i>Contact Tracker
 * Profile</i> and the "Measure from the image" buttons of Fiji's dialog and TrackMate's panel
 * ({@link ShownFrameProfile}).
 */
public final class ProfileReport {

	/** What starts the line of a warning. */
	public static final String WARNING = "  warning: ";

	private ProfileReport() {}

	/**
	 * @param integerData whether the image holds whole grey levels (the threshold is rounded up for them)
	 * @return the lines that explain the numbers, the kinds of particle ({@link #kinds}), then a {@link #WARNING}
	 *         line for each finding (no trailing newlines)
	 */
	public static List<String> lines(final ProfileAnalysis.Result r, final boolean integerData) {
		final List<String> lines = new ArrayList<>();
		lines.add(String.format(Locale.ROOT, "  background %.2f, noise sigma %.2f (robust, around the particles), " +
			"peak %.2f (grey levels)", r.background(), r.noise(), r.peak()));
		lines.add(String.format(Locale.ROOT, "  diameter %.2f px%s; profile of %d particle%s", r.diameter(), r
			.diameterEstimated() ? " (estimated)" : "", r.particles(), r.particles() == 1 ? "" : "s"));
		lines.add(String.format(Locale.ROOT,
			"  profile within the noise of the background beyond %.2f px; + %.0f px = %.2f -> r_out = %.0f px", r
				.reach(), Margins.R_OUT_MARGIN_PX, r.rOut(), r.suggestedROut()));
		lines.add(String.format(Locale.ROOT, "  brightest point between two or three particles at contact " +
			"(D = %.2f px): %.2f; + %.0f sigma = %.2f%s -> threshold = %s", r.diameter(), r.bridge(),
			Margins.THRESHOLD_MARGIN_SIGMAS, r.atContact(), r.threshold() > r.atContact() ? String.format(
				Locale.ROOT, ", raised to %.2f (see the warnings)", r.threshold()) : "", fmt(r.suggestedThreshold(
					integerData))));
		final double threshold = r.suggestedThreshold(integerData);
		lines.add(String.format(Locale.ROOT, "  active area radius at this threshold: %.2f px (D/2 = %.2f px)%s", r
			.activeRadius(), r.diameter() / 2, r.smallParticles(threshold) ? String.format(Locale.ROOT,
				"; area %.1f px, below twice the default min_area -> min_area = %d (half the area)", Math.PI * r
					.activeRadius() * r.activeRadius(), r.suggestedMinArea(threshold)) : ""));
		final double kept = r.secondPassArea();
		if (r.activeRadius() > 0 && kept < TrackerParameters.DEFAULT_MIN_SECOND_AREA) lines.add(String.format(Locale.ROOT, "  at contact " +
			"(D = %.2f px), r_out %.0f px leaves %.0f of the active area's %.0f px outside the neighbour's disc, fewer " +
			"than min_second_area (%d): --method paper keeps the first pass there (FELL_BACK); the default fit models " +
			"the neighbours' light and needs none", r.diameter(), r.suggestedROut(), kept, Math.PI * r.activeRadius() * r
				.activeRadius(), TrackerParameters.DEFAULT_MIN_SECOND_AREA));
		for (final String k : kinds(r.kinds()))
			lines.add("  " + k);
		for (final String w : warnings(r))
			lines.add(WARNING + w);
		return lines;
	}

	/**
	 * @return the kinds of particle, a line each, numbered as in the {@code KIND} column (e.g. {@code kind 2 of 2: 37
	 *         particles, core radius 8.1 px, active radius 9.4 px, central contrast 120, dark ring 35 deep at 12 px};
	 *         {@code 185 particles in 5 frames} when found on several); one line when there is one kind or none; then
	 *         how many particles are of no kind, if any (no indent, no full stop)
	 */
	public static List<String> kinds(final ProfileAnalysis.ParticleKinds found) {
		final List<String> lines = new ArrayList<>();
		final List<Kinds.Kind> kinds = found.kinds();
		final String frames = found.frames() > 1 ? " in " + found.frames() + " frames" : "";
		if (kinds.isEmpty()) lines.add("kinds: none (no particle with a bright core at this threshold)");
		for (final Kinds.Kind k : kinds)
			lines.add(kind(k, kinds.size(), frames));
		if (found.unclassified() > 0 && !kinds.isEmpty()) lines.add(particles(found.unclassified()) + frames +
			" of no kind (KIND 0: no bright core, e.g. cut by the border)");
		return lines;
	}

	/** @return one kind's line */
	private static String kind(final Kinds.Kind k, final int of, final String frames) {
		final StringBuilder b = new StringBuilder("kind " + k.kind() + " of " + of);
		if (of == 1) b.append(" (all particles alike)");
		b.append(": ").append(particles(k.count())).append(frames);
		b.append(", core radius ").append(Numbers.fmt(k.coreRadius(), 1)).append(" px");
		if (!Double.isNaN(k.activeRadius())) b.append(", active radius ").append(Numbers.fmt(k.activeRadius(), 1))
			.append(" px");
		b.append(", central contrast ").append(Numbers.fmt(k.peak(), 0));
		if (k.ringDepth() > 0 && !Double.isNaN(k.ringRadius())) b.append(", dark ring ").append(Numbers.fmt(k
			.ringDepth(), 0)).append(" deep at ").append(Numbers.fmt(k.ringRadius(), 1)).append(" px");
		else b.append(", no dark ring");
		return b.toString();
	}

	private static String particles(final int n) {
		return n + " particle" + (n == 1 ? "" : "s");
	}

	/** @return a sentence for each of the result's findings, in their order */
	public static List<String> warnings(final ProfileAnalysis.Result r) {
		final List<String> sentences = new ArrayList<>();
		for (final Finding f : r.findings())
			sentences.add(sentence(f));
		return sentences;
	}

	/**
	 * The values at a particle that is not isolated are the frame's: the sentence names the frame's r_out, the one
	 * given, says that the particle's own profile is disturbed within that reach, and names the particle's own r_out
	 * only as the value not used, so that a user reads which r_out to take.
	 */
	private static String frameValuesAtPoint(final Finding.FrameValuesAtPoint f) {
		final String near = f.edge() ? "the particle lies " + fmt2(f.neighbour()) + " px from the image's edge " +
			"(beyond it neighbours go unseen)" : "the particle's nearest neighbour is " + fmt2(f.neighbour()) + " px away";
		final String disturbed = f.edge() ? "its own profile is cut by the edge" : "its own profile holds its " +
			"neighbours' light";
		final String given = ", so the profile and values given are the frame's, from its " + f.others() + " most " +
			"isolated particle" + (f.others() == 1 ? "" : "s") + ": use them";
		if (Double.isNaN(f.ownROut())) return near + " and its own profile could not be measured (the frame's r_out " +
			"is " + fmt2(f.frameROut()) + " px)" + given;
		if (f.neighbour() < 2 * f.frameROut()) return near + ", less than twice the frame's r_out (2 x " + fmt2(f
			.frameROut()) + " px): within that reach " + disturbed + " (its own r_out, " + fmt2(f.ownROut()) + " px, is " +
			"not used)" + given;
		return near + ", less than twice the r_out its own profile gives (2 x " + fmt2(f.ownROut()) + " px), a reach " +
			"the frame's isolated particles do not show (the frame's r_out is " + fmt2(f.frameROut()) + " px): " +
			disturbed + given;
	}

	/** @return the finding in words: one sentence, no full stop */
	public static String sentence(final Finding finding) {
		if (finding instanceof Finding.DiameterFromImage f)
			return diameterEstimated(f.diameter(), "twice the radius where the particles' image returns to the " +
				"background (" + fmt2(f.imageRadius()) + " px)");
		if (finding instanceof Finding.DiameterFromHalfHeight f)
			return diameterEstimated(f.diameter(), "twice the radius where the particles' profile falls to half its " +
				"height, the rim of a blurred sphere (their image returns to the background " + fmt2(f.imageRadius()) +
				" px out)");
		if (finding instanceof Finding.DiameterFromSpacing f)
			return diameterEstimated(f.diameter(), "the " + fmt(f.percentile()) + "-th percentile of the " + f.spots() +
				" spots' nearest-neighbour distances, closer than the particles' image reaches (" + fmt2(f
					.imageAcross()) + " px across)");
		if (finding instanceof Finding.SpotsTooClose f)
			return f.spots() + " spots lie closer to another than two such particles can and still be told apart (" +
				fmt2(f.closest()) + " px): left out of the spacing; bright marks in the frame (a timestamp, a scale " +
				"bar)? In Fiji, select the region to track";
		if (finding instanceof Finding.MergedAtPoint)
			return "the particle's active area looks merged with a neighbour's: pick an isolated particle";
		if (finding instanceof Finding.FrameValuesAtPoint f)
			return frameValuesAtPoint(f);
		if (finding instanceof Finding.NotRefined)
			return "could not refine the centre; the profile is taken around the point given";
		if (finding instanceof Finding.NotIsolated f)
			return "no particle is isolated: the most isolated has a neighbour at " + fmt2(f.neighbour()) + " px (" +
				fmt2(f.neighbour() / f.diameter()) + " diameters); the profile's outer part may show neighbours";
		if (finding instanceof Finding.NeighboursMaskedCloser f)
			return "the field is dense: pixels within " + fmt2(f.wanted()) + " px of a neighbour left no background " +
				"around the particles, so neighbours were masked within " + fmt2(f.mask()) + " px only; their light may " +
				"show in the profile's outer part";
		if (finding instanceof Finding.NotBackToBackground f)
			return "the profile has not returned to the background by " + fmt2(f.radius()) + " px: increase " +
				"max_radius (r_out is a lower bound)";
		if (finding instanceof Finding.BackgroundTexture f)
			return "at " + fmt2(f.atContact()) + ", " + f.spots() + " bright spots of the background (halos, rings; up " +
				"to " + fmt2(f.textureTop()) + " above it) would be taken for particles, whose cores rise at least " +
				fmt2(f.coreBottom()) + " above it: the threshold is raised to the middle of that gap";
		if (finding instanceof Finding.RaisedUntilRound f)
			return "at " + fmt2(f.from()) + ", " + f.notRound() + " of the frame's " + f.areas() + " active areas have " +
				"the shape of no single particle (bright fringes between touching particles, or particles merged): the " +
				"threshold is raised until they are round";
		if (finding instanceof Finding.NotRound f)
			return f.notRound() + " of the frame's " + f.areas() + " active areas have the shape of no single particle " +
				"up to " + fmt2(f.ceiling()) + " (half the cores' height): they will be flagged MERGED, or dropped when " +
				"smaller than two particles' active areas (fringes, marks)";
		if (finding instanceof Finding.ThresholdAboveCentre)
			return "the suggested threshold is above the particle's centre: at contact no threshold separates two such " +
				"particles (the profile is too long-ranged for the method)";
		throw new IllegalArgumentException("no words for " + finding);
	}

	private static String diameterEstimated(final double diameter, final String how) {
		return "the diameter (" + fmt2(diameter) + " px) is estimated as " + how + ": give it if you know it";
	}
}
