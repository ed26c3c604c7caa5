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
package io.github.contacttracker.io;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.track.FrameResult;
import net.imglib2.Cursor;
import net.imglib2.RandomAccessibleInterval;
import net.imglib2.type.numeric.RealType;

/**
 * Draws frames with their spots into a PNG, panels side by side: the disc the paper's second pass leaves out
 * around each particle's first-pass centre (cyan, radius {@code r_out}), the second active area's outline (green),
 * the first-pass centre (yellow dot), the final centre (red cross); a flagged spot's disc is drawn in magenta.
 */
public final class OverlayPng {

	/**
	 * One panel: a frame, what was found in it, the discs' radius (px:
	 * {@link io.github.contacttracker.core.TrackerParameters#exclusionRadius()}), and a caption.
	 */
	public record Panel(RandomAccessibleInterval<? extends RealType<?>> frame, FrameResult result,
		double exclusionRadius, String caption)
	{}

	public static final Color DISC = Color.CYAN;
	/** A mid-dark green: pure green (0, 255, 0) is nearly as light as the white of a saturated core. */
	public static final Color SECOND_AREA = new Color(0, 190, 0);
	public static final Color FIRST_PASS = Color.YELLOW;
	public static final Color FINAL = Color.RED;
	public static final Color FLAGGED = Color.MAGENTA;

	private OverlayPng() {}

	/** Writes the panels, each magnified {@code scale} times, atomically. */
	public static void write(final Path file, final List<Panel> panels, final int scale) throws IOException {
		int width = 0, height = 0;
		for (final Panel p : panels) {
			width += (int) p.frame().dimension(0) * scale;
			height = Math.max(height, (int) p.frame().dimension(1) * scale + 24);
		}
		final BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
		final Graphics2D g = img.createGraphics();
		g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
		int x0 = 0;
		for (final Panel p : panels) {
			draw(g, img, p, x0, scale);
			x0 += (int) p.frame().dimension(0) * scale;
		}
		g.dispose();
		AtomicFile.write(file, out -> ImageIO.write(img, "png", out));
	}

	private static void draw(final Graphics2D g, final BufferedImage img, final Panel p, final int x0,
		final int scale)
	{
		final RandomAccessibleInterval<? extends RealType<?>> f = p.frame();
		double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
		for (final RealType<?> t : f) {
			min = Math.min(min, t.getRealDouble());
			max = Math.max(max, t.getRealDouble());
		}
		final double range = max > min ? max - min : 1;
		final Cursor<? extends RealType<?>> c = f.localizingCursor();
		while (c.hasNext()) {
			final int v = (int) Math.round(255 * (c.next().getRealDouble() - min) / range);
			final int rgb = v << 16 | v << 8 | v;
			final int px = (int) (c.getLongPosition(0) - f.min(0)), py = (int) (c.getLongPosition(1) - f.min(1));
			for (int dy = 0; dy < scale; dy++)
				for (int dx = 0; dx < scale; dx++)
					img.setRGB(x0 + px * scale + dx, 24 + py * scale + dy, rgb);
		}
		g.setColor(Color.WHITE);
		g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
		g.drawString(p.caption(), x0 + 4, 17);
		final double ox = x0 + 0.5 * scale - f.min(0) * scale, oy = 24 + 0.5 * scale - f.min(1) * scale;
		g.setStroke(new BasicStroke(1.5f));
		final List<Localization> spots = p.result().spots();
		for (int k = 0; k < spots.size(); k++) {
			final Localization s = spots.get(k);
			final double cx = ox + s.x() * scale, cy = oy + s.y() * scale, r = p.exclusionRadius() * scale;
			g.setColor(s.isFlagged() ? FLAGGED : DISC);
			g.draw(new Ellipse2D.Double(ox + s.firstX() * scale - r, oy + s.firstY() * scale - r, 2 * r, 2 * r));
			if (k < p.result().secondAreas().size())
				outline(g, p.result().secondAreas().get(k), x0 - (int) f.min(0) * scale, 24 - (int) f.min(1) * scale,
					scale);
			g.setColor(FIRST_PASS);
			g.fill(new Ellipse2D.Double(ox + s.firstX() * scale - 2.5, oy + s.firstY() * scale - 2.5, 5, 5));
			g.setColor(FINAL);
			g.draw(new Line2D.Double(cx - 6, cy, cx + 6, cy));
			g.draw(new Line2D.Double(cx, cy - 6, cx, cy + 6));
		}
	}

	/** Draws the pixel edges between the region and the outside. */
	private static void outline(final Graphics2D g, final Region region, final int ox, final int oy,
		final int scale)
	{
		g.setColor(SECOND_AREA);
		region.forEachPixel((x, y) -> {
			final int left = ox + x * scale, top = oy + y * scale;
			if (!region.contains(x - 1, y)) g.drawLine(left, top, left, top + scale);
			if (!region.contains(x + 1, y)) g.drawLine(left + scale, top, left + scale, top + scale);
			if (!region.contains(x, y - 1)) g.drawLine(left, top, left + scale, top);
			if (!region.contains(x, y + 1)) g.drawLine(left, top + scale, left + scale, top + scale);
		});
	}
}
