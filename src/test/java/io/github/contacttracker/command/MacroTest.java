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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.scijava.Cancelable;
import org.scijava.Context;
import org.scijava.prefs.PrefService;

import ij.IJ;
import ij.ImagePlus;
import ij.Macro;
import ij.WindowManager;
import ij.macro.Interpreter;
import ij.measure.ResultsTable;
import ij.process.ColorProcessor;
import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.ImageFiles;
import io.github.contacttracker.io.SpotCsvWriter;
import io.github.contacttracker.settings.TrackingSettings;

/**
 * ImageJ macros calling Contact Tracker, run by ImageJ 1.x's own macro interpreter in this process, headless.
 * {@code run("Contact Tracker", ...)} reaches the SciJava command through {@link FijiMacroBridge}, which does what
 * Fiji's bridge does (another thread, inputs from the macro options, cancellation ignored); so these tests prove
 * what the command does to the macro (ImageJ's Results table, aborting it), not Fiji's bridge itself.
 */
class MacroTest {

	private static Context context;
	private static final double T = Simulated.TYPE.threshold(), R = Simulated.TYPE.rOut();

	@BeforeAll
	static void start() throws Exception {
		context = new Context();
		FijiMacroBridge.install(context);
	}

	@AfterAll
	static void stop() {
		context.dispose();
	}

	@BeforeEach
	void fresh() {
		context.service(PrefService.class).clearAll();
		ResultsTable.getResultsTable().reset();
		IJ.redirectErrorMessages(false);
	}

	/**
	 * Runs macro code in ImageJ 1.x's interpreter, on this thread.
	 *
	 * @return what the macro printed (headless, ImageJ's Log window is standard output)
	 */
	static String macro(final String code, final String argument) {
		final PrintStream out = System.out;
		final ByteArrayOutputStream printed = new ByteArrayOutputStream();
		System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
		try {
			new Interpreter().run(code, argument);
		}
		catch (final RuntimeException e) {
			if (!Macro.MACRO_CANCELED.equals(e.getMessage())) throw e; // how an aborted macro may end
		}
		finally {
			System.setOut(out);
		}
		return printed.toString(StandardCharsets.UTF_8);
	}

	private static String macro(final String code) {
		return macro(code, null);
	}

	private static String options(final String more) {
		return String.format(Locale.ROOT, "threshold=%s r_out=%s %s", T, R, more);
	}

	/** @return the command line's CSV for the simulated movie with the default parameters */
	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static String cliCsv(final ImagePlus imp) throws Exception {
		final ImagePlusFrames frames = ImagePlusFrames.of(imp, 0);
		final TrackerParameters params = new TrackerParameters(T, R, TrackerParameters.DEFAULT_MIN_AREA,
			Connectivity.EIGHT, TrackerParameters.DEFAULT_MIN_SECOND_AREA, Method.DEFAULT);
		final StringWriter csv = new StringWriter();
		SpotCsvWriter.write(csv, StackTracker.spots(new StackTracker(params).track((List) frames.frames(), false)),
			frames.calibration());
		return csv.toString();
	}

	@Test
	void theMacroReadsTheSpotsFromTheResultsTable(@TempDir final Path dir) throws Exception {
		final Path movie = dir.resolve("movie.tif");
		ImageFiles.saveTiff(Simulated.image(), movie);
		final String printed = macro("setBatchMode(true);\n" + //
			"open('" + movie + "');\n" + //
			"run('Contact Tracker', '" + options("overlay=false") + "');\n" + //
			"print('n=' + nResults);\n" + //
			"for (i = 0; i < nResults; i++) print('row ' + i + ': ' + getResult('FRAME', i) + ' ' + " +
			"d2s(getResult('POSITION_X', i), 9) + ' ' + d2s(getResult('SIGMA_Y', i), 9) + ' ' + " +
			"getResult('FLAG_FELL_BACK', i));\n" + //
			"close('*');\n" + //
			"print('images=' + nImages);\n");
		// the values of the CSV, in the same units
		final List<String> csv = cliCsv(ImageFiles.open(movie)).lines().toList();
		final List<String> header = List.of(csv.get(0).split(","));
		assertTrue(printed.contains("n=" + (csv.size() - 1) + "\n"), printed);
		for (int i = 1; i < csv.size(); i++) {
			final String[] v = csv.get(i).split(",");
			final String expected = String.format(Locale.ROOT, "row %d: %s %.9f %.9f %s", i - 1, v[header.indexOf("FRAME")],
				Double.parseDouble(v[header.indexOf("POSITION_X")]), Double.parseDouble(v[header.indexOf("SIGMA_Y")]),
				v[header.indexOf("FLAG_FELL_BACK")]);
			assertTrue(printed.contains(expected + "\n"), () -> expected + " not in\n" + printed);
		}
		assertTrue(printed.contains("Contact Tracker: 10 spots in 5 frames of 'movie.tif', 0 flagged"), printed);
		assertTrue(printed.contains("images=0"), printed);
	}

