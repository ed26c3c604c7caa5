package io.github.contacttracker.trackmate;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.SpotBase;
import fiji.plugin.trackmate.detection.SpotDetector;
import io.github.contacttracker.core.ContactTracker;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.SpotColumn;
import net.imagej.ImgPlus;
import net.imagej.axis.Axes;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.NativeType;
import net.imglib2.type.numeric.RealType;
import net.imglib2.view.Views;

/**
 * Runs Contact Tracker on one frame of a TrackMate image, the way TrackMate drives every per-frame detector:
 * {@link #checkInput()}, {@link #process()}, {@link #getResult()}, and {@link #getErrorMessage()} when one of
 * them returned {@code false}.
 * <p>
 * TrackMate hands over the WHOLE image (all channels and frames) and the crop interval (no time axis, maybe a
 * one-wide channel axis). The detector takes out the target channel and the frame itself, crops to the
 * interval and runs {@link ContactTracker#track} on the resulting 2D view. Images with more than one Z slice
 * are refused in {@link #checkInput()}.
 * <p>
 * Spots are in TrackMate's convention: physical units, whole-image coordinates, pixel centre at
 * {@code index * pixel size}, {@code z = 0}. They are {@link SpotBase}s with
 * <ul>
 * <li>{@code POSITION_X/Y} = final centre x {@code dx}, y {@code dy};</li>
 * <li>{@code RADIUS} = equivalent radius of the active area, {@code sqrt(area / pi)}, times
 * {@code sqrt(dx dy)};</li>
 * <li>{@code QUALITY} = integrated intensity above the threshold over the active area (grey levels x pixels):
 * brighter and larger particles score higher;</li>
 * <li>every extra {@link SpotColumn} (first-pass position, active and second areas, solves, standard errors,
 * flags as 0/1) as a spot feature, skipped when not a finite number.</li>
 * </ul>
 */
public final class ContactTrackerDetector<T extends RealType<T> & NativeType<T>> implements SpotDetector<T> {

	private final ImgPlus<T> img;
	private final Interval interval;
	private final int frame;
	private final TrackerParameters params;
	private final int targetChannel;
	private final String settingsError;

	private RandomAccessibleInterval<T> plane;
	private double dx;
	private double dy;
	private List<Spot> result = new ArrayList<>();
	private String errorMessage;
	private long processingTime;

	/**
	 * @param img the whole image, as TrackMate gives it (X, Y and optionally channel, Z of size 1 and time axes)
	 * @param interval the region to analyse, without time axis (as TrackMate gives it); {@code null} for the
	 *        whole frame
	 * @param frame the 0-based frame index
	 * @param params the localizer parameters
	 * @param targetChannel the 1-based channel to analyse
	 */
	public ContactTrackerDetector(final ImgPlus<T> img, final Interval interval, final int frame,
		final TrackerParameters params, final int targetChannel)
	{
		this(img, interval, frame, params, targetChannel, params == null ? "Contact Tracker: no parameters given." : null);
	}

	/** From a TrackMate settings map: invalid settings make {@link #checkInput()} fail with their message. */
	ContactTrackerDetector(final ImgPlus<T> img, final Interval interval, final int frame,
		final Map<String, Object> settings)
	{
		this(img, interval, frame, parametersOrNull(settings), channelOrZero(settings), DetectorSettings.check(settings));
	}

	private ContactTrackerDetector(final ImgPlus<T> img, final Interval interval, final int frame,
		final TrackerParameters params, final int targetChannel, final String settingsError)
	{
		this.img = img;
		this.interval = interval;
		this.frame = frame;
		this.params = params;
		this.targetChannel = targetChannel;
		this.settingsError = settingsError;
	}

