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
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;

import org.junit.jupiter.api.Test;

/**
 * Where the Contact Tracker dialog goes: beside its image, not over it (in a real ImageJ2 + imagej-legacy 2.0.3 it
 * opened in the middle of the screen, over the image its Preview draws on).
 */
class DialogBesideImageTest {

	private static final Rectangle SCREEN = new Rectangle(0, 0, 1600, 1000);
	/** The dialog's size as seen on screen. */
	private static final Dimension DIALOG = new Dimension(623, 637);

	@Test
	void rightOfTheImageWhenItFits() {
		final Rectangle image = new Rectangle(100, 90, 460, 540);
		assertEquals(new Rectangle(100 + 460 + DialogBesideImage.GAP, 90, 623, 637), DialogBesideImage.beside(image,
			DIALOG, SCREEN));
	}

	/** The ImageJ window of the real check: the image opened under the toolbar, right of the middle. */
	@Test
	void leftOfTheImageWhenTheRightHasNoRoom() {
		final Rectangle image = new Rectangle(790, 90, 460, 540);
		final Rectangle at = DialogBesideImage.beside(image, DIALOG, SCREEN);
		assertEquals(790 - DialogBesideImage.GAP - 623, at.x);
		assertFalse(at.intersects(image));
	}

	@Test
	void aWideImageGetsTheDialogOnItsRoomierSideOnTheScreen() {
		final Rectangle image = new Rectangle(200, 50, 1300, 900);
		final Rectangle at = DialogBesideImage.beside(image, DIALOG, SCREEN);
		assertEquals(0, at.x, "more room left (200 px) than right (100 px): at the screen's left edge");
		assertEquals(50, at.y);
	}

	@Test
	void keptOnTheScreenVertically() {
		final Rectangle image = new Rectangle(100, 700, 300, 250);
		assertEquals(1000 - 637, DialogBesideImage.beside(image, DIALOG, SCREEN).y);
	}

	@Test
	void aDialogLargerThanTheScreenIsLeftWhereItIs() {
		assertNull(DialogBesideImage.beside(new Rectangle(0, 0, 100, 100), new Dimension(700, 1200), SCREEN));
	}

	@Test
	void headlessNothingWatches() {
		if (!GraphicsEnvironment.isHeadless()) return;
		final DialogBesideImage d = new DialogBesideImage("Contact Tracker", () -> null, () -> {});
		d.arm();
		assertFalse(d.armed());
		d.disarm();
	}

	/** The rows hidden under a scroll with screen to spare: the dialog grows until every row shows. */
	@Test
	void aDialogGrowsToShowEveryRow() {
		assertEquals(new Dimension(623, 737), DialogBesideImage.fitted(new Dimension(623, 637), new Dimension(600, 500),
			new Dimension(600, 600), SCREEN));
		// not beyond the screen
		assertEquals(SCREEN.height, DialogBesideImage.fitted(new Dimension(623, 637), new Dimension(600, 500),
			new Dimension(600, 1600), SCREEN).height);
		// a row cut on the right widens it
		assertEquals(643, DialogBesideImage.fitted(new Dimension(623, 637), new Dimension(600, 500), new Dimension(620,
			500), SCREEN).width);
	}

	/** 200 px of blank space below the rows: the dialog shrinks to them, not below a usable height. */
	@Test
	void aDialogShrinksToItsRows() {
		assertEquals(new Dimension(623, 437), DialogBesideImage.fitted(new Dimension(623, 637), new Dimension(600, 500),
			new Dimension(580, 300), SCREEN));
		assertEquals(DialogBesideImage.MIN_HEIGHT, DialogBesideImage.fitted(new Dimension(623, 637), new Dimension(600,
			500), new Dimension(580, 10), SCREEN).height);
	}
}
