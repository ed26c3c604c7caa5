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

import java.awt.AWTEvent;
import java.awt.Component;
import java.awt.Container;
import java.awt.Dialog;
import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.AWTEventListener;
import java.awt.event.WindowEvent;
import java.util.function.Supplier;

import javax.swing.JLabel;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;

import ij.ImagePlus;
import io.github.contacttracker.ui.WindowsBeside;

/**
 * Sizes a command's dialog to its rows and puts it beside its image instead of over it. SciJava's Swing dialog (the input harvester's) is
 * modal and opens in the middle of the screen, where it covered the image that its Preview draws on and that its
 * "Measure from the image" button measures (seen in a real ImageJ2 + imagej-legacy 2.0.3). The command arms this
 * before its dialog exists (from its initializer); when the dialog of that title opens, it is sized to show every
 * row without blank space ({@link #fitted}) and moved beside the image's window, on the side with room for it,
 * and this disarms itself. No dialog (a macro, a script, headless):
 * {@link #disarm()} when the command runs.
 */
final class DialogBesideImage implements AWTEventListener {

	/** Between the image's window and the dialog (px). */
	static final int GAP = 8;

	private final String title;
	private final Supplier<ImagePlus> image;
	private final Runnable opened;
	private boolean armed; // guarded by DialogBesideImage.class
	/** The dialog, once open. */
	private volatile Dialog dialog;

	/**
	 * @param title the dialog's title (the command's label)
	 * @param image the command's image, read when the dialog opens (SciJava fills it in before the dialog)
	 * @param opened what the command does when its dialog has opened (on the event thread)
	 */
	DialogBesideImage(final String title, final Supplier<ImagePlus> image, final Runnable opened) {
		this.title = title;
		this.image = image;
		this.opened = opened;
	}

	/**
	 * Changes the text of one of the dialog's message rows (SciJava shows a message input as a label, drawn when the
	 * dialog opens): what a command learns while its dialog is open (a preview's spot count) shows in the dialog.
	 * Nothing happens before the dialog opens, or headless.
	 *
	 * @param from the row's text now
	 * @param to its new text
	 */
	void relabel(final String from, final String to) {
		final Dialog d = dialog;
		if (d == null || from.equals(to)) return;
		SwingUtilities.invokeLater(() -> {
			final JLabel label = label(d, from);
			if (label != null) label.setText(to);
		});
	}

	/** @return the first label with this text in the container, or null */
	private static JLabel label(final Container c, final String text) {
		for (final Component child : c.getComponents()) {
			if (child instanceof JLabel l && text.equals(l.getText())) return l;
			if (child instanceof Container inner) {
				final JLabel l = label(inner, text);
				if (l != null) return l;
			}
		}
		return null;
	}

	/** The one armed, if any: a run cancelled before its dialog must not place the next run's dialog. */
	private static DialogBesideImage current;

	/** Watches for the dialog (not headless), instead of any run's that still watches. */
	void arm() {
		if (GraphicsEnvironment.isHeadless()) return;
		synchronized (DialogBesideImage.class) {
			if (current != null) current.disarm();
			current = this;
			Toolkit.getDefaultToolkit().addAWTEventListener(this, AWTEvent.WINDOW_EVENT_MASK);
			armed = true;
		}
	}

	/** Stops watching: the dialog was placed, or the command runs without one. */
	void disarm() {
		synchronized (DialogBesideImage.class) {
			if (!armed) return;
			Toolkit.getDefaultToolkit().removeAWTEventListener(this);
			armed = false;
			if (current == this) current = null;
		}
	}

	/** @return whether it watches for the dialog */
	boolean armed() {
		synchronized (DialogBesideImage.class) {
			return armed;
		}
	}

	@Override
	public void eventDispatched(final AWTEvent event) {
		if (event.getID() != WindowEvent.WINDOW_OPENED || !(event.getSource() instanceof Dialog)) return;
		final Dialog dialog = (Dialog) event.getSource();
		if (!title.equals(dialog.getTitle())) return;
		disarm();
		this.dialog = dialog;
		opened.run();
		final ImagePlus imp = image.get();
		final Window window = imp == null ? null : imp.getWindow();
		final boolean besideWindow = window != null && window.isShowing();
		final Rectangle screen = WindowsBeside.usableScreen((besideWindow ? window : dialog).getGraphicsConfiguration());
		final JScrollPane scroll = firstScrollPane(dialog);
		if (scroll != null) {
			// every row shown, no blank space: the dialog as large as its rows, as far as the screen allows
			final Dimension size = fitted(dialog.getSize(), scroll.getViewport().getExtentSize(), scroll.getViewport()
				.getView() == null ? scroll.getViewport().getExtentSize() : scroll.getViewport().getView()
					.getPreferredSize(), screen);
			if (!size.equals(dialog.getSize())) {
				dialog.setSize(size);
				dialog.validate();
			}
		}
		if (!besideWindow) return;
		final Rectangle at = beside(window.getBounds(), dialog.getSize(), screen);
		if (at != null) dialog.setLocation(at.x, at.y);
	}

	/** @return the first scroll pane in the dialog (the one the dialog's rows are in), or null */
	private static JScrollPane firstScrollPane(final Container c) {
		for (final Component child : c.getComponents()) {
			if (child instanceof JScrollPane s) return s;
			if (child instanceof Container inner) {
				final JScrollPane s = firstScrollPane(inner);
				if (s != null) return s;
			}
		}
		return null;
	}

	/**
	 * The size of a dialog whose rows lie in a scroll pane, grown or shrunk so that the pane shows all of its rows
	 * and nothing more (the Threads row was hidden under a scroll with screen to spare; other dialogs carried
	 * 200 px of blank space), kept within the screen. Not wider than now unless a row is cut.
	 *
	 * @param dialog the dialog's size
	 * @param viewport the size the scroll pane shows
	 * @param rows the size its rows need
	 * @param screen the usable screen
	 * @return the dialog's new size
	 */
	static Dimension fitted(final Dimension dialog, final Dimension viewport, final Dimension rows,
		final Rectangle screen)
	{
		final int h = dialog.height + rows.height - viewport.height;
		final int w = dialog.width + Math.max(0, rows.width - viewport.width);
		return new Dimension(Math.min(w, screen.width), Math.max(Math.min(h, screen.height), Math.min(dialog.height,
			MIN_HEIGHT)));
	}

	/** A dialog is never shrunk below this height (px): its buttons and a few rows. */
	static final int MIN_HEIGHT = 160;

	/**
	 * Where a dialog goes beside an image's window: to its right if the dialog fits there on the screen, else to its
	 * left, else to the side with more room, overlapping the image as little as it can; top aligned with the
	 * window's, kept on the screen.
	 *
	 * @param image the image window's bounds
	 * @param dialog the dialog's size
	 * @param screen the usable screen
	 * @return the dialog's new bounds, or {@code null} if it does not fit on the screen at all (leave it)
	 */
	static Rectangle beside(final Rectangle image, final Dimension dialog, final Rectangle screen) {
		if (dialog.width > screen.width || dialog.height > screen.height) return null;
		final int right = image.x + image.width + GAP, left = image.x - GAP - dialog.width;
		final int roomRight = screen.x + screen.width - (right + dialog.width), roomLeft = left - screen.x;
		int x;
		if (roomRight >= 0) x = right;
		else if (roomLeft >= 0) x = left;
		else x = roomRight >= roomLeft ? screen.x + screen.width - dialog.width : screen.x;
		final int y = Math.max(screen.y, Math.min(image.y, screen.y + screen.height - dialog.height));
		return new Rectangle(x, y, dialog.width, dialog.height);
	}
}
