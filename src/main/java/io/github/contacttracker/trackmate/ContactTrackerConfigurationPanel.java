package io.github.contacttracker.trackmate;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.Locale;
import java.util.Map;

import javax.swing.BorderFactory;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;

import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import io.github.contacttracker.core.Method;
import ij.ImagePlus;

/**
 * TrackMate's configuration panel for {@link ContactTrackerDetectorFactory}: one control per setting of
 * {@link DetectorSettings}. {@link #getSettings()} always returns a complete map of correctly typed values.
 */
public final class ContactTrackerConfigurationPanel extends ConfigurationPanel {

	private static final long serialVersionUID = 1L;

	private static final double BIG = 1e15;
	/** Width of the wrapped texts, in pixels: TrackMate's wizard panels are about 300 pixels wide. */
	private static final int TEXT_WIDTH = 210;

	private final JSpinner channel;
	private final JSpinner threshold;
	private final JSpinner rOut;
	private final JSpinner minArea;
	private final JSpinner minSecondArea;
	private final JComboBox<Integer> connectivity;
	private final JComboBox<String> method;
	private final JLabel scale;
	private final double pixelWidth;
	private final String unit;

	/**
	 * @param nChannels channels of the image (bounds the target channel)
	 * @param imp the image, for its pixel size; may be {@code null}
	 */
	public ContactTrackerConfigurationPanel(final int nChannels, final ImagePlus imp) {
		final Map<String, Object> d = DetectorSettings.defaults();
		channel = new JSpinner(new SpinnerNumberModel(1, 1, Math.max(1, nChannels), 1));
		threshold = doubleSpinner((Double) d.get(DetectorSettings.KEY_THRESHOLD), -BIG, BIG, 1);
		rOut = doubleSpinner((Double) d.get(DetectorSettings.KEY_R_OUT), 0.5, 1e6, 0.5);
		minArea = new JSpinner(new SpinnerNumberModel(((Integer) d.get(DetectorSettings.KEY_MIN_AREA)).intValue(), 1,
			Integer.MAX_VALUE, 1));
		minSecondArea = new JSpinner(new SpinnerNumberModel(((Integer) d.get(DetectorSettings.KEY_MIN_SECOND_AREA))
			.intValue(), 3, Integer.MAX_VALUE, 1));
		connectivity = new JComboBox<>(new Integer[] { 8, 4 });
		final Method[] methods = Method.values();
		final String[] keys = new String[methods.length];
		for (int i = 0; i < methods.length; i++)
			keys[i] = methods[i].key();
		method = new JComboBox<>(keys);
		if (imp != null && imp.getCalibration() != null && imp.getCalibration().pixelWidth > 0) {
			pixelWidth = imp.getCalibration().pixelWidth;
			unit = imp.getCalibration().getUnit();
		}
		else {
			pixelWidth = 1;
			unit = "pixel";
		}
		for (final JSpinner s : new JSpinner[] { channel, threshold, rOut, minArea, minSecondArea })
			((JSpinner.DefaultEditor) s.getEditor()).getTextField().setColumns(7);
		scale = new JLabel();
		rOut.addChangeListener(e -> updateScale());

		setLayout(new GridBagLayout());
		setBorder(BorderFactory.createEmptyBorder(5, 5, 5, 5));
		int row = 0;
		final JLabel title = new JLabel("Settings for detector:");
		add(title, at(0, row++, 2));
		final JLabel name = new JLabel("<html><body style='width:" + TEXT_WIDTH + "px'>" +
			ContactTrackerDetectorFactory.NAME + "</body></html>");
		name.setFont(name.getFont().deriveFont(name.getFont().getSize2D() + 2f));
		add(name, at(0, row++, 2));
		final JLabel info = new JLabel(ContactTrackerDetectorFactory.INFO_TEXT.replace("<html>",
			"<html><body style='width:" + TEXT_WIDTH + "px'>"));
		info.setFont(info.getFont().deriveFont(info.getFont().getSize2D() - 2f));
		add(info, at(0, row++, 2));
		row = addRow(row, "Target channel:", channel, "Channel analysed (1-based).");
		row = addRow(row, "Threshold (grey level):", threshold, "Pixels at or above it form the active areas.");
		row = addRow(row, "R_out (pixels):", rOut,
			"Radius of a particle's effective disc: where its image has returned to background, plus 2 pixels.");
		add(scale, at(1, row++, 1));
		row = addRow(row, "Min area (pixels):", minArea, "Smaller active areas are noise and dropped.");
		row = addRow(row, "Min second area (pixels):", minSecondArea,
			"Below this many pixels left by the neighbours' discs, a spot keeps its first-pass centre (flagged).");
		row = addRow(row, "Connectivity:", connectivity, "Pixel neighbourhood of the labelling.");
		row = addRow(row, "Method:", method, "How centres are computed: first = one pass (biased near contact), paper = the paper's two passes; see the README for the others.");
		final GridBagConstraints filler = at(0, row, 2);
		filler.weighty = 1;
		add(new JLabel(), filler);
		setSettings(d);
	}

