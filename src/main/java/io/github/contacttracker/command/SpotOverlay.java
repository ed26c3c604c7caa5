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
import java.awt.Rectangle;
import java.awt.geom.Area;
import java.awt.geom.Path2D;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.StringJoiner;

import ij.ImagePlus;
import ij.gui.OvalRoi;
import ij.gui.Overlay;
import ij.gui.PointRoi;
import ij.gui.Roi;
import ij.gui.ShapeRoi;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.image.Region;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.io.OverlayPng;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.pipeline.KindRadii;

/**
 * The ROIs Contact Tracker draws on an image: per spot, the particle's outline (a circle of the spot's
 * {@code RADIUS} around its centre: cyan, or thicker in its flag's colour when the spot is flagged,
 * {@link #flagColor}), the first-pass centre (yellow dot) and, drawn over it, the final centre (red cross). For
 * diagnostics, on request, the {@code r_out} disc around the first-pass centre (grey-blue) and the second active
 * area's outline (green, 1.5 px): they showed how the method works, but a clipped crescent at contact read as a
 * failed detection and overlapping large discs cluttered the image. The centres' colours are {@link OverlayPng}'s.
 * Each ROI sits on its frame; {@link #legend} says what the colours mean, in the Log and in a legend window
 * ({@link OverlayLegend}).
 * <p>
 * Coordinates: spots are in TrackMate's convention (pixel (0,0)'s centre at 0,0); ImageJ puts pixel (0,0)'s
 * centre at 0.5,0.5, so centres and discs are drawn at {@code position + 0.5}. The outline follows pixel edges.
 * <p>
 * Every ROI carries the property {@value #KIND_PROPERTY} (its {@link Kind}) and {@value #SPOT_PROPERTY} (the
 * spot's ID, its row in the spots table); running Contact Tracker again replaces these ROIs and keeps the
 * image's other overlay elements.
 */
public final class SpotOverlay {

	/** Roi property naming what the ROI shows. */
	public static final String KIND_PROPERTY = "ContactTracker";
	/** Roi property holding the spot's ID. */
	public static final String SPOT_PROPERTY = "ContactTrackerSpot";
	/** Stroke width of a flagged spot's disc (px). */
	public static final float FLAGGED_STROKE = 2.5f;
	/** Stroke width of the second active area's outline (px). */
	public static final float OUTLINE_STROKE = 1.5f;

	/** What a ROI shows. */
	public enum Kind {
		/** The particle: a circle of the spot's {@code RADIUS} around the final centre. */
		PARTICLE("particle", OverlayPng.DISC),
		/** The {@code r_out} disc around the first-pass centre (diagnostics). */
		DISC("r_out disc", new Color(120, 150, 200)),
		/** The outline of the second active area (diagnostics). */
		SECOND_AREA("second area", OverlayPng.SECOND_AREA),
		/** The first-pass centre, a small dot. */
		FIRST_PASS("first pass", OverlayPng.FIRST_PASS),
		/** The final centre, a cross. */
		FINAL("final", OverlayPng.FINAL);

		private final String label;
		private final Color color;

		Kind(final String label, final Color color) {
			this.label = label;
			this.color = color;
		}

		/** @return the words used in ROI names */
		public String label() {
			return label;
		}

		/** @return the colour (a flagged spot's particle circle has its flag's colour instead, {@link #flagColor}) */
		public Color color() {
			return color;
		}
	}

	/** Puts a ROI on a frame of an image. */
	@FunctionalInterface
	public interface FramePlacer {
		void place(Roi roi, int frame);
	}

	/** The warning flags in the order their colour wins when a spot has several. */
	private static final List<Flag> FLAG_ORDER = List.of(Flag.MERGED, Flag.NOT_CONVERGED, Flag.FELL_BACK,
		Flag.DEGENERATE, Flag.UNMODELLED_NEIGHBOUR, Flag.AT_BORDER);
	private static final Map<Flag, Color> FLAG_COLORS = new EnumMap<>(Map.of(Flag.MERGED, OverlayPng.FLAGGED,
		Flag.NOT_CONVERGED, new Color(0, 140, 255), Flag.FELL_BACK, Color.WHITE, Flag.DEGENERATE, new Color(255, 130,
			170), Flag.UNMODELLED_NEIGHBOUR, new Color(160, 90, 255), Flag.AT_BORDER, Color.ORANGE));
	private static final Map<Flag, String> COLOR_NAMES = Map.of(Flag.MERGED, "magenta", Flag.NOT_CONVERGED, "blue",
		Flag.FELL_BACK, "white", Flag.DEGENERATE, "pink", Flag.UNMODELLED_NEIGHBOUR, "purple", Flag.AT_BORDER,
		"orange");

