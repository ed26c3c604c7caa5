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
package io.github.contacttracker.ij;

import java.io.UncheckedIOException;
import java.util.AbstractList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import ij.ImagePlus;
import ij.ImageStack;
import ij.process.ImageProcessor;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.image.Inversion;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.RgbPixels;
import net.imglib2.Interval;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.view.Views;
import net.imglib2.type.numeric.RealType;

/**
 * The frames of an ImageJ image as ImgLib2 planes, read when asked for: a frame of an image in memory is wrapped
 * without copying (so the core takes its primitive-array fast path); a frame of a virtual stack (a movie on disk,
 * Fiji's virtual stacks) is read from its file when a thread needs it, so a movie of any length is tracked in a
 * fixed heap.
 * <p>
 * Every time point is a frame. A plain stack of 2D planes (one channel, slices only) is a time series. In a
 * multi-channel image one channel is tracked. An image with both Z and T above 1 is refused: the method is 2D.
 * <p>
 * <b>Colour.</b> An RGB image (colour cameras; MJPEG, which codes even grey movies in colour) has three channels,
 * 1 red, 2 green, 3 blue, tracked as 8-bit grey. Without a chosen channel, an image whose first frame is grey (red,
 * green and blue equal at every pixel) is tracked as grey (each frame's mean of the three, exactly the grey of a
 * grey movie); a colour one in the channel that holds the particles' contrast, when one does ({@link #dominant}: the
 * mean would add the noise of channels without signal to it), else in the mean, and {@link #colourChoice} says
 * which.
 * <p>
 * <b>Values.</b> Frames hold the image's own values: for 8- and 16-bit images with a calibration function (ImageJ
 * stores signed 16-bit data with an offset of 32768 and such a function), each frame is converted to those values,
 * so that a threshold means what the user sees.
 * <p>
 * <b>Threads.</b> {@link #frame(int)} may be called from several threads. The planes of our own TIFF reader are
 * read in parallel (each read opens the file); reads from other virtual stacks are serialised (ImageJ's virtual
 * stacks are not all thread-safe; the AVI reader shares one file handle). The last few frames read are kept, so that a frame asked for twice in a row (the profile methods' passes) is read once; no more than
 * {@link #CACHED_FRAMES} frames are held.
 */
public final class ImagePlusFrames {

	/** At most this many frames of a virtual stack are kept after reading. */
	public static final int CACHED_FRAMES = 4;

	private final ImageStack stack;
	private final int[] stackIndex;
	private final float[] cTable;
	private final Calibration calibration;
	private final int width, height, channel;
	/** Of an RGB image: the component tracked, 1 red, 2 green, 3 blue, or 0 the mean of the three (a grey image). */
	private final int colour;
	/** Whether each frame is inverted ({@link Inversion}: dark particles). */
	private final boolean dark;
	/** How the colour tracked was chosen, when nobody chose it in a colour image; empty otherwise. */
	private final String colourChoice;
	private final boolean virtual;
	private final Map<Integer, RandomAccessibleInterval<? extends RealType<?>>> cache;
	private int reads;

	private ImagePlusFrames(final ImageStack stack, final int[] stackIndex, final float[] cTable,
		final Calibration calibration, final int width, final int height, final int channel, final int colour,
		final boolean dark, final String colourChoice)
	{
		this.colour = colour;
		this.dark = dark;
		this.colourChoice = colourChoice;
		this.stack = stack;
		this.stackIndex = stackIndex;
		this.cTable = cTable;
		this.calibration = calibration;
		this.width = width;
		this.height = height;
		this.channel = channel;
		this.virtual = stack.isVirtual();
		this.cache = new LinkedHashMap<>(8, 0.75f, true) {

			private static final long serialVersionUID = 1L;

			@Override
			protected boolean removeEldestEntry(final Map.Entry<Integer, RandomAccessibleInterval<? extends RealType<?>>> e) {
				return size() > CACHED_FRAMES;
			}
		};
	}

	/**
	 * @param imp the image
	 * @param channel the 1-based channel to track (of an RGB image: 1 red, 2 green, 3 blue); 0 accepts only
	 *        single-channel images and RGB ones (of which a colour is chosen: {@link #colourChoice})
	 * @throws InvalidInputException with a one-line message when the image cannot be tracked
	 */
	public static ImagePlusFrames of(final ImagePlus imp, final int channel) {
		return of(imp, channel, false);
	}

