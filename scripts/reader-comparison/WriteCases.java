package io.github.contacttracker.io;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * Benchmark, not part of the build (run.sh compiles it against the test classes): writes the 44 broken files of
 * {@link BrokenFilesIT} and, for each TIFF seed, the seed and 40 random mutations of its header bytes (those of
 * {@code BrokenFilesTest}) into the folder given.
 */
public class WriteCases {

	public static void main(final String[] args) throws Exception {
		final Path out = Files.createDirectories(Path.of(args[0]));
		final Map<String, byte[]> seeds = SeedFiles.all(Files.createTempDirectory("seeds"));
		for (final Map.Entry<String, byte[]> c : BrokenFilesIT.cases(seeds).entrySet())
			Files.write(out.resolve("issue-" + c.getKey()), c.getValue());
		for (final String seed : List.of("imagej.tif", "pages16.tif", "big.tif", "float64.tif")) {
			Files.write(out.resolve("valid-" + seed), seeds.get(seed));
			final Random random = new Random(seed.hashCode());
			for (int k = 0; k < 40; k++)
				Files.write(out.resolve("random" + k + "-" + seed), SeedFiles.randomHeaderBytes(seeds.get(seed), random));
		}
	}
}
