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
package io.github.contacttracker.trackmate;

import io.github.contacttracker.settings.FrontEnd;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackMateSettings;
import io.github.contacttracker.settings.TrackingSettings;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.text.DecimalFormat;
import java.text.DecimalFormatSymbols;
import java.util.Locale;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Supplier;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.ImageIcon;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JEditorPane;
import javax.swing.JLabel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.ScrollPaneConstants;
import javax.swing.SpinnerNumberModel;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import fiji.plugin.trackmate.util.DetectionPreview;
import ij.ImagePlus;
import io.github.contacttracker.core.InvalidInputException;
import io.github.contacttracker.pipeline.MeasuredSettings;
import io.github.contacttracker.report.ShownFrameProfile;
import io.github.contacttracker.ui.WindowsBeside;

/**
 * TrackMate's configuration panel for {@link ContactTrackerDetectorFactory}, laid out like TrackMate's own
 * detector panels: icon and name, a short text, compact labelled fields, and TrackMate's Preview (which runs the
 * detector on the current frame and shows the spots on the image). It fits TrackMate's wizard at its default
 * size (about 300 x 510 pixels).
 * <p>
 * {@code r_out} is a size, so it is asked in the image's physical units (with its value in pixels beside it); the
 * setting {@code R_OUT} itself stays in pixels, as on the command line. {@link #getSettings()} always returns a
 * complete map of correctly typed values.
 * <p>
 * A "Measure from the image" button fills in the threshold, {@code r_out} and the diameter from the profile helper,
 * run on the frame on display of TrackMate's image, as the same button of Fiji's Contact Tracker dialog does.
 */
public final class ContactTrackerConfigurationPanel extends ConfigurationPanel {

	private static final long serialVersionUID = 1L;

	/** TrackMate's panel fonts (Arial 10, titles 14). */
	static final Font FONT = new Font("Arial", Font.PLAIN, 10);
	static final Font BIG_FONT = new Font("Arial", Font.PLAIN, 14);

	/** The wizard's panel size, which this panel must fit (TrackMate's own detector panels use it). */
	public static final Dimension WIZARD_SIZE = new Dimension(300, 511);

	/** The icon on the title line: {@link #icon()} at 32 px, as the panel has no height to spare in the wizard. */
	private static final ImageIcon TITLE_ICON = icon(32);

	/** The DOI as the info text shows it. */
	static final String DOI_TEXT = "doi:10.1088/1361-648X/aa908e";

	private static final String SHORT_INFO = "<html><body style='font-family:Arial; font-size:8pt'>"
		+ "Centres of bright particles (dark ones with <b>Particles</b> dark), also when they touch: pixels at or "
		+ "above the <b>threshold</b> form one "
		+ "active area per particle; each centre is found by radial symmetry and refined away from the neighbours "
		+ "(within <b>r_out</b>, where a particle's image ends). <b>fit</b> (default) is unbiased at contact.<br>"
		+ "Y&uuml;cel &amp; Okumu&#351;o&#287;lu, J. Phys.: Condens. Matter 29, 465101 (2017),<br>"
		// the DOI starts a line: Swing breaks lines at its slashes, which cut it in two in the real wizard
		+ "<a href='" + ContactTrackerDetectorFactory.URL + "'>" + DOI_TEXT + "</a>. "
		+ "2D images and time-lapses only.</body></html>";

	/** The label of the button that fills in threshold, r_out and the diameter from the profile helper. */
	static final String MEASURE = "Measure from the image";
	/** Width the measurement's message wraps at (CSS px, which Swing draws about 4/3 wider): the wizard's width. */
	private static final int MESSAGE_WIDTH = 200;

	/** One field per setting of {@link TrackingSettings#ALL}, in that order. */
	private final Map<Setting<?>, Field> fields = new LinkedHashMap<>();
	private final double pixelWidth;
	private final String unit;
	/** TrackMate's image, which the button measures on; null without one. */
	private final transient ImagePlus imp;
	private final JButton measureButton = new JButton(MEASURE);
	/** What the last measurement filled in, or why it did not. */
	private final JLabel measured = new JLabel();

	/**
	 * One setting's control. Lengths in pixels ({@link Setting.Unit#PIXELS}) are shown in the image's physical
	 * units, their value in pixels beside them; the setting itself stays in pixels, as on the command line.
	 */
	private final class Field {
		final Setting<?> setting;
		final JComponent control;
		final JLabel unitLabel = new JLabel();

