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
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.scijava.module.Module;
import org.scijava.prefs.PrefService;

import ij.ImagePlus;
import ij.gui.Line;
import ij.gui.OvalRoi;
import ij.gui.PointRoi;
import ij.gui.Roi;
import ij.measure.ResultsTable;
import io.github.contacttracker.command.ContactTrackerProfileCommand;
import io.github.contacttracker.command.WithContext;

/**
 * Fuzzes the Profile command headless, as a script runs it: random images from 1x1 (8, 16, 32 bits and RGB, floats
 * with NaN and infinities, a few frames), a random selection (none, a point on the brightest pixel or anywhere, on
 * the edge or outside the image, a line, a rectangle down to one pixel, an oval) and random inputs. The property:
 * no exception escapes the command's run; a refusal is the command's own error, one line; a run that measures
 * gives the Results table its one row of suggestions.
 * <p>
 * In the suite it runs {@value #SHORT_RUN} cases; a longer run, from a given seed:
 * <pre>
 * mvn -B test -Dtest=ProfileCommandFuzzTest -Dcontact.tracker.fuzz.cases=2000 -Dcontact.tracker.fuzz.seed=7
 * </pre>
 */
class ProfileCommandFuzzTest extends WithContext {

	/** Cases in the suite's run. */
	static final int SHORT_RUN = 150;
	/** The least share of cases that must measure (0.32 to 0.35 do in long runs, 0.44 in the suite's). */
	static final double REACH_FLOOR = 0.25;


	@Test
	void noImageOrSelectionEndsInAnException() throws Exception {
		final int cases = FuzzCase.cases(SHORT_RUN);
		final SplittableRandom rnd = FuzzCase.seeds();
		int measured = 0, refused = 0;
		for (int c = 0; c < cases; c++) {
			final long caseSeed = rnd.nextLong();
			final SplittableRandom r = new SplittableRandom(caseSeed);
			final ImagePlus imp = FuzzImages.image(r, 4);
			final String selection = select(r, imp);
			final Map<String, Object> inputs = inputs(r, imp);
			final String what = "case seed " + caseSeed + ": " + imp.getWidth() + " x " + imp.getHeight() + " x " + imp
				.getStackSize() + ", " + imp.getBitDepth() + "-bit, " + selection + ", inputs " + inputs;
			inputs.put("imp", imp);
			context.service(PrefService.class).clearAll();
			ResultsTable.getResultsTable().reset();
			final Module m = CommandRuns.run(context, ContactTrackerProfileCommand.class, inputs, what);
			if (CommandRuns.refused(m, what)) refused++;
			else {
				measured++;
				if (Boolean.TRUE.equals(inputs.get("results")))
					assertEquals(1, ResultsTable.getResultsTable().size(), "one row of suggestions: " + what);
			}
		}
		FuzzCase.reach("Profile command fuzz", cases, measured, refused, REACH_FLOOR);
	}

	/**
	 * Found by this fuzz (seed 7, case seed 610438763714647442): a diameter far beyond the frame (1e6 px on a 4 x 96
	 * image) kept the Profile command, and {@code profile --diameter}, busy for hours in the threshold's search
	 * between touching particles, whose work grows as the diameter squared. Now refused in one line naming the
	 * diameter and the frame.
	 */
	@Test
	void aDiameterWiderThanTheFrameIsRefusedInOneLine() throws Exception {
		final ij.process.ByteProcessor ip = new ij.process.ByteProcessor(4, 96);
		for (int y = 0; y < 96; y++)
			for (int x = 0; x < 4; x++)
				ip.set(x, y, (int) (20 + 200 * Math.exp(-((y - 32) * (y - 32)) / 8.0)));
		final ImagePlus imp = new ImagePlus("thin", ip);
		imp.setRoi(new PointRoi(3, 32));
		final Map<String, Object> inputs = new LinkedHashMap<>(Map.of("imp", imp, "diameter", 1e6, "plot", false));
		final Module m = CommandRuns.run(context, ContactTrackerProfileCommand.class, inputs, "diameter 1e6");
		assertTrue(CommandRuns.refused(m, "diameter 1e6"), "refused");
		final String reason = ((org.scijava.Cancelable) m).getCancelReason();
		assertTrue(reason.startsWith("diameter 1000000 px is wider than the frame (4 x 96 px)"), reason);
	}

