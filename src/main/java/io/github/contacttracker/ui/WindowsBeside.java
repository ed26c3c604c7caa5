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

import java.awt.Dialog;
import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.Window;
import java.util.ArrayList;
import java.util.List;

import ij.IJ;
import ij.ImagePlus;
import ij.WindowManager;

/**
 * Moves the windows our commands open (the Log, tables, plots) to where they cover neither the image being
 * worked on nor an open dialog: beside them on the screen. ImageJ opens such windows where it last had them, or in
 * the middle of the screen, and there they covered the image, the modal dialog's Preview and Measure, TrackMate's
 * Next button, or a table they belong with (seen in a real ImageJ2 and TrackMate 8.0.0). A window that already
 * covers none of them stays where the user put it.
 */
public final class WindowsBeside {

	/** Between windows (px). */
	static final int GAP = 8;

	private WindowsBeside() {}

	/**
	 * Writes to ImageJ's Log window, then moves it clear of the image and open dialogs.
	 *
	 * @param text the lines
	 * @param imp the image worked on (may be null)
	 * @param keep other windows to keep clear (TrackMate's wizard, ...; nulls ignored)
	 */
	public static void log(final String text, final ImagePlus imp, final Window... keep) {
		IJ.log(text);
		move(WindowManager.getWindow("Log"), imp, keep);
	}

	/**
	 * Moves a window clear of the image's window, every showing dialog and the windows given, if it covers one of
	 * them, and as far as it can clear of every other window (our tables, the Log, plots: they matter less), to the
	 * first clear place beside them on the screen (else to where it covers least, the image and dialogs weighing
	 * most).
	 *
	 * @param w the window (null, hidden or headless: nothing happens)
	 * @param imp the image worked on (may be null)
	 * @param keep other windows to keep clear (nulls ignored)
	 */
	public static void move(final Window w, final ImagePlus imp, final Window... keep) {
		if (w == null || GraphicsEnvironment.isHeadless() || !w.isShowing()) return;
		final List<Rectangle> avoid = new ArrayList<>();
		if (imp != null && imp.getWindow() != null && imp.getWindow().isShowing()) avoid.add(imp.getWindow()
			.getBounds());
		for (final Window k : keep)
			if (k != null && k != w && k.isShowing()) avoid.add(k.getBounds());
		final List<Rectangle> rather = new ArrayList<>();
		for (final Window d : Window.getWindows()) {
			if (d == w || !d.isShowing() || d == ij.IJ.getInstance()) continue;
			if (d instanceof Dialog) avoid.add(d.getBounds());
			else if (!avoid.contains(d.getBounds())) rather.add(d.getBounds());
		}
		final Point at = place(w.getBounds(), avoid, rather, usableScreen(w.getGraphicsConfiguration()));
		if (at != null) w.setLocation(at);
	}

	/** How much more covering the image or a dialog weighs than covering another window. */
	static final long MUST = 1000;

	/**
	 * Where a window goes: where it is if it covers none of {@code avoid} nor of {@code rather}; else the first place
	 * beside one of them (right, left, below, above of each in turn, the first most wanted) that is on the screen and
	 * covers none; else the place among those that covers least ({@code avoid} weighing {@link #MUST} times more).
	 *
	 * @param window the window's bounds
	 * @param avoid what it must not cover, most important first
	 * @param rather what it had better not cover
	 * @param screen the usable screen
	 * @return its new top-left corner, or null to leave it where it is
	 */
	static Point place(final Rectangle window, final List<Rectangle> avoid, final List<Rectangle> rather,
		final Rectangle screen)
	{
		final long now = MUST * covered(window, avoid) + covered(window, rather);
		if (now == 0) return null;
		final Dimension d = window.getSize();
		final List<Rectangle> all = new ArrayList<>(avoid);
		all.addAll(rather);
		Point best = null;
		long least = now;
		for (final Rectangle r : all) {
			final Point[] beside = { new Point(r.x + r.width + GAP, r.y), new Point(r.x - GAP - d.width, r.y), new Point(
				r.x, r.y + r.height + GAP), new Point(r.x, r.y - GAP - d.height) };
			for (final Point p : beside) {
				final Point on = onScreen(p, d, screen);
				final Rectangle at = new Rectangle(on, d);
				final long c = MUST * covered(at, avoid) + covered(at, rather);
				if (c < least) {
					least = c;
					best = on;
				}
				if (c == 0) return on;
			}
		}
		return best;
	}

	/** @return the corner moved so that the window lies on the screen (its top-left kept on it if it is larger) */
	private static Point onScreen(final Point p, final Dimension d, final Rectangle screen) {
		final int x = Math.max(screen.x, Math.min(p.x, screen.x + screen.width - d.width));
		final int y = Math.max(screen.y, Math.min(p.y, screen.y + screen.height - d.height));
		return new Point(x, y);
	}

	/** @return the area of the window that covers the rectangles, summed */
	private static long covered(final Rectangle window, final List<Rectangle> avoid) {
		long area = 0;
		for (final Rectangle r : avoid) {
			final Rectangle i = window.intersection(r);
			if (!i.isEmpty()) area += (long) i.width * i.height;
		}
		return area;
	}

	/** @return the screen's bounds less its task bars */
	public static Rectangle usableScreen(final GraphicsConfiguration gc) {
		final Rectangle screen = gc.getBounds();
		final Insets insets = Toolkit.getDefaultToolkit().getScreenInsets(gc);
		screen.x += insets.left;
		screen.y += insets.top;
		screen.width -= insets.left + insets.right;
		screen.height -= insets.top + insets.bottom;
		return screen;
	}
}
