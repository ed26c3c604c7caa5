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
package io.github.contacttracker.lab.cli;

import io.github.contacttracker.core.InvalidInputException;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.Numbers;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.SimulatedStack;
import net.imglib2.img.array.ArrayImg;
import net.imglib2.img.basictypeaccess.array.ByteArray;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import io.github.contacttracker.settings.CommandOptions;
import io.github.contacttracker.settings.Option;
import io.github.contacttracker.cli.ContactTrackerCli;
import io.github.contacttracker.cli.Report;

/**
 * {@code bench}: speed of each method on a simulated 512x512 8-bit stack with 12 particles (4 touching pairs),
 * on one thread and on all, against the time of one plain read pass over the same frames (the memory limit).
 */
final class BenchCommand extends ContactTrackerCli.Subcommand {

	private final Option<Integer> framesOption = options.add(Option.integer("--frames", "N", "Frames.").withDefault(
		"400"));
	private final Option<Integer> roundsOption = options.add(Option.integer("--rounds", "N", "Timed rounds (the best " +
		"counts).").withDefault("5"));
	private final Option<Integer> profileFramesOption = options.add(Option.integer("--profile-frames", "N", "Frames " +
		"for the slower profile methods (deblend, fit) in the in-process part.").withDefault("64"));
	private final Option<Boolean> endToEndOption = options.add(Option.negatableFlag("--end-to-end", "Also time " +
		"'track' from the TIFF file to the CSV file, every method on all frames (default: on).").withDefaultExplained(
			"true"));
	private final Option<Path> saveStackOption = options.add(Option.path("--save-stack", "FILE.tif", "Also save the " +
		"simulated stack here (e.g. to time another tracker on the same frames: scripts/compare-trackpy-speed.py)."));
	private final Option<Path> reportOption = options.add(Option.path("--report", "FILE.md", "Also write the tables " +
		"as a markdown page, stamped with this command, the version and the date (the documentation's reports)."));

	/** The tables as they are printed, for {@code --report}: in process, end to end, start-up. */
	private final List<List<String>> inProcess = new ArrayList<>(), endToEnd = new ArrayList<>(), startUp =
		new ArrayList<>();
	/** The printed lines that head the tables, for {@code --report}. */
	private final List<String> headings = new ArrayList<>();

	BenchCommand(final PrintStream out) {
		super(new CommandOptions("contact-tracker bench", "Speed of each method on a simulated 512x512 8-bit stack " +
			"with 12 particles, on one thread and on all."), out);
	}

