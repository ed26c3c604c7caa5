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
package io.github.contacttracker.settings;

import java.util.Arrays;
import java.util.List;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.settings.Setting.Unit;

/**
 * The settings of a tracking run, each described once ({@link Setting}); every front end derives its own form
 * from this list: the command line's options and help, the Fiji command's dialog, the TrackMate settings map, its
 * XML and its panel. {@link SettingValues} holds a set of values. The limits of the core's parameters come from
 * {@link TrackerParameters}, which checks them again.
 */
public final class TrackingSettings {

	private TrackingSettings() {}

	/** Help text of {@link #THRESHOLD}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_THRESHOLD = "Grey level: pixels at or above it form the active areas, one " +
		"per particle. It must be above the brightest point between two touching particles (the profile helper " +
		"suggests it).";

	/** Help text of {@link #R_OUT}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_R_OUT = "How far a particle's image reaches: where its profile has returned " +
		"to background, plus 2 pixels.";

	/** Help text of {@link #MIN_AREA}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_MIN_AREA = "Active areas smaller than this are noise and dropped.";

	/** Help text of {@link #MIN_SECOND_AREA}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_MIN_SECOND_AREA = "paper and iterative: below this many pixels left outside " +
		"the neighbours' discs, a spot keeps its first-pass centre and is flagged FELL_BACK.";

	/** Help text of {@link #CONNECTIVITY}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_CONNECTIVITY = "Pixel neighbourhood of the active areas: 8 or 4.";

	/** Help text of {@link #METHOD}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_METHOD = "How centres are computed: fit (joint fit with the measured " +
		"profile, unbiased at contact), deblend, iterative, paper (the paper's two passes), first (one pass, biased " +
		"near contact).";

	/** Help text of {@link #DIAMETER}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_DIAMETER = "The particles' diameter in pixels (the profile helper measures " +
		"it): RADIUS is half of it. 0 = not given: RADIUS is then the active area's equivalent radius " +
		"(ACTIVE_RADIUS), smaller than the particle.";

	/** Help text of {@link #KINDS}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_KINDS = "Kinds of particle the profile methods (fit, deblend) tell apart by " +
		"size and brightness, each with its own measured profile: 0 finds them automatically, 1 treats all " +
		"particles as alike. The KIND column says each spot's kind.";

	/** Help text of {@link #CHANNEL}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_CHANNEL = "The channel to track, 1-based; single-channel images have only " +
		"channel 1, colour (RGB) ones three: 1 red, 2 green, 3 blue.";

	/** Help text of {@link #PARTICLES}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_PARTICLES = "bright: particles brighter than the background at their centre; " +
		"dark: darker, and the image is inverted first (255 - v for 8 bits, as Edit > Invert; 65535 - v for 16 bits, " +
		"-v for 32 bits): the threshold and every grey level are then the inverted image's. Measured with the " +
		"threshold (dark where the frame looks so) when neither is given.";

	/** Help text of {@link #DETECTION}, a constant so that annotations (SciJava's {@code @Parameter}) can use it. */
	public static final String HELP_DETECTION = "How the profile methods (fit, deblend) find the particles: threshold, " +
		"each connected area at or above the threshold is one particle; image, the peaks of the image filtered at the " +
		"particles' diameter, split, added and removed by the fit, which finds touching particles that every " +
		"threshold merges, dim particles and particles on uneven or clipped backgrounds (needs the diameter); auto, " +
		"the image where the threshold joins touching particles on the movie's sample frames, else the threshold " +
		"(the run says which).";

	/** The value of {@link #DETECTION} that finds particles by the threshold's components. */
	public static final String BY_THRESHOLD = "threshold";

	/** The value of {@link #DETECTION} that chooses per movie between the threshold and the image. */
	public static final String AUTO = "auto";

	/** The value of {@link #DETECTION} that finds particles by their image. */
	public static final String IMAGE = "image";

	/** The value of {@link #PARTICLES} for dark particles. */
	public static final String DARK = "dark";

	/** The first channel: channels count from 1. (The core's parameters state their own limits.) */
	public static final int CHANNEL_AT_LEAST = 1;

	/**
	 * Pixels at or above it form the active areas. Its TrackMate key is {@code GREY_THRESHOLD}, not TrackMate's
	 * {@code THRESHOLD}: the LoG and DoG detectors use that key for a quality cut-off, and TrackMate's wizard carries
	 * values from one detector's settings to another's by key.
	 */
	public static final Setting<Double> THRESHOLD = Setting.decimal("threshold", "Threshold",
		HELP_THRESHOLD, 100, Double.NEGATIVE_INFINITY,
		true, TrackerParameters.THRESHOLD_ALLOWED, Unit.GREY_LEVEL).imageSpecific().trackMateKey("GREY_THRESHOLD");

