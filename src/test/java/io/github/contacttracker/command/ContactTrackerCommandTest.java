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
package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.jdom2.Document;
import org.jdom2.input.SAXBuilder;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.app.event.StatusEvent;
import org.scijava.command.CommandInfo;
import org.scijava.command.CommandModule;
import org.scijava.command.CommandService;
import org.scijava.event.EventHandler;
import org.scijava.event.EventService;
import org.scijava.module.Module;
import org.scijava.module.ModuleService;
import org.scijava.prefs.PrefService;

import ij.ImagePlus;
import ij.ImageStack;
import ij.VirtualStack;
import ij.gui.OvalRoi;
import ij.gui.Overlay;
import ij.gui.Roi;
import ij.measure.ResultsTable;
import ij.process.ByteProcessor;
import ij.process.ColorProcessor;
import ij.process.ImageProcessor;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.io.OverlayPng;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.io.SpotColumn;
import io.github.contacttracker.io.SpotCsvWriter;

/**
 * The Contact Tracker command, headless through SciJava's {@link ModuleService} (what {@code CommandService},
 * scripts and Fiji's macro bridge use), on the simulated 5-frame stack of {@link Simulated}.
 */
class ContactTrackerCommandTest extends WithContext {

	private static final double THRESHOLD = Simulated.TYPE.threshold();
	private static final double R_OUT = Simulated.TYPE.rOut();

	/** Runs the command from the documented defaults (nothing remembered from an earlier run) */
	private static Module run(final ImagePlus imp, final Object... more) throws Exception {
		context.service(PrefService.class).clearAll();
		final List<Object> inputs = new ArrayList<>(Arrays.asList("imp", imp, "threshold", THRESHOLD, "r_out", R_OUT));
		inputs.addAll(Arrays.asList(more));
		return Simulated.run(context, ContactTrackerCommand.class, inputs.toArray());
	}

	private static TrackerParameters params() {
		return new TrackerParameters(THRESHOLD, R_OUT, TrackerParameters.DEFAULT_MIN_AREA, Connectivity.EIGHT,
			TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.DEFAULT);
	}

	/** What the core finds on the image, regions kept. */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static List<FrameResult> core(final ImagePlus imp, final int channel) {
		final List frames = ImagePlusFrames.of(imp, channel).frames();
		return new StackTracker(params()).track(frames, true);
	}

	private static void assertSucceeded(final Module m) {
		final Cancelable c = (Cancelable) m;
		assertFalse(c.isCanceled(), () -> "cancelled: " + c.getCancelReason());
	}

	/**
	 * Dark particles: the movie inverted (Edit > Invert, 255 - v) with particles = dark gives the bright movie's
	 * table; the image shown is not changed.
	 */
	@Test
	void darkParticlesGiveTheBrightMoviesTable() throws Exception {
		final ImagePlus bright = Simulated.image();
		final ResultsTable reference = (ResultsTable) run(bright, "overlay", false).getOutput("spots");
		final ImageStack stack = new ImageStack(bright.getWidth(), bright.getHeight());
		for (int t = 1; t <= Simulated.FRAMES; t++) {
			final ImageProcessor ip = bright.getStack().getProcessor(t).duplicate();
			ip.invert();
			stack.addSlice(ip);
		}
		final ImagePlus dark = new ImagePlus("dark", stack);
		dark.setCalibration(bright.getCalibration());
		final byte[] before = ((byte[]) stack.getPixels(1)).clone();
		final Module m = run(dark, "overlay", false, "particles", "dark");
		assertSucceeded(m);
		assertSameTable(reference, (ResultsTable) m.getOutput("spots"));
		assertArrayEquals(before, (byte[]) stack.getPixels(1), "the image is left as it was");
	}

	private static void assertSameTable(final ResultsTable expected, final ResultsTable actual) {
		assertArrayEquals(expected.getHeadings(), actual.getHeadings());
		assertEquals(expected.size(), actual.size());
		for (final String h : expected.getHeadings())
			for (int row = 0; row < expected.size(); row++)
				assertEquals(expected.getValue(h, row), actual.getValue(h, row), 0, h + " row " + row);
	}

	/**
	 * A virtual stack as Fiji opens it (File > Import > TIFF Virtual Stack) is tracked frame by frame, with the
	 * same spots as the stack in memory.
	 */
	@Test
	void aVirtualStackGivesTheSameSpotsAsTheStackInMemory(@TempDir final Path dir) throws Exception {
		final ImagePlus inMemory = Simulated.image();
		final Path tif = dir.resolve("movie.tif");
		io.github.contacttracker.io.ImageFiles.saveTiff(inMemory, tif);
		final ImagePlus virtual = ij.plugin.FileInfoVirtualStack.openVirtual(tif.toString());
		assertTrue(virtual.getStack().isVirtual());
		// TIFF stores the pixel size as a fraction: compare the pixels' path, not that rounding
		virtual.setCalibration(inMemory.getCalibration());
		final ResultsTable expected = (ResultsTable) run(inMemory, "overlay", false).getOutput("spots");
		final Module m = run(virtual, "overlay", false);
		assertSucceeded(m);
		assertSameTable(expected, (ResultsTable) m.getOutput("spots"));
		final ImagePlusFrames frames = ImagePlusFrames.of(virtual, 0);
		assertEquals(0, frames.reads(), "no frame is read before it is needed");
	}

