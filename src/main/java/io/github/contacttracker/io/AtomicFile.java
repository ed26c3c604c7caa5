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
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import io.github.contacttracker.core.InvalidInputException;
import java.nio.file.StandardCopyOption;

/**
 * Writes a file so that it either appears whole or not at all: the content goes to a temporary file beside
 * the target, which is moved into place only when writing succeeded. A failed write leaves nothing behind.
 */
public final class AtomicFile {

	/** The body of a write: fills the stream. */
	@FunctionalInterface
	public interface Body {
		void writeTo(OutputStream out) throws IOException;
	}

	private AtomicFile() {}

	/**
	 * Checks that a file can be created where asked: its folder exists. Done before a long run, so that a typo in
	 * an output path costs nothing.
	 *
	 * @param what what the file is, for the message ("csv")
	 * @throws InvalidInputException naming the file and the missing folder
	 */
	public static void checkFolder(final String what, final Path target) {
		final Path dir = target.toAbsolutePath().getParent();
		if (dir == null || !Files.isDirectory(dir))
			throw new InvalidInputException("cannot write " + what + " " + target + ": folder " + dir + " does not exist");
	}

	/**
	 * Writes several files so that either all appear or none: each is written to a temporary file beside its
	 * target, and only when every one succeeded are they moved into place. If a move fails, the targets already
	 * moved are deleted again.
	 *
	 * @param targets the files to create or replace
	 * @param bodies their contents, same order
	 * @throws IOException naming the file that failed; no target is left behind
	 */
	public static void writeAll(final List<Path> targets, final List<Body> bodies) throws IOException {
		final List<Path> temps = new ArrayList<>();
		final List<Path> moved = new ArrayList<>();
		boolean done = false;
		try {
			for (int i = 0; i < targets.size(); i++)
				temps.add(temporary(targets.get(i), bodies.get(i)));
			for (int i = 0; i < targets.size(); i++) {
				move(temps.get(i), targets.get(i).toAbsolutePath());
				moved.add(targets.get(i).toAbsolutePath());
			}
			done = true;
		}
		finally {
			if (!done) {
				for (final Path t : temps)
					Files.deleteIfExists(t);
				for (final Path m : moved)
					Files.deleteIfExists(m);
			}
		}
	}

	private static Path temporary(final Path target, final Body body) throws IOException {
		final Path abs = target.toAbsolutePath();
		final Path dir = abs.getParent();
		if (dir == null || !Files.isDirectory(dir))
			throw new IOException("cannot write " + target + ": folder " + dir + " does not exist");
		final Path tmp = createPart(dir, abs.getFileName().toString());
		boolean done = false;
		try {
			try (OutputStream out = Files.newOutputStream(tmp)) {
				body.writeTo(out);
			}
			done = true;
			return tmp;
		}
		finally {
			if (!done) Files.deleteIfExists(tmp);
		}
	}

	private static final AtomicLong PARTS = new AtomicLong();

	/**
	 * A new, empty hidden file beside the target, named by this process and a counter and created only if it does
	 * not exist (so never shared with another writer). Not {@link Files#createTempFile}: its random names seed a
	 * SecureRandom, a tenth of the CSV's writing time on a short run.
	 */
	private static Path createPart(final Path dir, final String name) throws IOException {
		final long pid = ProcessHandle.current().pid();
		for (int attempt = 0;; attempt++) {
			try {
				return Files.createFile(dir.resolve("." + name + "." + pid + "-" + PARTS.incrementAndGet() + ".part"));
			}
			catch (final FileAlreadyExistsException e) {
				if (attempt >= 100) throw e; // a left-over of a crashed run with this pid: try the next numbers only
			}
		}
	}

	private static void move(final Path tmp, final Path abs) throws IOException {
		try {
			Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
		}
		catch (final AtomicMoveNotSupportedException e) {
			Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
		}
	}

	/**
	 * @param target the file to create or replace
	 * @param body writes the content
	 * @throws IOException with the target named, when the folder is missing or writing fails
	 */
	public static void write(final Path target, final Body body) throws IOException {
		writeAll(List.of(target), List.of(body));
	}

}