		Field(final Setting<?> setting, final int nChannels) {
			this.setting = setting;
			if (!setting.choices().isEmpty()) control = new JComboBox<>(setting.choices().toArray());
			else if (setting == TrackingSettings.CHANNEL) control = new JSpinner(new SpinnerNumberModel(1, 1, Math.max(1,
				nChannels), 1));
			else if (setting.type() == Integer.class) control = new JSpinner(new SpinnerNumberModel(setting.min()
				.intValue(), setting.min().intValue(), setting.max() == null ? Integer.MAX_VALUE : setting.max().intValue(),
				1));
			else if (setting.unit() == Setting.Unit.PIXELS) {
				final double min = setting.min() == null ? 0 : setting.min().doubleValue();
				control = doubleSpinner(min * pixelWidth, min * pixelWidth, 1e6 * pixelWidth, pixelWidth, "0.####");
				((JSpinner) control).addChangeListener(e -> showPixels());
			}
			else control = doubleSpinner(0, -1e15, 1e15, 1, "0.###");
			unitLabel.setFont(FONT);
			if (setting.unit() == Setting.Unit.PIXELS && !"pixel".equals(unit)) {
				// wide enough for "micron (9999.99 px)" from the start: the fields do not shift as the pixels change
				final FontMetrics fm = unitLabel.getFontMetrics(FONT);
				final Dimension d = new Dimension(fm.stringWidth(unit + " (9999.99 px)"), fm.getHeight());
				unitLabel.setPreferredSize(d);
				unitLabel.setMinimumSize(d);
			}
		}

		/** Shows a value of the setting's type. */
		void show(final Object value) {
			if (control instanceof JComboBox) ((JComboBox<?>) control).setSelectedItem(value);
			else if (setting.unit() == Setting.Unit.PIXELS) ((JSpinner) control).setValue(units(((Number) value)
				.doubleValue(), pixelWidth));
			else ((JSpinner) control).setValue(value);
			showPixels();
		}

		/** @return the value shown, of the setting's type, in the setting's unit */
		Object value() {
			if (control instanceof JComboBox) return ((JComboBox<?>) control).getSelectedItem();
			final Number n = (Number) ((JSpinner) control).getValue();
			if (setting.type() == Integer.class) return n.intValue();
			// in pixels, to 0.01 px: a length typed in the image's units (shown to 4 decimals) lands on the pixels shown
			// beside it (61 px, not 60.999998), and values in pixels (the helper's, to 0.01 px) survive the units
			if (setting.unit() == Setting.Unit.PIXELS) return pixels(n.doubleValue(), pixelWidth);
			return n.doubleValue();
		}

		private void showPixels() {
			if (setting.unit() != Setting.Unit.PIXELS) return;
			final String px = new DecimalFormat("0.##", DecimalFormatSymbols.getInstance(Locale.ROOT)).format(value());
			unitLabel.setText("pixel".equals(unit) ? "px" : unit + " (" + px + " px)");
		}
	}

	/**
	 * The length to show for a value in pixels: the one with the fewest decimals (up to the 4 the field shows) that
	 * {@link #pixels} takes back to exactly those pixels, so a length typed in the image's units comes back as typed
	 * (5.53 um, not 5.5301 um, after a detector switch or in a new session); else the exact product.
	 *
	 * @param px a length in pixels
	 * @param pixelWidth the pixel width, in the image's units
	 * @return the length in the image's units
	 */
	static double units(final double px, final double pixelWidth) {
		final double exact = px * pixelWidth;
		for (int decimals = 0; decimals <= 4; decimals++) {
			final double scale = Math.pow(10, decimals);
			final double shown = Math.round(exact * scale) / scale;
			if (pixels(shown, pixelWidth) == px) return shown;
		}
		return exact;
	}

	/**
	 * @param length a length in the image's units
	 * @param pixelWidth the pixel width, in the same units
	 * @return the length in pixels, to 0.01 px
	 */
	static double pixels(final double length, final double pixelWidth) {
		return Math.round(length / pixelWidth * 100) / 100.0;
	}