	@Test
	void tableRowsAreTheCoreSpotsInCalibratedUnits(@TempDir final Path dir) throws Exception {
		final ImagePlus imp = Simulated.image();
		final Path csv = dir.resolve("spots.csv");
		final Module m = run(imp, "csv", csv.toFile());
		assertSucceeded(m);
		final ResultsTable rt = (ResultsTable) m.getOutput("spots");
		assertNotNull(rt);
		assertEquals("Contact Tracker spots: simulated pair", rt.getTitle(), "one table per image, titled by it");
		assertNull(m.getOutput("pairs"), "no pair table without pair_cutoff");
		assertTrue(m.isOutputResolved("spots"), "the command shows its table itself: SciJava must not display it");

		final Calibration cal = ImagePlusFrames.of(imp, 0).calibration();
		assertEquals(Simulated.TYPE.pixelSizeMicrons(), cal.pixelWidth(), 1e-12);
		final List<Localization> spots = StackTracker.spots(core(imp, 0));
		assertEquals(2 * Simulated.FRAMES, spots.size(), "two particles in each frame");
		assertEquals(spots.size(), rt.size(), "one row per spot");

		final SpotColumn[] columns = SpotColumn.values();
		assertEquals(columns.length, SpotTables.DISPLAY_ORDER.size());
		assertEquals(new java.util.HashSet<>(Arrays.asList(columns)), new java.util.HashSet<>(SpotTables.DISPLAY_ORDER),
			"every CSV column once");
		final List<String> keys = new ArrayList<>(SpotTables.DISPLAY_ORDER.stream().map(SpotColumn::key).toList());
		keys.add(keys.indexOf("SIGMA_Y") + 1, SpotTables.FLAGS);
		keys.add(keys.indexOf("FRAME") + 1, SpotTables.SLICE);
		assertEquals(keys, Arrays.asList(rt.getHeadings()), "the CSV's columns, the slice and the flags in words");
		assertEquals(List.of("ID", "FRAME", "SLICE", "POSITION_X", "POSITION_Y", "RADIUS", "QUALITY", "SIGMA_X",
			"SIGMA_Y", "FLAGS"), Arrays.asList(rt.getHeadings()).subList(0, 10), "where, how big and bright, how " +
				"precise, flags");
		// the 1-based slice ImageJ's slider shows, beside TrackMate's 0-based frame
		for (int id = 0; id < spots.size(); id++)
			assertEquals(rt.getValue("FRAME", id) + 1, rt.getValue(SpotTables.SLICE, id), 0);
		assertEquals("1", rt.getStringValue(SpotTables.SLICE, 0));
		for (int id = 0; id < spots.size(); id++)
			assertEquals(spots.get(id).isFlagged() ? spots.get(id).flagSet().stream().filter(f -> f.isWarning()).map(
				f -> f.description()).collect(java.util.stream.Collectors.joining("; ")) : "-", rt.getStringValue(
					SpotTables.FLAGS, id));
		// integers without decimals; whole values of real columns too, others with 4 decimals
		assertEquals(Integer.toString((int) rt.getValue("ID", 1)), rt.getStringValue("ID", 1));
		assertFalse(rt.getStringValue("POSITION_X", 0).isEmpty());
		assertEquals(4, rt.getStringValue("POSITION_X", 0).length() - rt.getStringValue("POSITION_X", 0).indexOf('.') - 1,
			rt.getStringValue("POSITION_X", 0));
		assertEquals("0", rt.getStringValue("POSITION_Z", 0), "a whole value of a real column shows no decimals");
		for (int id = 0; id < spots.size(); id++)
			for (final SpotColumn c : columns)
				assertEquals(c.value(spots.get(id), id, cal), rt.getValue(c.key(), id), 0, c.key() + " of spot " + id);

		// calibrated positions of the true centres, TrackMate's convention
		for (int id = 0; id < spots.size(); id++) {
			final int t = (int) rt.getValue("FRAME", id);
			assertEquals(t * Simulated.FRAME_INTERVAL, rt.getValue("POSITION_T", id), 1e-12);
			final double x = rt.getValue("POSITION_X", id) / cal.pixelWidth(), y = rt.getValue("POSITION_Y", id) / cal
				.pixelHeight();
			double nearest = Double.POSITIVE_INFINITY;
			for (final double[] c : Simulated.truth(t))
				nearest = Math.min(nearest, Math.hypot(c[0] - x, c[1] - y));
			assertTrue(nearest < 0.5, "spot " + id + " is " + nearest + " px from the nearest true centre");
		}

		// the CSV is the command line's, byte for byte
		final StringWriter expected = new StringWriter();
		SpotCsvWriter.write(expected, spots, cal);
		assertEquals(expected.toString(), Files.readString(csv));

		// frames in parallel give the same table
		final Module parallel = run(Simulated.image(), "threads", 3, "overlay", false);
		assertSucceeded(parallel);
		assertSameTable(rt, (ResultsTable) parallel.getOutput("spots"));
	}

	@Test
	void overlayRoisSitOnTheirFramesAndPixels() throws Exception {
		final ImagePlus imp = Simulated.image();
		final Roi mine = new OvalRoi(1, 1, 5, 5);
		imp.setOverlay(new Overlay(mine));
		assertSucceeded(run(imp));
		final List<FrameResult> results = core(imp, 0);
		final List<Localization> spots = StackTracker.spots(results);
		final List<Region> seconds = new ArrayList<>();
		for (final FrameResult r : results)
			seconds.addAll(r.secondAreas());

		Overlay overlay = imp.getOverlay();
		assertNotNull(overlay);
		assertTrue(overlay.contains(mine), "the user's own overlay elements stay");
		assertEquals(1 + 3 * spots.size(), overlay.size(), "particle circle, final cross and first-pass dot per spot");
		Map<String, Roi> byKey = byKey(overlay);
		for (int id = 0; id < spots.size(); id++) {
			final Localization s = spots.get(id);
			final Roi cross = byKey.get(id + " FINAL"), dot = byKey.get(id + " FIRST_PASS");
			final Roi particle = byKey.get(id + " PARTICLE");
			for (final Roi roi : new Roi[] { cross, dot, particle }) {
				assertNotNull(roi, "spot " + id);
				assertEquals(s.frame() + 1, roi.getPosition(), "spot " + id + " " + roi.getName() + " on its frame");
			}
			assertNull(byKey.get(id + " DISC"), "no r_out disc unless asked for");
			assertNull(byKey.get(id + " SECOND_AREA"), "no second area unless asked for");
			// ImageJ puts pixel (0,0)'s centre at (0.5, 0.5), TrackMate at (0, 0)
			assertEquals(s.x() + 0.5, cross.getFloatPolygon().xpoints[0], 1e-4);
			assertEquals(s.y() + 0.5, cross.getFloatPolygon().ypoints[0], 1e-4);
			assertEquals(s.firstX() + 0.5, dot.getFloatPolygon().xpoints[0], 1e-4);
			assertEquals(s.firstY() + 0.5, dot.getFloatPolygon().ypoints[0], 1e-4);
			// the particle: a circle of its RADIUS (px) around the final centre
			final java.awt.geom.Rectangle2D.Double b = particle.getFloatBounds();
			assertEquals(s.x() + 0.5 - s.radius(), b.x, 1e-9);
			assertEquals(s.y() + 0.5 - s.radius(), b.y, 1e-9);
			assertEquals(2 * s.radius(), b.width, 1e-9);
			assertEquals(OverlayPng.FINAL, cross.getStrokeColor());
			assertEquals(OverlayPng.FIRST_PASS, dot.getStrokeColor());
			assertEquals(SpotOverlay.flagColor(s), particle.getStrokeColor());
		}

		// the diagnostics on request: the r_out disc and the second active area's outline too
		assertSucceeded(run(imp, "r_out_circles", true));
		overlay = imp.getOverlay();
		assertEquals(1 + 5 * spots.size(), overlay.size());
		assertTrue(overlay.contains(mine));
		byKey = byKey(overlay);
		for (int id = 0; id < spots.size(); id++) {
			final Localization s = spots.get(id);
			final Roi disc = byKey.get(id + " DISC"), outline = byKey.get(id + " SECOND_AREA");
			final java.awt.geom.Rectangle2D.Double b = disc.getFloatBounds();
			assertEquals(s.firstX() + 0.5 - R_OUT, b.x, 1e-9);
			assertEquals(s.firstY() + 0.5 - R_OUT, b.y, 1e-9);
			assertEquals(2 * R_OUT, b.width, 1e-9);
			assertEquals(2 * R_OUT, b.height, 1e-9);
			assertOutlines(seconds.get(id), outline);
			assertEquals(OverlayPng.SECOND_AREA, outline.getStrokeColor());
			assertEquals(SpotOverlay.Kind.DISC.color(), disc.getStrokeColor());
			assertEquals(s.frame() + 1, disc.getPosition());
		}
	}