	@Test
	void theMacroReadsThePairsWithResultsPairs() {
		WindowManager.setTempCurrentImage(Simulated.image());
		final double cutoff = 1.2 * Simulated.SEPARATION * Simulated.TYPE.diameterPx() * Simulated.TYPE
			.pixelSizeMicrons();
		final String printed = macro("run('Contact Tracker', '" + options("overlay=false results=pairs pair_cutoff=" +
			cutoff) + "');\nprint('pairs=' + nResults + ' d=' + getResult('DISTANCE', 0) + ' a=' + getResult('SPOT_A', 1));");
		final ResultsTable pairs = (ResultsTable) FijiMacroBridge.last().getOutput("pairs");
		assertTrue(printed.contains("pairs=5 d=" + IJ.d2s(pairs.getValue("DISTANCE", 0), 4) + " a=" + (int) pairs.getValue(
			"SPOT_A", 1)), printed);
		WindowManager.setTempCurrentImage(null);
	}

	@ParameterizedTest
	@CsvSource(delimiter = '|', value = { //
		"simulated | threshold=abc r_out=20      | threshold must be a number, not 'abc'", // Fiji would pass 0
		"simulated | threshold=60 r_out=-3       | r_out must be a positive number of pixels, not -3.0",
		"simulated | threshold=60 method=best    | method must be one of first, paper, iterative, deblend, fit",
		"simulated | threshold=60 kinds=5        | kinds must be 0 (found automatically), 1 (all alike) or up to 4, not 5",
		"simulated | threshold=6000 r_out=20     | threshold 6000 is outside the data range",
		"rgb       | threshold=60 channel=4      | channel 4 does not exist: 'rgb' has 3 channels" })
	void invalidInputStopsTheMacroAndChangesNothing(final String image, final String options, final String reason) {
		final ImagePlus imp = image.equals("rgb") ? new ImagePlus("rgb", new ColorProcessor(40, 30)) : Simulated.image();
		ResultsTable.getResultsTable().incrementCounter();
		ResultsTable.getResultsTable().addValue("Mine", 7);
		WindowManager.setTempCurrentImage(imp);
		final String printed = macro("print('before');\nrun('Contact Tracker', '" + options + "');\nprint('after');");
		WindowManager.setTempCurrentImage(null);
		assertTrue(printed.contains("before"), printed);
		assertFalse(printed.contains("after"), "the macro must stop at the failing run:\n" + printed);
		final Cancelable module = (Cancelable) FijiMacroBridge.last();
		assertTrue(module.isCanceled());
		assertTrue(module.getCancelReason().startsWith(reason), module.getCancelReason());
		assertNull(imp.getOverlay(), "nothing drawn");
		assertEquals(1, ResultsTable.getResultsTable().size(), "the Results table is untouched");
		assertEquals(7, ResultsTable.getResultsTable().getValue("Mine", 0));
	}

	@Test
	void aUsersBatchLoopWithRedirectedErrorsReportsTheFileAndGoesOn(@TempDir final Path dir) throws Exception {
		final Path in = Files.createDirectories(dir.resolve("in"));
		ImageFiles.saveTiff(Simulated.image(), in.resolve("a.tif"));
		ImageFiles.saveTiff(Simulated.zAndT("volume"), in.resolve("b volume.tif"));
		ImageFiles.saveTiff(Simulated.image(), in.resolve("c.tif"));
		final String printed = macro("dir = getArgument();\n" + //
			"setBatchMode(true);\n" + //
			"list = getFileList(dir);\n" + //
			"for (i = 0; i < list.length; i++) {\n" + //
			"  open(dir + list[i]);\n" + //
			"  IJ.redirectErrorMessages();\n" + //
			"  run('Contact Tracker', '" + options("overlay=false") + "');\n" + //
			"  print(list[i] + ': ' + nResults + ' spots');\n" + //
			"  close();\n" + //
			"}\n" + //
			"print('open images: ' + nImages);", in + "/");
		assertTrue(printed.contains("a.tif: 10 spots"), printed);
		assertTrue(printed.contains("Contact Tracker ('b volume.tif'): 'b volume.tif' has 2 Z slices and 2 time frames"),
			printed);
		assertTrue(printed.contains("b volume.tif: 0 spots"), "not the previous file's spots:\n" + printed);
		assertTrue(printed.contains("c.tif: 10 spots"), "the loop goes on:\n" + printed);
		assertTrue(printed.contains("open images: 0"), printed);
		assertFalse(IJ.redirectingErrorMessages(), "redirectErrorMessages() applies to one command");
	}

