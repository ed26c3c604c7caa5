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
package io.github.contacttracker.io;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import ij.IJ;
import io.github.contacttracker.core.InvalidInputException;

/**
 * ImageJ 1's own messages while our readers call its decoders: caught, not printed. Without a window (the command
 * line, headless Fiji) ImageJ prints its errors and its log to standard output ({@code FileInfo parameter error},
 * {@code AVI File Error: ...}, {@code Unsupported format or file not found}), several lines before ours; a reader
 * turns what was caught into its own one line instead.
 * <p>
 * While any read runs, {@link System#out} and {@link System#err} are a router that sends what a reading thread
 * prints to that thread's buffer and what other threads print where it went before; the streams are put back
 * when the last read ends. ImageJ's error dialogs are redirected to its log for the same time (so Fiji shows no
 * dialog for a file we then refuse in one line).
 */
final class ImageJMessages {

	private ImageJMessages() {}

	/** A read that may call ImageJ. */
	@FunctionalInterface
	interface Read<T> {
		T run() throws IOException;
	}

	/**
	 * What a read returned and what ImageJ printed meanwhile.
	 *
	 * @param value the read's result (ImageJ's readers return null when they fail)
	 * @param messages ImageJ's messages on one line, empty if none
	 */
	record Result<T>(T value, String messages) {}

	private static final Object LOCK = new Object();
	private static final ThreadLocal<ByteArrayOutputStream> BUFFER = new ThreadLocal<>();
	/** Reads running; the streams and the redirect flag as they were before the first. */
	private static int running;
	private static PrintStream out, err, routerOut, routerErr;
	private static boolean redirected;

	/**
	 * Runs {@code read} with ImageJ's messages caught. ImageJ's readers allocate what a file declares without a
	 * check (DICOM element lengths, a PNG's size, ...); where ours could not check first, running out of memory on
	 * such a request (one allocation that failed, so the heap is intact) is a refusal naming the file.
	 *
	 * @param file the file read (a path, or an address such as hdfs://nn/a.tif), for the message
	 * @throws IOException also when the read ran out of memory
	 */
	static <T> Result<T> call(final Object file, final Read<T> read) throws IOException {
		final ByteArrayOutputStream previous = BUFFER.get(); // a read inside a read: the outer one's buffer
		final ByteArrayOutputStream buffer = previous != null ? previous : new ByteArrayOutputStream();
		BUFFER.set(buffer);
		install();
		try {
			return new Result<>(read.run(), InvalidInputException.oneLine(buffer.toString(StandardCharsets.UTF_8)));
		}
		catch (final OutOfMemoryError e) {
			throw new IOException("cannot read " + file + ": ImageJ's reader ran out of memory on it (" + e.getMessage() +
				", Java heap " + (Runtime.getRuntime().maxMemory() >> 20) + " MB): the file is damaged, or its images " +
				"need more memory (CONTACT_TRACKER_JAVA_OPTS=-Xmx8g; in Fiji Edit > Options > Memory & Threads)");
		}
		finally {
			if (previous == null) BUFFER.remove();
			uninstall();
		}
	}

	private static void install() {
		synchronized (LOCK) {
			if (running++ > 0) return;
			out = System.out;
			err = System.err;
			routerOut = new PrintStream(new Router(out), true, StandardCharsets.UTF_8);
			routerErr = new PrintStream(new Router(err), true, StandardCharsets.UTF_8);
			System.setOut(routerOut);
			System.setErr(routerErr);
			redirected = IJ.redirectingErrorMessages();
			IJ.redirectErrorMessages(true);
		}
	}

	private static void uninstall() {
		synchronized (LOCK) {
			if (--running > 0) return;
			// streams someone else set meanwhile stay
			if (System.out == routerOut) System.setOut(out);
			if (System.err == routerErr) System.setErr(err);
			IJ.redirectErrorMessages(redirected);
			out = err = routerOut = routerErr = null;
		}
	}

	/** Sends a reading thread's output to its buffer, any other thread's to the stream it replaced. */
	private static final class Router extends OutputStream {

		private final OutputStream fallback;

		Router(final OutputStream fallback) {
			this.fallback = fallback;
		}

		private OutputStream target() {
			final ByteArrayOutputStream buffer = BUFFER.get();
			return buffer != null ? buffer : fallback;
		}

		@Override
		public void write(final int b) throws IOException {
			target().write(b);
		}

		@Override
		public void write(final byte[] b, final int off, final int len) throws IOException {
			target().write(b, off, len);
		}

		@Override
		public void flush() throws IOException {
			fallback.flush();
		}
	}
}