	private static Map<String, Roi> byKey(final Overlay overlay) {
		final Map<String, Roi> byKey = new HashMap<>();
		for (final Roi roi : overlay.toArray())
			if (SpotOverlay.kind(roi) != null) byKey.put(SpotOverlay.spotId(roi) + " " + SpotOverlay.kind(roi), roi);
		return byKey;
	}

	/** The outline covers exactly the region's pixels. */
	private static void assertOutlines(final Region region, final Roi outline) {
		for (int y = region.minY() - 1; y <= region.maxY() + 1; y++)
			for (int x = region.minX() - 1; x <= region.maxX() + 1; x++)
				assertEquals(region.contains(x, y), outline.containsPoint(x + 0.5, y + 0.5), "pixel " + x + "," + y);
	}

	@Test
	void hyperstackChannelAndPlainStack() throws Exception {
		final ImagePlus single = Simulated.image();
		final ResultsTable reference = (ResultsTable) run(single, "overlay", false).getOutput("spots");

		// two channels, the particles in channel 2: ROIs get hyperstack positions (every channel, frame t)
		final ImageStack stack = new ImageStack(single.getWidth(), single.getHeight());
		for (int t = 1; t <= Simulated.FRAMES; t++) {
			stack.addSlice(new ByteProcessor(single.getWidth(), single.getHeight()));
			stack.addSlice(single.getStack().getProcessor(t));
		}
		final ImagePlus twoChannels = new ImagePlus("two channels", stack);
		twoChannels.setDimensions(2, 1, Simulated.FRAMES);
		twoChannels.setOpenAsHyperStack(true);
		twoChannels.setCalibration(single.getCalibration());
		final Module m = run(twoChannels, "channel", 2);
		assertSucceeded(m);
		assertSameTable(reference, (ResultsTable) m.getOutput("spots"));
		for (final Roi roi : twoChannels.getOverlay().toArray()) {
			final int id = SpotOverlay.spotId(roi);
			assertEquals(0, roi.getCPosition(), "drawn on every channel");
			assertEquals((int) reference.getValue("FRAME", id) + 1, roi.getTPosition());
		}

		// a plain stack of 5 slices is a time series of 5 frames
		final ImagePlus plain = new ImagePlus("plain", single.getStack());
		plain.setCalibration(single.getCalibration());
		assertEquals(Simulated.FRAMES, plain.getNSlices());
		final Module p = run(plain);
		assertSucceeded(p);
		final ResultsTable rt = (ResultsTable) p.getOutput("spots");
		assertArrayEquals(reference.getColumn("FRAME"), rt.getColumn("FRAME"));
		assertArrayEquals(reference.getColumn("POSITION_X"), rt.getColumn("POSITION_X"));
		for (final Roi roi : plain.getOverlay().toArray())
			assertEquals((int) rt.getValue("FRAME", SpotOverlay.spotId(roi)) + 1, roi.getPosition());
	}

	@Test
	void stringValuesConvertAsAMacroPassesThem() throws Exception {
		final ImagePlus imp = Simulated.image();
		final ResultsTable numeric = (ResultsTable) run(Simulated.image(), "overlay", false).getOutput("spots");
		final Module m = Simulated.run(context, ContactTrackerCommand.class, "imp", imp, "threshold", Double.toString(
			THRESHOLD), "r_out", Double.toString(R_OUT), "min_area", "20", "min_second_area", "50", "connectivity", "8",
			"method", Method.DEFAULT.name(), "channel", "1", "pair_cutoff", "0", "threads", "2", "overlay", "false", "table", "false");
		assertSucceeded(m);
		assertSameTable(numeric, (ResultsTable) m.getOutput("spots"));
		assertNull(imp.getOverlay(), "overlay=false leaves the image alone");

		// and they do reach the core: first-pass centres differ from the paper's
		final Module first = Simulated.run(context, ContactTrackerCommand.class, "imp", Simulated.image(), "threshold",
			Double.toString(THRESHOLD), "r_out", Double.toString(R_OUT), "method", "first", "overlay", "false");
		assertSucceeded(first);
		final ResultsTable f = (ResultsTable) first.getOutput("spots");
		assertArrayEquals(f.getColumn("FIRST_PASS_X"), f.getColumn("POSITION_X"));
		assertEquals(1, f.getValue("ITERATIONS", 0));
	}

	@Test
	void commandServiceReturnsTheModuleAndItsOutputs() throws Exception {
		// what scripts do (see scripts/contact-tracker-batch.groovy)
		final CommandModule m = context.service(CommandService.class).run(ContactTrackerCommand.class, true, "imp",
			Simulated.image(), "threshold", THRESHOLD, "r_out", R_OUT, "table", false).get();
		assertSucceeded(m);
		assertEquals(2 * Simulated.FRAMES, ((ResultsTable) m.getOutput("spots")).size());
	}

	static Stream<Arguments> badInputs() {
		return Stream.of(
			Arguments.of(new ImagePlus("rgb", new ColorProcessor(32, 32)), new Object[] { "channel", 4 },
				"channel 4 does not exist: 'rgb' has 3 channels"),
			Arguments.of(Simulated.zAndT("zt"), new Object[0],
				"'zt' has 2 Z slices and 2 time frames: the method is 2D; make a projection or pick one slice first"),
			Arguments.of(Simulated.image(), new Object[] { "r_out", 0.0 }, "r_out must be a positive number of pixels, not 0.0"),
			Arguments.of(Simulated.image(), new Object[] { "r_out", "-3" }, "r_out must be a positive number of pixels, not -3.0"),
			Arguments.of(Simulated.image(), new Object[] { "method", "best" }, "method must be one of " + methodKeys() +
				", not 'best'"),
			Arguments.of(Simulated.image(), new Object[] { "connectivity", "6" }, "connectivity must be one of 8, 4, not 6"),
			Arguments.of(Simulated.image(), new Object[] { "channel", 2 },
				"channel 2 does not exist: 'simulated pair' has 1 channel"),
			Arguments.of(Simulated.image(), new Object[] { "threshold", 1000.0 }, "threshold 1000 is outside the data range"),
			Arguments.of(Simulated.image(), new Object[] { "min_area", 0 }, "min_area must be at least 1 pixel, not 0"),
			Arguments.of(Simulated.image(), new Object[] { "csv", new java.io.File("/no/such/folder/x.csv") },
				"cannot write csv /no/such/folder/x.csv: folder /no/such/folder does not exist"),
			Arguments.of(null, new Object[0], "'imp' is required but unset"),
			// a movie on disk whose second frame cannot be read, or does not fit: named, no stack trace
			Arguments.of(failingOnFrame2(new UncheckedIOException(new IOException("cannot read plane 2 of " +
				"/data/broken.tif: truncated TIFF"))), new Object[0], "frame 2: cannot read plane 2 of " +
					"/data/broken.tif: truncated TIFF"),
			Arguments.of(failingOnFrame2(new OutOfMemoryError("Java heap space")), new Object[0],
				"out of memory (Java heap space): give Fiji more with Edit > Options > Memory & Threads"));
	}

