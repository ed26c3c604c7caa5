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
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.Context;
import org.scijava.module.Module;

import ij.gui.Plot;
import ij.measure.ResultsTable;

/** The Fiji command, headless: from a results table and from a CSV file, and refusing bad input. */
class PotentialCommandTest extends WithContext {

	@TempDir
	Path dir;

	private static ResultsTable triangle() {
		final ResultsTable rt = new ResultsTable();
		final double[][] rows = { { 0, 1, 1, 0 }, { 0, 4, 1, 0 }, { 0, 1, 5, 0 }, { 0, 9, 9, 1 } };
		for (final double[] row : rows) {
			rt.incrementCounter();
			rt.addValue("FRAME", row[0]);
			rt.addValue("POSITION_X", row[1]);
			rt.addValue("POSITION_Y", row[2]);
			rt.addValue("FLAG_MERGED", row[3]);
		}
		return rt;
	}

	/** Puts the spots into ImageJ's Results table, where Contact Tracker leaves them. */
	private static void triangleInResults() {
		final ResultsTable system = ResultsTable.getResultsTable();
		system.reset();
		final ResultsTable t = triangle();
		for (final String c : t.getHeadings())
			for (int i = 0; i < t.size(); i++)
				system.setValue(c, i, t.getValue(c, i));
	}

	@Test
	void tableInTableAndPlotOut() throws Exception {
		triangleInResults();
		final Module m = Simulated.run(context, ContactTrackerPotentialCommand.class, "table", "Results", "bin",
			1.0, "r_max", 6.0, "width", 10.0, "height", 8.0, "show", false);
		final ResultsTable out = (ResultsTable) m.getOutput("potential");
		assertNotNull(out);
		assertEquals(6, out.size());
		assertEquals(3.5, out.getValue("R", 3), 1e-12);
		assertEquals(1, out.getValue("PAIRS", 3), 0);
		assertEquals(0, out.getValue("PAIRS", 2), 0); // the flagged spot at (9, 9) is left out
		assertTrue(Double.isNaN(out.getValue("U_KT", 2))); // empty bin: shown as an empty cell
		assertEquals(1, out.getValue("U_KT_ERR", 5), 1e-12);
		assertTrue(m.getOutput("plot") instanceof Plot);
		// the values reach a macro's nResults and getResult
		final ResultsTable system = ResultsTable.getResultsTable();
		assertEquals(6, system.size());
		assertEquals(3.5, system.getValue("R", 3), 1e-12);
		assertEquals(1, system.getValue("U_KT_ERR", 5), 1e-12);
	}

	/** OK with the dialog's own defaults works: bin 0 and r_max 0 are chosen from the field of view. */
	@Test
	void theDefaultsWork() throws Exception {
		triangleInResults();
		final Module m = Simulated.run(context, ContactTrackerPotentialCommand.class, "table", "Results", "bin",
			0.0, "r_max", 0.0, "width", 10.0, "height", 8.0, "show", false);
		assertNull(((ContactTrackerPotentialCommand) m.getDelegateObject()).getCancelReason());
		final ResultsTable out = (ResultsTable) m.getOutput("potential");
		// r_max half the smaller side (8 / 2 = 4), 50 bins of 0.08
		assertEquals(ContactTrackerPotentialCommand.AUTO_BINS, out.size());
		assertEquals(0.04, out.getValue("R", 0), 1e-12);
		assertEquals(4 - 0.04, out.getValue("R", out.size() - 1), 1e-9);
		// the pair at distance 3 (1,1)-(4,1) falls in the bin [2.96, 3.04)
		assertEquals(1, out.getValue("PAIRS", 37), 0);
	}

	/**
	 * No ResultsTable input: Fiji's ResultsTablePreprocessor fills a command's only ResultsTable input with the
	 * Results table, which then won over csv= and table=. A csv given is read although the Results table holds
	 * other spots.
	 */
	@Test
	void aCsvWinsOverTheResultsTable(@TempDir final Path csvDir) throws Exception {
		final org.scijava.command.CommandInfo info = context.service(org.scijava.command.CommandService.class)
			.getCommand(ContactTrackerPotentialCommand.class);
		for (final org.scijava.module.ModuleItem<?> input : info.inputs())
			assertFalse(ResultsTable.class.isAssignableFrom(input.getType()), input.getName());
		triangleInResults();
		final Path csv = csvDir.resolve("two.csv");
		Files.write(csv, List.of("FRAME,POSITION_X,POSITION_Y", "0,1,1", "0,3,1"));
		final Module m = Simulated.run(context, ContactTrackerPotentialCommand.class, "csv", csv.toFile(), "bin", 1.0,
			"r_max", 4.0, "width", 10.0, "height", 8.0, "show", false);
		final ResultsTable out = (ResultsTable) m.getOutput("potential");
		double pairs = 0;
		for (int i = 0; i < out.size(); i++)
			pairs += out.getValue("PAIRS", i);
		assertEquals(1, pairs, 0, "the CSV's one pair, not the Results table's three");
		assertEquals(1, out.getValue("PAIRS", 2), 0);
	}