	/** {@code kinds=1} is taken and tracked with: the TrackMate file records the parameters the core got. */
	@Test
	void theMacroSetsTheKindsOfParticle(@TempDir final Path dir) throws Exception {
		final Path xml = dir.resolve("kinds.xml");
		WindowManager.setTempCurrentImage(Simulated.image());
		final String printed = macro("run('Contact Tracker', '" + options("overlay=false kinds=1 trackmate_xml=[" + xml +
			"]") + "');\nprint('n=' + nResults);");
		WindowManager.setTempCurrentImage(null);
		final Cancelable module = (Cancelable) FijiMacroBridge.last();
		assertFalse(module.isCanceled(), module.getCancelReason());
		assertEquals(1, FijiMacroBridge.last().getInput("kinds"));
		assertTrue(printed.contains("n=10\n"), printed);
		assertTrue(Files.readString(xml).contains(" KINDS=\"1\" "), Files.readString(xml));
	}

	@Test
	void aMacroLeavingKeysOutGetsTheDefaultsNotTheDialogsLastValues() throws Exception {
		// an interactive run remembers r_out = 30, min_area = 25 and kinds = 2
		final ImagePlus imp = Simulated.image();
		Simulated.run(context, ContactTrackerCommand.class, "imp", imp, "threshold", T, "r_out", 30.0, "min_area", 25,
			"kinds", 2, "overlay", false);
		WindowManager.setTempCurrentImage(imp);
		macro("run('Contact Tracker', 'threshold=" + T + " r_out=" + R + " overlay=false');");
		WindowManager.setTempCurrentImage(null);
		assertEquals(R, (Double) FijiMacroBridge.last().getInput("r_out"), 0, "the macro's value wins");
		assertEquals(TrackerParameters.DEFAULT_MIN_AREA, FijiMacroBridge.last().getInput("min_area"),
			"a key left out takes the documented default");
		assertEquals(TrackingSettings.KINDS.defaultValue(), FijiMacroBridge.last().getInput("kinds"));
	}

	/**
	 * A macro without values measures them on the first frame, as the command line's track does (the same
	 * values), says so in the Log, and finds the particles: one spot per particle, where the fixed defaults fit no
	 * movie.
	 */
	@Test
	void aMacroWithoutValuesMeasuresThemAsTrackDoes() throws Exception {
		final ImagePlus imp = Simulated.image();
		final io.github.contacttracker.pipeline.MeasuredSettings.Result expected = io.github.contacttracker.pipeline
			.MeasuredSettings.of(imp.getTitle(), ImagePlusFrames.of(imp, 0).frame(0), true,
				io.github.contacttracker.settings.SettingValues.defaults(), java.util.Set.of(), FrontEnd.COMMAND_LINE);
		WindowManager.setTempCurrentImage(imp);
		final String printed;
		try {
			printed = macro("run('Contact Tracker', 'overlay=false');");
		}
		finally {
			WindowManager.setTempCurrentImage(null);
		}
		final org.scijava.module.Module m = FijiMacroBridge.last();
		assertFalse(((Cancelable) m).isCanceled(), () -> ((Cancelable) m).getCancelReason());
		assertEquals(expected.settings().get(TrackingSettings.THRESHOLD), (Double) m.getInput("threshold"), 0);
		assertEquals(expected.settings().get(TrackingSettings.R_OUT), (Double) m.getInput("r_out"), 0);
		assertEquals(expected.settings().diameter(), (Double) m.getInput("diameter"), 0);
		assertNotEquals(TrackingSettings.THRESHOLD.defaultValue(), (Double) m.getInput("threshold"));
		assertTrue(printed.contains("not given by the macro, measured on frame 1 by the profile helper: threshold=" +
			io.github.contacttracker.pipeline.MeasuredSettings.optionValue(expected.settings().get(
				TrackingSettings.THRESHOLD))), printed);
		// two particles per frame, each found once
		assertEquals(2 * Simulated.FRAMES, ResultsTable.getResultsTable().size(), printed);
	}

