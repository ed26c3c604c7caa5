package io.github.contacttracker.trackmate;

import io.github.contacttracker.settings.TrackMateSettings;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.text.DecimalFormat;
import java.text.DecimalFormatSymbols;
import java.util.Locale;
import java.util.Map;

import javax.swing.BorderFactory;
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

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import fiji.plugin.trackmate.util.DetectionPreview;
import io.github.contacttracker.core.Method;

/**
 * TrackMate's configuration panel for {@link ContactTrackerDetectorFactory}, laid out like TrackMate's own
 * detector panels: icon and name, a short text, compact labelled fields, and TrackMate's Preview (which runs the
 * detector on the current frame and shows the spots on the image). It fits TrackMate's wizard at its default
 * size (about 300 x 510 pixels).
 * <p>
 * {@code r_out} is a size, so it is asked in the image's physical units (with its value in pixels beside it); the
 * setting {@code R_OUT} itself stays in pixels, as on the command line. {@link #getSettings()} always returns a
 * complete map of correctly typed values.
 */
public final class ContactTrackerConfigurationPanel extends ConfigurationPanel {

	private static final long serialVersionUID = 1L;

	/** TrackMate's panel fonts (Arial 10, titles 14). */
	static final Font FONT = new Font("Arial", Font.PLAIN, 10);
	static final Font BIG_FONT = new Font("Arial", Font.PLAIN, 14);

	/** The wizard's panel size, which this panel must fit (TrackMate's own detector panels use it). */
	public static final Dimension WIZARD_SIZE = new Dimension(300, 511);

	private static final String SHORT_INFO = "<html><body style='font-family:Arial; font-size:8pt'>"
		+ "Centres of bright particles, also when they touch: pixels at or above the <b>threshold</b> form one "
		+ "active area per particle; each centre is found by radial symmetry and refined away from the neighbours "
		+ "(within <b>r_out</b>, where a particle's image ends). <b>fit</b> (default) is unbiased at contact.<br>"
		+ "Y&uuml;cel &amp; Okumu&#351;o&#287;lu, J. Phys.: Condens. Matter 29, 465101 (2017), "
		+ "<a href='" + ContactTrackerDetectorFactory.URL + "'>doi:10.1088/1361-648X/aa908e</a>. "
		+ "2D images and time-lapses only.</body></html>";

	private final JSpinner channel;
	private final JSpinner threshold;
	private final JSpinner rOut;
	private final JLabel rOutPixels;
	private final JSpinner minArea;
	private final JSpinner minSecondArea;
	private final JComboBox<Integer> connectivity;
	private final JComboBox<String> method;
	private final double pixelWidth;

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
		final String unit = hasImage && settings.imp.getCalibration().scaled() ? settings.imp.getCalibration()
			.getUnit() : "pixel";

		final Map<String, Object> d = TrackMateSettings.defaults();
		channel = new JSpinner(new SpinnerNumberModel(1, 1, nChannels, 1));
		threshold = doubleSpinner((Double) d.get(TrackMateSettings.KEY_THRESHOLD), -1e15, 1e15, 1, "0.###");
		rOut = doubleSpinner(1, 0.5 * pixelWidth, 1e6 * pixelWidth, pixelWidth, "0.####");
		rOutPixels = new JLabel();
		minArea = new JSpinner(new SpinnerNumberModel(1, 1, Integer.MAX_VALUE, 1));
		minSecondArea = new JSpinner(new SpinnerNumberModel(3, 3, Integer.MAX_VALUE, 1));
		connectivity = new JComboBox<>(new Integer[] { 8, 4 });
		final Method[] methods = Method.values();
		final String[] keys = new String[methods.length];
		for (int i = 0; i < methods.length; i++)
			keys[i] = methods[i].key();
		method = new JComboBox<>(keys);
		rOut.addChangeListener(e -> updateRoutPixels());