	/** @return the simulated movie as a virtual stack whose frame 2 fails with {@code failure} when it is read */
	private static ImagePlus failingOnFrame2(final Throwable failure) {
		final ImagePlus movie = Simulated.image();
		final ImageStack frames = movie.getStack();
		final VirtualStack disk = new VirtualStack(frames.getWidth(), frames.getHeight(), null, "/data") {

			@Override
			public ImageProcessor getProcessor(final int n) {
				if (n == 2 && failure instanceof Error error) throw error;
				if (n == 2) throw (RuntimeException) failure;
				return frames.getProcessor(n);
			}

			@Override
			public int getSize() {
				return frames.getSize();
			}
		};
		final ImagePlus imp = new ImagePlus("broken.tif", disk);
		imp.setCalibration(movie.getCalibration());
		imp.setDimensions(1, 1, frames.getSize());
		return imp;
	}

	/** @return every method's key, as Method.parse lists them */
	private static String methodKeys() {
		final List<String> keys = new ArrayList<>();
		for (final Method m : Method.values())
			keys.add(m.key());
		return String.join(", ", keys);
	}

	@ParameterizedTest
	@MethodSource("badInputs")
	void badInputsCancelWithAClearMessage(final ImagePlus imp, final Object[] more, final String message)
		throws Exception
	{
		final Module m = run(imp, more);
		final Cancelable c = (Cancelable) m;
		assertTrue(c.isCanceled(), "should have been refused");
		assertNotNull(c.getCancelReason());
		assertTrue(c.getCancelReason().startsWith(message), () -> "reason: " + c.getCancelReason());
		assertFalse(c.getCancelReason().contains("\n"), "one line");
		assertFalse(c.getCancelReason().contains("Exception"), "no stack trace or exception name");
		assertNull(m.getOutput("spots"));
		if (imp != null) assertNull(imp.getOverlay());
	}

	@Test
	void pairTableListsCloseSpotsOfEachFrameInCalibratedUnits() throws Exception {
		final double pw = Simulated.TYPE.pixelSizeMicrons();
		final double cutoff = 1.2 * Simulated.SEPARATION * Simulated.TYPE.diameterPx() * pw;
		final Module m = run(Simulated.image(), "pair_cutoff", cutoff, "overlay", false);
		assertSucceeded(m);
		final ResultsTable spots = (ResultsTable) m.getOutput("spots");
		final ResultsTable pairs = (ResultsTable) m.getOutput("pairs");
		assertEquals(SpotTables.PAIRS_TITLE + ": simulated pair", pairs.getTitle());
		assertEquals(Simulated.FRAMES, pairs.size(), "the pair of each frame");
		for (int row = 0; row < pairs.size(); row++) {
			final int a = (int) pairs.getValue("SPOT_A", row), b = (int) pairs.getValue("SPOT_B", row);
			assertEquals(row, (int) pairs.getValue("FRAME", row));
			assertEquals(row, (int) spots.getValue("FRAME", a));
			assertEquals(row, (int) spots.getValue("FRAME", b));
			final double d = Math.hypot(spots.getValue("POSITION_X", a) - spots.getValue("POSITION_X", b), spots
				.getValue("POSITION_Y", a) - spots.getValue("POSITION_Y", b));
			assertEquals(d, pairs.getValue("DISTANCE", row), 1e-9);
			assertEquals(Simulated.SEPARATION * Simulated.TYPE.diameterPx() * pw, d, 0.1 * pw, "true distance");
		}
		// a cutoff below the pair distance lists none
		final Module none = run(Simulated.image(), "pair_cutoff", 0.5 * cutoff, "overlay", false);
		assertEquals(0, ((ResultsTable) none.getOutput("pairs")).size());
	}

	@Test
	void trackMateXmlIsWrittenWhenAsked(@TempDir final Path dir) throws Exception {
		final Path xml = dir.resolve("spots.xml");
		final Module m = run(Simulated.image(), "trackmate_xml", xml.toFile(), "overlay", false);
		assertSucceeded(m);
		final Document doc = new SAXBuilder().build(xml.toFile());
		assertEquals("TrackMate", doc.getRootElement().getName());
		assertEquals(Integer.toString(((ResultsTable) m.getOutput("spots")).size()), doc.getRootElement().getChild(
			"Model").getChild("AllSpots").getAttributeValue("nspots"));
	}

	/** Cancels the module it watches at its first progress report (SciJava delivers status events later). */
	public static final class CancelAtFirstFrame {
		final AtomicInteger reports = new AtomicInteger();
		volatile Cancelable module;

		@EventHandler
		public void onEvent(final StatusEvent e) {
			if (e.getProgressMaximum() > 0 && e.getProgressValue() >= 1 && module != null && reports
				.getAndIncrement() == 0) module.cancel("stop");
		}
	}

