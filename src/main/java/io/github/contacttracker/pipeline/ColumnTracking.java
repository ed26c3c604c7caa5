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

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccess;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Tracks frames handed over as pixel arrays ({@link PixelPlanes}) with settings given by name as text, and
 * returns the spots as columns of primitive numbers: the shape a data-frame library (pandas, through JPype) takes
 * without a loop per spot. Settings are read and checked by the one descriptor ({@link TrackingSettings}), and
 * those not given are measured on the first frame as {@code track} measures them ({@link MeasuredSettings}), so
 * the same frames give the same spots as {@code track}, to the last digit.
 */
public final class ColumnTracking {

	private ColumnTracking() {}

	/**
	 * The spots of a run as columns.
	 *
	 * @param keys the column keys, {@link SpotColumn} order ({@code POSITION_X}, ...)
	 * @param columns one array per key, a value per spot, in pixels (IDs from 0, frames from 0)
	 * @param mass each spot's brightness above the threshold: the sum of {@code v - threshold} over the pixels
	 *        within {@code RADIUS} of its centre whose value {@code v} (of the frame as tracked: inverted for dark
	 *        particles) is above the threshold
	 * @param settings every setting's value as used, by name, in the descriptor's order
	 * @param measured the names of the settings measured on the first frame rather than given
	 * @param notice what {@code track} says about the measured settings (or the diameter it could not measure), one
	 *        line; empty when nothing was measured
	 * @param summary the run's summary line (spots, frames, flagged, time)
	 * @param warnings what the user must know about how the result was obtained, one line each
	 */
	public record Table(String[] keys, double[][] columns, double[] mass, Map<String, String> settings,
		List<String> measured, String notice, String summary, List<String> warnings)
	{}

	/**
	 * @param frames the frames
	 * @param name the movie's name, for messages
	 * @param given settings by their names ({@code r_out}) as text; the others measured or at their defaults
	 * @param threads worker threads (below 1: one per processor)
	 * @return the spots
	 * @throws InvalidInputException for an unknown setting, a bad value, or one that cannot be measured
	 */
	public static Table track(final PixelPlanes frames, final String name, final Map<String, String> given,
		final int threads)
	{
		SettingValues settings = SettingValues.defaults();
		final Set<Setting<?>> named = new HashSet<>();
		for (final Map.Entry<String, String> e : given.entrySet()) {
			final Setting<?> s = TrackingSettings.named(e.getKey());
			if (s == null) throw new InvalidInputException("unknown setting '" + e.getKey() + "': the settings are " +
				TrackingSettings.ALL.stream().map(Setting::name).collect(Collectors.joining(", ")));
			if (s == TrackingSettings.CHANNEL && !"1".equals(e.getValue().trim())) throw new InvalidInputException(
				"channel must be 1: the frames handed over have one channel (pass the channel's plane)");
			settings = settings.withText(s, e.getValue());
			named.add(s);
		}
		final MeasuredSettings.Result measured = MeasuredSettings.of(name, frames::frame, frames.frameCount(), frames
			.integerData(), settings, named, FrontEnd.COMMAND_LINE);
		final TrackingPipeline pipeline = new TrackingPipeline(measured.settings());
		final FrameSource source = frames.source(name);
		final TrackingResult result;
		try {
			result = pipeline.run(source, Outputs.NONE, threads, false, null, () -> false);
		}
		catch (final IOException e) {
			throw new AssertionError("no file is written", e);
		}
		return new Table(keys(), columns(result.spots()), mass(result.spots(), pipeline.frames(source), measured
			.settings().get(TrackingSettings.THRESHOLD)), byName(measured.settings()), measured(settings,
			measured.settings(), named), measured.notice(), result
			.summary(name), result.warnings());
	}

	/** @return the column keys, in {@link SpotColumn} order */
	public static String[] keys() {
		final SpotColumn[] cols = SpotColumn.values();
		final String[] keys = new String[cols.length];
		for (int c = 0; c < cols.length; c++)
			keys[c] = cols[c].key();
		return keys;
	}

	private static double[][] columns(final List<Localization> spots) {
		final SpotColumn[] cols = SpotColumn.values();
		final double[][] out = new double[cols.length][spots.size()];
		for (int i = 0; i < spots.size(); i++) {
			final Localization s = spots.get(i);
			for (int c = 0; c < cols.length; c++)
				out[c][i] = cols[c].value(s, i, Calibration.PIXELS);
		}
		return out;
	}

	/** @return each spot's brightness above {@code threshold} within {@code RADIUS} of its centre */
	private static double[] mass(final List<Localization> spots, final FrameSource seen, final double threshold) {
		final double[] mass = new double[spots.size()];
		int frame = -1;
		RandomAccess<? extends RealType<?>> pixels = null;
		long w = 0, h = 0;
		for (int i = 0; i < spots.size(); i++) {
			final Localization s = spots.get(i);
			if (s.frame() != frame) {
				frame = s.frame();
				final RandomAccessibleInterval<? extends RealType<?>> f = seen.frame(frame);
				pixels = f.randomAccess();
				w = f.dimension(0);
				h = f.dimension(1);
			}
			final double r = s.radius(), r2 = r * r;
			final long x0 = Math.max(0, (long) Math.ceil(s.x() - r)), x1 = Math.min(w - 1, (long) Math.floor(s.x() + r));
			final long y0 = Math.max(0, (long) Math.ceil(s.y() - r)), y1 = Math.min(h - 1, (long) Math.floor(s.y() + r));
			double sum = 0;
			for (long y = y0; y <= y1; y++)
				for (long x = x0; x <= x1; x++) {
					final double dx = x - s.x(), dy = y - s.y();
					if (dx * dx + dy * dy > r2) continue;
					pixels.setPosition(x, 0);
					pixels.setPosition(y, 1);
					final double v = pixels.get().getRealDouble();
					if (v > threshold) sum += v - threshold;
				}
			mass[i] = sum;
		}
		return mass;
	}

	/** @return the names of the settings not given whose value the helper measured (or confirmed) */
	private static List<String> measured(final SettingValues before, final SettingValues after,
		final Set<Setting<?>> given)
	{
		final List<String> names = new ArrayList<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			if (!given.contains(s) && (s.isImageSpecific() || !before.get(s).equals(after.get(s)))) names.add(s.name());
		return names;
	}

	/** @return every setting's value as text, by name, in the descriptor's order */
	static Map<String, String> byName(final SettingValues values) {
		final Map<String, String> m = new LinkedHashMap<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			m.put(s.name(), String.valueOf(values.get(s)));
		return m;
	}
}
