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
package io.github.contacttracker.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.Cancelable;
import org.scijava.command.CommandService;
import org.scijava.module.Module;
import org.scijava.module.ModuleRunner;
import org.scijava.module.ModuleService;
import org.scijava.module.process.PostprocessorPlugin;
import org.scijava.module.process.PreprocessorPlugin;
import org.scijava.plugin.PluginService;
import org.scijava.prefs.PrefService;

import ij.ImagePlus;
import ij.Macro;
import ij.gui.OvalRoi;
import ij.gui.Roi;
import ij.measure.ResultsTable;
import io.github.contacttracker.command.ContactTrackerCommand;
import io.github.contacttracker.command.WithContext;

/**
 * Fuzzes the Fiji command headless, as scripts (SciJava inputs) and ImageJ macros (an options string, which leaves
 * out values the profile helper then measures) run it: random images from 1x1 (8, 16, 32 bits and RGB, floats with
 * NaN and infinities, several channels), selections down to one pixel wide or outside the image, and random
 * inputs. The property: no exception escapes the command's run; a refusal is the command's own error display, a
 * cancelled module whose reason is one line; a run that tracks has finite positions, inside the image unless
 * flagged; a CSV asked for is written by a run that tracks and not left behind a refusal.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases; a longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=FijiCommandFuzzTest -Dcontact.tracker.fuzz.cases=2000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 */
class FijiCommandFuzzTest extends WithContext {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 150;
	/** The least share of cases that must track. */
	static final double REACH_FLOOR = 0.3;

	@TempDir
	Path dir;


