package io.github.contacttracker.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
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
	 * @param target the file to create or replace
	 * @param body writes the content
	 * @throws IOException with the target named, when the folder is missing or writing fails
	 */
	public static void write(final Path target, final Body body) throws IOException {
		final Path abs = target.toAbsolutePath();
		final Path dir = abs.getParent();
		if (dir == null || !Files.isDirectory(dir))
			throw new IOException("cannot write " + target + ": folder " + dir + " does not exist");
		final Path tmp = Files.createTempFile(dir, "." + abs.getFileName(), ".part");
		boolean done = false;
		try {
			try (OutputStream out = Files.newOutputStream(tmp)) {
				body.writeTo(out);
			}
			try {
				Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
			}
			catch (final AtomicMoveNotSupportedException e) {
				Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
			}
			done = true;
		}
		finally {
			if (!done) Files.deleteIfExists(tmp);
		}
	}
}