	/** @return the selection given to the image, for a failure's message */
	private static String select(final SplittableRandom r, final ImagePlus imp) {
		final int w = imp.getWidth(), h = imp.getHeight();
		// two cases in three as a user: a point on a particle (the brightest pixel, the darkest one for dark particles)
		switch (r.nextInt(3) > 0 ? 8 : r.nextInt(8)) {
			case 0:
				return "no selection";
			case 8: {
				final int[] at = brightest(imp.getProcessor(), FuzzImages.dark(imp) ? -1 : 1);
				imp.setRoi(new PointRoi(at[0], at[1]));
				return "point on the " + (FuzzImages.dark(imp) ? "darkest" : "brightest") + " pixel " + at[0] + ", " + at[1];
			}
			case 1:
				imp.setRoi(new PointRoi(r.nextInt(w), r.nextInt(h)));
				return "point " + imp.getRoi().getBounds().getLocation();
			case 2: {
				final int x = r.nextBoolean() ? 0 : w - 1, y = r.nextInt(h);
				imp.setRoi(new PointRoi(x, y));
				return "point on the edge " + x + ", " + y;
			}
			case 3:
				imp.setRoi(new PointRoi(w + 3 + r.nextInt(50), -1 - r.nextInt(20)));
				return "point outside the image";
			case 4:
				imp.setRoi(new Line(0, 0, w, h));
				return "a line";
			case 5: {
				final int x = r.nextInt(w), y = r.nextInt(h);
				imp.setRoi(new Roi(x, y, 1 + r.nextInt(w - x), 1 + r.nextInt(h - y)));
				return "selection " + imp.getRoi().getBounds();
			}
			case 6:
				imp.setRoi(new OvalRoi(0, 0, w, h));
				return "an oval selection";
			default:
				imp.setRoi(new Roi(w + 5, h + 5, 10, 10));
				return "a rectangle outside the image";
		}
	}

	/**
	 * @param sign 1 for the brightest pixel, -1 for the darkest
	 * @return the first brightest pixel's x and y (for colour, of the processor's own value)
	 */
	private static int[] brightest(final ij.process.ImageProcessor ip, final int sign) {
		int bx = 0, by = 0;
		float best = Float.NEGATIVE_INFINITY;
		for (int y = 0; y < ip.getHeight(); y++)
			for (int x = 0; x < ip.getWidth(); x++)
				if (sign * ip.getPixelValue(x, y) > best) {
					best = sign * ip.getPixelValue(x, y);
					bx = x;
					by = y;
				}
		return new int[] { bx, by };
	}

	/**
	 * @return random inputs: the sensible ones (the diameter measured or the particles', the profile's reach
	 *         measured) but for none, one or two that are out of range or odd; some left out
	 */
	private static Map<String, Object> inputs(final SplittableRandom r, final ImagePlus imp) {
		final Object[][] choices = { { "diameter", r.nextBoolean() ? 0.0 : (double) FuzzImages.diameter(imp), 4.0, 12.0,
			1.0, 0.1, -2.0, 1e6, Double.NaN, Double.POSITIVE_INFINITY }, { "max_radius", 0.0, 20.0, 2.0, 0.5, -1.0, 1e7,
				Double.NaN }, { "plot", false, true }, { "results", true, false } };
		final List<Integer> odd = FuzzCase.oddOnes(r, choices.length);
		final Map<String, Object> in = new LinkedHashMap<>();
		for (int i = 0; i < choices.length; i++) {
			final Object[] c = choices[i];
			if (odd.contains(i)) in.put((String) c[0], c[1 + r.nextInt(c.length - 1)]);
			else if (r.nextBoolean()) in.put((String) c[0], c[1]);
		}
		return in;
	}
}