	@Override
	public Integer call() throws IOException {
		final int frames = options.value(framesOption);
		final int rounds = options.value(roundsOption);
		final int profileFrames = Math.min(frames, options.value(profileFramesOption));
		final Path saveStack = options.value(saveStackOption);
		if (frames < 1 || rounds < 1 || profileFrames < 1)
			throw new InvalidInputException("--frames, --rounds and --profile-frames must be at least 1");
		if (saveStack != null) AtomicFile.checkFolder("--save-stack", saveStack);
		final Path report = ContactTrackerCli.output("--report", options.value(reportOption));
		final long start = System.nanoTime();
		final ParticleType type = PaperParticles.silica553();
		final SimulatedStack<UnsignedByteType> stack = SimulatedStack.benchmarkStack(type, frames, 7);
		if (saveStack != null) ImageFiles.saveTiff(TimeSeries.of(saveStack.getFileName().toString(), stack
			.frames(), Calibration.ofPixelSize(type.pixelSizeMicrons(), "micron")), saveStack);
		final List<ArrayImg<UnsignedByteType, ?>> imgs = stack.frames();
		final double mpx = (double) frames * stack.width() * stack.height() / 1e6;
		final int cores = Runtime.getRuntime().availableProcessors();
		headings.add(String.format(Locale.ROOT, "%d frames of %dx%d 8-bit, 12 particles (4 touching pairs) of %s, %d " +
			"cores, best of %d rounds", frames, stack.width(), stack.height(), type.name(), cores, rounds));
		out.println(headings.get(0));

		final double readSeconds = best(rounds, () -> {
			long sum = 0;
			for (final ArrayImg<UnsignedByteType, ?> img : imgs) {
				final byte[] px = ((ByteArray) img.update(null)).getCurrentStorageArray();
				for (final byte b : px)
					sum += b & 0xff;
			}
			if (sum == 42) out.print(""); // keep the JIT from dropping the loop
		});
		out.printf(Locale.ROOT, "%-28s %10s %10s %12s%n", "", "frames/s", "Mpixel/s", "x read time");
		row("read pass (1 thread)", frames, mpx, readSeconds, readSeconds);
		final TrackerParameters base = TrackerParameters.of(type.threshold(), type.rOut());
		// Warm the JIT on every method first, so the first method measured is not penalised.
		final List<ArrayImg<UnsignedByteType, ?>> few = imgs.subList(0, Math.min(frames, 20));
		for (int w = 0; w < 3; w++)
			for (final Method m : Method.values())
				new StackTracker(base.withMethod(m)).track(few, false); // imglib2's default executor
		for (final Method m : Method.values()) {
			// The profile methods are slower: they run on the first --profile-frames frames (and pass over them
			// three times: iterative centres, then the profile measured twice).
			final List<ArrayImg<UnsignedByteType, ?>> set = m.needsProfile() ? imgs.subList(0, profileFrames) : imgs;
			final double setMpx = mpx * set.size() / frames;
			for (final int threads : new int[] { 1, cores }) {
				final StackTracker tracker = new StackTracker(base.withMethod(m));
				final int n = threads;
				final double s = best(rounds, () -> StackTracker.withThreads(n, () -> tracker.track(set, false)));
				row(m.key() + " (" + threads + " thread" + (threads == 1 ? "" : "s") + ")", set.size(), setMpx, s,
					readSeconds * set.size() / frames);
			}
		}
		if (options.value(endToEndOption)) endToEnd(stack, type, cores, rounds);
		if (report != null) report().write(report, arguments, (System.nanoTime() - start) * 1e-9);
		return 0;
	}

	/** @return the tables printed, as a markdown page */
	private Report report() {
		final Report r = new Report("Speed: bench").paragraph("A simulated 512x512 8-bit stack, 12 particles of the " +
			"5.53 µm-like kind (4 touching pairs, 4 single), every method on 1 thread and on all cores, best of the " +
			"rounds after a warm-up. The profile methods (`deblend`, `fit`) run in process on the first " +
			"`--profile-frames` frames, all their passes included.");
		r.heading("In process").paragraph(headings.get(0) + ": the tracking alone on frames in memory, against one " +
			"plain read pass over the same frames.").table(List.of("", "frames/s", "Mpixel/s", "x read time"),
				inProcess);
		if (!endToEnd.isEmpty()) r.heading("End to end").paragraph(headings.get(1) + ".").table(endToEnd.get(0).size() ==
			5 ? List.of("", "frames/s", "ms/frame", "new process: frames/s", "ms/frame") : List.of("", "frames/s",
				"ms/frame"), endToEnd);
		if (!startUp.isEmpty()) r.heading("Start-up").paragraph(headings.get(2)).table(List.of("", "start-up (s)",
			"then ms/frame"), startUp);
		return r;
	}