	@Test
	void canBeCancelledBetweenFrames() throws Exception {
		// a long movie (the 5 frames over and over, sharing their pixels) so that the cancel arrives in time
		final int frames = 60;
		final ImagePlus five = Simulated.image();
		final ImageStack stack = new ImageStack(five.getWidth(), five.getHeight());
		for (int t = 0; t < frames; t++)
			stack.addSlice(five.getStack().getProcessor(1 + t % Simulated.FRAMES));
		final ImagePlus imp = new ImagePlus("long", stack);
		imp.setDimensions(1, 1, frames);

		final CommandInfo info = context.service(CommandService.class).getCommand(ContactTrackerCommand.class);
		final ModuleService modules = context.service(ModuleService.class);
		final Module module = modules.createModule(info);
		final CancelAtFirstFrame watcher = new CancelAtFirstFrame();
		watcher.module = (Cancelable) module;
		final EventService events = context.service(EventService.class);
		final List<org.scijava.event.EventSubscriber<?>> subscribers = events.subscribe(watcher);
		final Module m;
		try {
			m = modules.run(module, true, "imp", imp, "threshold", THRESHOLD, "r_out", R_OUT, "threads", 1).get();
		}
		finally {
			events.unsubscribe(subscribers);
		}
		assertSame(module, m);
		final String reason = ((Cancelable) m).getCancelReason();
		assertTrue(((Cancelable) m).isCanceled());
		final java.util.regex.Matcher done = java.util.regex.Pattern.compile("cancelled after (\\d+) of (\\d+) passes " +
			"over a frame").matcher(reason);
		assertTrue(done.matches(), reason);
		assertTrue(Integer.parseInt(done.group(1)) < Integer.parseInt(done.group(2)), reason);
		assertTrue(Integer.parseInt(done.group(2)) >= frames, reason);
		assertNull(m.getOutput("spots"));
		assertNull(imp.getOverlay());

		// cancelled before it starts: nothing is done, the first reason stays
		final Module early = modules.createModule(info);
		((Cancelable) early).cancel("user");
		final ImagePlus untouched = Simulated.image();
		modules.run(early, true, "imp", untouched, "threshold", THRESHOLD, "r_out", R_OUT).get();
		assertTrue(((Cancelable) early).isCanceled());
		assertEquals("user", ((Cancelable) early).getCancelReason());
		assertNull(early.getOutput("spots"));
		assertNull(untouched.getOverlay());
	}

	@Test
	void menuPathsAndParameters() throws Exception {
		final CommandService commands = context.service(CommandService.class);
		assertEquals("Plugins > Tracking > Contact Tracker", commands.getCommand(ContactTrackerCommand.class)
			.getMenuPath().getMenuString());
		assertEquals("Plugins > Tracking > Contact Tracker Profile", commands.getCommand(
			ContactTrackerProfileCommand.class).getMenuPath().getMenuString());
		assertTrue(commands.getCommand(ContactTrackerCommand.class).canRunHeadless());

		final Module m = context.service(ModuleService.class).createModule(commands.getCommand(
			ContactTrackerCommand.class));
		// the dialog remembers its values like Fiji's, except the image and the output files (and the measure
		// button, which has no value, and the Preview box, so that opening the dialog never starts tracking)
		final List<String> notRemembered = List.of("imp", "csv", "trackmate_xml", "measure", "preview", "header",
			"help", "origin", "preview_note");
		m.getInfo().inputs().forEach(item -> {
			if (!org.scijava.service.Service.class.isAssignableFrom(item.getType()) && item.getType() != Context.class)
				assertEquals(!notRemembered.contains(item.getName()), item.isPersisted(), item.getName());
		});
		// method is a choice list of every method, in Method's order
		assertEquals(methodKeys(), String.join(", ", m.getInfo().getInput("method", String.class).getChoices()));
		assertEquals(List.of("spots", "pairs", "none"), m.getInfo().getInput("results", String.class).getChoices());
		// lengths show the helper's 0.01 px (a measured diameter of 34.06 px showed as 34.1 in the real dialog)
		for (final String length : List.of("r_out", "diameter")) {
			final String format = org.scijava.widget.WidgetStyle.getStyleModifier(m.getInfo().getInput(length)
				.getWidgetStyle(), "format");
			assertEquals("34.06", new java.text.DecimalFormat(format, java.text.DecimalFormatSymbols.getInstance(
				java.util.Locale.ROOT)).format(34.06), length);
			assertEquals("43.0", new java.text.DecimalFormat(format, java.text.DecimalFormatSymbols.getInstance(
				java.util.Locale.ROOT)).format(43), length);
		}
	}

	@Test
	void flaggedSpotsStandOutInTheirFlagsColour() {
		final Localization ok = new Localization(0, 10, 10, 10, 10, 50, 50, 1, 4, 0, 2, 0.01, 0.01, Double.NaN,
			Double.NaN, 0);
		final Localization fellBack = new Localization(0, 30, 10, 30.5, 10, 50, 10, 1, 4,
			io.github.contacttracker.core.Flag.FELL_BACK.bit(), 1, 0.01, 0.01, Double.NaN, Double.NaN, 0);
		final Localization merged = new Localization(0, 50, 10, 50, 10, 50, 10, 1, 4,
			io.github.contacttracker.core.Flag.MERGED.bit() | io.github.contacttracker.core.Flag.AT_BORDER.bit(), 1, 0.01,
			0.01, Double.NaN, Double.NaN, 0);
		final List<Roi> rois = SpotOverlay.rois(List.of(new FrameResult(List.of(ok, fellBack, merged), List.of(), List
			.of(), 1, 0, false)), 8, 0, false, (roi, frame) -> {});
		assertEquals(9, rois.size());
		final Roi okCircle = rois.get(0), fellBackCircle = rois.get(3), mergedCircle = rois.get(6);
		assertEquals(SpotOverlay.Kind.PARTICLE, SpotOverlay.kind(fellBackCircle));
		assertEquals(OverlayPng.DISC, okCircle.getStrokeColor());
		assertEquals(Color.WHITE, fellBackCircle.getStrokeColor(), "each flag its colour");
		assertEquals(Color.MAGENTA, mergedCircle.getStrokeColor(), "merged wins over at border");
		assertEquals(2 * 4, okCircle.getFloatBounds().width, 1e-12, "the particle's RADIUS (4 px), not r_out (8)");
		// with a diameter given, the circle is the particle's (RADIUS = D/2, as in the table), not its active area's
		assertEquals(17, SpotOverlay.rois(List.of(new FrameResult(List.of(ok), List.of(), List.of(), 1, 0, false)), 8,
			17, false, (roi, frame) -> {}).get(0).getFloatBounds().width, 1e-12);
		// the final cross comes after (is drawn over) the first-pass dot: the result stays visible
		assertEquals(SpotOverlay.Kind.FIRST_PASS, SpotOverlay.kind(rois.get(1)));
		assertEquals(SpotOverlay.Kind.FINAL, SpotOverlay.kind(rois.get(2)));
		assertTrue(((ij.gui.PointRoi) rois.get(1)).getSize() < ((ij.gui.PointRoi) rois.get(2)).getSize());
		// the legend window's picture: every mark in its colour, one row each, flags included
		final ij.process.ColorProcessor picture = OverlayLegend.picture(false);
		final java.util.Set<Integer> colours = new java.util.HashSet<>();
		for (final int p : (int[]) picture.getPixels())
			colours.add(p & 0xffffff);
		for (final OverlayLegend.Row row : OverlayLegend.rows(false))
			assertTrue(colours.contains(row.color().getRGB() & 0xffffff), row.text());
		assertEquals(3 + SpotOverlay.flagColors().size(), OverlayLegend.rows(false).size());
		assertEquals(OverlayLegend.rows(false).size() + 2, OverlayLegend.rows(true).size());
		assertTrue(picture.getHeight() >= OverlayLegend.rows(false).size() * OverlayLegend.ROW);
		assertTrue(fellBackCircle.getStrokeWidth() > okCircle.getStrokeWidth());
		assertTrue(fellBackCircle.getName().contains("fell back to first pass"), fellBackCircle.getName());
		assertTrue(mergedCircle.getName().contains("suspected merge, touches border") || mergedCircle.getName().contains(
			"touches border, suspected merge"), mergedCircle.getName());
		// the legend names each flag's colour, in short lines
		final List<String> legend = SpotOverlay.legend(false);
		final String words = String.join(" ", legend).replaceAll(" +", " ");
		assertTrue(words.contains("magenta = suspected merge"), legend.toString());
		assertTrue(words.contains("white = fell back to first pass"), legend.toString());
		for (final String line : legend)
			assertTrue(line.length() <= ShownFrameProfile.LOG_WIDTH, line);
	}