	/**
	 * @param settings TrackMate's settings (for the image: channels, pixel size, Preview); may be {@code null}
	 * @param model TrackMate's model, where Preview puts its spots; may be {@code null}
	 * @param factory the detector factory Preview runs
	 */
	public ContactTrackerConfigurationPanel(final Settings settings, final Model model,
		final SpotDetectorFactoryBase<?> factory)
	{
		final boolean hasImage = settings != null && settings.imp != null;
		final int nChannels = hasImage ? Math.max(1, settings.imp.getNChannels()) : 1;
		pixelWidth = hasImage && settings.dx > 0 && Double.isFinite(settings.dx) ? settings.dx : 1;
		unit = hasImage && settings.imp.getCalibration().scaled() ? settings.imp.getCalibration().getUnit() : "pixel";
		imp = hasImage ? settings.imp : null;

		setLayout(new GridBagLayout());
		setBorder(BorderFactory.createEmptyBorder(5, 5, 5, 5));
		setPreferredSize(WIZARD_SIZE);
		int row = 0;
		final JLabel title = new JLabel(ContactTrackerDetectorFactory.SHORT_NAME, TITLE_ICON, SwingConstants.CENTER);
		title.setFont(BIG_FONT);
		final GridBagConstraints tc = at(0, row++, 3);
		tc.anchor = GridBagConstraints.CENTER;
		tc.fill = GridBagConstraints.NONE;
		add(title, tc);
		add(infoPane(), at(0, row++, 3));

		for (final Setting<?> s : TrackingSettings.ALL) {
			final Field f = new Field(s, nChannels);
			fields.put(s, f);
			// the channel is asked only where there is a choice, as in TrackMate's own panels
			if (s == TrackingSettings.CHANNEL && nChannels < 2) continue;
			if (s.unit() != Setting.Unit.PIXELS) f.unitLabel.setText(s.unit().symbol());
			// the settings' help speaks of pixels, as the command line does; here a length is typed in the image's units
			final String tip = s.unit() == Setting.Unit.PIXELS && !"pixel".equals(unit) ? s.help() + " Typed here in " +
				unit + "; its value in pixels shows beside." : s.help();
			row = addRow(row, s.label(), f.control, f.unitLabel, tip);
		}

		row = addMeasureRows(row);

		final GridBagConstraints fc = at(0, row++, 3);
		fc.weighty = 1;
		fc.fill = GridBagConstraints.BOTH;
		if (hasImage && factory != null) {
			// TrackMate's own preview; our GREY_THRESHOLD is a grey level, not a quality cut-off, so no threshold key
			final DetectionPreview preview = DetectionPreview.create().model(model).settings(settings)
				.detectorFactory(factory).detectionSettingsSupplier(this::getSettings).thresholdKey(null)
				.axisLabel("Quality histogram").get();
			add(preview.getPanel(), fc);
		}
		else add(new JLabel(), fc);
		setSettings(LastSettings.get());
	}

	/** The "Measure from the image" button and, under it, its message. */
	private int addMeasureRows(final int row) {
		measureButton.setFont(FONT);
		measureButton.setMargin(new Insets(1, 6, 1, 6));
		measureButton.setToolTipText("<html>Runs the profile helper on the most isolated particles of the frame on " +
			"display (in the target channel)<br>and fills in threshold, r_out and the particle diameter; a diameter " +
			"above 0 is kept and used<br>(estimated instead if it does not fit this image).</html>");
		measureButton.setEnabled(imp != null);
		measureButton.addActionListener(e -> measureInBackground());
		final GridBagConstraints bc = at(1, row, 2);
		bc.fill = GridBagConstraints.NONE;
		add(measureButton, bc);
		measured.setFont(FONT);
		final GridBagConstraints mc = at(0, row + 1, 3);
		mc.insets = new Insets(0, 3, 0, 3); // no height at all until there is a message: the wizard is short
		add(measured, mc);
		return row + 2;
	}