	@Test
	void noInputEndsInAnException() throws Exception {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int tracked = 0, refused = 0, macros = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final ImagePlus imp = FuzzImages.image(r, 4);
			final String shape = shape(r, imp);
			final Path csv = dir.resolve("case" + c + ".csv");
			final Map<String, Object> inputs = inputs(r, imp);
			if (r.nextInt(4) == 0) inputs.put("csv", csv.toFile());
			final boolean macro = r.nextBoolean();
			final String options = macro ? options(r, inputs) : null;
			final String what = "case seed " + caseSeed + ": " + imp.getWidth() + " x " + imp.getHeight() + " x " + imp
				.getStackSize() + ", " + imp.getBitDepth() + "-bit, " + shape + (macro ? ", macro options '" + options + "'"
					: ", inputs " + inputs);
			context.service(PrefService.class).clearAll();
			final Module m = macro ? runAsMacro(imp, options, inputs.get("csv"), what) : runAsScript(imp, inputs, what);
			final Cancelable run = (Cancelable) m;
			if (CommandRuns.refused(m, what)) {
				refused++;
				assertFalse(Files.exists(csv), "no CSV left behind a refusal: " + run.getCancelReason() + "; " + what);
			}
			else {
				tracked++;
				positionsInside((ResultsTable) m.getOutput("spots"), what);
				if (inputs.containsKey("csv")) assertTrue(Files.exists(csv), "the CSV asked for: " + what);
			}
			if (macro) macros++;
			Files.deleteIfExists(csv);
		}
		FuzzCase.reach("Fiji command fuzz (" + macros + " as macros)", cases, tracked, refused, REACH_FLOOR);
	}

	/**
	 * The macro half of the fuzz runs the command as a macro does only if the command sees the options: ImageJ gives
	 * a thread its macro options only when the thread's name starts with {@code Run$_}. Its thread was once named
	 * otherwise, and every "macro" case ran as a script with the default values: a threshold given in the options
	 * must be the module's, and one left out measured by the profile helper, not the default 100.
	 */
	@Test
	void theMacroCasesRunWithTheirOptions() throws Exception {
		final ij.process.ShortProcessor ip = new ij.process.ShortProcessor(60, 60);
		for (int y = 0; y < 60; y++)
			for (int x = 0; x < 60; x++)
				ip.set(x, y, (int) (2000 + 40000 * Math.exp(-((x - 30) * (x - 30) + (y - 30) * (y - 30)) / 8.0)));
		final Module given = runAsMacro(new ImagePlus("one", ip.duplicate()), "threshold=20000 r_out=8 table=false", null,
			"threshold given");
		assertFalse(((Cancelable) given).isCanceled(), ((Cancelable) given).getCancelReason());
		assertEquals(20000.0, given.getInput("threshold"));
		assertEquals(1, ((ResultsTable) given.getOutput("spots")).size());
		final Module measured = runAsMacro(new ImagePlus("one", ip.duplicate()), "r_out=8 table=false", null,
			"threshold left out");
		assertFalse(((Cancelable) measured).isCanceled(), ((Cancelable) measured).getCancelReason());
		final double t = (Double) measured.getInput("threshold");
		assertTrue(t > 2000 && t < 42000, "measured by the helper within the data, not the default: " + t);
	}

	/**
	 * Found by this fuzz (seed 3, case seed -91774238770812134): an r_out of 2 px or less with a method that measures
	 * the profile (fit, the default, or deblend) on a movie of particles ended in an exception from the profile's
	 * estimator (its reach, 1.5 r_out, must exceed 3 px), in Fiji and as {@code track}'s internal error. Now refused
	 * in one line naming r_out and the method that tracks particles this small; r_out just above 2 px tracks.
	 */
	@Test
	void anROutTooSmallForTheProfileIsRefusedInOneLine(@TempDir final Path tmp) throws Exception {
		final ij.process.ByteProcessor ip = new ij.process.ByteProcessor(80, 80);
		for (int y = 0; y < 80; y++)
			for (int x = 0; x < 80; x++) {
				double v = 20;
				for (int cy = 10; cy < 80; cy += 16)
					for (int cx = 10; cx < 80; cx += 16)
						v += 180 * Math.exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * 2.5 * 2.5));
				ip.set(x, y, (int) Math.min(255, v));
			}
		final Path tif = tmp.resolve("grid.tif");
		io.github.contacttracker.io.ImageFiles.saveTiff(new ImagePlus("grid", ip), tif);
		for (final String method : new String[] { "fit", "deblend" })
			for (final double rOut : new double[] { 0.5, 2 }) {
				final Map<String, Object> inputs = new LinkedHashMap<>(Map.of("threshold", 100.0, "r_out", rOut, "method",
					method, "table", false, "overlay", false));
				final Cancelable run = (Cancelable) runAsScript(new ImagePlus("grid", ip.duplicate()), inputs, method + " " +
					rOut);
				assertTrue(run.isCanceled(), method + " " + rOut);
				assertTrue(run.getCancelReason().startsWith("r_out must exceed 2.0 px for the " + method + " method") && run
					.getCancelReason().contains("paper method"), run.getCancelReason());
				final FuzzCase cli = new FuzzCase(0, List.of("track", tif.toString(), "--threshold", "100", "--r-out", String
					.valueOf(rOut), "--method", method, "--csv", tmp.resolve("o.csv").toString()));
				assertTrue(cli.refused() && cli.said.contains("r_out must exceed 2.0 px"), cli.what);
			}
		final Module tracked = runAsScript(new ImagePlus("grid", ip.duplicate()), new LinkedHashMap<>(Map.of("threshold",
			100.0, "r_out", 2.1, "table", false, "overlay", false)), "fit 2.1");
		assertFalse(((Cancelable) tracked).isCanceled(), ((Cancelable) tracked).getCancelReason());
		assertEquals(25, ((ResultsTable) tracked.getOutput("spots")).size());
	}

	/**
	 * A movie on disk (a virtual stack, as Fiji opens a long one) whose later frame cannot be read, its compressed
	 * data damaged: the run is refused in one line naming the file, as for any other reason, not ended by the
	 * reader's exception.
	 */
	@Test
	void aFrameThatCannotBeReadIsRefusedInOneLine(@TempDir final Path tmp) throws Exception {
		final io.github.contacttracker.io.TiffLayoutsTest.Page p = new io.github.contacttracker.io.TiffLayoutsTest.Page(
			40, 30, 16, 1, 2, 2, 1, 5, 1, 0, 30);
		final Path movie = io.github.contacttracker.io.TiffLayoutsTest.write(tmp.resolve("damaged.tif"), p, 3,
			java.nio.ByteOrder.LITTLE_ENDIAN);
		final byte[] b = Files.readAllBytes(movie);
		final long pageBytes = (b.length - 8) / 3;
		for (int i = 0; i < 40; i++)
			b[(int) (8 + 2 * pageBytes / 2 + pageBytes / 4 + i)] = (byte) 0xff; // page 3's LZW codes: beyond the table
		Files.write(movie, b);
		final ImagePlus imp = io.github.contacttracker.io.ImageFiles.open(movie);
		final Module m = runAsScript(imp, new LinkedHashMap<>(Map.of("threshold", 950.0, "r_out", 5.0, "channel", 1,
			"table", false, "overlay", false)), "damaged.tif");
		final Cancelable run = (Cancelable) m;
		assertTrue(run.isCanceled(), "refused");
		assertEquals(1, run.getCancelReason().lines().count(), run.getCancelReason());
		assertTrue(run.getCancelReason().contains("damaged.tif"), run.getCancelReason());
	}

	/**
	 * Gives the image a shape a Fiji user has: as it is, its frames as channels, or a selection (1 pixel wide, a
	 * random rectangle, an oval, one outside the image).
	 *
	 * @return the shape, for a failure's message
	 */
	private static String shape(final SplittableRandom r, final ImagePlus imp) {
		final int w = imp.getWidth(), h = imp.getHeight();
		switch (r.nextInt(6)) {
			case 0:
				if (imp.getStackSize() > 1 && imp.getBitDepth() != 24) {
					imp.setDimensions(imp.getStackSize(), 1, 1);
					return imp.getStackSize() + " channels";
				}
				return "no selection";
			case 1:
				imp.setRoi(new Roi(r.nextInt(w), 0, 1, h));
				return "a 1-pixel-wide selection";
			case 2: {
				final int x = r.nextInt(w), y = r.nextInt(h);
				imp.setRoi(new Roi(x, y, 1 + r.nextInt(w - x), 1 + r.nextInt(h - y)));
				return "selection " + imp.getRoi().getBounds();
			}
			case 3:
				imp.setRoi(new OvalRoi(0, 0, w, h));
				return "an oval selection";
			case 4:
				imp.setRoi(new Roi(w + 5, h + 5, 10, 10));
				return "a selection outside the image";
			default:
				return "no selection";
		}
	}

	/**
	 * @return random inputs: sensible values (a threshold inside the image's range) but for none, one or two, which
	 *         are out of range, not numbers, or other sensible ones; some left out
	 */
	private static Map<String, Object> inputs(final SplittableRandom r, final ImagePlus imp) {
		final Object[][] choices = { { "threshold", FuzzImages.threshold(imp), 0.0, -3.0, 1e9, Double.NaN, 20000.0 }, {
			"r_out", (double) FuzzImages.rOut(imp), 0.5, 0.0, -1.0, 400.0, Double.POSITIVE_INFINITY }, { "diameter", 0.0,
				(double) FuzzImages.diameter(imp), 4.0, 30.0, 1e6, -2.0 }, { "method", "fit", "paper", "deblend", "first",
					"iterative", "nope" }, { "detection", "threshold", "image", "other" }, { "min_area", 5, 1, 20, 0, -5 }, {
						"min_second_area", 10, 0, 1000000 }, { "kinds", 1, 0, 4, 9, -1 }, { "particles", FuzzImages.dark(imp)
							? "dark" : "bright", FuzzImages.dark(imp) ? "bright" : "dark", "grey" }, { "connectivity", "8", "4",
								"6" }, { "channel", 1, 0, 2, 3, -1, 7 }, { "pair_cutoff", 0.0, 10.0, -1.0, Double.NaN }, {
									"results", "spots", "pairs", "none", "all" }, { "threads", 1, 0, 2, -1 }, { "overlay",
										true, false }, { "r_out_circles", false, true } };
		final List<Integer> oddOnes = FuzzCase.oddOnes(r, choices.length);
		final Map<String, Object> in = new LinkedHashMap<>();
		for (int i = 0; i < choices.length; i++) {
			final Object[] c = choices[i];
			if (oddOnes.contains(i)) in.put((String) c[0], c[1 + r.nextInt(c.length - 1)]);
			// a script gives the threshold and r_out (left out, their defaults are no image's); a macro may leave them out
			else if (r.nextInt(4) > 0 || i < 2 || c[0].equals("channel")) in.put((String) c[0], c[1]);
		}
		in.put("table", false); // headless no window opens; the table is the output either way
		return in;
	}

	/**
	 * @return the inputs as a macro's options: some left out (threshold and r_out then measured by the profile
	 *         helper), some words that are no numbers
	 */
	private static String options(final SplittableRandom r, final Map<String, Object> inputs) {
		final StringBuilder b = new StringBuilder();
		for (final Map.Entry<String, Object> e : inputs.entrySet()) {
			// threshold and r_out are left out together or one at a time: the helper measures what is left out
			if (e.getKey().equals("csv") || r.nextInt(6) == 0) continue;
			final Object v = e.getValue();
			final String text = r.nextInt(60) == 0 ? "x" : v instanceof Double d ? String.format(Locale.ROOT, "%s", d)
				: String.valueOf(v);
			b.append(e.getKey()).append('=').append(text).append(' ');
		}
		return b.toString().strip();
	}

	/** Runs the command as a script does: SciJava inputs, every pre- and postprocessor. */
	private static Module runAsScript(final ImagePlus imp, final Map<String, Object> inputs, final String what)
		throws InterruptedException
	{
		final Map<String, Object> all = new LinkedHashMap<>(inputs);
		all.put("imp", imp);
		return CommandRuns.run(context, ContactTrackerCommand.class, all, what);
	}

	/**
	 * Runs the command as an ImageJ macro does in Fiji: on a thread that carries the macro's options, every pre- and
	 * postprocessor (the test's stand-in for Fiji's macro preprocessor sets the inputs from the options).
	 */
	private static Module runAsMacro(final ImagePlus imp, final String options, final Object csv, final String what)
		throws InterruptedException
	{
		final Module module = context.service(ModuleService.class).createModule(context.service(CommandService.class)
			.getCommand(ContactTrackerCommand.class));
		module.setInput("imp", imp);
		module.resolveInput("imp");
		if (csv != null) {
			module.setInput("csv", (File) csv);
			module.resolveInput("csv");
		}
		final PluginService plugins = context.service(PluginService.class);
		final List<PreprocessorPlugin> pre = plugins.createInstancesOfType(PreprocessorPlugin.class);
		final List<PostprocessorPlugin> post = plugins.createInstancesOfType(PostprocessorPlugin.class);
		final Throwable[] escaped = new Throwable[1];
		final Thread thread = new Thread(() -> {
			try {
				new ModuleRunner(context, module, pre, post).call();
			}
			catch (final RuntimeException e) {
				escaped[0] = e.getCause() != null ? e.getCause() : e;
			}
		}, "Run$_fuzz-macro"); // ImageJ gives a thread its macro options only when its name starts so
		Macro.setOptions(thread, options.isEmpty() ? " " : options);
		final PrintStream out = System.out, err = System.err;
		CommandRuns.quiet();
		try {
			thread.start();
			thread.join();
		}
		finally {
			Macro.setOptions(thread, null);
			System.setOut(out);
			System.setErr(err);
		}
		if (escaped[0] != null) throw new AssertionError("an exception escaped the command: " + what, escaped[0]);
		return module;
	}

	/** Every spot has finite coordinates, within the image's extent unless it is flagged. */
	private static void positionsInside(final ResultsTable rt, final String what) {
		assertTrue(rt != null, "a run that tracks gives its spots table: " + what);
		if (rt.size() == 0) return;
		final double[] x = rt.getColumn("POSITION_X"), y = rt.getColumn("POSITION_Y");
		assertTrue(x != null && y != null, "positions in the spots table: " + what);
		final List<double[]> flags = new ArrayList<>();
		for (final String h : rt.getHeadings())
			if (h.startsWith("FLAG_") && !h.equals("FLAG_SECOND_PASS")) flags.add(rt.getColumn(h));
		for (int i = 0; i < rt.size(); i++) {
			assertTrue(Double.isFinite(x[i]) && Double.isFinite(y[i]), "finite: spot " + i + " " + what);
			boolean flagged = false;
			for (final double[] f : flags)
				flagged |= f[i] == 1;
			assertTrue(flagged || x[i] >= -0.5 && y[i] >= -0.5, "inside unless flagged: spot " + i + " at " + x[i] + ", " +
				y[i] + "; " + what);
		}
	}
}