	/** Profile's suggestion reaches the macro through the Results table: nResults 1, getResult of each column. */
	@Test
	void theMacroReadsProfilesSuggestion() {
		final ImagePlus imp = Simulated.image();
		WindowManager.setTempCurrentImage(imp);
		final double[] c = Simulated.truth(0).get(0);
		final String printed = macro(String.format(Locale.ROOT, "makePoint(%d, %d);\n" + //
			"run('Contact Tracker Profile', 'diameter=%s max_radius=60 plot=false');\n" + //
			"print('n=' + nResults + ' t=' + d2s(getResult('THRESHOLD', 0), 6) + ' r=' + d2s(getResult('R_OUT', 0), 6) + " +
			"' x=' + d2s(getResult('X', 0), 6));", Math.round(c[0]), Math.round(c[1]), Simulated.TYPE.diameterPx()));
		WindowManager.setTempCurrentImage(null);
		final org.scijava.module.Module m = FijiMacroBridge.last();
		assertNull(((Cancelable) m).getCancelReason());
		assertTrue(printed.contains(String.format(Locale.ROOT, "n=1 t=%.6f r=%.6f x=%.6f", (Double) m.getOutput(
			"suggested_threshold"), (Double) m.getOutput("suggested_r_out"), (Double) m.getOutput("centre_x"))), printed);
		assertEquals(c[0], (Double) m.getOutput("centre_x"), 0.5, "the particle marked");
	}

	/**
	 * Pair Potential in a macro: the defaults (bin 0, r_max 0) work, csv= is read although the Results table holds
	 * other spots, the values reach nResults; a bad value stops the macro.
	 */
	@Test
	void pairPotentialInAMacro(@TempDir final Path dir) throws Exception {
		final Path csv = dir.resolve("two.csv");
		Files.write(csv, List.of("FRAME,POSITION_X,POSITION_Y", "0,1,1", "0,4,1", "0,9,7"));
		ResultsTable.getResultsTable().incrementCounter();
		ResultsTable.getResultsTable().addValue("POSITION_X", 5);
		final String printed = macro("run('Contact Tracker Pair Potential', 'csv=[" + csv + "] width=10 height=8 " +
			"show=false');\nprint('n=' + nResults + ' pairs=' + getResult('PAIRS', 37));\n" + //
			"run('Contact Tracker Pair Potential', 'csv=[" + csv + "] bin=-1 show=false');\nprint('after');");
		assertTrue(printed.contains("n=50 pairs=1"), printed);
		assertFalse(printed.contains("after"), "bin=-1 stops the macro:\n" + printed);
		assertEquals("bin must be a number >= 0, not -1.0", ((Cancelable) FijiMacroBridge.last()).getCancelReason());
	}

	@Test
	void shippedBatchMacroWritesEachCsvAndReportsFailures(@TempDir final Path dir) throws Exception {
		final Path in = Files.createDirectories(dir.resolve("in")), out = Files.createDirectories(dir.resolve("out"));
		ImageFiles.saveTiff(Simulated.image(), in.resolve("movie.tif"));
		ImageFiles.saveTiff(Simulated.zAndT("volume"), in.resolve("volume.tif"));
		// hostile: the directory chain loops back to the first directory (ImageJ's open() never ends on it)
		final byte[] loop = Files.readAllBytes(in.resolve("movie.tif"));
		final java.nio.ByteBuffer b = java.nio.ByteBuffer.wrap(loop).order(loop[0] == 'I' ? java.nio.ByteOrder.LITTLE_ENDIAN
			: java.nio.ByteOrder.BIG_ENDIAN);
		final int ifd = b.getInt(4);
		b.putInt(ifd + 2 + 12 * (b.getShort(ifd) & 0xffff), ifd);
		Files.write(in.resolve("loop.tif"), loop);
		Files.write(in.resolve("empty.tif"), new byte[0]);
		final String code = Files.readString(Path.of(System.getProperty("basedir", ".")).resolve(
			"scripts/contact-tracker-batch.ijm"));
		final String printed = macro(code, String.format(Locale.ROOT,
			"input=[%s] output=[%s] threshold=%s r_out=%s method=%s", in, out, T, R, Method.DEFAULT.key()));
		assertTrue(printed.contains("movie.tif: 10 spots -> "), printed);
		assertTrue(printed.contains("Contact Tracker ('volume.tif'): 'volume.tif' has 2 Z slices and 2 time frames"),
			printed);
		assertTrue(printed.contains("volume.tif: FAILED"), printed);
		assertTrue(printed.contains("loop.tif: FAILED: cannot read " + in.resolve("loop.tif") + ": damaged TIFF: its " +
			"chain of image directories loops back"), printed);
		assertTrue(printed.contains("empty.tif: FAILED: cannot read " + in.resolve("empty.tif") + ": it is empty"),
			printed);
		assertTrue(printed.contains("Contact Tracker batch: 1 image(s) done, 3 failed"), printed);
		assertTrue(printed.contains("open images: 0"), printed);
		assertEquals(cliCsv(ImageFiles.open(in.resolve("movie.tif"))), Files.readString(out.resolve("movie.csv")));
		assertFalse(Files.exists(out.resolve("volume.csv")));
	}
}
