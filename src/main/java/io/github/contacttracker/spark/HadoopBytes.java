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
package io.github.contacttracker.spark;

import java.io.EOFException;
import java.io.IOException;
import java.net.URI;
import java.nio.ByteBuffer;

import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.ChecksumFileSystem;
import org.apache.hadoop.fs.FSDataInputStream;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.Path;

import io.github.contacttracker.io.SeekableBytes;

/**
 * A file read by offset through Hadoop's {@link FileSystem} API: {@code file://}, {@code hdfs://} and, where the
 * cluster has the connector, {@code s3a://}. Positioned reads ({@code readFully(position, ...)}) leave the stream's
 * own position alone, so the tasks of one executor share one open stream.
 */
final class HadoopBytes implements SeekableBytes {

	private final String name;
	private final URI uri;
	private FSDataInputStream in;
	private long size = -1;

	/**
	 * @param uri the file's address, with its scheme ({@code file:/data/a.tif})
	 * @param name the movie as the user gave it, for messages
	 */
	HadoopBytes(final URI uri, final String name) {
		this.uri = uri;
		this.name = name;
	}

	private synchronized FSDataInputStream in() throws IOException {
		if (in == null) {
			// the cluster's settings (HADOOP_CONF_DIR) where there are any; Hadoop caches the FileSystem itself
			final Path path = new Path(uri);
			FileSystem fs = FileSystem.get(uri, new Configuration());
			// A local file without Hadoop's checksum file beside it (a microscope's) has nothing to verify: read it
			// through the raw file system, whose positioned reads share the open file. The checksummed one opens the
			// file and looks for the checksum file again on every read: each of a TIFF's thousands of directories.
			if (fs instanceof ChecksumFileSystem checked && !checked.exists(checked.getChecksumFile(path))) fs = checked
				.getRawFileSystem();
			try {
				size = fs.getFileStatus(path).getLen();
			}
			catch (final java.io.FileNotFoundException e) {
				throw new IOException("file not found: " + name, e);
			}
			in = fs.open(path);
		}
		return in;
	}

	@Override
	public long size() throws IOException {
		in();
		return size;
	}

	@Override
	public void read(final long at, final ByteBuffer into) throws IOException {
		final int length = into.remaining();
		final byte[] b = into.hasArray() ? into.array() : new byte[length];
		final int offset = into.hasArray() ? into.arrayOffset() + into.position() : 0;
		try {
			in().readFully(at, b, offset, length);
		}
		catch (final EOFException e) {
			throw new IOException("cannot read " + name + ": truncated (ends before byte " + (at + length) + ")", e);
		}
		if (!into.hasArray()) into.put(b);
		else into.position(into.position() + length);
	}

	@Override
	public String name() {
		return name;
	}
}