	/**
	 * The user's view: {@code track MOVIE.tif ... --csv OUT.csv} run in this JVM (so JIT warm, no JVM start-up),
	 * from reading the TIFF file to the CSV file, every method on every frame: reading, the threshold check, the
	 * tracking, the uncertainties and the writing included.
	 */
	private void endToEnd(final SimulatedStack<UnsignedByteType> stack, final ParticleType type, final int cores,
		final int rounds) throws IOException
	{
		final int frames = stack.frames().size();
		final Path dir = Files.createTempDirectory("contact-tracker-bench");
		try {
			final Path tif = dir.resolve("bench.tif"), csv = dir.resolve("spots.csv");
			ImageFiles.saveTiff(TimeSeries.of("bench", stack.frames(), Calibration.ofPixelSize(type
				.pixelSizeMicrons(), "micron")), tif);
			final Path launcher = launcher();
			headings.add(String.format(Locale.ROOT, "End to end: track %s (%d frames, %.0f MB) --csv, best of %d: in " +
				"this JVM (warm, no start-up)%s", tif.getFileName(), frames, Files.size(tif) / 1e6, Math.min(rounds, 2),
				launcher == null ? "" : "; and as a user runs it, " + launcher.getFileName() + " in a new process (JVM " +
					"start-up and warm-up included)"));
			out.printf(Locale.ROOT, "%n%s%n", headings.get(1));
			out.printf(Locale.ROOT, "%-28s %10s %10s %14s %12s%n", "", "frames/s", "ms/frame", launcher == null ? "" :
				"new process/s", launcher == null ? "" : "ms/frame");
			final ByteArrayOutputStream sink = new ByteArrayOutputStream();
			final PrintStream quiet = new PrintStream(sink, true, StandardCharsets.UTF_8);
			final java.util.Map<Method, Double> newProcess = new java.util.EnumMap<>(Method.class); // new process, all cores
			for (final Method m : Method.values())
				for (final int threads : new int[] { 1, cores }) {
					final String[] args = { "track", tif.toString(), "--threshold", Numbers.fmt(type.threshold()),
						"--r-out", Numbers.fmt(type.rOut()), "--method", m.key(), "--threads", Integer.toString(threads),
						"--csv", csv.toString(), "--no-progress" };
					final double s = best(Math.min(rounds, 2), () -> {
						sink.reset();
						if (ContactTrackerCli.run(args, quiet, quiet) != 0)
							throw new IllegalStateException("track failed: " + sink.toString(StandardCharsets.UTF_8));
					});
					final String name = m.key() + " (" + threads + " thread" + (threads == 1 ? "" : "s") + ")";
					if (launcher == null) {
						out.printf(Locale.ROOT, "%-28s %10.0f %10.2f%n", name, frames / s, 1000 * s / frames);
						endToEnd.add(List.of(name, String.format(Locale.ROOT, "%.0f", frames / s), String.format(Locale.ROOT,
							"%.2f", 1000 * s / frames)));
						continue;
					}
					final String[] command = new String[args.length];
					command[0] = launcher.toString();
					System.arraycopy(args, 0, command, 1, args.length - 1);
					final double f = best(Math.min(rounds, 2), () -> runProcess(command));
					if (threads == cores) newProcess.put(m, f);
					out.printf(Locale.ROOT, "%-28s %10.0f %10.2f %14.0f %12.2f%n", name, frames / s, 1000 * s / frames,
						frames / f, 1000 * f / frames);
					endToEnd.add(List.of(name, String.format(Locale.ROOT, "%.0f", frames / s), String.format(Locale.ROOT,
						"%.2f", 1000 * s / frames), String.format(Locale.ROOT, "%.0f", frames / f), String.format(Locale.ROOT,
							"%.2f", 1000 * f / frames)));
				}
			if (launcher != null) startUp(stack, type, cores, rounds, dir, launcher, newProcess);
		}
		finally {
			try (var files = Files.list(dir)) {
				for (final Path p : (Iterable<Path>) files::iterator)
					Files.deleteIfExists(p);
			}
			Files.deleteIfExists(dir);
		}
	}

