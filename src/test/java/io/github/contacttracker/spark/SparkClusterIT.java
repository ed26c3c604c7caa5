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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Spark job on a real standalone cluster, not {@code local}: a Master and two Workers (one core each) started
 * from Spark's own classes on 127.0.0.1 only, the packaged {@code -spark.jar} submitted to it by Spark's own
 * {@code SparkSubmit}, its CSVs compared with the command line's byte for byte. Bounded in time: the cluster must be
 * up within 2 minutes and the job done within 5; every process is ended afterwards.
 * <p>
 * Spark's jars are those Maven resolved (target/spark-classpath.txt); a Worker starts its executors from a Spark
 * home's {@code jars} folder, so the test links them into one (target/spark-home/jars).
 */
class SparkClusterIT {

	@TempDir
	Path dir;

	private final List<Process> started = new ArrayList<>();

	@AfterEach
	void stopCluster() {
		for (final Process p : started) {
			p.descendants().forEach(ProcessHandle::destroy); // the Workers' executors
			p.destroy();
		}
		for (final Process p : started)
			try {
				if (!p.waitFor(20, TimeUnit.SECONDS)) p.destroyForcibly();
			}
			catch (final InterruptedException e) {
				Thread.currentThread().interrupt();
			}
	}

	@Test
	void submittedToAMasterAndTwoWorkersTheJarWritesTheCommandLinesCsvs() throws Exception {
		final Path target = Path.of(System.getProperty("basedir", ".")).resolve("target");
		final Path jar = SparkJarIT.jar("spark");
		final Path home = target.resolve("spark-home"), jars = home.resolve("jars");
		Files.createDirectories(jars);
		for (final String entry : Files.readString(target.resolve("spark-classpath.txt")).strip().split(
			java.io.File.pathSeparator))
		{
			final Path link = jars.resolve(Path.of(entry).getFileName());
			if (!Files.exists(link, java.nio.file.LinkOption.NOFOLLOW_LINKS)) Files.createSymbolicLink(link, Path.of(
				entry));
		}
		final Path[] movies = SparkTestMovies.movies(dir);
		final Path cliDir = Files.createDirectories(dir.resolve("cli")), sparkDir = Files.createDirectories(dir.resolve(
			"spark"));
		final Object[] c = SparkTestMovies.cli("track", movies[0].toString(), movies[1].toString(), "--out-dir", cliDir
			.toString());
		assertEquals(0, c[0], (String) c[2]);

		final int port;
		try (ServerSocket free = new ServerSocket(0)) {
			port = free.getLocalPort();
		}
		final String master = "spark://127.0.0.1:" + port;
		final Path masterLog = dir.resolve("master.log");
		start(home, masterLog, "-Xmx384m", "org.apache.spark.deploy.master.Master", "--host", "127.0.0.1", "--port",
			String.valueOf(port), "--webui-port", "0");
		for (int w = 1; w <= 2; w++)
			start(home, dir.resolve("worker" + w + ".log"), "-Xmx384m", "org.apache.spark.deploy.worker.Worker", "--host",
				"127.0.0.1", "--cores", "1", "--memory", "1g", "--webui-port", "0", "--work-dir", Files.createDirectories(
					dir.resolve("work" + w)).toString(), master);
		final long upBy = System.nanoTime() + TimeUnit.MINUTES.toNanos(2);
		while (registeredWorkers(masterLog) < 2) {
			assertTrue(System.nanoTime() < upBy, "the cluster did not come up within 2 minutes:\n" + Files.readString(
				masterLog));
			assertTrue(started.stream().allMatch(Process::isAlive), "a cluster process ended:\n" + Files.readString(
				masterLog));
			Thread.sleep(500);
		}

		final Path submitLog = dir.resolve("submit.log");
		final Process submit = start(home, submitLog, "-Xmx1g", "org.apache.spark.deploy.SparkSubmit", "--master",
			master, "--class", "io.github.contacttracker.spark.SparkTrack", "--conf", "spark.driver.host=127.0.0.1",
			"--conf", "spark.driver.bindAddress=127.0.0.1", "--conf", "spark.executor.memory=768m", jar.toString(),
			movies[0].toString(), movies[1].toString(), "--out-dir", sparkDir.toString(), "--chunk", "3");
		assertTrue(submit.waitFor(5, TimeUnit.MINUTES), "the job did not end within 5 minutes:\n" + Files.readString(
			submitLog));
		assertEquals(0, submit.exitValue(), Files.readString(submitLog));
		for (final String name : List.of("padded.csv", "pair.csv"))
			assertArrayEquals(Files.readAllBytes(cliDir.resolve(name)), Files.readAllBytes(sparkDir.resolve(name)), name);
		final String log = Files.readString(submitLog);
		for (final Path m : List.of(movies[0], movies[1])) // the summaries are the command line's, but for the time
			assertEquals(SparkTestMovies.summary((String) c[1], m.toString()), SparkTestMovies.summary(log, m.toString()));
		// the tasks ran on both Workers' executors
		int workersUsed = 0;
		for (int w = 1; w <= 2; w++)
			try (var files = Files.walk(dir.resolve("work" + w))) {
				if (files.anyMatch(p -> p.getFileName().toString().equals("stderr") && contains(p, "Finished task")))
					workersUsed++;
			}
		assertEquals(2, workersUsed, "both Workers ran tasks");
	}

	private static boolean contains(final Path file, final String text) {
		try {
			return Files.readString(file).contains(text);
		}
		catch (final IOException e) {
			return false;
		}
	}

	private static int registeredWorkers(final Path masterLog) throws IOException {
		return (int) Files.readAllLines(masterLog).stream().filter(l -> l.contains("Registering worker")).count();
	}

	/** Starts a JVM on Spark's jars (loopback only, Spark's Java 17 flags), its output into {@code log}. */
	private Process start(final Path home, final Path log, final String heap, final String... mainAndArgs)
		throws IOException
	{
		final List<String> cmd = new ArrayList<>();
		cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
		cmd.add(heap);
		for (final String o : System.getProperty("spark.java.options", "").split(" +"))
			if (!o.isEmpty()) cmd.add(o);
		cmd.add("-cp");
		cmd.add(home.resolve("jars") + "/*");
		cmd.addAll(List.of(mainAndArgs));
		final ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
		pb.environment().put("SPARK_HOME", home.toString());
		pb.environment().put("SPARK_SCALA_VERSION", "2.13");
		pb.environment().put("SPARK_LOCAL_IP", "127.0.0.1");
		final Process p = pb.start();
		started.add(p);
		return p;
	}
}