	@Override
	public boolean checkInput() {
		plane = null;
		if (settingsError != null) return fail("Invalid Contact Tracker settings:\n" + settingsError);
		if (img == null) return fail("Contact Tracker: no image given.");
		final int n = img.numDimensions();
		final int xd = img.dimensionIndex(Axes.X);
		final int yd = img.dimensionIndex(Axes.Y);
		final int zd = img.dimensionIndex(Axes.Z);
		final int cd = img.dimensionIndex(Axes.CHANNEL);
		final int td = img.dimensionIndex(Axes.TIME);
		if (xd < 0 || yd < 0) return fail("Contact Tracker: the image has no X or no Y axis.");
		if (zd >= 0 && img.dimension(zd) > 1)
			return fail("Contact Tracker works on 2D images and 2D time-lapses, but this image has " +
				img.dimension(zd) + " Z slices. If the slices are time points, swap Z and T with " +
				"Image > Hyperstacks > Re-order Hyperstacks; otherwise project the stack to 2D first.");
		for (int d = 0; d < n; d++)
			if (d != xd && d != yd && d != zd && d != cd && d != td && img.dimension(d) > 1)
				return fail("Contact Tracker: the image has an axis of unknown type (dimension " + d + ", size " +
					img.dimension(d) + "); only X, Y, channel, time and a single Z slice are supported.");
		final long channels = cd < 0 ? 1 : img.dimension(cd);
		if (targetChannel < 1 || targetChannel > channels)
			return fail("Contact Tracker: TARGET_CHANNEL is " + targetChannel + " but the image has " + channels +
				(channels == 1 ? " channel." : " channels."));
		final long frames = td < 0 ? 1 : img.dimension(td);
		if (frame < 0 || frame >= frames)
			return fail("Contact Tracker: frame " + frame + " does not exist; the image has " + frames +
				(frames == 1 ? " frame." : " frames."));
		dx = img.averageScale(xd);
		dy = img.averageScale(yd);
		if (!(dx > 0) || !(dy > 0) || !Double.isFinite(dx) || !Double.isFinite(dy))
			return fail("Contact Tracker: the pixel size must be positive, not " + dx + " x " + dy + ".");

		// the crop, in whole-image pixel indices
		final long[] xr = { img.min(xd), img.max(xd) };
		final long[] yr = { img.min(yd), img.max(yd) };
		if (interval != null) {
			final int nNoTime = n - (td < 0 ? 0 : 1);
			final int ix, iy;
			if (interval.numDimensions() == nNoTime) {
				ix = td >= 0 && td < xd ? xd - 1 : xd;
				iy = td >= 0 && td < yd ? yd - 1 : yd;
			}
			else if (interval.numDimensions() == n) {
				ix = xd;
				iy = yd;
			}
			else return fail("Contact Tracker: the detection interval has " + interval.numDimensions() +
				" dimensions, but the image has " + n + (td < 0 ? "." : " (" + nNoTime + " without time)."));
			xr[0] = Math.max(xr[0], interval.min(ix));
			xr[1] = Math.min(xr[1], interval.max(ix));
			yr[0] = Math.max(yr[0], interval.min(iy));
			yr[1] = Math.min(yr[1], interval.max(iy));
			if (xr[0] > xr[1] || yr[0] > yr[1])
				return fail("Contact Tracker: the detection interval does not overlap the image.");
		}

		// one plane: slice off every axis but X and Y, highest dimension first so indices stay valid
		RandomAccessibleInterval<T> view = img;
		for (int d = n - 1; d >= 0; d--) {
			if (d == xd || d == yd) continue;
			final long pos = d == td ? img.min(d) + frame : d == cd ? img.min(d) + targetChannel - 1 : img.min(d);
			view = Views.hyperSlice(view, d, pos);
		}
		if (yd < xd) view = Views.permute(view, 0, 1);
		plane = Views.interval(view, new long[] { xr[0], yr[0] }, new long[] { xr[1], yr[1] });
		errorMessage = null;
		return true;
	}

	@Override
	public boolean process() {
		final long start = System.currentTimeMillis();
		if (plane == null && !checkInput()) return false;
		final List<Localization> found;
		try {
			found = new ContactTracker(params).track(plane, frame);
		}
		catch (final IllegalArgumentException e) {
			return fail("Contact Tracker failed on frame " + frame + ": " + e.getMessage());
		}
		final List<Spot> spots = new ArrayList<>(found.size());
		for (final Localization loc : found)
			spots.add(toSpot(loc, dx, dy));
		result = spots;
		processingTime = System.currentTimeMillis() - start;
		return true;
	}

	/** @return the spots of the last successful {@link #process()} (a new, modifiable list) */
	@Override
	public List<Spot> getResult() {
		return result;
	}

	@Override
	public String getErrorMessage() {
		return errorMessage;
	}

	@Override
	public long getProcessingTime() {
		return processingTime;
	}

	/**
	 * Converts a localization (pixels) into a TrackMate spot (physical units), with the same numbers as every
	 * other output through {@link SpotColumn}.
	 *
	 * @param loc the localization, in whole-image pixel indices
	 * @param pixelWidth pixel size along x
	 * @param pixelHeight pixel size along y
	 * @return a new spot with our extra features attached
	 */
	public static Spot toSpot(final Localization loc, final double pixelWidth, final double pixelHeight) {
		final Calibration cal = new Calibration(pixelWidth, pixelHeight, null, 1, null);
		final Spot spot = new SpotBase(SpotColumn.POSITION_X.value(loc, 0, cal), SpotColumn.POSITION_Y.value(loc, 0, cal),
			0, SpotColumn.RADIUS.value(loc, 0, cal), SpotColumn.QUALITY.value(loc, 0, cal));
		for (final SpotColumn c : SpotColumn.values()) {
			if (c.isTrackMateKey()) continue;
			final double v = c.value(loc, 0, cal);
			if (Double.isFinite(v)) spot.putFeature(c.key(), v);
		}
		return spot;
	}

	private boolean fail(final String message) {
		errorMessage = message;
		plane = null;
		return false;
	}

	private static TrackerParameters parametersOrNull(final Map<String, Object> settings) {
		try {
			return DetectorSettings.parameters(settings);
		}
		catch (final IllegalArgumentException e) {
			return null;
		}
	}

	private static int channelOrZero(final Map<String, Object> settings) {
		try {
			return DetectorSettings.targetChannel(settings);
		}
		catch (final IllegalArgumentException e) {
			return 0;
		}
	}
}