	/**
	 * Measures on the image, off the event thread (the helper can take a moment on a large frame), then shows the
	 * outcome on the event thread; the button waits meanwhile.
	 */
	private void measureInBackground() {
		measureButton.setEnabled(false);
		final int channel = (Integer) fields.get(TrackingSettings.CHANNEL).value();
		final boolean dark = dark();
		final double diameter = (Double) fields.get(TrackingSettings.DIAMETER).value();
		final SettingValues chosen = chosen();
		final Thread worker = new Thread(() -> {
			Supplier<String> outcome;
			try {
				outcome = measure(channel, dark, diameter, chosen);
			}
			catch (final RuntimeException e) {
				// a bug, not a frame without particles: in full to ImageJ, and the button stays usable
				ij.IJ.handleException(e);
				outcome = () -> showMessage("Not measured: " + e);
			}
			final Supplier<String> shown = outcome;
			SwingUtilities.invokeLater(() -> {
				shown.get();
				measureButton.setEnabled(true);
			});
		}, "Contact Tracker: " + MEASURE);
		worker.setDaemon(true);
		worker.start();
	}

	/**
	 * What the button does, at once on the calling thread (for tests): runs the profile helper on the most isolated
	 * particles of the frame on display, in the target channel, and fills in the threshold, {@code r_out} and the
	 * diameter with its suggestions, and lowers {@code min_area} for particles so small that the default would drop
	 * some; a diameter already given (above 0) is kept and used (estimated instead if the
	 * helper cannot measure with it: {@link ShownFrameProfile#measure}). {@code r_out} and the
	 * diameter are shown in the image's units like every length here. When the helper finds nothing to measure the
	 * fields stay as they were. The outcome is shown under the button and written to ImageJ's Log window, with the
	 * helper's warnings.
	 *
	 * @return the message shown under the button
	 */
	String measureFromImage() {
		return measure((Integer) fields.get(TrackingSettings.CHANNEL).value(), dark(), (Double) fields.get(
			TrackingSettings.DIAMETER).value(), chosen()).get();
	}

	/** @return the method and detection the fields say (read on the event thread, for the helper's fall-back) */
	private SettingValues chosen() {
		return SettingValues.defaults().withText(TrackingSettings.METHOD, String.valueOf(fields.get(
			TrackingSettings.METHOD).value())).withText(TrackingSettings.DETECTION, String.valueOf(fields.get(
				TrackingSettings.DETECTION).value()));
	}

	/** @return whether the fields say the particles are dark */
	private boolean dark() {
		return TrackingSettings.DARK.equals(fields.get(TrackingSettings.PARTICLES).value());
	}

	/**
	 * Runs the helper (on any thread).
	 *
	 * @return what shows its outcome (on the event thread): fills the fields, or not, and returns the message
	 */
	private Supplier<String> measure(final int channel, final boolean dark, final double diameter,
		final SettingValues chosen)
	{
		final ShownFrameProfile p;
		try {
			p = ShownFrameProfile.measure(imp, channel, dark, diameter);
		}
		catch (final InvalidInputException e) {
			return () -> {
				WindowsBeside.log(ContactTrackerDetectorFactory.SHORT_NAME + ": cannot measure from the image: " + e
					.getMessage(), imp, javax.swing.SwingUtilities.getWindowAncestor(this));
				return showMessage("Not measured: " + e.getMessage());
			};
		}
		if (!p.thresholdInFrame()) return byImage(p, dark, diameter, chosen);
		return () -> {
			if (p.darkFound()) fields.get(TrackingSettings.PARTICLES).show(TrackingSettings.DARK);
			fields.get(TrackingSettings.THRESHOLD).show(p.threshold());
			fields.get(TrackingSettings.R_OUT).show(p.rOut());
			fields.get(TrackingSettings.DIAMETER).show(p.diameter());
			if (p.smallParticles()) fields.get(TrackingSettings.MIN_AREA).show(Math.min((Integer) fields.get(
				TrackingSettings.MIN_AREA).value(), p.minArea()));
			// beside TrackMate's wizard and the image, not over the wizard's Preview and Next
			WindowsBeside.log(p.logText(ContactTrackerDetectorFactory.SHORT_NAME + ": measured"), imp, javax.swing
				.SwingUtilities.getWindowAncestor(this));
			return showMessage("Measured " + p.status());
		};
	}

