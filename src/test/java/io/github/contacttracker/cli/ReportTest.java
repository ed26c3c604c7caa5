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
package io.github.contacttracker.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import io.github.contacttracker.io.ProjectVersion;

/**
 * {@code --report FILE} of {@code accuracy} and {@code bench}: a markdown page stamped with the command, the version
 * and the date, whose figures are those the command printed.
 */
class ReportTest {

	@TempDir
	Path dir;

	/** Runs the command; checks it wrote the page with its title and stamp; returns {the page, the output}. */
	private static String[] run(final Path md, final String title, final String... args) throws Exception {
		final Object[] r = ContactTrackerCliTest.run(args);
		assertEquals(0, r[0], (String) r[2]);
		final String page = Files.readString(md);
		assertTrue(page.startsWith("# " + title + "\n\n"), page);
		final String stamp = page.lines().skip(2).findFirst().orElseThrow();
		assertTrue(stamp.startsWith("Written by `scripts/contact-tracker " + String.join(" ", args) +
			"` (Contact Tracker " + ProjectVersion.get() + ") on " + LocalDate.now(ZoneOffset.UTC) + " (UTC), "), stamp);
		return new String[] { page, (String) r[1] };
	}

	@Test
	void accuracyReportHasThePrintedFigures() throws Exception {
		final Path md = dir.resolve("accuracy.md");
		final String[] args = { "accuracy", "--particle", "5.53", "--scenario", "pair", "--methods", "paper,fit",
			"--separations", "1.2,1", "--reps", "3", "--threads", "1", "--report", md.toString() };
		final String[] r = run(md, "Accuracy: the paper's protocol", args);
		final String page = r[0];
		// the printed row of fit at contact, in the table at contact: the same mean error, std and CRB
		final String printed = r[1].lines().filter(l -> l.startsWith("  1.00 fit")).findFirst()
			.orElseThrow();
		final String[] cells = printed.split("[|\\s]+");
		final String atContact = page.lines().filter(l -> l.startsWith("| silica 5.53 um pair | `fit` |")).findFirst()
			.orElseThrow();
		final List<String> row = List.of(atContact.split(" \\| "));
		assertEquals(Double.parseDouble(cells[3]), Double.parseDouble(row.get(2)), 0, atContact);
		assertEquals(cells[4], row.get(3), atContact);
		assertEquals(cells[cells.length - 1], row.get(4), atContact);
		assertTrue(page.contains("## Every separation"), page);
		assertEquals(2, page.lines().filter(l -> l.startsWith("| 1.00 |")).count(), page);
	}

	@Test
	void sceneReportHasATablePerParticle() throws Exception {
		final Path md = dir.resolve("scenes.md");
		final String[] args = { "accuracy", "--scene", "pair", "--particle", "5.53", "--reps", "2", "--threads", "1",
			"--report", md.toString() };
		final String page = run(md, "Accuracy: harder scenes at contact", args)[0];
		assertTrue(page.contains("## silica 5.53 um\n"), page);
		assertEquals(1, page.lines().filter(l -> l.startsWith("| pair |")).count(), page);
	}

	@Test
	void benchReportHasEveryMethod() throws Exception {
		final Path md = dir.resolve("bench.md");
		final String[] args = { "bench", "--frames", "2", "--rounds", "1", "--profile-frames", "1", "--no-end-to-end",
			"--report", md.toString() };
		final String page = run(md, "Speed: bench", args)[0];
		for (final String m : List.of("first", "paper", "iterative", "deblend", "fit"))
			assertTrue(page.contains("| " + m + " (1 thread) |"), page);
		assertTrue(page.contains("| read pass (1 thread) |"), page);
	}
}
