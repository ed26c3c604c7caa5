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
package io.github.contacttracker.pipeline;

import java.util.EnumMap;
import java.util.Map;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * What a run that flags many of its spots says about it: the flag most spots carry, its cause in words and what to
 * try. A result most of whose spots are flagged is not one to use as it is, and the user must hear why. The same
 * flag has different causes under different methods (a second pass that falls back for want of pixels, a fit that
 * cannot be made), so the words follow the parameters the run used, and what to try is never what it already did.
 * Each setting to change is named as the user meets it ({@link FrontEnd}): an option on the command line, a field
 * and its macro key in Fiji, a field of TrackMate's panel.
 */
public final class FlagAdvice {

	/** A run says why when more than this share of its spots carry a warning flag. */
	public static final double SHARE = 0.2;

	private FlagAdvice() {}

	/**
	 * The warning flags, causes first: where as many spots carry two flags, the one that explains the other is named
	 * (a merge is not refined, so it falls back; an unmodelled neighbour or a fit that does not settle leaves
	 * centres where the first pass put them).
	 */
	private static final List<Flag> CAUSES = List.of(Flag.MERGED, Flag.DEGENERATE, Flag.UNMODELLED_NEIGHBOUR,
		Flag.NOT_CONVERGED, Flag.FELL_BACK, Flag.AT_BORDER);

	/**
	 * @param spots the run's spots
	 * @param used the parameters the run used
	 * @param ui where the user changes the settings, which names them in the advice
	 * @return the warning for these spots, or null when at most {@link #SHARE} of them are flagged
	 */
	public static String of(final List<Localization> spots, final TrackerParameters used, final FrontEnd ui) {
		final Map<Flag, Integer> count = new EnumMap<>(Flag.class);
		int flagged = 0;
		for (final Localization s : spots) {
			if (!s.isFlagged()) continue;
			flagged++;
			for (final Flag f : Flag.decode(s.flags()))
				if (f.isWarning()) count.merge(f, 1, Integer::sum);
		}
		if (spots.isEmpty() || flagged <= SHARE * spots.size()) return null;
		Flag main = null;
		for (final Flag f : CAUSES)
			if (count.containsKey(f) && (main == null || count.get(f) > count.get(main))) main = f;
		return String.format(Locale.ROOT, "%d of %d spots (%.0f%%) are flagged, most %s (%d): %s", flagged, spots
			.size(), 100.0 * flagged / spots.size(), main.name(), count.get(main), advice(main, used, ui));
	}

	/**
	 * A run that found nothing says so, what it left out and what to try (a diameter given three times the particles'
	 * finds no peak at their scale; a threshold above them, or bright particles asked for on dark ones, no area).
	 *
	 * @param spots the run's spots
	 * @param frames the frames it tracked
	 * @param discarded the candidates it left out: areas too small or flat, or the image's seeds too faint or not
	 *        needed by the fit
	 * @param used the parameters the run used
	 * @param inverted whether the frames were inverted for dark particles
	 * @param ui where the user changes the settings, which names them in the advice
	 * @return the warning, or null where the run found a spot or had no frame
	 */
	public static String nothingFound(final int spots, final int frames, final int discarded,
		final TrackerParameters used, final boolean inverted, final FrontEnd ui)
	{
		if (spots > 0 || frames == 0) return null;
		final String what;
		if (used.detectsByImage()) what = "no peak of the image filtered at the particles' diameter was kept as a " +
			"particle" + (discarded > 0 ? " (" + discarded + " seeds left out: too faint, or not needed by the fit)"
				: "") + ": " + checkDiameter(used, ui);
		else what = "no area at or above " + ui.name(TrackingSettings.THRESHOLD) + " " + Numbers.fmt(used.threshold(),
			2) + " was kept" + (discarded > 0 ? " (" + discarded + " smaller than " + ui.name(TrackingSettings.MIN_AREA) +
				" " + used.minArea() + ", flat, or the thin fringes between particles)" : "") + ": check " + ui.name(
					TrackingSettings.THRESHOLD) + " and " + ui.name(TrackingSettings.MIN_AREA) + againstTheSize(ui);
		final String dark = inverted ? "" : "; if the particles are darker than the background, " + ui.set(
			TrackingSettings.PARTICLES, TrackingSettings.DARK);
		return "no spot found in " + frames + (frames == 1 ? " frame: " : " frames: ") + what + dark;
	}