	@Override
	public void setSettings(final Map<String, Object> settings) {
		final Map<String, Object> d = DetectorSettings.defaults();
		final int c = value(settings, d, DetectorSettings.KEY_TARGET_CHANNEL, Integer.class);
		final SpinnerNumberModel cm = (SpinnerNumberModel) channel.getModel();
		if (c > (Integer) cm.getMaximum()) cm.setMaximum(c);
		channel.setValue(Math.max(1, c));
		threshold.setValue(value(settings, d, DetectorSettings.KEY_THRESHOLD, Double.class));
		rOut.setValue(Math.max(0.5, value(settings, d, DetectorSettings.KEY_R_OUT, Double.class)));
		minArea.setValue(Math.max(1, value(settings, d, DetectorSettings.KEY_MIN_AREA, Integer.class)));
		minSecondArea.setValue(Math.max(3, value(settings, d, DetectorSettings.KEY_MIN_SECOND_AREA, Integer.class)));
		connectivity.setSelectedItem(value(settings, d, DetectorSettings.KEY_CONNECTIVITY, Integer.class) == 4 ? 4 : 8);
		String m = value(settings, d, DetectorSettings.KEY_METHOD, String.class);
		try {
			m = Method.parse(m).key();
		}
		catch (final IllegalArgumentException e) {
			m = (String) d.get(DetectorSettings.KEY_METHOD);
		}
		method.setSelectedItem(m);
		updateScale();
	}

	@Override
	public Map<String, Object> getSettings() {
		final Map<String, Object> map = DetectorSettings.defaults();
		map.put(DetectorSettings.KEY_TARGET_CHANNEL, ((Number) channel.getValue()).intValue());
		map.put(DetectorSettings.KEY_THRESHOLD, ((Number) threshold.getValue()).doubleValue());
		map.put(DetectorSettings.KEY_R_OUT, ((Number) rOut.getValue()).doubleValue());
		map.put(DetectorSettings.KEY_MIN_AREA, ((Number) minArea.getValue()).intValue());
		map.put(DetectorSettings.KEY_MIN_SECOND_AREA, ((Number) minSecondArea.getValue()).intValue());
		map.put(DetectorSettings.KEY_CONNECTIVITY, (Integer) connectivity.getSelectedItem());
		map.put(DetectorSettings.KEY_METHOD, (String) method.getSelectedItem());
		return map;
	}

	@Override
	public void clean() {
		// no preview overlay to remove
	}

	private void updateScale() {
		final double r = ((Number) rOut.getValue()).doubleValue();
		scale.setText(pixelWidth == 1 && "pixel".equals(unit) ? " "
			: String.format(Locale.ROOT, "= %.4g %s", r * pixelWidth, unit));
	}

	private int addRow(final int row, final String label, final JComponent field, final String tip) {
		final JLabel l = new JLabel(label);
		l.setToolTipText(tip);
		field.setToolTipText(tip);
		add(l, at(0, row, 1));
		final GridBagConstraints c = at(1, row, 1);
		c.fill = GridBagConstraints.HORIZONTAL;
		c.weightx = 1;
		add(field, c);
		return row + 1;
	}

	private static GridBagConstraints at(final int x, final int y, final int width) {
		final GridBagConstraints c = new GridBagConstraints();
		c.gridx = x;
		c.gridy = y;
		c.gridwidth = width;
		c.anchor = GridBagConstraints.WEST;
		c.insets = new Insets(2, 2, 2, 2);
		if (width > 1) c.fill = GridBagConstraints.HORIZONTAL;
		return c;
	}

	private static JSpinner doubleSpinner(final double value, final double min, final double max, final double step) {
		final JSpinner s = new JSpinner(new SpinnerNumberModel(value, min, max, step));
		s.setEditor(new JSpinner.NumberEditor(s, "0.####"));
		return s;
	}

	private static <V> V value(final Map<String, Object> settings, final Map<String, Object> defaults, final String key,
		final Class<V> type)
	{
		final Object v = settings == null ? null : settings.get(key);
		return type.isInstance(v) ? type.cast(v) : type.cast(defaults.get(key));
	}
}