	private SpotOverlay() {}

	/**
	 * @return the colour of a flagged spot's particle circle: its first warning flag's in the order merged, not
	 *         converged, fell back, degenerate, neighbour not modelled, at border; {@link OverlayPng#DISC} (cyan) when none
	 */
	public static Color flagColor(final Localization s) {
		for (final Flag f : FLAG_ORDER)
			if (s.has(f)) return FLAG_COLORS.get(f);
		return OverlayPng.DISC;
	}

	/** @return the warning flags in the order their colour wins, each with its colour */
	static Map<Flag, Color> flagColors() {
		final Map<Flag, Color> out = new java.util.LinkedHashMap<>();
		for (final Flag f : FLAG_ORDER)
			out.put(f, FLAG_COLORS.get(f));
		return out;
	}

	/**
	 * @param diagnostics whether the r_out discs and second areas are drawn
	 * @return short lines for the Log: what each colour means
	 */
	public static List<String> legend(final boolean diagnostics) {
		final List<String> items = new ArrayList<>();
		items.add("  overlay: cyan circle = particle (RADIUS), red cross = centre, yellow dot = first-pass centre");
		final StringJoiner flags = new StringJoiner(", ", "  flagged (thicker circle): ", "");
		for (final Flag f : FLAG_ORDER)
			flags.add(COLOR_NAMES.get(f) + " = " + f.description());
		items.add(flags.toString());
		if (diagnostics) items.add("  grey-blue circle = r_out around the first-pass centre, green = second active " +
			"area");
		// ImageJ's Log window cuts (or, narrower, wraps word by word) long lines
		final List<String> lines = new ArrayList<>();
		for (final String item : items)
			lines.addAll(List.of(ShownFrameProfile.wrap(item, ShownFrameProfile.LOG_WIDTH, "    ").split("\n")));
		return lines;
	}

	/**
	 * How ROIs are put on frames of {@code imp}, frames counted as {@code ImagePlusFrames} counts them (time
	 * points; the slices of a plain stack). A hyperstack gets the hyperstack position {@code (c = 0: every
	 * channel, z, t)}; a plain stack gets the stack position; a single frame gets none.
	 */
	public static FramePlacer placer(final ImagePlus imp) {
		final int nz = imp.getNSlices(), nt = imp.getNFrames();
		if (Math.max(nz, nt) <= 1) return (roi, frame) -> {};
		if (imp.isHyperStack() || imp.getNDimensions() > 3) {
			if (nt > 1) return (roi, frame) -> roi.setPosition(0, 0, frame + 1);
			return (roi, frame) -> roi.setPosition(0, frame + 1, 0);
		}
		return (roi, frame) -> roi.setPosition(frame + 1);
	}

	/**
	 * @param results one result per frame, in frame order
	 * @param exclusion the radius (px) of the disc the second pass leaves out around a neighbour's first-pass centre
	 *        ({@code r_out}: {@link io.github.contacttracker.core.TrackerParameters#exclusionRadius()})
	 * @param diameter the particle diameter given (px; 0 = none): the particle circles' radius is the table's
	 *        {@code RADIUS}, half of it, each kind its own ({@link KindRadii}; else each spot's own, its active
	 *        area's)
	 * @param diagnostics whether to draw the r_out discs and the second active areas too
	 * @param placer puts each ROI on its frame
	 * @return the ROIs, spot by spot (IDs counted over all frames, as in the spots table)
	 */
	public static List<Roi> rois(final List<FrameResult> results, final double exclusion, final double diameter,
		final boolean diagnostics, final FramePlacer placer)
	{
		final List<Roi> rois = new ArrayList<>();
		final double[] radii = diameter > 0 ? KindRadii.of(all(results), diameter) : null;
		int id = 0;
		for (final FrameResult r : results) {
			final List<Localization> spots = r.spots();
			for (int k = 0; k < spots.size(); k++, id++) {
				final Localization s = spots.get(k);
				final String name = "spot " + id;
				final String flags = flagText(s);

				final double radius = radii != null ? radii[s.kind()] : s.radius();
				final Roi particle = new OvalRoi(s.x() + 0.5 - radius, s.y() + 0.5 - radius, 2 * radius, 2 * radius);
				add(rois, particle, Kind.PARTICLE, id, name + " " + Kind.PARTICLE.label() + flags, s, placer);
				if (s.isFlagged()) {
					particle.setStrokeColor(flagColor(s));
					particle.setStrokeWidth(FLAGGED_STROKE);
				}
				if (diagnostics) {
					final Roi disc = new OvalRoi(s.firstX() + 0.5 - exclusion, s.firstY() + 0.5 - exclusion, 2 * exclusion,
						2 * exclusion);
					add(rois, disc, Kind.DISC, id, name + " " + Kind.DISC.label(), s, placer);
				}
				if (diagnostics && k < r.secondAreas().size() && r.secondAreas().get(k).area() > 0) {
					final Roi outline = outline(r.secondAreas().get(k));
					// a 1 px line is lost on a saturated core: a wider one stays visible
					outline.setStrokeWidth(OUTLINE_STROKE);
					add(rois, outline, Kind.SECOND_AREA, id, name + " " + Kind.SECOND_AREA.label(), s, placer);
				}

				// the dot before the cross, so that the result, the cross, is drawn on top (the dot hid it at 100%);
				// where the two centres are less than a pixel apart the dot shows between the cross's arms
				final PointRoi first = new PointRoi(s.firstX() + 0.5, s.firstY() + 0.5);
				first.setPointType(PointRoi.DOT);
				first.setSize(1); // small: the cross's centre stays visible over it
				add(rois, first, Kind.FIRST_PASS, id, name + " " + Kind.FIRST_PASS.label(), s, placer);

				final PointRoi last = new PointRoi(s.x() + 0.5, s.y() + 0.5);
				last.setPointType(PointRoi.CROSS);
				last.setSize(3); // large
				add(rois, last, Kind.FINAL, id, name + " " + Kind.FINAL.label() + flags, s, placer);
			}
		}
		return rois;
	}