	/** A run warns of the other contrast's blobs from this many on its first frame... */
	public static final int OTHER_CONTRAST_AT_LEAST = 5;
	/** ...and this share of the spots it found there. */
	public static final double OTHER_CONTRAST_SHARE = 0.2;

	/**
	 * @param blobs the blobs of the contrast the run did not track that stand out on its first frame as its particles
	 *        do, away from them ({@link io.github.contacttracker.core.detect.OtherContrast})
	 * @param spots the spots the run found on that frame
	 * @param inverted whether the run tracked dark particles (the frames inverted)
	 * @return the warning where there are at least {@value #OTHER_CONTRAST_AT_LEAST} such blobs and a fifth as many
	 *         as the spots, else null: a run tracks one contrast, and the other's particles get no spot
	 */
	public static String otherContrast(final int blobs, final int spots, final boolean inverted, final FrontEnd ui) {
		if (blobs < OTHER_CONTRAST_AT_LEAST || blobs < OTHER_CONTRAST_SHARE * spots) return null;
		return "frame 1 also holds " + blobs + " blobs " + (inverted ? "brighter" : "darker") + " than the background, " +
			"at least half as strong as the " + spots + " particles tracked there and away from them: a run tracks one " +
			"contrast; if they are particles too, track them in a second run: " + ui.set(TrackingSettings.PARTICLES,
				inverted ? "bright" : TrackingSettings.DARK);
	}

	/**
	 * @param used the parameters of the run that flagged the spots
	 * @param ui where the user changes the settings, which names them in the advice
	 * @return the flag's usual cause under those parameters and what to try that the run did not, in words
	 */
	static String advice(final Flag flag, final TrackerParameters used, final FrontEnd ui) {
		return switch (flag) {
			case AT_BORDER -> "particles cut by the frame's edge, whose centres move when the frame is cropped: use the " +
				"others, a larger field of view, or a selection away from the edge";
			case MERGED -> "active areas holding several particles, " + (used.detectsByImage() ? "which detection by " +
				"the image did not split: " + checkDiameter(used, ui) : "as the threshold joins touching particles: " +
					byImage(used, ui) + "; or raise " + ui.name(TrackingSettings.THRESHOLD));
			case FELL_BACK -> secondPass(used) ? fellBackFromSecondPass(used, ui) : fellBackFromFit(ui);
			case NOT_CONVERGED -> secondPass(used) ? "second passes that stopped at their limit before the centres " +
				"settled, as neighbours' discs take pixels from each other in turn: try a smaller " + ui.name(
					TrackingSettings.R_OUT) + ", or " + modelsNeighbours(ui) : notSettledFit(used, ui);
			case UNMODELLED_NEIGHBOUR -> "a neighbour within reach that the fit could not model, usually a merge of " +
				"particles" + (used.detectsByImage() ? " that detection by the image did not split: " + checkDiameter(
					used, ui) : ": " + byImage(used, ui));
			case DEGENERATE -> "areas without gradient lines that meet, such as flat tops or noise: raise " + ui.name(
				TrackingSettings.MIN_AREA) + " above " + used.minArea() + (used.diameter() > 0 ? "" : ", or give " +
					ui.name(TrackingSettings.DIAMETER));
			case SECOND_PASS -> "";
		};
	}

	/** @return the advice for centres the paper's second pass cannot place: a method that needs no exclusion disc */
	private static String modelsNeighbours(final FrontEnd ui) {
		return ui.set(TrackingSettings.METHOD, Method.FIT.key()) + " or " + Method.DEBLEND.key() + ", which model " +
			"each neighbour's light instead of cutting it out";
	}

	/** @return the end of a sentence that checks a setting against the particles' size, and says what measures it */
	private static String againstTheSize(final FrontEnd ui) {
		return " against the particles' size, which " + ui.measuresSize() + " measures";
	}

	/** @return whether the run's centres come from the paper's second pass (once or iterated) */
	private static boolean secondPass(final TrackerParameters used) {
		return used.method() == Method.PAPER || used.method() == Method.ITERATIVE;
	}