	/** How far a particle's image reaches. */
	public static final Setting<Double> R_OUT = Setting.decimal("r_out", "r_out",
		HELP_R_OUT, 20, TrackerParameters.R_OUT_ABOVE,
		false, TrackerParameters.R_OUT_ALLOWED, Unit.PIXELS).imageSpecific();

	/** Smaller active areas are noise. */
	public static final Setting<Integer> MIN_AREA = Setting.integer("min_area", "Min area",
		HELP_MIN_AREA, TrackerParameters.DEFAULT_MIN_AREA, TrackerParameters.MIN_AREA_AT_LEAST,
		TrackerParameters.MIN_AREA_ALLOWED, Unit.PIXEL_COUNT, null);

	/** Below it the paper's second pass falls back to the first-pass centre. */
	public static final Setting<Integer> MIN_SECOND_AREA = Setting.integer("min_second_area", "Min second area",
		HELP_MIN_SECOND_AREA, TrackerParameters.DEFAULT_MIN_SECOND_AREA, TrackerParameters.MIN_SECOND_AREA_AT_LEAST,
		TrackerParameters.MIN_SECOND_AREA_ALLOWED, Unit.PIXEL_COUNT, null);

	/** Pixel neighbourhood of the labelling. */
	public static final Setting<Integer> CONNECTIVITY = Setting.choice("connectivity", "Connectivity",
		HELP_CONNECTIVITY, Integer.class, 8, List.of(8, 4));

	/** How centres are computed. */
	public static final Setting<String> METHOD = Setting.choice("method", "Method",
		HELP_METHOD, String.class,
		Method.DEFAULT.key(), Arrays.stream(Method.values()).map(Method::key).toList());

	/** The particles' diameter, for RADIUS. */
	public static final Setting<Double> DIAMETER = Setting.decimal("diameter", "Particle diameter",
		HELP_DIAMETER, 0, TrackerParameters.DIAMETER_AT_LEAST, true,
		"a number of pixels >= 0 (0 = not given)", Unit.PIXELS);

	/**
	 * The fewest kinds of particle: 0, found automatically. TrackerParameters states the largest number
	 * ({@code KINDS_AT_MOST}) and the words as constants but checks this one without a constant; SettingsMatchCoreTest
	 * pins the two together.
	 */
	public static final int KINDS_AT_LEAST = 0;

	/**
	 * Kinds of particle the profile methods tell apart. Added after settings maps without it were written: a
	 * TrackMate map that lacks {@code KINDS} means 0, found automatically.
	 */
	public static final Setting<Integer> KINDS = Setting.integer("kinds", "Kinds of particle", HELP_KINDS, 0,
		KINDS_AT_LEAST, TrackerParameters.KINDS_AT_MOST, TrackerParameters.KINDS_ALLOWED, Unit.NONE).optionalInMaps();

	/** The channel tracked. */
	public static final Setting<Integer> CHANNEL = Setting.integer("channel", "Channel",
		HELP_CHANNEL, 1, CHANNEL_AT_LEAST, "at least 1 (1-based)",
		Unit.NONE, "TARGET_CHANNEL");

	/**
	 * Whether the particles are brighter or darker than the background (dark: the frames are inverted first). Added
	 * after settings maps without it were written: a TrackMate map that lacks {@code PARTICLES} means bright.
	 */
	public static final Setting<String> PARTICLES = Setting.choice("particles", "Particles", HELP_PARTICLES,
		String.class, "bright", List.of("bright", DARK)).optionalInMaps();

	/**
	 * How the profile methods find the particles ({@link io.github.contacttracker.core.Detection}). Added after
	 * settings maps without it were written: a TrackMate map that lacks {@code DETECTION} means the threshold, which
	 * such maps were tracked with (the default has since become auto).
	 */
	public static final Setting<String> DETECTION = Setting.choice("detection", "Detection", HELP_DETECTION,
		String.class, io.github.contacttracker.core.Detection.DEFAULT.key(), List.of(AUTO, BY_THRESHOLD,
		IMAGE)).optionalInMaps(BY_THRESHOLD);

	/** Every setting, in the order front ends list them. */
	public static final List<Setting<?>> ALL = List.of(THRESHOLD, R_OUT, MIN_AREA, MIN_SECOND_AREA, CONNECTIVITY,
		METHOD, DIAMETER, KINDS, PARTICLES, DETECTION, CHANNEL);

	/**
	 * @return the setting named {@code name} ({@code r_out}), or {@code null}
	 */
	public static Setting<?> named(final String name) {
		for (final Setting<?> s : ALL)
			if (s.name().equals(name)) return s;
		return null;
	}
}