		setLayout(new GridBagLayout());
		setBorder(BorderFactory.createEmptyBorder(5, 5, 5, 5));
		setPreferredSize(WIZARD_SIZE);
		int row = 0;
		final JLabel title = new JLabel(ContactTrackerDetectorFactory.SHORT_NAME, ContactTrackerDetectorFactory.ICON,
			SwingConstants.CENTER);
		title.setFont(BIG_FONT);
		final GridBagConstraints tc = at(0, row++, 3);
		tc.anchor = GridBagConstraints.CENTER;
		tc.fill = GridBagConstraints.NONE;
		add(title, tc);
		add(infoPane(), at(0, row++, 3));

		if (nChannels > 1) row = addRow(row, "Target channel", channel, null,
			"Channel analysed (1-based).");
		row = addRow(row, "Threshold", threshold, "grey level",
			"Pixels at or above this grey level form the active areas, one per particle. It must be above the "
				+ "brightest point between two touching particles (the Contact Tracker Profile command suggests it).");
		row = addRow(row, "r_out", rOut, unit,
			"How far a particle's image reaches: where its profile has returned to background, plus 2 pixels.");
		final GridBagConstraints pc = at(1, row++, 2);
		rOutPixels.setFont(FONT);
		add(rOutPixels, pc);
		row = addRow(row, "Min area", minArea, "pixels", "Active areas smaller than this are noise and dropped.");
		row = addRow(row, "Min second area", minSecondArea, "pixels",
			"paper/iterative: below this many pixels left outside the neighbours' discs, a spot keeps its "
				+ "first-pass centre and is flagged FELL_BACK.");
		row = addRow(row, "Connectivity", connectivity, null, "Pixel neighbourhood of the labelling.");
		row = addRow(row, "Method", method, null, "<html>fit (default): joint fit with the measured profile, "
			+ "unbiased at contact<br>deblend: subtracts the neighbours' modelled light<br>iterative / paper: the "
			+ "paper's second pass (repeated / once)<br>first: one pass, biased near contact</html>");

