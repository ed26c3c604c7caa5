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

import java.awt.Color;
import java.awt.Font;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import ij.ImagePlus;
import ij.WindowManager;
import ij.process.ColorProcessor;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.ui.WindowsBeside;

/**
 * The overlay's legend as a small picture in a window of its own, beside the image: each mark of
 * {@link SpotOverlay} drawn as on the image, in its colour, with what it means. A legend only in the Log was not
 * found where the marks are seen; drawn on the image it would hide particles (a 100 x 100 image has no free
 * corner). One window, replaced by each run.
 */
final class OverlayLegend {

	/** The legend window's title. */
	static final String TITLE = "Contact Tracker overlay legend";

	static final int ROW = 18, WIDTH = 250, SYMBOL_X = 14, TEXT_X = 30;
	static final Color BACKGROUND = new Color(40, 40, 40);

	private OverlayLegend() {}

	/** One row: a mark and its meaning. */
	record Row(SpotOverlay.Kind mark, Color color, boolean thick, String text) {}

	/** @return the rows: the centres, the particle, each flag's colour, and the diagnostics when drawn */
	static List<Row> rows(final boolean diagnostics) {
		final List<Row> rows = new ArrayList<>();
		rows.add(new Row(SpotOverlay.Kind.FINAL, SpotOverlay.Kind.FINAL.color(), false, "centre (the result)"));
		rows.add(new Row(SpotOverlay.Kind.FIRST_PASS, SpotOverlay.Kind.FIRST_PASS.color(), false, "first-pass centre"));
		rows.add(new Row(SpotOverlay.Kind.PARTICLE, SpotOverlay.Kind.PARTICLE.color(), false, "particle (RADIUS)"));
		for (final Map.Entry<Flag, Color> f : SpotOverlay.flagColors().entrySet())
			rows.add(new Row(SpotOverlay.Kind.PARTICLE, f.getValue(), true, "flagged: " + f.getKey().description()));
		if (diagnostics) {
			rows.add(new Row(SpotOverlay.Kind.DISC, SpotOverlay.Kind.DISC.color(), false, "r_out around first pass"));
			rows.add(new Row(SpotOverlay.Kind.SECOND_AREA, SpotOverlay.Kind.SECOND_AREA.color(), true,
				"second active area"));
		}
		return rows;
	}

	/** @return the legend drawn: one row per mark, on a dark background as the marks are seen on an image */
	static ColorProcessor picture(final boolean diagnostics) {
		final List<Row> rows = rows(diagnostics);
		final ColorProcessor cp = new ColorProcessor(WIDTH, rows.size() * ROW + 8);
		cp.setColor(BACKGROUND);
		cp.fill();
		cp.setAntialiasedText(true);
		cp.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
		for (int i = 0; i < rows.size(); i++) {
			final Row r = rows.get(i);
			final int cy = 4 + i * ROW + ROW / 2;
			cp.setColor(r.color());
			cp.setLineWidth(r.thick() ? 2 : 1);
			switch (r.mark()) {
				case FINAL -> {
					cp.drawLine(SYMBOL_X - 5, cy, SYMBOL_X + 5, cy);
					cp.drawLine(SYMBOL_X, cy - 5, SYMBOL_X, cy + 5);
				}
				case FIRST_PASS -> cp.fillOval(SYMBOL_X - 2, cy - 2, 5, 5);
				case SECOND_AREA -> cp.drawRect(SYMBOL_X - 6, cy - 5, 12, 10);
				default -> cp.drawOval(SYMBOL_X - 6, cy - 6, 13, 13);
			}
			cp.setLineWidth(1);
			cp.setColor(Color.WHITE);
			cp.drawString(r.text(), TEXT_X, cy + 6);
		}
		return cp;
	}

	/**
	 * Shows the legend in its window beside the image (replacing the previous run's), not headless.
	 *
	 * @param imp the image the overlay is on
	 * @param diagnostics whether the diagnostics are drawn
	 * @param keep windows the legend must not cover (the spots table, ...)
	 */
	static void show(final ImagePlus imp, final boolean diagnostics, final Window... keep) {
		if (GraphicsEnvironment.isHeadless()) return;
		final ColorProcessor cp = picture(diagnostics);
		final ImagePlus open = WindowManager.getImage(TITLE);
		if (open != null) {
			open.setProcessor(cp);
			return;
		}
		final ImagePlus legend = new ImagePlus(TITLE, cp);
		legend.show();
		WindowsBeside.move(legend.getWindow(), imp, keep);
	}
}