	/**
	 * What every new process pays whatever the movie's length: {@code track} on the stack's first frame alone
	 * (JVM start-up, class loading, the file's header, one frame, the CSV), so that a movie's time is about this
	 * plus its frames at the rate beyond it.
	 */
	private void startUp(final SimulatedStack<UnsignedByteType> stack, final ParticleType type, final int cores,
		final int rounds, final Path dir, final Path launcher, final java.util.Map<Method, Double> movie)
		throws IOException
	{
		final Path one = dir.resolve("one.tif");
		ImageFiles.saveTiff(TimeSeries.of("one", stack.frames().subList(0, 1), Calibration.ofPixelSize(type
			.pixelSizeMicrons(), "micron")), one);
		final int frames = stack.frames().size();
		headings.add(String.format(Locale.ROOT, "Start-up of a new process (track on 1 frame, best of %d), and the rate " +
			"beyond it on the %d frames above (new process, all cores):", Math.min(rounds, 2), frames));
		out.printf(Locale.ROOT, "%n%s%n", headings.get(2));
		for (final Method m : new Method[] { Method.PAPER, Method.FIT }) {
			final String[] command = { launcher.toString(), "track", one.toString(), "--threshold", Numbers.fmt(type
				.threshold()), "--r-out", Numbers.fmt(type.rOut()), "--method", m.key(), "--threads", Integer.toString(cores), "--csv", dir
					.resolve("one.csv").toString(), "--no-progress" };
			final double s = best(Math.min(rounds, 2), () -> runProcess(command));
			out.printf(Locale.ROOT, "%-28s %8.3f s%s%n", m.key() + " (" + cores + " threads)", s, frames > 1 ? String
				.format(Locale.ROOT, ", then %.2f ms/frame", 1000 * (movie.get(m) - s) / (frames - 1)) : "");
			startUp.add(List.of(m.key() + " (" + cores + " threads)", String.format(Locale.ROOT, "%.3f", s), frames > 1
				? String.format(Locale.ROOT, "%.2f", 1000 * (movie.get(m) - s) / (frames - 1)) : ""));
		}
	}

	/**
	 * @return the user's command, {@code scripts/contact-tracker} beside the folder of the jar this runs from (as
	 *         built by Maven in {@code target/}), or null when this does not run from such a jar
	 */
	static Path launcher() {
		try {
			final Path jar = Path.of(BenchCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
			if (!Files.isRegularFile(jar) || jar.getParent() == null || jar.getParent().getParent() == null) return null;
			final Path script = jar.getParent().getParent().resolve("scripts").resolve("contact-tracker");
			return Files.isExecutable(script) ? script : null;
		}
		catch (final java.net.URISyntaxException | SecurityException | java.nio.file.InvalidPathException e) {
			return null;
		}
	}

	/** Runs {@code command} to its end, its output discarded; fails if it does not exit with 0. */
	private static void runProcess(final String[] command) {
		try {
			final Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(
				ProcessBuilder.Redirect.DISCARD).start();
			final int code = p.waitFor();
			if (code != 0) throw new IllegalStateException(String.join(" ", command) + " exited with " + code);
		}
		catch (final IOException e) {
			throw new java.io.UncheckedIOException(e);
		}
		catch (final InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new IllegalStateException("interrupted", e);
		}
	}

	private void row(final String name, final int frames, final double mpx, final double seconds,
		final double readSeconds)
	{
		out.printf(Locale.ROOT, "%-28s %10.0f %10.0f %12.1f%n", name, frames / seconds, mpx / seconds, seconds /
			readSeconds);
		inProcess.add(List.of(name, String.format(Locale.ROOT, "%.0f", frames / seconds), String.format(Locale.ROOT,
			"%.0f", mpx / seconds), String.format(Locale.ROOT, "%.1f", seconds / readSeconds)));
	}

	/** Best wall time of {@code rounds} runs after one warm-up run. */
	private static double best(final int rounds, final Runnable job) {
		job.run();
		double best = Double.POSITIVE_INFINITY;
		for (int r = 0; r < rounds; r++) {
			final long t0 = System.nanoTime();
			job.run();
			best = Math.min(best, (System.nanoTime() - t0) * 1e-9);
		}
		return best;
	}
}
