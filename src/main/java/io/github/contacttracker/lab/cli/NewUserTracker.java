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

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.IntFunction;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.detect.DetectionChoice;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.lab.eval.DetectionStudy;
import io.github.contacttracker.lab.sim.DetectionScene;
import io.github.contacttracker.pipeline.FrameSource;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.pipeline.Outputs;
import io.github.contacttracker.pipeline.TrackingPipeline;
import io.github.contacttracker.pipeline.TrackingResult;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Tracks a scene's movie as {@code track MOVIE --csv out.csv} does with no value given: the profile helper measures
 * the threshold, r_out and diameter on the movie ({@link MeasuredSettings}, falling back to detection by the image
 * where it cannot), then the pipeline tracks every frame with the default method and detection, the data range
 * checked. A movie the command would refuse gives no spot, and the refusal is kept as the notice.
 */
final class NewUserTracker implements DetectionStudy.Tracker {

	private final int threads;
	private final boolean trueDiameter;
	/** A value given as a user types it (null: none), and its setting. */
	private final Setting<Double> setting;
	private final double value;

	/** @param threads worker threads (below 1: all) */
	NewUserTracker(final int threads) {
		this(threads, false);
	}

	/**
	 * @param threads worker threads (below 1: all)
	 * @param trueDiameter whether to give the scene's true diameter ({@code --diameter}), as a control that tells
	 *        the helper's diameter from the detection's own failures; the rest is measured as without it
	 */
	NewUserTracker(final int threads, final boolean trueDiameter) {
		this(threads, trueDiameter, null, Double.NaN);
	}

	private NewUserTracker(final int threads, final boolean trueDiameter, final Setting<Double> setting,
		final double value)
	{
		this.threads = threads;
		this.trueDiameter = trueDiameter;
		this.setting = setting;
		this.value = value;
	}

	/**
	 * @return this tracker with {@code setting} given as {@code value} (as {@code --r-out 7} on the command line), the
	 *         rest measured as without it: a control that tells one measured value's part in a scene's failures
	 */
	NewUserTracker given(final Setting<Double> setting, final double value) {
		return new NewUserTracker(threads, trueDiameter, setting, value);
	}

	@Override
	public DetectionStudy.Tracked track(final DetectionScene scene) {
		final long start = System.nanoTime();
		final String name = scene.key() + ".tif";
		final int n = scene.frames().size();
		final IntFunction<RandomAccessibleInterval<? extends RealType<?>>> frame = t -> cast(scene.frames().get(t));
		try {
			SettingValues given = trueDiameter ? SettingValues.defaults().with(TrackingSettings.DIAMETER, scene.scene()
				.type().diameterPx()) : SettingValues.defaults();
			final Set<Setting<?>> typed = new HashSet<>();
			if (trueDiameter) typed.add(TrackingSettings.DIAMETER);
			if (setting != null) {
				given = given.with(setting, value);
				typed.add(setting);
			}
			final MeasuredSettings.Result measured = MeasuredSettings.of(name, frame, n, true, given, typed,
				FrontEnd.COMMAND_LINE);
			final SettingValues used = measured.settings();
			final TrackingResult result = new TrackingPipeline(used).run(FrameSource.of(n, frame, Calibration.PIXELS,
				name, t -> ImagePlusFrames.range(frame.apply(t), t)), Outputs.NONE, threads, false, null, () -> false);
			final List<List<Localization>> spots = new ArrayList<>();
			for (final FrameResult r : result.frames())
				spots.add(r.spots());
			final DetectionChoice choice = result.frames().isEmpty() ? null : result.frames().get(0).detection();
			final String detection = choice != null ? choice.detection().key() + " (auto)" : used.get(
				TrackingSettings.DETECTION) + (measured.notice().contains("--detection") ? " (helper's fallback)" : "");
			return new DetectionStudy.Tracked(spots, detection, used.diameter() > 0 ? used.diameter() : Double.NaN,
				(System.nanoTime() - start) * 1e-9, measured.notice());
		}
		catch (final InvalidInputException e) {
			final List<List<Localization>> none = new ArrayList<>();
			for (int t = 0; t < n; t++)
				none.add(List.of());
			return new DetectionStudy.Tracked(none, "refused", Double.NaN, (System.nanoTime() - start) * 1e-9,
				"refused: " + InvalidInputException.oneLine(e.getMessage()));
		}
		catch (final IOException e) {
			throw new UncheckedIOException("no file is written, yet " + e.getMessage(), e);
		}
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static RandomAccessibleInterval<? extends RealType<?>> cast(final RandomAccessibleInterval frame) {
		return frame;
	}
}
