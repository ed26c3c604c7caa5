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
package io.github.contacttracker.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.Rectangle;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Windows our commands open go beside the image and the dialog, never over them. */
class WindowsBesideTest {

	private static final Rectangle SCREEN = new Rectangle(0, 0, 1680, 1050);
	/** A 501 x 501 image at 100%, and the dialog beside it, as in the screenshots. */
	private static final Rectangle IMAGE = new Rectangle(20, 60, 520, 580), DIALOG = new Rectangle(548, 60, 623, 900);

	@Test
	void aWindowCoveringNothingStays() {
		assertNull(WindowsBeside.place(new Rectangle(1200, 60, 400, 300), List.of(IMAGE, DIALOG), List.of(), SCREEN));
	}

	/** The Log (its default size) opened over the image and half behind the dialog: it goes beside both. */
	@Test
	void theLogGoesBesideTheImageAndTheDialog() {
		final Rectangle log = new Rectangle(300, 300, 500, 400);
		final Point at = WindowsBeside.place(log, List.of(IMAGE, DIALOG), List.of(), SCREEN);
		final Rectangle moved = new Rectangle(at, log.getSize());
		assertTrue(!moved.intersects(IMAGE) && !moved.intersects(DIALOG), moved.toString());
		assertTrue(SCREEN.contains(moved), moved.toString());
		// below the image: the first clear place beside it
		assertEquals(new Point(IMAGE.x, IMAGE.y + IMAGE.height + WindowsBeside.GAP), at);
	}

	/** No clear place on the screen: the place that covers least. */
	@Test
	void noClearPlaceCoversLeast() {
		final Rectangle big = new Rectangle(0, 0, 1600, 1000);
		final Rectangle log = new Rectangle(100, 100, 500, 400);
		final Point at = WindowsBeside.place(log, List.of(big), List.of(), SCREEN);
		final Rectangle moved = new Rectangle(at, log.getSize());
		assertTrue(SCREEN.contains(moved));
		assertTrue(moved.intersection(big).width * moved.intersection(big).height < 500 * 400, moved.toString());
	}

	/**
	 * The Log after the spots table: clear of the image and of the table too (it opened over the table, both left of
	 * the image, seen under Xvfb); covering the table is better than covering the image when nothing is clear.
	 */
	@Test
	void theLogAlsoKeepsClearOfTheTable() {
		final Rectangle image = new Rectangle(850, 80, 510, 540), table = new Rectangle(140, 80, 700, 500);
		final Rectangle log = new Rectangle(440, 80, 400, 300);
		final Point at = WindowsBeside.place(log, List.of(image), List.of(table), SCREEN);
		final Rectangle moved = new Rectangle(at, log.getSize());
		assertTrue(!moved.intersects(image) && !moved.intersects(table) && SCREEN.contains(moved), moved.toString());
		// a screen too small for both: the table is covered, not the image
		final Rectangle small = new Rectangle(0, 0, 1400, 640);
		final Rectangle squeezed = new Rectangle(WindowsBeside.place(log, List.of(image), List.of(table), small), log
			.getSize());
		assertTrue(!squeezed.intersects(image) && small.contains(squeezed), squeezed.toString());
	}
}
