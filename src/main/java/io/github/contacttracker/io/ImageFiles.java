package io.github.contacttracker.io;

import io.github.contacttracker.core.InvalidInputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import java.util.List;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.io.Opener;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.img.basictypeaccess.array.FloatArray;
import net.imglib2.img.basictypeaccess.array.ShortArray;

/** Opening and saving images with ImageJ's readers and writers (headless). */
public final class ImageFiles {

	private ImageFiles() {}

	/**
	 * @throws IOException with a one-line message when the file is missing, unreadable or not an image
	 */
	public static ImagePlus open(final Path file) throws IOException {
		if (!Files.exists(file)) throw new IOException("file not found: " + file);
		if (Files.isDirectory(file)) throw new IOException(file + " is a folder, not an image file");
		if (!Files.isReadable(file)) throw new IOException("cannot read " + file + ": permission denied");
		final ImagePlus imp;
		try {
			imp = new Opener().openImage(file.toAbsolutePath().toString());
		}
		catch (final RuntimeException e) {
			throw new IOException("cannot read " + file + " as an image: " + e.getMessage(), e);
		}
		if (imp == null) throw new IOException("cannot read " + file + " as an image (TIFF expected)");
		return imp;
	}

	/** Saves {@code imp} as a TIFF (stack), atomically: nothing appears at {@code file} if saving fails. */
	public static void saveTiff(final ImagePlus imp, final Path file) throws IOException {
		final Path abs = file.toAbsolutePath();
		if (abs.getParent() == null || !Files.isDirectory(abs.getParent()))
			throw new IOException("cannot write " + file + ": folder " + abs.getParent() + " does not exist");
		final Path tmp = Files.createTempFile(abs.getParent(), "." + abs.getFileName(), ".part.tif");
		boolean done = false;
		try {
			final FileSaver saver = new FileSaver(imp);
			final boolean ok = imp.getStackSize() > 1 ? saver.saveAsTiffStack(tmp.toString()) : saver.saveAsTiff(tmp
				.toString());
			if (!ok) throw new IOException("could not write " + file);
			Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
			done = true;
		}
		finally {
			if (!done) Files.deleteIfExists(tmp);
		}
	}

	/**
	 * Builds an ImageJ time series (T = number of frames) sharing the frames' pixel arrays.
	 *
	 * @param frames 2D unsigned-byte, unsigned-short or float {@link ArrayImg}s of equal size
	 * @param cal the calibration to set (pixel size, unit, frame interval)
	 */
	public static ImagePlus timeSeries(final String title, final List<? extends ArrayImg<?, ?>> frames,
		final Calibration cal)
	{
		if (frames.isEmpty()) throw new InvalidInputException("no frames");
		final int w = (int) frames.get(0).dimension(0), h = (int) frames.get(0).dimension(1);
		final ImageStack stack = new ImageStack(w, h);
		for (final ArrayImg<?, ?> f : frames) {
			final Object access = f.update(null);
			if (access instanceof ByteArray) stack.addSlice(null, ((ByteArray) access).getCurrentStorageArray());
			else if (access instanceof ShortArray) stack.addSlice(null, ((ShortArray) access).getCurrentStorageArray());
			else if (access instanceof FloatArray) stack.addSlice(null, ((FloatArray) access).getCurrentStorageArray());
			else throw new InvalidInputException("unsupported pixel storage " + access.getClass().getSimpleName());
		}
		final ImagePlus imp = new ImagePlus(title, stack);
		imp.setDimensions(1, 1, frames.size());
		final ij.measure.Calibration c = imp.getCalibration();
		c.pixelWidth = cal.pixelWidth();
		c.pixelHeight = cal.pixelHeight();
		c.pixelDepth = 1;
		c.setUnit(cal.unit());
		c.frameInterval = cal.frameInterval();
		c.setTimeUnit(cal.timeUnit());
		return imp;
	}
}
