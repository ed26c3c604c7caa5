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

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * A file read by offset, wherever it lives: a local file here, a Hadoop {@code FileSystem} path in the Spark job
 * (which implements this without {@code io} knowing Hadoop). {@link ImageFiles#openByOffset} reads TIFF movies
 * through it, one plane at a time.
 */
public interface SeekableBytes {

	/** @return the file's length in bytes */
	long size() throws IOException;

	/**
	 * Fills {@code into} (from its position to its limit) with the bytes from offset {@code at}; safe to call from
	 * several threads at once.
	 *
	 * @throws IOException when the file ends before, naming it
	 */
	void read(long at, ByteBuffer into) throws IOException;

	/** @return the file's name or address, for messages ({@code hdfs://nn/movies/a.tif}) */
	String name();

	/** @return a local file read by offset, opened for each read */
	static SeekableBytes of(final Path file) {
		return new SeekableBytes() {

			@Override
			public long size() throws IOException {
				return java.nio.file.Files.size(file);
			}

			@Override
			public void read(final long at, final ByteBuffer into) throws IOException {
				try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
					of(ch, file).read(at, into);
				}
			}

			@Override
			public String name() {
				return file.toString();
			}
		};
	}

	/** @return a local file's open channel read by offset (positional reads: several threads may read at once) */
	static SeekableBytes of(final FileChannel ch, final Path file) {
		return new SeekableBytes() {

			@Override
			public long size() throws IOException {
				return ch.size();
			}

			@Override
			public void read(final long at, final ByteBuffer into) throws IOException {
				long pos = at;
				while (into.hasRemaining()) {
					final int n = ch.read(into, pos);
					if (n < 0) throw new IOException("cannot read " + file + ": truncated (ends before byte " + (pos + into
						.remaining()) + ")");
					pos += n;
				}
			}

			@Override
			public String name() {
				return file.toString();
			}
		};
	}

	/**
	 * @return the bytes from offset 0 as a stream whose {@code skip} seeks (what ImageJ's decoders read), except
	 *         that the 4 bytes at {@code zeroAt} read as zeros (-1: none)
	 */
	default InputStream stream(final long zeroAt) {
		final SeekableBytes bytes = this;
		return new InputStream() {
			private long pos;
			private final long size = sizeOrZero();

			private long sizeOrZero() {
				try {
					return bytes.size();
				}
				catch (final IOException e) {
					return 0;
				}
			}

			@Override
			public int read() throws IOException {
				final byte[] one = new byte[1];
				return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
			}

			@Override
			public int read(final byte[] b, final int off, final int len) throws IOException {
				if (len == 0) return 0;
				if (pos >= size) return -1;
				final int n = (int) Math.min(len, Math.min(size - pos, 1 << 20));
				bytes.read(pos, ByteBuffer.wrap(b, off, n));
				for (int i = 0; i < n; i++)
					if (zeroAt >= 0 && pos + i >= zeroAt && pos + i < zeroAt + 4) b[off + i] = 0;
				pos += n;
				return n;
			}

			@Override
			public long skip(final long n) {
				final long to = Math.max(pos, Math.min(size, pos + n));
				final long skipped = to - pos;
				pos = to;
				return skipped;
			}
		};
	}
}