	/**
	 * Where the helper's threshold lies outside the frame measured, no threshold keeps two such particles apart: the
	 * fields get what {@code track} measures on that frame, by the particles' image ({@link MeasuredSettings}), so that
	 * no threshold outside the image is filled in.
	 */
	private Supplier<String> byImage(final ShownFrameProfile p, final boolean dark, final double diameter,
		final SettingValues chosen)
	{
		final MeasuredSettings.Result m;
		try {
			m = MeasuredSettings.of(imp.getTitle(), p.frameAsGiven(imp), p.integerData(), chosen, diameter, dark
				? TrackingSettings.DARK : null, FrontEnd.TRACKMATE);
		}
		catch (final InvalidInputException e) {
			return () -> {
				WindowsBeside.log(ContactTrackerDetectorFactory.SHORT_NAME + ": cannot measure from the image: " + e
					.getMessage(), imp, javax.swing.SwingUtilities.getWindowAncestor(this));
				return showMessage("Not measured: " + e.getMessage());
			};
		}
		final SettingValues v = m.settings();
		return () -> {
			fields.get(TrackingSettings.PARTICLES).show(v.get(TrackingSettings.PARTICLES));
			fields.get(TrackingSettings.DETECTION).show(v.get(TrackingSettings.DETECTION));
			fields.get(TrackingSettings.THRESHOLD).show(v.get(TrackingSettings.THRESHOLD));
			fields.get(TrackingSettings.R_OUT).show(v.get(TrackingSettings.R_OUT));
			fields.get(TrackingSettings.DIAMETER).show(v.diameter());
			WindowsBeside.log(p.logText(ContactTrackerDetectorFactory.SHORT_NAME + ": measured") + "\n" + m.notice(),
				imp, javax.swing.SwingUtilities.getWindowAncestor(this));
			return showMessage("Measured: no threshold keeps these particles apart, so they are found by their image");
		};
	}

	/** Shows a message under the button, wrapped to the panel's width. */
	private String showMessage(final String message) {
		final String html = message.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
		measured.setText("<html><body style='width:" + MESSAGE_WIDTH + "px'>" + html + "</body></html>");
		measured.setToolTipText(message);
		revalidate();
		return message;
	}