	/**
	 * The paper's second pass (and its iteration) falls back when the neighbours' discs leave too few pixels: the
	 * centre of a touching neighbour lies one diameter away, so once r_out reaches the diameter its disc covers the
	 * particle's centre. Repeating the pass does not help; a method that models the neighbours' light does.
	 */
	private static String fellBackFromSecondPass(final TrackerParameters used, final FrontEnd ui) {
		final double r = used.exclusionRadius(), d = used.diameter();
		final String cover = d > 0 && r >= d ? "; r_out is at least the diameter, " + Numbers.fmt(d, 2) + " px, so a " +
			"touching neighbour's disc covers the particle's centre" : "";
		return "centres kept from the first pass: the neighbours' discs, of radius r_out = " + Numbers.fmt(r, 2) +
			" px, left fewer than " + used.minSecondArea() + " pixels of the active area, the least that " + ui.name(
				TrackingSettings.MIN_SECOND_AREA) + " allows, or lines that do not meet" + cover + ". In a field of " +
			"touching particles " + modelsNeighbours(ui) + "; or check " + ui.name(TrackingSettings.R_OUT) +
			againstTheSize(ui);
	}

	/** A profile method whose fit could not be made: the second pass's centres need no fit. */
	private static String fellBackFromFit(final FrontEnd ui) {
		return "centres kept from a first pass because the refinement could not be made: too few pixels were left, or " +
			"the fit had too little light; on a background clipped at 0, as confocal images have, the fit leaves out " +
			"every pixel near 0 and cannot place the background. Check " + ui.name(TrackingSettings.R_OUT) +
			againstTheSize(ui) + ", or " + ui.set(TrackingSettings.METHOD, Method.ITERATIVE.key()) + ", whose " +
			"centres need no fit";
	}

	/**
	 * A profile method's fit or rounds that did not settle: under detection by the image, a diameter that is not the
	 * particles' (the image filtered at a bead's texture or the pieces of its rim: a public tweezer stack of one bead
	 * 62 px across, dark inside a bright rim, tracked at the 18.6 px of its blobs, gave ten spots a frame, every one
	 * flagged); one profile for unlike particles; or too dense a field.
	 */
	private static String notSettledFit(final TrackerParameters used, final FrontEnd ui) {
		final String denser = "the field may be denser than the fit can hold, so try a smaller " + ui.name(
			TrackingSettings.R_OUT);
		final String scale = used.detectsByImage() ? checkDiameter(used, ui) + ", at which the image is filtered: for " +
			"particles dark inside a bright rim, give their outer diameter and " + ui.value(TrackingSettings.PARTICLES,
				TrackingSettings.DARK) + "; or " : "";
		return "fits or profile rounds that did not settle: " + scale + switch (used.kinds()) {
			case 0 -> "the particles' profiles may differ, so give their number of kinds with " + ui.name(
				TrackingSettings.KINDS) + "; or " + denser;
			case 1 -> "the particles may be of several kinds, each with its own profile, so " + ui.set(
				TrackingSettings.KINDS, "0") + " to find them; or " + denser;
			default -> denser;
		};
	}

	/** @return the advice to check a given diameter, which sets the scale of the detection by the image */
	private static String checkDiameter(final TrackerParameters used, final FrontEnd ui) {
		return "check " + ui.name(TrackingSettings.DIAMETER) + ", now " + Numbers.fmt(used.diameter(), 2) + " px," +
			againstTheSize(ui);
	}

	/** @return what to try for particles the threshold merges: detection by the image, and what it needs */
	private static String byImage(final TrackerParameters used, final FrontEnd ui) {
		final boolean methodFinds = used.method().needsProfile() || used.method() == Method.ITERATIVE;
		final String image = TrackingSettings.IMAGE;
		return "to find the particles by their image instead, " + (methodFinds ? ui.set(TrackingSettings.DETECTION,
			image) : ui.set(TrackingSettings.METHOD, Method.FIT.key(), TrackingSettings.DETECTION, image)) + (used
				.diameter() > 0 ? "" : " and give " + ui.name(TrackingSettings.DIAMETER));
	}
}