	/**
	 * As {@link #of(ImagePlus, int)}, each frame inverted for dark particles (the profile helper's view of them; the
	 * tracking pipeline inverts its frames itself).
	 *
	 * @param dark whether to invert the frames ({@link Inversion})
	 */
	public static ImagePlusFrames of(final ImagePlus imp, final int channel, final boolean dark) {
		if (imp == null) throw new InvalidInputException("no image");
		final String name = "'" + imp.getTitle() + "'";
		final int bits = imp.getBitDepth();
		if (imp.getWidth() < 1 || imp.getHeight() < 1) throw new InvalidInputException(name + " has no pixels (" + imp
			.getWidth() + " x " + imp.getHeight() + ")");
		if (bits != 8 && bits != 16 && bits != 24 && bits != 32)
			throw new InvalidInputException(name + " has an unsupported bit depth: " + bits);
		final boolean rgb = bits == 24;
		if (rgb && imp.getNChannels() > 1) throw new InvalidInputException(name + " is an RGB image of " + imp
			.getNChannels() + " channels: split it (Image > Color > Split Channels) and track one");
		final int nc = rgb ? 3 : imp.getNChannels(), nz = imp.getNSlices(), nt = imp.getNFrames();
		if (nz > 1 && nt > 1)
			throw new InvalidInputException(name + " has " + nz + " Z slices and " + nt +
				" time frames: the method is 2D; make a projection or pick one slice first");
		if (channel < 0 || channel > nc)
			throw new InvalidInputException("channel " + channel + " does not exist: " + name + " has " + nc +
				" channel" + (nc == 1 ? "" : "s"));
		if (channel == 0 && nc > 1 && !rgb) {
			final String samples = ImageFiles.samples(imp);
			throw new InvalidInputException(name + " has " + nc + " channels: choose one to track (channel = 1.." +
				nc + ")" + (samples != null ? "; " + samples : ""));
		}
		final int c = rgb ? 1 : Math.max(channel, 1); // an RGB image's colours are in each of its planes
		final int count = Math.max(nz, nt); // Z slices of a plain stack are frames
		final int[] index = new int[count];
		for (int t = 1; t <= count; t++)
			index[t - 1] = nt > 1 ? imp.getStackIndex(c, 1, t) : imp.getStackIndex(c, t, 1);
		int colour = rgb ? channel : -1;
		String colourChoice = "";
		ImageProcessor first = null;
		if (rgb && channel == 0) {
			first = imp.getStack().getProcessor(index[0]);
			if (first == null) throw new InvalidInputException("cannot read frame 1 of " + name);
			final double[] spread = RgbPixels.spread((int[]) first.getPixels());
			if (spread != null) {
				colour = dominant(spread);
				colourChoice = name + " has colour frames: tracked in " + (colour == 0 ? "the mean of red, green and " +
					"blue" : COLOURS[colour - 1] + ", the channel with the particles' contrast") + String.format(
						java.util.Locale.ROOT, " (the channels' spread in frame 1: %.1f, %.1f, %.1f grey levels); --channel 1, " +
							"2 or 3 tracks red, green or blue", spread[0], spread[1], spread[2]);
			}
		}
		final ij.measure.Calibration cal = imp.getCalibration();
		// a calibration function (signed 16-bit data, or one the user set) maps stored to real values
		final float[] cTable = bits != 32 && !rgb && cal.calibrated() ? cal.getCTable() : null;
		final double pw = cal.pixelWidth > 0 ? cal.pixelWidth : 1, ph = cal.pixelHeight > 0 ? cal.pixelHeight : 1;
		final double dt = cal.frameInterval > 0 ? cal.frameInterval : 1;
		final String unit = cal.scaled() ? cal.getXUnit() : "pixel";
		final String timeUnit = cal.frameInterval > 0 ? cal.getTimeUnit() : "frame";
		final ImagePlusFrames frames = new ImagePlusFrames(imp.getStack(), index, cTable, new Calibration(cal.scaled()
			? pw : 1, cal.scaled() ? ph : 1, unit, dt, timeUnit), imp.getWidth(), imp.getHeight(), rgb ? Math.max(colour,
				1) : c, colour, dark, colourChoice);
		// the first frame of a movie on disk, read for its colours, is kept: the helper and the tracker read it next
		if (first != null && frames.virtual) synchronized (frames.cache) {
			frames.reads++;
			frames.remember(0, first);
		}
		return frames;
	}