	/** @return the info text in its scroll pane, at the wizard's width */
	static JComponent infoPane() {
		final JEditorPane info = new JEditorPane("text/html", SHORT_INFO);
		info.setEditable(false);
		info.setOpaque(false);
		info.addHyperlinkListener(e -> {
			if (e.getEventType() == javax.swing.event.HyperlinkEvent.EventType.ACTIVATED && e.getURL() != null)
				ij.IJ.runPlugIn("ij.plugin.BrowserLauncher", e.getURL().toString());
		});
		final JScrollPane scroll = new JScrollPane(info, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
			ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
		scroll.setBorder(BorderFactory.createEmptyBorder());
		// two lines, the rest by scrolling: the settings (eleven rows with the channel) and TrackMate's Preview need the
		// wizard's height
		scroll.setPreferredSize(new Dimension(280, 34));
		// the wizard is a little shorter than the panel's preferred size, so GridBagLayout falls back to minimum
		// sizes: keep the text readable and let TrackMate's histogram give way instead
		scroll.setMinimumSize(new Dimension(200, 34));
		return scroll;
	}

	/**
	 * Shows a settings map; a missing, mistyped or invalid value shows the value last used in this session
	 * instead, else the default (TrackMate checks the map itself with the factory's {@code checkSettings}; its
	 * wizard hands over null for keys the previous detector did not have). A key a map may lack (a map of an earlier
	 * version, without {@code KINDS}) shows its default when it lacks it. A channel beyond the image's is kept.
	 */
	@Override
	public void setSettings(final Map<String, Object> settings) {
		final Map<String, Object> d = LastSettings.get();
		for (final Field f : fields.values()) {
			final String key = f.setting.trackMateKey();
			Object v = settings == null ? null : settings.get(key);
			if (settings != null && f.setting.isOptionalInMaps() && !settings.containsKey(key)) v = f.setting
				.absentInMaps();
			if (!f.setting.type().isInstance(v) || !allowed(f.setting, v)) v = d.get(key);
			if (f.setting == TrackingSettings.CHANNEL) {
				final SpinnerNumberModel cm = (SpinnerNumberModel) ((JSpinner) f.control).getModel();
				if ((Integer) v > (Integer) cm.getMaximum()) cm.setMaximum((Integer) v);
			}
			f.show(v);
		}
	}

	@SuppressWarnings("unchecked")
	private static <V> boolean allowed(final Setting<V> s, final Object v) {
		try {
			s.check((V) v);
			return true;
		}
		catch (final IllegalArgumentException e) {
			return false;
		}
	}

	/** @return a complete map of correctly typed values, in {@link TrackMateSettings#keys()} order */
	@Override
	public Map<String, Object> getSettings() {
		final Map<String, Object> map = new LinkedHashMap<>();
		for (final Field f : fields.values())
			map.put(f.setting.trackMateKey(), f.value());
		LastSettings.remember(map); // TrackMate takes the settings from here when the user moves on
		return map;
	}

	@Override
	public void clean() {
		// Preview's spots belong to TrackMate's model, which TrackMate itself clears on the next step
	}

	private int addRow(final int row, final String label, final JComponent field, final JLabel unitLabel,
		final String tip)
	{
		final JLabel l = new JLabel(label);
		l.setFont(FONT);
		l.setHorizontalAlignment(SwingConstants.RIGHT);
		l.setToolTipText(tip);
		field.setToolTipText(tip);
		field.setFont(FONT);
		// the fields touch, with no gap between the rows: the wizard has no height to spare for the settings
		final Insets tight = new Insets(0, 3, 0, 3);
		if (field instanceof JComboBox) {
			// no taller than a spinner (Swing's combo boxes are a few pixels taller)
			final Dimension d = field.getPreferredSize();
			field.setPreferredSize(new Dimension(d.width, Math.min(d.height, new JSpinner().getPreferredSize().height)));
		}
		final GridBagConstraints lc = at(0, row, 1);
		lc.anchor = GridBagConstraints.EAST;
		lc.insets = tight;
		add(l, lc);
		final GridBagConstraints c = at(1, row, 1);
		c.fill = GridBagConstraints.HORIZONTAL;
		c.weightx = 1;
		c.insets = tight;
		add(field, c);
		final GridBagConstraints uc = at(2, row, 1);
		uc.insets = tight;
		add(unitLabel, uc);
		return row + 1;
	}

	private static GridBagConstraints at(final int x, final int y, final int width) {
		final GridBagConstraints c = new GridBagConstraints();
		c.gridx = x;
		c.gridy = y;
		c.gridwidth = width;
		c.anchor = GridBagConstraints.WEST;
		c.insets = new Insets(1, 3, 1, 3);
		if (width > 1) c.fill = GridBagConstraints.HORIZONTAL;
		return c;
	}

	private static JSpinner doubleSpinner(final double value, final double min, final double max, final double step,
		final String format)
	{
		final JSpinner s = new JSpinner(new SpinnerNumberModel(value, min, max, step));
		s.setEditor(new JSpinner.NumberEditor(s, format));
		((JSpinner.DefaultEditor) s.getEditor()).getTextField().setColumns(6);
		return s;
	}

	/** Width and height of the detector's icon: TrackMate's own detector icons are 64 x 64. */
	static final int ICON_SIZE = 64;

	/**
	 * A 64 x 64 icon: two touching particles, each with its centre marked. As wide as TrackMate's own detector icons,
	 * so that the names in its detector list line up (the list draws each icon's middle strip, about 16 px high, in
	 * front of the name); the particles' centres lie on that strip.
	 */
	static ImageIcon icon() {
		return icon(ICON_SIZE);
	}

	/**
	 * @param size the icon's width and height: {@value #ICON_SIZE} for TrackMate's lists, 32 on the panel's title
	 *        line (the panel has no height to spare in the wizard)
	 * @return the icon of {@link #icon()}, drawn at that size
	 */
	static ImageIcon icon(final int size) {
		final BufferedImage img = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
		final Graphics2D g = img.createGraphics();
		g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
		g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
		g.scale(size / (double) ICON_SIZE, size / (double) ICON_SIZE);
		final int d = 30, top = (ICON_SIZE - d) / 2; // two discs of 30 px touching at the icon's centre
		final int[] lefts = { ICON_SIZE / 2 - d, ICON_SIZE / 2 };
		for (final int left : lefts) {
			g.setColor(new Color(250, 200, 60));
			g.fillOval(left, top, d, d);
			g.setColor(new Color(120, 80, 0));
			g.setStroke(new BasicStroke(2f));
			g.drawOval(left + 1, top + 1, d - 2, d - 2);
			g.setColor(Color.RED);
			final int cx = left + d / 2, cy = top + d / 2;
			g.drawLine(cx - 5, cy, cx + 5, cy);
			g.drawLine(cx, cy - 5, cx, cy + 5);
		}
		g.dispose();
		return new ImageIcon(img);
	}
}
