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
package io.github.contacttracker.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.ImageSource;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackingSettings;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.real.FloatType;
import net.imglib2.type.numeric.RealType;

/** The one tracking service of every front end: checks first, then tracking, then all files or none. */
class TrackingPipelineTest {

	private static final ParticleType TYPE = PaperParticles.silica553();
	private static final Calibration CAL = Calibration.ofPixelSize(TYPE.pixelSizeMicrons(), "micron");
	private static SimulatedStack<?> stack;

	@TempDir
	Path dir;

	@BeforeAll
	static void simulate() {
		stack = SimulatedStack.simulate(TYPE, Scenario.PAIR, 1.0, 3, 5, 8);
	}

	/** The stack as a source that counts how often its frames are read. */
	private static FrameSource source(final AtomicInteger reads, final double[] range) {
		return FrameSource.of(stack.frameCount(), t -> {
			reads.incrementAndGet();
			return stack.frames().get(t);
		}, CAL, "pair", range == null ? null : t -> range);
	}

	private static SettingValues settings() {
		return SettingValues.defaults().with(TrackingSettings.THRESHOLD, TYPE.threshold()).with(TrackingSettings.R_OUT,
			TYPE.rOut()).with(TrackingSettings.METHOD, Method.PAPER.key());
	}

	private Outputs both() {
		return new Outputs(dir.resolve("spots.csv"), dir.resolve("spots.xml"), new ImageSource("pair.tif", "", stack
			.width(), stack.height(), 1, stack.frameCount()));
	}

	private List<String> files() throws IOException {
		try (Stream<Path> s = Files.list(dir)) {
			return s.map(p -> p.getFileName().toString()).sorted().toList();
		}
	}

	@Test
	void tracksEveryFrameAndWritesBothFilesWithTheSameSpots() throws IOException {
		final TrackingResult r = new TrackingPipeline(settings()).run(source(new AtomicInteger(), null), both(), 2,
			false, null, () -> false);
		assertEquals(3, r.frames().size());
		assertEquals(6, r.spots().size(), "a pair in each of three frames");
		assertEquals(List.of("spots.csv", "spots.settings.txt", "spots.xml"), files());
		final StringWriter csv = new StringWriter();
		SpotCsvWriter.write(csv, r.spots(), CAL);
		assertEquals(csv.toString(), Files.readString(dir.resolve("spots.csv")));
		assertTrue(Files.readString(dir.resolve("spots.xml")).contains("nspots=\"6\""));
		assertTrue(r.summary("pair").startsWith("6 spots in 3 frames of 'pair', 0 flagged, 0 components discarded"), r
			.summary("pair"));
	}

	@Test
	void aMissingOutputFolderIsRefusedBeforeAnyFrameIsRead() {
		final AtomicInteger reads = new AtomicInteger();
		final Outputs bad = new Outputs(dir.resolve("spots.csv"), dir.resolve("no/such/spots.xml"), both().source());
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> new TrackingPipeline(settings())
			.run(source(reads, null), bad, 1, false, null, () -> false));
		assertTrue(e.getMessage().startsWith("cannot write trackmate_xml"), e.getMessage());
		assertEquals(0, reads.get());
	}

	@Test
	void aThresholdOutsideTheDataIsRefusedBeforeAnyFrameIsReadAndNothingIsWritten() throws IOException {
		final AtomicInteger reads = new AtomicInteger();
		final InvalidInputException e = assertThrows(InvalidInputException.class, () -> new TrackingPipeline(settings())
			.run(source(reads, new double[] { 10, 60 }), both(), 1, false, null, () -> false));
		assertEquals("threshold 85 is outside the data range [10, 60] of 'pair'", e.getMessage());
		assertEquals(0, reads.get());
		assertEquals(List.of(), files());
	}

	@Test
	void aCancelledRunWritesNothing() throws IOException {
		assertThrows(CancellationException.class, () -> new TrackingPipeline(settings()).run(source(new AtomicInteger(),
			null), both(), 2, false, null, () -> true));
		assertEquals(List.of(), files());
	}

	/**
	 * When no profile can be measured over the movie (here every component is a merge whose reach covers the small
	 * frame, so no pixel is usable), the frames fall back to their own; the run says so instead of hiding it.
	 */
	@Test
	void aProfileFallbackIsReportedOnTheResult() {
		final int w = 60, h = 40;
		final List<RandomAccessibleInterval<FloatType>> frames = new java.util.ArrayList<>();
		for (int t = 0; t < 3; t++) {
			final float[] px = new float[w * h];
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++)
					for (final double cx : new double[] { 24 + t, 36 + t })
						px[y * w + x] += (float) (20 + 200 * Math.exp(-((x - cx) * (x - cx) + (y - 20.0) * (y - 20.0)) / 32));
			frames.add(ArrayImgs.floats(px, w, h));
		}
		final FrameSource merged = FrameSource.of(frames.size(), frames::get, Calibration.PIXELS, "merged", null);

		final TrackingResult r = new TrackingPipeline(SettingValues.defaults().with(TrackingSettings.THRESHOLD, 60.0)
			.with(TrackingSettings.R_OUT, 20.0)).run(merged, false);
		assertTrue(r.spots().stream().allMatch(s -> s.has(io.github.contacttracker.core.Flag.MERGED)), "every spot a merge");
		assertEquals(3, r.spots().size(), r.spots().toString());
		assertTrue(r.frames().stream().allMatch(FrameResult::ownProfile));
		assertEquals(2, r.warnings().size(), r.warnings().toString());
		assertTrue(r.summary("merged").contains("warning: the particles' profile could not be measured over the movie"),
			r.summary("merged"));
		// most spots flagged: the run says which flag, why and what to try
		assertTrue(r.warnings().get(1).startsWith("3 of 3 spots (100%) are flagged, most MERGED (3): "), r.warnings()
			.toString());
		assertTrue(r.warnings().get(1).contains("--detection image"), r.warnings().toString());
		// and a movie whose profile can be measured has no warning
		assertEquals(List.of(), new TrackingPipeline(settings().with(TrackingSettings.METHOD, Method.FIT.key())).run(
			source(new AtomicInteger(), null), false).warnings());
	}

	@Test
	void theParticleDiameterSetsRadiusAndKeepsTheActiveRadius() {
		final TrackingResult plain = new TrackingPipeline(settings()).run(source(new AtomicInteger(), null), false);
		final TrackingResult withD = new TrackingPipeline(settings().with(TrackingSettings.DIAMETER, 65.3)).run(source(
			new AtomicInteger(), null), false);
		for (int i = 0; i < plain.spots().size(); i++) {
			final Localization a = plain.spots().get(i), b = withD.spots().get(i);
			assertEquals(65.3 / 2, b.radius(), 1e-12);
			assertEquals(a.x(), b.x(), 0);
			assertEquals(Math.sqrt(a.activeArea() / Math.PI), a.radius(), 1e-12, "without a diameter: the active radius");
		}
	}
}
