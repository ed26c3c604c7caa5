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

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.ChecksumException;
import org.apache.hadoop.fs.FSDataOutputStream;
import org.apache.hadoop.fs.FileSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reading by offset through Hadoop: a local file without a checksum file (read through the raw file system) gives
 * its bytes, from several threads at once; a file Hadoop wrote with its checksum file is still verified.
 */
class HadoopBytesTest {

	@TempDir
	Path dir;

	private static byte[] bytes(final int n) {
		final byte[] b = new byte[n];
		for (int i = 0; i < n; i++)
			b[i] = (byte) (i * 31 + i / 7);
		return b;
	}

	private static byte[] read(final HadoopBytes in, final long at, final int length) throws IOException {
		final ByteBuffer into = ByteBuffer.allocate(length);
		in.read(at, into);
		assertEquals(length, into.position());
		return into.array();
	}

	@Test
	void aPlainFileIsReadByOffsetFromSeveralThreads() throws Exception {
		final byte[] content = bytes(300_000);
		final Path file = Files.write(dir.resolve("plain.tif"), content);
		final HadoopBytes in = new HadoopBytes(file.toUri(), "plain.tif");
		assertEquals(content.length, in.size());
		final ExecutorService pool = Executors.newFixedThreadPool(4);
		try {
			final List<Future<?>> reads = new ArrayList<>();
			for (int t = 0; t < 4; t++) {
				final int seed = t;
				reads.add(pool.submit(() -> {
					for (int k = 0; k < 500; k++) {
						final int at = (k * 7919 + seed * 104_729) % (content.length - 1000), length = 1 + (k * 13) % 999;
						assertArrayEquals(Arrays.copyOfRange(content, at, at + length), read(in, at, length));
					}
					return null;
				}));
			}
			for (final Future<?> r : reads)
				r.get();
		}
		finally {
			pool.shutdown();
		}
		final IOException truncated = assertThrows(IOException.class, () -> read(in, content.length - 10, 20));
		assertTrue(truncated.getMessage().contains("truncated"), truncated.getMessage());
	}

	@Test
	void aFileWithHadoopsChecksumFileIsVerified() throws Exception {
		final Path file = dir.resolve("checked.tif");
		final FileSystem local = FileSystem.getLocal(new Configuration());
		try (FSDataOutputStream out = local.create(new org.apache.hadoop.fs.Path(file.toUri()))) {
			out.write(bytes(10_000));
		}
		assertTrue(Files.exists(dir.resolve(".checked.tif.crc")), "Hadoop wrote its checksum file");
		final HadoopBytes good = new HadoopBytes(file.toUri(), "checked.tif");
		assertArrayEquals(Arrays.copyOfRange(bytes(10_000), 5000, 6000), read(good, 5000, 1000));
		final byte[] corrupt = Files.readAllBytes(file);
		corrupt[5500] ^= 0x55;
		Files.write(file, corrupt);
		final HadoopBytes bad = new HadoopBytes(file.toUri(), "checked.tif");
		assertThrows(ChecksumException.class, () -> read(bad, 5000, 1000));
	}
}