	@Test
	void systemResultsTableGetsTheSpotsOrThePairsOrIsLeftAlone() throws Exception {
		final Module m = run(Simulated.image(), "overlay", false);
		assertSucceeded(m);
		final ResultsTable system = ResultsTable.getResultsTable();
		assertSameTable((ResultsTable) m.getOutput("spots"), system);
		assertEquals(2 * Simulated.FRAMES, system.size(), "what a macro's nResults reads");

		final double cutoff = 1.2 * Simulated.SEPARATION * Simulated.TYPE.diameterPx() * Simulated.TYPE
			.pixelSizeMicrons();
		final Module pairs = run(Simulated.image(), "overlay", false, "pair_cutoff", cutoff, "results", "pairs");
		assertSucceeded(pairs);
		assertSameTable((ResultsTable) pairs.getOutput("pairs"), ResultsTable.getResultsTable());
		assertEquals(Simulated.FRAMES, ResultsTable.getResultsTable().size(), "one pair per frame");

		ResultsTable.getResultsTable().reset();
		ResultsTable.getResultsTable().incrementCounter();
		ResultsTable.getResultsTable().addValue("Mine", 42);
		assertSucceeded(run(Simulated.image(), "overlay", false, "results", "none"));
		assertEquals(42, ResultsTable.getResultsTable().getValue("Mine", 0), "results=none leaves it alone");

		final Module refused = run(Simulated.image(), "results", "pairs");
		assertTrue(((Cancelable) refused).isCanceled());
		assertTrue(((Cancelable) refused).getCancelReason().startsWith("results=pairs needs pair_cutoff > 0"));
		assertEquals(42, ResultsTable.getResultsTable().getValue("Mine", 0), "a refused run changes nothing");
	}

	@Test
	void diameterGivesTheRadiusAndTheActiveAreaKeepsItsOwn() throws Exception {
		final double px = Simulated.TYPE.pixelSizeMicrons();
		final ResultsTable plain = (ResultsTable) run(Simulated.image(), "overlay", false).getOutput("spots");
		final ResultsTable sized = (ResultsTable) run(Simulated.image(), "overlay", false, "diameter", 65.0).getOutput(
			"spots");
		for (int id = 0; id < plain.size(); id++) {
			final double active = Math.sqrt(plain.getValue("ACTIVE_AREA", id) / Math.PI) * px;
			assertEquals(active, plain.getValue("ACTIVE_RADIUS", id), 1e-12);
			assertEquals(active, plain.getValue("RADIUS", id), 1e-12, "without a diameter: the active area's");
			assertEquals(32.5 * px, sized.getValue("RADIUS", id), 1e-12, "half the diameter, calibrated");
			assertEquals(active, sized.getValue("ACTIVE_RADIUS", id), 1e-12);
			assertEquals(plain.getValue("POSITION_X", id), sized.getValue("POSITION_X", id), 0);
		}
		final Module bad = run(Simulated.image(), "diameter", -1.0);
		assertTrue(((Cancelable) bad).getCancelReason().startsWith("diameter must be a number of pixels >= 0"));
	}

	@Test
	void dialogValuesAreRememberedButRefusedOnesAreNot() throws Exception {
		final CommandInfo info = context.service(CommandService.class).getCommand(ContactTrackerCommand.class);
		final ModuleService modules = context.service(ModuleService.class);
		// a run given r_out and min_area: the next run, not given them, starts from them (as Fiji's dialog does)
		assertSucceeded(run(Simulated.image(), "min_area", 25, "overlay", false)); // from the defaults
		final Module next = modules.run(info, true, "imp", Simulated.image(), "threshold", THRESHOLD, "overlay", false)
			.get();
		assertSucceeded(next);
		assertEquals(R_OUT, (Double) next.getInput("r_out"), 0);
		assertEquals(25, next.getInput("min_area"));
		// a refused value is not remembered
		assertTrue(((Cancelable) modules.run(info, true, "imp", Simulated.image(), "min_area", 0).get()).isCanceled());
		final Module after = modules.run(info, true, "imp", Simulated.image(), "threshold", THRESHOLD, "overlay",
			false).get();
		assertEquals(25, after.getInput("min_area"));
	}

	/**
	 * A refused value of one of the command's own inputs is set back on that input, by its name: the next run gets
	 * the value remembered before it, for each of two inputs refused in turn, and the other input is left as it was.
	 */
	@Test
	void aRefusedOwnInputIsSetBackByItsName() throws Exception {
		final CommandInfo info = context.service(CommandService.class).getCommand(ContactTrackerCommand.class);
		final ModuleService modules = context.service(ModuleService.class);
		assertSucceeded(run(Simulated.image(), "pair_cutoff", 3.5, "threads", 2, "overlay", false));
		final Object[][] refusals = { { ContactTrackerCommand.THREADS, -1, "threads must be >= 0" }, {
			ContactTrackerCommand.PAIR_CUTOFF, -1.0, "pair_cutoff must be a distance >= 0" } };
		for (final Object[] refusal : refusals) {
			final Module refused = modules.run(info, true, "imp", Simulated.image(), "threshold", THRESHOLD, "r_out",
				R_OUT, refusal[0], refusal[1], "overlay", false).get();
			assertTrue(((Cancelable) refused).isCanceled(), () -> refusal[0] + " " + refusal[1]);
			assertTrue(((Cancelable) refused).getCancelReason().startsWith((String) refusal[2]), () -> "reason: " +
				((Cancelable) refused).getCancelReason());
			final Module next = modules.run(info, true, "imp", Simulated.image(), "threshold", THRESHOLD, "r_out", R_OUT,
				"overlay", false).get();
			assertSucceeded(next);
			assertEquals(2, next.getInput(ContactTrackerCommand.THREADS), () -> "after refusing " + refusal[0]);
			assertEquals(3.5, (Double) next.getInput(ContactTrackerCommand.PAIR_CUTOFF), 0, () -> "after refusing " +
				refusal[0]);
		}
	}

