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

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.report.ProfileReport;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * The profile helper's report on frames handed over as pixel arrays, as a map of plain values (numbers, arrays of
 * numbers, text): what {@code contact-tracker profile} prints, in a form a scripting language turns into its own
 * dictionary. The particles are taken for dark ones where the frame looks so unless said, as {@code track} and
 * {@code profile} do.
 */
public final class ProfileSummary {

	private ProfileSummary() {}

	/**
	 * @param frames the frames
	 * @param frame the frame to profile, 0-based
	 * @param diameter the particles' diameter in px, 0 to estimate it
	 * @param maxRadius how far out the profile is measured in px, 0 for 2.5 diameters
	 * @param particles {@code bright}, {@code dark}, or {@code null} to decide as {@code track} does
	 * @return the report: the suggested {@code threshold}, {@code r_out}, {@code diameter}, {@code min_area} and
	 *         {@code particles} (the settings to pass to tracking), the profile ({@code radius}, {@code level},
	 *         {@code count}), {@code background}, {@code noise}, {@code peak}, {@code centres} of the particles
	 *         profiled ({x, y} each), {@code lines} (the report's text) and {@code warnings}
	 * @throws InvalidInputException when the frame does not exist or the profile cannot be measured
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	public static Map<String, Object> of(final PixelPlanes frames, final int frame, final double diameter,
		final double maxRadius, final String particles)
	{
		if (frame < 0 || frame >= frames.frameCount()) throw new InvalidInputException("frame " + frame + " does not " +
			"exist: there " + (frames.frameCount() == 1 ? "is 1 frame" : "are " + frames.frameCount() + " frames") +
			" (counted from 0)");
		final boolean dark = particles == null ? Contrast.looksDark(frames.frame(frame), diameter) : SettingValues
			.defaults().withText(TrackingSettings.PARTICLES, particles).dark();
		final List<RandomAccessibleInterval<? extends RealType<?>>> kindFrames = new ArrayList<>();
		for (final int t : ProfileAnalysis.kindFrames(frame, frames.frameCount()))
			kindFrames.add(seen(frames, t, dark));
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse((RandomAccessibleInterval) seen(frames, frame, dark),
			diameter, maxRadius, (List) kindFrames);
		final boolean integerData = frames.integerData();
		final double threshold = r.suggestedThreshold(integerData);
		final Map<String, Object> m = new LinkedHashMap<>();
		m.put("threshold", threshold);
		m.put("r_out", r.suggestedROut());
		m.put("diameter", r.suggestedDiameter());
		m.put("min_area", r.smallParticles(threshold) ? r.suggestedMinArea(threshold)
			: TrackingSettings.MIN_AREA.defaultValue());
		m.put("particles", dark ? TrackingSettings.DARK : TrackingSettings.PARTICLES.defaultValue());
		m.put("frame", frame);
		m.put("particles_profiled", r.particles());
		m.put("diameter_estimated", r.diameterEstimated());
		m.put("background", r.background());
		m.put("noise", r.noise());
		m.put("peak", r.peak());
		m.put("radius", r.radius().clone());
		m.put("level", r.level().clone());
		m.put("count", r.count().clone());
		m.put("centres", r.centres().toArray(new double[0][]));
		m.put("lines", ProfileReport.lines(r, integerData).toArray(new String[0]));
		m.put("warnings", ProfileReport.warnings(r).toArray(new String[0]));
		return m;
	}

	private static RandomAccessibleInterval<? extends RealType<?>> seen(final PixelPlanes frames, final int t,
		final boolean dark)
	{
		return dark ? Inversion.of(frames.frame(t)) : frames.frame(t);
	}
}