	private static List<Localization> all(final List<FrameResult> results) {
		final List<Localization> all = new ArrayList<>();
		for (final FrameResult r : results)
			all.addAll(r.spots());
		return all;
	}

	/**
	 * Sets the ROIs as the image's overlay, replacing Contact Tracker's ROIs of an earlier run and keeping any
	 * other overlay element.
	 */
	public static void show(final ImagePlus imp, final List<Roi> rois) {
		Overlay overlay = imp.getOverlay();
		if (overlay == null) {
			overlay = new Overlay();
			overlay.drawLabels(false);
		}
		else remove(overlay);
		for (final Roi roi : rois)
			overlay.add(roi);
		imp.setOverlay(overlay);
	}

	/** Removes Contact Tracker's ROIs from the image's overlay, if any. */
	public static void clear(final ImagePlus imp) {
		final Overlay overlay = imp.getOverlay();
		if (overlay == null) return;
		remove(overlay);
		imp.setOverlay(overlay.size() == 0 ? null : overlay);
	}

	private static void remove(final Overlay overlay) {
		for (int i = overlay.size() - 1; i >= 0; i--)
			if (overlay.get(i).getProperty(KIND_PROPERTY) != null) overlay.remove(i);
	}

	/** @return the kind of one of our ROIs, or null for any other ROI */
	public static Kind kind(final Roi roi) {
		final String k = roi.getProperty(KIND_PROPERTY);
		if (k == null) return null;
		for (final Kind kind : Kind.values())
			if (kind.name().equals(k)) return kind;
		return null;
	}

	/** @return the spot ID of one of our ROIs, or -1 */
	public static int spotId(final Roi roi) {
		final String id = roi.getProperty(SPOT_PROPERTY);
		return id == null ? -1 : Integer.parseInt(id);
	}

	/** @return the outline of a region along its pixels' edges (ImageJ coordinates) */
	static Roi outline(final Region region) {
		final Path2D.Double path = new Path2D.Double(Path2D.WIND_NON_ZERO);
		for (int i = 0; i < region.runCount(); i++)
			path.append(new Rectangle(region.runStart(i), region.runY(i), region.runEnd(i) - region.runStart(i) + 1, 1),
				false);
		final ShapeRoi shape = new ShapeRoi(new Area(path));
		final Roi simple = shape.trySimplify();
		return simple != null ? simple : shape;
	}

	private static void add(final List<Roi> rois, final Roi roi, final Kind kind, final int id, final String name,
		final Localization s, final FramePlacer placer)
	{
		roi.setStrokeColor(kind.color());
		roi.setName(name);
		roi.setProperty(KIND_PROPERTY, kind.name());
		roi.setProperty(SPOT_PROPERTY, Integer.toString(id));
		placer.place(roi, s.frame());
		rois.add(roi);
	}

	private static String flagText(final Localization s) {
		if (!s.isFlagged()) return "";
		final StringJoiner j = new StringJoiner(", ", " [", "]");
		for (final Flag f : s.flagSet())
			if (f.isWarning()) j.add(f.description());
		return j.toString();
	}
}