		final GridBagConstraints fc = at(0, row++, 3);
		fc.weighty = 1;
		fc.fill = GridBagConstraints.BOTH;
		if (hasImage && factory != null) {
			// TrackMate's own preview; our THRESHOLD is a grey level, not a quality cut-off, so no threshold key
			final DetectionPreview preview = DetectionPreview.create().model(model).settings(settings)
				.detectorFactory(factory).detectionSettingsSupplier(this::getSettings).thresholdKey(null)
				.axisLabel("Quality histogram").get();
			add(preview.getPanel(), fc);
		}
		else add(new JLabel(), fc);
		setSettings(d);
	}

	private static JComponent infoPane() {
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
		scroll.setPreferredSize(new Dimension(280, 72));
		// the wizard is a little shorter than the panel's preferred size, so GridBagLayout falls back to minimum
		// sizes: keep the text readable and let TrackMate's histogram give way instead
		scroll.setMinimumSize(new Dimension(200, 72));
		return scroll;
	}

	@Override
	public void setSettings(final Map<String, Object> settings) {
		final Map<String, Object> d = TrackMateSettings.defaults();
		final int c = value(settings, d, TrackMateSettings.KEY_TARGET_CHANNEL, Integer.class);
		final SpinnerNumberModel cm = (SpinnerNumberModel) channel.getModel();
		if (c > (Integer) cm.getMaximum()) cm.setMaximum(c);
		channel.setValue(Math.max(1, c));
		threshold.setValue(value(settings, d, TrackMateSettings.KEY_THRESHOLD, Double.class));
		rOut.setValue(Math.max(0.5, value(settings, d, TrackMateSettings.KEY_R_OUT, Double.class)) * pixelWidth);
		minArea.setValue(Math.max(1, value(settings, d, TrackMateSettings.KEY_MIN_AREA, Integer.class)));
		minSecondArea.setValue(Math.max(3, value(settings, d, TrackMateSettings.KEY_MIN_SECOND_AREA, Integer.class)));
		connectivity.setSelectedItem(value(settings, d, TrackMateSettings.KEY_CONNECTIVITY, Integer.class) == 4 ? 4 : 8);
		String m = value(settings, d, TrackMateSettings.KEY_METHOD, String.class);
		try {
			m = Method.parse(m).key();
		}
		catch (final IllegalArgumentException e) {
			m = (String) d.get(TrackMateSettings.KEY_METHOD);
		}
		method.setSelectedItem(m);
		updateRoutPixels();
	}

	@Override
	public Map<String, Object> getSettings() {
		final Map<String, Object> map = TrackMateSettings.defaults();
		map.put(TrackMateSettings.KEY_TARGET_CHANNEL, ((Number) channel.getValue()).intValue());
		map.put(TrackMateSettings.KEY_THRESHOLD, ((Number) threshold.getValue()).doubleValue());
		map.put(TrackMateSettings.KEY_R_OUT, rOutInPixels());
		map.put(TrackMateSettings.KEY_MIN_AREA, ((Number) minArea.getValue()).intValue());
		map.put(TrackMateSettings.KEY_MIN_SECOND_AREA, ((Number) minSecondArea.getValue()).intValue());
		map.put(TrackMateSettings.KEY_CONNECTIVITY, (Integer) connectivity.getSelectedItem());
		map.put(TrackMateSettings.KEY_METHOD, (String) method.getSelectedItem());
		return map;
	}

	@Override
	public void clean() {
		// Preview's spots belong to TrackMate's model, which TrackMate itself clears on the next step
	}

	/** r_out in pixels, rounded to 1e-6 px so a value typed in pixels survives the round trip through units. */
	private double rOutInPixels() {
		return Math.round(((Number) rOut.getValue()).doubleValue() / pixelWidth * 1e6) / 1e6;
	}

	private void updateRoutPixels() {
		rOutPixels.setText("= " + new DecimalFormat("0.##", DecimalFormatSymbols.getInstance(Locale.ROOT)).format(
			rOutInPixels()) + " pixels");
	}

	private int addRow(final int row, final String label, final JComponent field, final String unit,
		final String tip)
	{
		final JLabel l = new JLabel(label);
		l.setFont(FONT);
		l.setHorizontalAlignment(SwingConstants.RIGHT);
		l.setToolTipText(tip);
		field.setToolTipText(tip);
		field.setFont(FONT);
		final GridBagConstraints lc = at(0, row, 1);
		lc.anchor = GridBagConstraints.EAST;
		add(l, lc);
		final GridBagConstraints c = at(1, row, unit == null ? 2 : 1);
		c.fill = GridBagConstraints.HORIZONTAL;
		c.weightx = 1;
		add(field, c);
		if (unit != null) {
			final JLabel u = new JLabel(unit);
			u.setFont(FONT);
			add(u, at(2, row, 1));
		}
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

	private static <V> V value(final Map<String, Object> settings, final Map<String, Object> defaults, final String key,
		final Class<V> type)
	{
		final Object v = settings == null ? null : settings.get(key);
		return type.isInstance(v) ? type.cast(v) : type.cast(defaults.get(key));
	}

	/** A 32 x 32 icon: two touching particles, each with its centre marked. */
	static ImageIcon icon() {
		final BufferedImage img = new BufferedImage(32, 32, BufferedImage.TYPE_INT_ARGB);
		final Graphics2D g = img.createGraphics();
		g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
		g.setColor(new Color(250, 200, 60));
		g.fillOval(1, 8, 15, 15);
		g.fillOval(16, 8, 15, 15);
		g.setColor(new Color(120, 80, 0));
		g.setStroke(new BasicStroke(1.2f));
		g.drawOval(1, 8, 15, 15);
		g.drawOval(16, 8, 15, 15);
		g.setColor(Color.RED);
		g.drawLine(6, 15, 11, 15);
		g.drawLine(8, 13, 8, 18);
		g.drawLine(21, 15, 26, 15);
		g.drawLine(23, 13, 23, 18);
		g.dispose();
		return new ImageIcon(img);
	}
}
