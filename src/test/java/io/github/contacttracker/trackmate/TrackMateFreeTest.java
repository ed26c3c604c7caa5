package io.github.contacttracker.trackmate;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import io.github.contacttracker.core.Localization;

/**
 * Only the TrackMate adapter (this package) may refer to TrackMate, ImageJ2 or
 * imglib2-algorithm types: the command line and the ImageJ 1 command run without them, and the mirror of those
 * types never ships. Checked on the compiled classes' constant pools.
 */
class TrackMateFreeTest {

	private static final List<String> FORBIDDEN = List.of("fiji/plugin/trackmate/", "net/imagej/",
		"net/imglib2/algorithm/");

	@Test
	void everythingButTheAdapterIsFreeOfTrackMateTypes() throws IOException, URISyntaxException {
		final Path root = Path.of(Localization.class.getProtectionDomain().getCodeSource().getLocation().toURI());
		assertTrue(Files.isDirectory(root), "expected compiled classes in a folder, not " + root);
		final Path adapter = root.resolve("io/github/contacttracker/trackmate");
		final List<String> offenders = new ArrayList<>();
		int checked = 0;
		try (Stream<Path> classes = Files.walk(root.resolve("io/github/contacttracker"))) {
			for (final Path p : (Iterable<Path>) classes.filter(f -> f.toString().endsWith(".class"))::iterator) {
				final boolean inAdapter = p.getParent().equals(adapter);
				if (inAdapter) continue;
				checked++;
				final String pool = new String(Files.readAllBytes(p), StandardCharsets.ISO_8859_1);
				for (final String f : FORBIDDEN)
					if (pool.contains(f)) offenders.add(root.relativize(p) + " refers to " + f);
			}
		}
		assertTrue(checked > 10, "too few classes checked: " + checked);
		assertTrue(offenders.isEmpty(), String.join("\n", offenders));
	}
}
