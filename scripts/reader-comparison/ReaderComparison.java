import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.ImagePlusFrames;

/**
 * Benchmark, not part of the build (run.sh compiles it): TwelveMonkeys' TIFF reader against ours.
 * <ul>
 * <li>{@code read tm|ours FILE}: reads every frame (at most 8); prints READ, IOEXC (an IOException or our one
 * line), OTHER (any other exception) or OOM and exits 0.</li>
 * <li>{@code speed tm|ours|open FILE}: reads every frame on one thread (open: only opens the file), best of 5 rounds
 * after 2 rounds of warm-up.</li>
 * <li>{@code repeat ours FOLDER}: reads every file of the folder with our readers, 15 times over in one JVM (a
 * cluster job meeting thousands of files), and prints the heap in use after each round.</li>
 * </ul>
 */
public class ReaderComparison {

	public static void main(final String[] a) throws Exception {
		final File file = new File(a[2]);
		if (a[0].equals("read")) {
			try {
				System.out.println("READ " + read(a[1], file, 8, true));
			}
			catch (final IOException | InvalidInputException e) {
				System.out.println("IOEXC " + InvalidInputException.oneLine(e.getMessage()));
			}
			catch (final OutOfMemoryError e) {
				System.out.println("OOM " + e.getMessage());
			}
			catch (final RuntimeException e) {
				System.out.println("OTHER " + InvalidInputException.oneLine(e.toString()));
			}
			return;
		}
		if (a[0].equals("repeat")) {
			final File[] files = file.listFiles();
			final long start = System.nanoTime();
			for (int round = 1; round <= 15; round++) {
				for (final File f : files)
					try {
						read(a[1], f, 4, true);
					}
					catch (final IOException | RuntimeException e) {
						// refused: what the other modes count; here only time and memory matter
					}
				System.gc();
				final Runtime rt = Runtime.getRuntime();
				System.out.printf("%d files read, heap in use %.1f MB, %.1f s%n", round * files.length, (rt.totalMemory() -
					rt.freeMemory()) / 1e6, (System.nanoTime() - start) / 1e9);
			}
			return;
		}
		long best = Long.MAX_VALUE;
		for (int round = 0; round < 7; round++) {
			final long start = System.nanoTime();
			final String what = a[1].equals("open") ? ImageFiles.open(file.toPath()).getStackSize() + " frames" : read(
				a[1], file, Integer.MAX_VALUE, false);
			if (round >= 2) best = Math.min(best, System.nanoTime() - start);
			if (round == 6) System.out.printf("%s: %s, best of 5 %.3f s%n", a[1], what, best / 1e9);
		}
	}

	/**
	 * @param scan whether our frames' pixels are scanned for NaN as tracking does (not for speed: TwelveMonkeys'
	 *        frames are decoded, not scanned)
	 * @return what was read: frames, size, pixel type
	 */
	private static String read(final String reader, final File file, final int most, final boolean scan)
		throws IOException
	{
		if (reader.equals("ours")) {
			final ImagePlusFrames frames = ImagePlusFrames.of(ImageFiles.open(file.toPath()), 1);
			for (int t = 0; t < Math.min(most, frames.frameCount()); t++)
				if (scan) frames.frameRange(t);
				else frames.frame(t);
			return frames.frameCount() + " frames, " + frames.width() + "x" + frames.height();
		}
		try (ImageInputStream in = ImageIO.createImageInputStream(file)) {
			ImageReader tm = null;
			for (final Iterator<ImageReader> it = ImageIO.getImageReaders(in); it.hasNext();) {
				final ImageReader r = it.next();
				if (r.getClass().getName().startsWith("com.twelvemonkeys")) tm = r;
			}
			if (tm == null) throw new IOException("no TwelveMonkeys reader for it");
			tm.setInput(in);
			final int n = tm.getNumImages(true);
			if (n == 0) throw new IOException("TwelveMonkeys found no image in it");
			BufferedImage img = null;
			for (int i = 0; i < Math.min(most, n); i++)
				img = tm.read(i);
			return n + " frames, " + img.getWidth() + "x" + img.getHeight() + ", DataBuffer type " + img.getRaster()
				.getDataBuffer().getDataType();
		}
	}
}
