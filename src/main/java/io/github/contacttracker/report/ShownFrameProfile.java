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

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import ij.ImagePlus;
import io.github.contacttracker.advisor.Contrast;
import io.github.contacttracker.advisor.ProfileAnalysis;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.ij.ShownImage;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * The profile helper ({@link ProfileAnalysis}) run on the frame of an ImageJ image that is on display: what Fiji's
 * <i>Contact Tracker Profile</i> measures around a clicked particle, and what the "Measure from the image" buttons
 * of Fiji's Contact Tracker dialog and of TrackMate's panel measure on the frame's most isolated particles. One
 * place for the frame taken, the rounding of the suggestions and the lines reported, so that the front ends agree.
 * <p>
 * Suggestions: the threshold rounded up to a whole grey level for 8- and 16-bit images, {@code r_out} up to whole
 * pixels, an estimated diameter to 0.01 px (a given diameter is kept as given).
 *
 * @param result what the helper found
 * @param title the image's title
 * @param frame the 0-based frame measured (as {@link ImagePlusFrames} counts frames)
 * @param frameCount the image's frames
 * @param channel the 1-based channel measured
 * @param integerData whether the image holds whole grey levels (8- or 16-bit)
 * @param rejectedDiameter a diameter given (px) that the helper could not measure with, so it estimated the
 *        diameter instead ({@link #measure}); 0 if none
 * @param rejection why it could not, {@code null} if none
 * @param dark whether the frame was measured inverted: dark particles
 * @param darkFound whether that was found ({@link #measure}: the particles were said bright, the frame looks dark)
 * @param region the part of the frame measured ({@link ShownImage#selection}), {@code null} for all of it
 * @param range the darkest and brightest grey level of the frame measured, as the helper saw it (inverted for dark
 *        particles)
 */
public record ShownFrameProfile(ProfileAnalysis.Result result, String title, int frame, int frameCount, int channel,
	boolean integerData, double rejectedDiameter, String rejection, boolean dark, boolean darkFound, Interval region,
	double[] range)
{

	/** Longest line written to ImageJ's Log window: it does not wrap, and a default Log window is about this wide. */
	public static final int LOG_WIDTH = 70;

	/**
	 * The profile of the most isolated particles of the frame on display (the "Measure from the image" buttons).
	 * A diameter given is used; if the helper cannot measure with it (typically one left in the fields from another
	 * image, e.g. twice these particles' size on a dense monolayer: no background within reach), the diameter is
	 * estimated instead and {@link #summary()} and {@link #logText} say so ({@link #rejectedDiameter()}). Particles
	 * said bright on a frame that looks dark ({@link Contrast#looksDark}) are measured as dark ones, as {@code track}
	 * measures them when neither they nor the threshold are given, and the summary says so ({@link #darkFound()}):
	 * the buttons set the setting with the values.
	 *
	 * @param imp the image
	 * @param channel the 1-based channel to measure (the one that will be tracked)
	 * @param said whether the particles were said to be dark (the frame inverted first)
	 * @param diameter the particle diameter in pixels, or 0 to estimate it from the frame
	 * @return the profile and the suggestions
	 * @throws InvalidInputException with a one-line message: an image that cannot be tracked, or a frame the helper
	 *         finds no usable particle in (with the diameter given, if estimating it does not help either)
	 */
	public static ShownFrameProfile measure(final ImagePlus imp, final int channel, final boolean said,
		final double diameter)
	{
		final ImagePlusFrames plain = ImagePlusFrames.of(imp, channel);
		// within the selection, as the dialog tracks (text burned into a corner of the frame left out, say)
		final Interval region = ShownImage.selection(imp);
		final boolean found = !said && Contrast.looksDark(ImagePlusFrames.within(plain.frame(ShownImage.frame(
			imp)), region), diameter);
		final boolean dark = said || found;
		// one view of the frames for both tries, its frames read once
		final ImagePlusFrames frames = dark ? ImagePlusFrames.of(imp, channel, true) : plain;
		try {
			return run(imp, frames, region, dark, found, null, diameter, 0);
		}
		catch (final InvalidInputException e) {
			if (!(diameter > 0)) throw e;
			final ShownFrameProfile estimated;
			try {
				estimated = run(imp, frames, region, dark, found, null, 0, 0);
			}
			catch (final InvalidInputException again) {
				throw e;
			}
			return new ShownFrameProfile(estimated.result, estimated.title, estimated.frame, estimated.frameCount,
				estimated.channel, estimated.integerData, diameter, e.getMessage(), dark, found, region, estimated.range);
		}
	}

	/**
	 * The profile of the particle at a point of the frame and channel on display (<i>Contact Tracker Profile</i>).
	 *
	 * @param imp the image
	 * @param point {x, y} on the particle (px, TrackMate's convention)
	 * @param diameter the particle diameter in pixels, or 0 to estimate it from the frame
	 * @param maxRadius how far out to measure (px), 0 for the helper's default
	 * @return the profile and the suggestions
	 * @throws InvalidInputException with a one-line message
	 */
	public static ShownFrameProfile at(final ImagePlus imp, final double[] point, final double diameter,
		final double maxRadius)
	{
		if (imp == null) throw new InvalidInputException("no image");
		return run(imp, ImagePlusFrames.of(imp, imp.convertIndexToPosition(imp.getCurrentSlice())[0]), null, false,
			false, point, diameter, maxRadius);
	}

	/**
	 * @param frames the image's frames as the helper is to see them ({@code dark}: inverted)
	 * @param region the part of each frame to measure, {@code null} for all
	 */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static ShownFrameProfile run(final ImagePlus imp, final ImagePlusFrames frames, final Interval region,
		final boolean dark, final boolean darkFound, final double[] point, final double diameter,
		final double maxRadius)
	{
		final int t = ShownImage.frame(imp);
		// the frames' pixel type is known only at run time: the helper takes any real type
		final RandomAccessibleInterval frame = ImagePlusFrames.within(frames.frame(t), region);
		final List kindFrames = kindFrames(frames, t, region);
		final ProfileAnalysis.Result r = point == null ? ProfileAnalysis.analyse(frame, diameter, maxRadius,
			kindFrames) : ProfileAnalysis.analyse(frame, point[0], point[1], diameter, maxRadius, kindFrames);
		return new ShownFrameProfile(r, imp.getTitle(), t, frames.frameCount(), frames.channel(), imp
			.getBitDepth() != 32, 0, null, dark, darkFound, region, ImagePlusFrames.range(frame, t));
	}

	/**
	 * @return whether the suggested threshold lies within the grey levels of the frame measured: outside them no
	 *         threshold keeps two such particles apart at contact (or the background lies under every pixel, in a
	 *         field packed edge to edge), and {@code track} finds the particles by their image instead
	 */
	public boolean thresholdInFrame() {
		final double t = threshold();
		return t >= range[0] && t <= range[1];
	}

	/** @return the frame measured, as the image holds it (not inverted), within the region measured */
	public RandomAccessibleInterval<? extends RealType<?>> frameAsGiven(final ImagePlus imp) {
		return ImagePlusFrames.within(ImagePlusFrames.of(imp, channel).frame(frame), region);
	}

	/**
	 * @param t the frame profiled, 0-based
	 * @return the frames the profile helper finds the kinds of particle on ({@link ProfileAnalysis#kindFrames}),
	 *         each read when the helper comes to it
	 */
	public static List<RandomAccessibleInterval<? extends RealType<?>>> kindFrames(final ImagePlusFrames frames,
		final int t)
	{
		return kindFrames(frames, t, null);
	}

	/** As {@link #kindFrames(ImagePlusFrames, int)}, each frame cut to {@code region} (null: all of it). */
	private static List<RandomAccessibleInterval<? extends RealType<?>>> kindFrames(final ImagePlusFrames frames,
		final int t, final Interval region)
	{
		final List<Integer> indices = ProfileAnalysis.kindFrames(t, frames.frameCount());
		return new AbstractList<>() {

			@Override
			public RandomAccessibleInterval<? extends RealType<?>> get(final int i) {
				return ImagePlusFrames.within(frames.frame(indices.get(i)), region);
			}

			@Override
			public int size() {
				return indices.size();
			}
		};
	}

	/** @return the suggested threshold, rounded up to a whole grey level for 8- and 16-bit images */
	public double threshold() {
		return result.suggestedThreshold(integerData);
	}

	/** @return the suggested {@code r_out} (px), rounded up to whole pixels */
	public double rOut() {
		return result.suggestedROut();
	}

	/**
	 * @return the {@code min_area} for the particles at the suggested threshold
	 *         ({@link ProfileAnalysis.Result#suggestedMinArea}): below the default only for particles a few pixels
	 *         across, and only then do the buttons lower the field to it
	 */
	public int minArea() {
		return result.suggestedMinArea(threshold());
	}

	/** @return whether {@link #minArea()} is below the default {@code min_area} (the particles are that small) */
	public boolean smallParticles() {
		return result.smallParticles(threshold());
	}

	/** @return the particle diameter (px): as given, or the estimate rounded to 0.01 px */
	public double diameter() {
		return result.diameterEstimated() ? Math.round(result.diameter() * 100) / 100.0 : result.diameter();
	}

	/**
	 * @return one line, e.g. {@code 'movie.tif', frame 3: threshold 131, r_out 36 px, diameter 64.87 px (estimated)};
	 *         {@code (estimated: 65.29 px given did not fit)} when a diameter given could not be measured with
	 */
	public String summary() {
		return String.format(Locale.ROOT, "'%s'%s%s%s: %sthreshold %s, r_out %s px, diameter %s px (%s)", title,
			frameCount > 1 ? ", frame " + (frame + 1) : "", channel > 1 ? ", channel " + channel : "", region == null ? ""
				: " within the selection (" + ShownImage.describe(region) + ")", darkFound
				? "dark particles (the frame looks so), " : dark ? "dark particles, " : "", Numbers.fmt(
				threshold(), 3), Numbers.fmt(rOut(), 3), Numbers.fmt(diameter(), 3), rejectedDiameter > 0 ? "estimated: " +
					Numbers.fmt(rejectedDiameter, 3) + " px given did not fit" : result.diameterEstimated() ? "estimated"
						: "given") + (smallParticles() ? ", min area " + minArea() + " px (small particles)" : "");
	}

	/** @return {@link #summary()} and, if the helper warns, how many warnings the Log window holds */
	public String status() {
		final int n = result.findings().size() + (rejectedDiameter > 0 ? 1 : 0);
		return summary() + (n == 0 ? "" : "; " + n + " warning" + (n == 1 ? "" : "s") + " in the Log window");
	}

	/**
	 * @param who what measured, at the start of the first line (e.g. {@code Contact Tracker: measured})
	 * @return the summary, the kinds of particle ({@link ProfileReport#kinds}) and the helper's warnings, for
	 *         ImageJ's Log window, wrapped to {@link #LOG_WIDTH}
	 */
	public String logText(final String who) {
		final List<String> lines = new ArrayList<>();
		lines.add(wrap(who + " " + summary(), LOG_WIDTH, "    "));
		for (final String k : ProfileReport.kinds(result.kinds()))
			lines.add(wrap("  " + k, LOG_WIDTH, "    "));
		if (rejectedDiameter > 0) lines.add(wrap(ProfileReport.WARNING + "not measured with the diameter given, " +
			Numbers.fmt(rejectedDiameter, 3) + " px (left from another image?): " + rejection, LOG_WIDTH, "    "));
		for (final String w : ProfileReport.warnings(result))
			lines.add(wrap(ProfileReport.WARNING + w, LOG_WIDTH, "    "));
		return String.join("\n", lines);
	}

	/**
	 * Breaks a line at spaces so that no part is longer than {@code width} characters (ImageJ's Log window does
	 * not wrap: long warnings ran off its edge); continuation lines start with {@code indent}.
	 */
	public static String wrap(final String text, final int width, final String indent) {
		int lead = 0;
		while (lead < text.length() && text.charAt(lead) == ' ')
			lead++;
		final StringBuilder out = new StringBuilder(text.substring(0, lead));
		int lineStart = 0, lineWords = 0;
		for (final String word : text.substring(lead).split(" +")) {
			if (lineWords > 0 && out.length() - lineStart + 1 + word.length() > width) {
				out.append('\n');
				lineStart = out.length();
				out.append(indent);
				lineWords = 0;
			}
			if (lineWords > 0) out.append(' ');
			out.append(word);
			lineWords++;
		}
		return out.toString();
	}
}