	/**
	 * The dialog's two message rows: where its values come from, and what the preview does, with its spot count,
	 * inside the dialog (not only in the status bar).
	 */
	@Test
	void theDialogSaysWhereItsValuesComeFromAndWhatThePreviewFound() throws Exception {
		ij.Prefs.set(ValuesOrigin.MEASURED, null);
		ij.Prefs.set(ValuesOrigin.RUN, null);
		final ImagePlus imp = Simulated.image();
		imp.setT(2);
		final Module m = context.service(ModuleService.class).createModule(context.service(CommandService.class)
			.getCommand(ContactTrackerCommand.class));
		m.setInput("imp", imp);
		final ContactTrackerCommand command = (ContactTrackerCommand) m.getDelegateObject();
		m.preview();
		command.awaitPreview();
		assertTrue(command.notes()[0].contains("the defaults"), command.notes()[0]);
		assertEquals(ContactTrackerCommand.PREVIEW_OFF, command.notes()[1]);

		m.setInput("threshold", THRESHOLD);
		m.setInput("r_out", R_OUT);
		m.setInput("preview", true);
		m.preview();
		command.awaitPreview();
		assertTrue(command.notes()[0].contains("as set by hand"), command.notes()[0]);
		assertTrue(command.notes()[1].matches("<html>Preview: 2 spots on frame 2 \\(\\d+\\.\\d s\\)</html>"),
			command.notes()[1]);

		// values measured on another image are said to be so, in the dialog opened on this one
		ValuesOrigin.measured(new ValuesOrigin.Values("other.avi", THRESHOLD, R_OUT, 0));
		m.preview();
		command.awaitPreview();
		assertTrue(command.notes()[0].contains("measured on 'other.avi', <b>another image: press Measure"), command
			.notes()[0]);
		ValuesOrigin.measured(new ValuesOrigin.Values(imp.getTitle(), THRESHOLD, R_OUT, 0));
		m.preview();
		command.awaitPreview();
		assertEquals("<html>Values: measured on this image</html>", command.notes()[0]);
		// invalid values: the preview says why it did not run
		m.setInput("r_out", -1.0);
		m.preview();
		assertTrue(command.notes()[1].startsWith("<html>Preview: not run, "), command.notes()[1]);
		command.cancel();
		ij.Prefs.set(ValuesOrigin.MEASURED, null);
	}

	/** The origin's words for each case, from the values alone. */
	@Test
	void valuesOriginInWords() {
		final ValuesOrigin.Values defaults = new ValuesOrigin.Values("a.avi", 100, 20, 0), mine = new ValuesOrigin.Values(
			"a.avi", 186, 43, 34.06), theirs = new ValuesOrigin.Values("b.avi", 186, 43, 34.06);
		assertTrue(ValuesOrigin.describe(defaults, defaults, theirs, theirs).contains("the defaults"));
		assertTrue(ValuesOrigin.describe(mine, defaults, mine, null).contains("measured on this image"));
		assertTrue(ValuesOrigin.describe(mine, defaults, theirs, null).contains("measured on 'b.avi', <b>another image"));
		assertTrue(ValuesOrigin.describe(mine, defaults, null, theirs).contains("from the last run, on 'b.avi', " +
			"<b>another image"));
		assertTrue(ValuesOrigin.describe(mine, defaults, null, mine).contains("as in the last run on this image"));
		assertTrue(ValuesOrigin.describe(mine, defaults, null, null).contains("as set by hand"));
	}

	@Test
	void previewShowsTheCurrentFrameAndCancelPutsTheOverlayBack() throws Exception {
		final ImagePlus imp = Simulated.image();
		final Roi mine = new OvalRoi(1, 1, 5, 5);
		imp.setOverlay(new Overlay(mine));
		imp.setT(3);
		final Module m = context.service(ModuleService.class).createModule(context.service(CommandService.class)
			.getCommand(ContactTrackerCommand.class));
		m.setInput("imp", imp);
		m.setInput("threshold", THRESHOLD);
		m.setInput("r_out", R_OUT);
		final ContactTrackerCommand command = (ContactTrackerCommand) m.getDelegateObject();
		// the dialog calls preview() when it opens: with the box off by default, nothing is tracked
		assertEquals(false, m.getInput("preview"));
		m.preview();
		command.awaitPreview();
		assertEquals(1, imp.getOverlay().size(), "no preview before the box is ticked");
		m.setInput("preview", true);
		m.setInput("r_out_circles", true);
		m.preview();
		command.awaitPreview();
		final List<Roi> ours = new ArrayList<>();
		for (final Roi roi : imp.getOverlay().toArray())
			if (SpotOverlay.kind(roi) != null) ours.add(roi);
		assertEquals(5 * 2, ours.size(), "the two spots of the current frame, with their discs");
		for (final Roi roi : ours)
			assertEquals(3, roi.getPosition(), "on the frame shown");
		// what the core finds on that frame alone (methods that measure the profile measure it on this frame)
		@SuppressWarnings({ "unchecked", "rawtypes" })
		final List frames = ImagePlusFrames.of(imp, 0).frames().subList(2, 3);
		final List<Localization> frame3 = ((List<FrameResult>) new StackTracker(params()).track(frames, false)).get(0)
			.spots();
		final Roi cross = ours.stream().filter(r -> SpotOverlay.kind(r) == SpotOverlay.Kind.FINAL).findFirst().get();
		assertEquals(frame3.get(0).x() + 0.5, cross.getFloatPolygon().xpoints[0], 1e-4, "the run's centre");

		// r_out edited: the discs follow; an invalid value keeps the last preview
		m.setInput("r_out", R_OUT + 5);
		m.preview();
		command.awaitPreview();
		final Roi disc = Arrays.stream(imp.getOverlay().toArray()).filter(r -> SpotOverlay.kind(r) == SpotOverlay.Kind.DISC)
			.findFirst().get();
		assertEquals(2 * (R_OUT + 5), disc.getFloatBounds().width, 1e-9);
		m.setInput("r_out", -1.0);
		m.preview();
		command.awaitPreview();
		assertEquals(1 + 10, imp.getOverlay().size());
		// a newer value abandons a preview still computing: only the latest values are ever shown
		m.setInput("r_out", R_OUT + 9);
		m.preview();
		m.setInput("r_out", R_OUT + 2);
		m.preview();
		command.awaitPreview();
		assertEquals(2 * (R_OUT + 2), Arrays.stream(imp.getOverlay().toArray()).filter(r -> SpotOverlay.kind(
			r) == SpotOverlay.Kind.DISC).findFirst().get().getFloatBounds().width, 1e-9);
		// unticking the box takes the preview off
		m.setInput("preview", false);
		m.preview();
		assertEquals(1, imp.getOverlay().size());
		m.setInput("preview", true);
		m.preview();
		command.awaitPreview();
		assertEquals(1 + 10, imp.getOverlay().size());

		m.cancel(); // the dialog's Cancel
		assertEquals(1, imp.getOverlay().size());
		assertTrue(imp.getOverlay().contains(mine));
	}

