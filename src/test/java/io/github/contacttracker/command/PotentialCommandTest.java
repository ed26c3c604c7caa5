package io.github.contacttracker.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.Context;
import org.scijava.module.Module;

import ij.gui.Plot;
import ij.measure.ResultsTable;

/** The Fiji command, headless: from a results table and from a CSV file, and refusing bad input. */
class PotentialCommandTest {

	private static Context context;

	@TempDir
	Path dir;

	@BeforeAll
	static void start() {
		context = new Context();
	}

	@AfterAll
	static void stop() {
		context.dispose();
	}

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

	@Test
	void tableInTableAndPlotOut() throws Exception {
		final Module m = Simulated.run(context, ContactTrackerPotentialCommand.class, "spots", triangle(), "bin", 1.0,
			"r_max", 6.0, "width", 10.0, "height", 8.0, "show", false);
		final ResultsTable out = (ResultsTable) m.getOutput("potential");
		assertNotNull(out);
		assertEquals(6, out.size());
		assertEquals(3.5, out.getValue("R", 3), 1e-12);
		assertEquals(1, out.getValue("PAIRS", 3), 0);
		assertEquals(0, out.getValue("PAIRS", 2), 0); // the flagged spot at (9, 9) is left out
		assertTrue(Double.isNaN(out.getValue("U_KT", 2))); // empty bin: shown as an empty cell
		assertEquals(1, out.getValue("U_KT_ERR", 5), 1e-12);
		assertTrue(m.getOutput("plot") instanceof Plot);
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
}