	private static final String[] COLOURS = { "red", "green", "blue" };

	/**
	 * How much more a channel must vary over the frame than each of the others to be taken alone when none was
	 * chosen. Particles imaged in one colour (a dye, a filter) vary only in that channel; the others carry noise and
	 * a faint bleed, which vary many times less. Twice is far below that gap and never picks one of two channels that
	 * carry the particles alike.
	 */
	static final double DOMINANT_SPREAD = 2;

	/**
	 * @return the channel (1-3) whose spread is more than {@link #DOMINANT_SPREAD} times each other's: the one
	 *         that holds the particles; 0 (their mean) when none is, as in a grey scene through a colour camera,
	 *         whose channels' noise the mean averages
	 */
	private static int dominant(final double[] spread) {
		for (int c = 0; c < 3; c++)
			if (spread[c] > DOMINANT_SPREAD * spread[(c + 1) % 3] && spread[c] > DOMINANT_SPREAD * spread[(c + 2) % 3])
				return c + 1;
		return 0;
	}

	/**
	 * @param t the 0-based frame index
	 * @return frame {@code t}, 2D, in the image's own values
	 * @throws InvalidInputException when the frame cannot be read from its file (naming it and the reason)
	 */
	public RandomAccessibleInterval<? extends RealType<?>> frame(final int t) {
		if (t < 0 || t >= stackIndex.length) throw new IndexOutOfBoundsException("frame " + t + " of " +
			stackIndex.length);
		if (!virtual) return wrap(stack.getProcessor(stackIndex[t]));
		// Planes of our own TIFF reader are read in parallel (each read opens the file itself); other virtual stacks
		// (ImageJ's AVI reader, a plugin's) one at a time.
		if (!ImageFiles.readsConcurrently(stack)) {
			synchronized (cache) {
				final RandomAccessibleInterval<? extends RealType<?>> cached = cache.get(t);
				if (cached != null) return cached;
				final ImageProcessor ip = read(t);
				reads++;
				return remember(t, ip);
			}
		}
		synchronized (cache) {
			final RandomAccessibleInterval<? extends RealType<?>> cached = cache.get(t);
			if (cached != null) return cached;
		}
		final ImageProcessor ip = read(t);
		synchronized (cache) {
			reads++;
			final RandomAccessibleInterval<? extends RealType<?>> cached = cache.get(t); // read meanwhile by another
			return cached != null ? cached : remember(t, ip);
		}
	}

	private ImageProcessor read(final int t) {
		final ImageProcessor ip;
		try {
			ip = stack.getProcessor(stackIndex[t]);
		}
		catch (final UncheckedIOException e) {
			throw new InvalidInputException(e.getCause().getMessage(), e);
		}
		if (ip == null) throw new InvalidInputException("cannot read frame " + (t + 1) + " of the virtual stack");
		return ip;
	}

	/** Caches frame {@code t} read as {@code ip}; called holding the cache's lock. */
	private RandomAccessibleInterval<? extends RealType<?>> remember(final int t, final ImageProcessor ip) {
		final RandomAccessibleInterval<? extends RealType<?>> frame = wrap(ip);
		cache.put(t, frame);
		return frame;
	}

	/** @return how many frames were read from a virtual stack so far (for tests of the cache) */
	public int reads() {
		synchronized (cache) {
			return reads;
		}
	}

	private RandomAccessibleInterval<? extends RealType<?>> wrap(final ImageProcessor ip) {
		final RandomAccessibleInterval<? extends RealType<?>> frame = values(ip);
		return dark ? Inversion.of(frame) : frame;
	}