	/**
	 * An area selection (a rectangle drawn to leave out a timestamp burned into a corner, say): only its bounding
	 * rectangle is tracked, as TrackMate detects within it. The particle wholly inside keeps its place (in the
	 * image's coordinates) to within its error; one the selection's edge cuts is flagged AT_BORDER, as at the frame's
	 * edge; the others are not tracked; the Log says so. A line selection changes nothing.
	 */
	@Test
	@SuppressWarnings({ "unchecked", "rawtypes" })
	void anAreaSelectionIsTrackedWithin() throws Exception {
		// particles (D = 20 px) at (40, 40), (160, 40), (40, 160), a pair about (130, 130)
		final ImagePlus imp = io.github.contacttracker.io.ProfileScenes.particles("scene", 1, Calibration.PIXELS);
		final io.github.contacttracker.advisor.ProfileAnalysis.Result r = io.github.contacttracker.advisor.ProfileAnalysis
			.analyse((net.imglib2.RandomAccessibleInterval) ImagePlusFrames.of(imp, 1).frame(0), 0, 0);
		final Object[] inputs = { "imp", imp, "threshold", r.suggestedThreshold(true), "r_out", r.suggestedROut(),
			"diameter", r.suggestedDiameter(), "overlay", false };
		final ResultsTable whole = (ResultsTable) Simulated.run(context, ContactTrackerCommand.class, inputs).getOutput(
			"spots");
		assertEquals(5, whole.size());
		imp.setRoi(new ij.gui.Line(0, 0, 100, 100));
		assertSameTable(whole, (ResultsTable) Simulated.run(context, ContactTrackerCommand.class, inputs).getOutput(
			"spots"));

		imp.setRoi(new Roi(0, 0, 100, 165)); // (40, 40) inside; (40, 160) cut by the bottom edge, y 164
		final java.io.PrintStream out = System.out;
		final java.io.ByteArrayOutputStream printed = new java.io.ByteArrayOutputStream();
		System.setOut(new java.io.PrintStream(printed, true, java.nio.charset.StandardCharsets.UTF_8));
		final Module m;
		try {
			m = Simulated.run(context, ContactTrackerCommand.class, inputs);
		}
		finally {
			System.setOut(out);
		}
		assertSucceeded(m);
		final ResultsTable within = (ResultsTable) m.getOutput("spots");
		assertEquals(2, within.size(), "the particle inside and the one cut by the edge");
		final int inside = within.getValue("POSITION_Y", 0) < 100 ? 0 : 1, cut = 1 - inside;
		int same = -1;
		for (int row = 0; row < whole.size(); row++)
			if (Math.hypot(whole.getValue("POSITION_X", row) - 40, whole.getValue("POSITION_Y", row) - 40) < 3) same = row;
		for (final String c : new String[] { "POSITION_X", "POSITION_Y" })
			assertEquals(whole.getValue(c, same), within.getValue(c, inside), 3 * whole.getValue("SIGMA_X", same), c +
				": the image's coordinates, the same place");
		assertEquals(0, within.getValue("FLAG_AT_BORDER", inside));
		assertEquals(1, within.getValue("FLAG_AT_BORDER", cut), "cut by the selection's edge");
		assertEquals(40, within.getValue("POSITION_X", cut), 1);
		final String log = printed.toString(java.nio.charset.StandardCharsets.UTF_8);
		assertTrue(log.contains("\n  within the selection: x 0-99, y 0-164\n"), log);

		imp.setRoi(new Roi(250, 250, 20, 20)); // (ImageJ keeps a selection off the image)
		final Module outside = Simulated.run(context, ContactTrackerCommand.class, inputs);
		assertTrue(((Cancelable) outside).isCanceled());
		assertEquals("the selection on 'scene' lies outside the image", ((Cancelable) outside).getCancelReason());
	}

	/** @return what a successful run printed to ImageJ's Log window, which headless is standard output */
	private static String logOf(final ImagePlus imp, final Object... more) throws Exception {
		final java.io.PrintStream out = System.out;
		final java.io.ByteArrayOutputStream printed = new java.io.ByteArrayOutputStream();
		System.setOut(new java.io.PrintStream(printed, true, java.nio.charset.StandardCharsets.UTF_8));
		try {
			assertSucceeded(run(imp, more));
		}
		finally {
			System.setOut(out);
		}
		return printed.toString(java.nio.charset.StandardCharsets.UTF_8);
	}

	/**
	 * A run whose r_out reaches past the touching neighbour's centre flags its spots; the Log's advice names the
	 * dialog's fields and the macro keys, as a Fiji user sets them, not the command line's options.
	 */
	@Test
	void flaggedRunIsAdvisedInTheDialogsTerms() throws Exception {
		final String log = logOf(Simulated.image(), "method", "iterative", "r_out", 2 * Simulated.SEPARATION *
			Simulated.TYPE.diameterPx(), "diameter", Simulated.TYPE.diameterPx(), "overlay", false).replaceAll("\\s+",
				" ");
		assertTrue(log.contains("are flagged, most FELL_BACK"), log);
		assertTrue(log.contains("set 'Method' to fit (macro method=fit)"), log);
		assertFalse(log.contains("--method") || log.contains("--r-out"), log);
	}

	@Test
	void summaryGoesToTheLogWindow() throws Exception {
		final String log = logOf(Simulated.image());
		assertTrue(log.contains("Contact Tracker: 10 spots in 5 frames of 'simulated pair', 0 flagged\n"), log);
		assertTrue(log.contains("\n  0 components discarded, "), log);
		assertTrue(log.contains("\n  positions, RADIUS, SIGMA in micron; r_out and areas in pixels\n"), log);
		assertTrue(log.contains("\n  overlay: cyan circle = particle (RADIUS), red cross = centre"), "the legend:\n" + log);
		// short lines: ImageJ's Log window cuts long ones (the old one-line summary had 113 characters, and 90
		// characters wrapped word by word); the first line holds the image's title, however long
		for (final String line : log.split("\n"))
			if (!line.startsWith("[") && !line.startsWith("Contact Tracker: 10 spots")) assertTrue(line.length() <=
				ShownFrameProfile.LOG_WIDTH, line.length() + ": " + line);
	}
}