	@Test
	void readsACsvFileAndCancelsOnBadInput() throws Exception {
		final Path csv = dir.resolve("spots.csv");
		Files.write(csv, List.of("FRAME,POSITION_X,POSITION_Y", "0,1,1", "0,4,1", "0,1,5"));
		final Module ok = Simulated.run(context, ContactTrackerPotentialCommand.class, "csv", csv.toFile(), "bin", 1.0,
			"r_max", 6.0, "width", 10.0, "height", 8.0, "show", false);
		assertEquals(3, ((ResultsTable) ok.getOutput("potential")).getValue("PAIRS", 3) + ((ResultsTable) ok.getOutput(
			"potential")).getValue("PAIRS", 4) + ((ResultsTable) ok.getOutput("potential")).getValue("PAIRS", 5), 0);
		Files.write(csv, List.of("FRAME,POSITION_X", "0,1"));
		final Module bad = Simulated.run(context, ContactTrackerPotentialCommand.class, "csv", csv.toFile(), "bin", 1.0,
			"r_max", 6.0, "show", false);
		final ContactTrackerPotentialCommand c = (ContactTrackerPotentialCommand) bad.getDelegateObject();
		assertTrue(c.isCanceled());
		assertEquals("spots.csv: missing column POSITION_Y", c.getCancelReason());
		final Module none = Simulated.run(context, ContactTrackerPotentialCommand.class, "table", "no such table",
			"bin", 1.0, "r_max", 6.0, "show", false, "csv", (File) null);
		assertTrue(((ContactTrackerPotentialCommand) none.getDelegateObject()).getCancelReason().contains(
			"no open table titled 'no such table'"));
		assertFalse(((ContactTrackerPotentialCommand) ok.getDelegateObject()).isCanceled());
	}

	/**
	 * Track, then the Profile with its defaults (its suggestion replaces the spots in ImageJ's Results table), then
	 * Pair Potential with its defaults: it reads the spots Contact Tracker found last, says so, and takes the
	 * open image's real size as the field of view, not the spots' extent.
	 */
	@Test
	void theDefaultsWorkRightAfterTheProfile() throws Exception {
		context.service(org.scijava.prefs.PrefService.class).clearAll();
		final ij.ImagePlus imp = Simulated.image();
		final Module track = Simulated.run(context, ContactTrackerCommand.class, "imp", imp, "threshold", Simulated.TYPE
			.threshold(), "r_out", Simulated.TYPE.rOut(), "overlay", false, "table", false);
		assertNull(((ContactTrackerCommand) track.getDelegateObject()).getCancelReason());
		final int spots = ((ResultsTable) track.getOutput("spots")).size();
		assertEquals(2 * Simulated.FRAMES, spots);

		final double[] p = Simulated.truth(0).get(0);
		imp.setRoi(new ij.gui.PointRoi((int) Math.round(p[0]), (int) Math.round(p[1])));
		final Module profile = Simulated.run(context, ContactTrackerProfileCommand.class, "imp", imp, "plot", false);
		assertFalse(((org.scijava.Cancelable) profile).isCanceled(), () -> ((org.scijava.Cancelable) profile)
			.getCancelReason());
		assertEquals(-1, ResultsTable.getResultsTable().getColumnIndex("POSITION_X"), "the suggestion replaced the spots");

		ij.WindowManager.setTempCurrentImage(imp);
		try {
			final Module m = Simulated.run(context, ContactTrackerPotentialCommand.class, "show", false);
			assertNull(((ContactTrackerPotentialCommand) m.getDelegateObject()).getCancelReason());
			final ResultsTable out = (ResultsTable) m.getOutput("potential");
			// r_max half the image's smaller side in microns: the image's size, not the spots' extent
			final double side = Math.min(imp.getWidth(), imp.getHeight()) * imp.getCalibration().pixelWidth;
			assertEquals(side / 2 * (1 - 0.5 / ContactTrackerPotentialCommand.AUTO_BINS), out.getValue("R", out.size() -
				1), 1e-9);
			long pairs = 0;
			for (int i = 0; i < out.size(); i++)
				pairs += (long) out.getValue("PAIRS", i);
			assertTrue(pairs <= Simulated.FRAMES, "one pair per frame at most: " + pairs);
		}
		finally {
			ij.WindowManager.setTempCurrentImage(null);
		}

		// with no spots tracked in this session, the reason names what to do
		final ResultsTable none = ResultsTable.getResultsTable();
		none.reset();
		none.incrementCounter();
		none.addValue("THRESHOLD", 1);
		SpotTables.forgetLastRun();
		final String reason = ((ContactTrackerPotentialCommand) Simulated.run(context,
			ContactTrackerPotentialCommand.class, "show", false).getDelegateObject()).getCancelReason();
		assertTrue(reason.startsWith("the Results table holds no spots (no column POSITION_X): run Contact Tracker " +
			"first"), reason);
	}
}