	/** @return the frame's own values, without copying where it can */
	private RandomAccessibleInterval<? extends RealType<?>> values(final ImageProcessor ip) {
		if (ip.getWidth() != width || ip.getHeight() != height)
			throw new InvalidInputException("a frame is " + ip.getWidth() + " x " + ip.getHeight() + " pixels, not " +
				width + " x " + height + " like the first");
		final Object pixels = ip.getPixels();
		if (pixels instanceof int[] rgb) {
			if (colour < 0) throw new InvalidInputException("a frame is in colour (RGB), unlike the first");
			return ArrayImgs.unsignedBytes(RgbPixels.component(rgb, colour), width, height);
		}
		if (colour >= 0) throw new InvalidInputException("a frame is grey, unlike the first (RGB)");
		if (cTable != null) {
			final float[] real = new float[width * height];
			if (pixels instanceof byte[]) {
				final byte[] p = (byte[]) pixels;
				for (int i = 0; i < real.length; i++)
					real[i] = cTable[p[i] & 0xff];
			}
			else if (pixels instanceof short[]) {
				final short[] p = (short[]) pixels;
				for (int i = 0; i < real.length; i++)
					real[i] = cTable[p[i] & 0xffff];
			}
			else throw new InvalidInputException("unsupported pixel type " + pixels.getClass().getSimpleName());
			return ArrayImgs.floats(real, width, height);
		}
		if (pixels instanceof byte[]) return ArrayImgs.unsignedBytes((byte[]) pixels, width, height);
		if (pixels instanceof short[]) return ArrayImgs.unsignedShorts((short[]) pixels, width, height);
		if (pixels instanceof float[]) return ArrayImgs.floats((float[]) pixels, width, height);
		throw new InvalidInputException("unsupported pixel type " + pixels.getClass().getSimpleName());
	}

	/** @return the frames as a list; {@code get(t)} is {@link #frame(int)} (nothing is read before) */
	public List<RandomAccessibleInterval<? extends RealType<?>>> frames() {
		return new AbstractList<>() {

			@Override
			public RandomAccessibleInterval<? extends RealType<?>> get(final int t) {
				return frame(t);
			}

			@Override
			public int size() {
				return stackIndex.length;
			}
		};
	}

	/** @return the number of frames */
	public int frameCount() {
		return stackIndex.length;
	}

	/** @return pixel size, units and frame interval */
	public Calibration calibration() {
		return calibration;
	}

	/** @return image width (px) */
	public int width() {
		return width;
	}

	/** @return image height (px) */
	public int height() {
		return height;
	}

	/** @return the 1-based channel taken */
	public int channel() {
		return channel;
	}

	/**
	 * @return how the colour tracked was chosen in a colour image without a channel given, in one line (e.g.
	 *         {@code 'movie.avi' has colour frames: tracked in red, ...}); empty when there was no choice to make
	 */
	public String colourChoice() {
		return colourChoice;
	}

	/**
	 * The smallest and largest pixel value of one frame.
	 *
	 * @param t the 0-based frame index
	 * @return {min, max}
	 * @throws InvalidInputException naming the first NaN or infinite pixel
	 */
	public double[] frameRange(final int t) {
		return range(frame(t), t);
	}

	/**
	 * @param region the part to keep (the Fiji selection: {@link ShownImage#selection}), or {@code null} for all
	 * @return {@code frame} cut to {@code region}, its pixels at their places in the frame (a view)
	 */
	@SuppressWarnings({ "rawtypes", "unchecked" })
	public static RandomAccessibleInterval<? extends RealType<?>> within(
		final RandomAccessibleInterval<? extends RealType<?>> frame, final Interval region)
	{
		return region == null ? frame : (RandomAccessibleInterval) Views.interval((RandomAccessibleInterval) frame,
			region);
	}

	/**
	 * @return {min, max} of {@code frame}
	 * @throws InvalidInputException naming the first NaN or infinite pixel of frame {@code t} (0-based)
	 */
	public static double[] range(final RandomAccessibleInterval<? extends RealType<?>> frame, final int t) {
		double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
		final var cursor = frame.localizingCursor();
		while (cursor.hasNext()) {
			final double v = cursor.next().getRealDouble();
			if (!Double.isFinite(v))
				throw new InvalidInputException("frame " + (t + 1) + ", pixel (" + cursor.getLongPosition(0) + ", " + cursor
					.getLongPosition(1) + ") is " + v + ": images with NaN or infinite pixels cannot be tracked");
			if (v < min) min = v;
			if (v > max) max = v;
		}
		return new double[] { min, max };
	}
}
