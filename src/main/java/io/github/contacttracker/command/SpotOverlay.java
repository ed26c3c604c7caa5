package io.github.contacttracker.command;

import java.awt.Color;
import java.awt.Rectangle;
import java.awt.geom.Area;
import java.awt.geom.Path2D;
import java.util.ArrayList;
import java.util.List;
import java.util.StringJoiner;

import ij.ImagePlus;
import ij.gui.OvalRoi;
import ij.gui.Overlay;
import ij.gui.PointRoi;
import ij.gui.Roi;
import ij.gui.ShapeRoi;
import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.FrameResult;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Region;
import io.github.contacttracker.io.OverlayPng;

/**
 * The ROIs Contact Tracker draws on an image, in the colours of {@link OverlayPng} so that one scheme serves
 * both: per spot, the {@code r_out} disc around the first-pass centre (cyan; magenta and thicker when the spot
 * is flagged), the second active area's outline (green, 1.5 px), the final centre (red cross) and, drawn over
 * it, the first-pass centre (yellow dot). Each ROI sits on its frame.
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
		/** The {@code r_out} disc around the first-pass centre. */
		DISC("disc", OverlayPng.DISC),
		/** The outline of the second active area. */
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

		/** @return the colour (a flagged spot's disc is {@link OverlayPng#FLAGGED} instead) */
		public Color color() {
			return color;
		}
	}

	/** Puts a ROI on a frame of an image. */
	@FunctionalInterface
	public interface FramePlacer {
		void place(Roi roi, int frame);
	}

	private SpotOverlay() {}

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
	 * @param rOut the {@code r_out} used (px)
	 * @param placer puts each ROI on its frame
	 * @return the ROIs, spot by spot (IDs counted over all frames, as in the spots table)
	 */
	public static List<Roi> rois(final List<FrameResult> results, final double rOut, final FramePlacer placer) {
		final List<Roi> rois = new ArrayList<>();
		int id = 0;
		for (final FrameResult r : results) {
			final List<Localization> spots = r.spots();
			for (int k = 0; k < spots.size(); k++, id++) {
				final Localization s = spots.get(k);
				final String name = "spot " + id;
				final String flags = flagText(s);

				final Roi disc = new OvalRoi(s.firstX() + 0.5 - rOut, s.firstY() + 0.5 - rOut, 2 * rOut, 2 * rOut);
				add(rois, disc, Kind.DISC, id, name + " " + Kind.DISC.label() + flags, s, placer);
				if (s.isFlagged()) {
					disc.setStrokeColor(OverlayPng.FLAGGED);
					disc.setStrokeWidth(FLAGGED_STROKE);
				}
				if (k < r.secondAreas().size() && r.secondAreas().get(k).area() > 0) {
					final Roi outline = outline(r.secondAreas().get(k));
					// a 1 px line is lost on a saturated core: a wider one stays visible
					outline.setStrokeWidth(OUTLINE_STROKE);
					add(rois, outline, Kind.SECOND_AREA, id, name + " " + Kind.SECOND_AREA.label(), s, placer);
				}

				final PointRoi last = new PointRoi(s.x() + 0.5, s.y() + 0.5);
				last.setPointType(PointRoi.CROSS);
				last.setSize(3); // large
				add(rois, last, Kind.FINAL, id, name + " " + Kind.FINAL.label() + flags, s, placer);

				// after the cross, so that it is drawn on top: the two centres are often less than a pixel apart
				final PointRoi first = new PointRoi(s.firstX() + 0.5, s.firstY() + 0.5);
				first.setPointType(PointRoi.DOT);
				first.setSize(2); // medium: a small dot vanished under the cross
				add(rois, first, Kind.FIRST_PASS, id, name + " " + Kind.FIRST_PASS.label(), s, placer);
			}
		}
		return rois;
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
