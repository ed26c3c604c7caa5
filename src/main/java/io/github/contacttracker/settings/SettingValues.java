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
package io.github.contacttracker.settings;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

import io.github.contacttracker.core.Connectivity;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;

/**
 * A complete, checked set of values of {@link TrackingSettings#ALL}: immutable; every value of its setting's type
 * and allowed.
 */
public final class SettingValues {

	private final Map<Setting<?>, Object> values;

	private SettingValues(final Map<Setting<?>, Object> values) {
		this.values = Collections.unmodifiableMap(values);
	}

	/** @return every setting at its default */
	public static SettingValues defaults() {
		final Map<Setting<?>, Object> m = new LinkedHashMap<>();
		for (final Setting<?> s : TrackingSettings.ALL)
			m.put(s, s.defaultValue());
		return new SettingValues(m);
	}

	/**
	 * @return a copy with {@code setting} set to {@code value}
	 * @throws InvalidSettingException if the value is not allowed
	 */
	public <V> SettingValues with(final Setting<V> setting, final V value) {
		final Map<Setting<?>, Object> m = new LinkedHashMap<>(values);
		m.put(setting, setting.check(value));
		return new SettingValues(m);
	}

	/**
	 * @return a copy with {@code setting} read from {@code text}
	 * @throws InvalidSettingException naming the setting and the text
	 */
	public SettingValues withText(final Setting<?> setting, final String text) {
		final Map<Setting<?>, Object> m = new LinkedHashMap<>(values);
		m.put(setting, setting.parse(text));
		return new SettingValues(m);
	}

	/** @return the value of {@code setting} */
	public <V> V get(final Setting<V> setting) {
		return setting.type().cast(values.get(setting));
	}

	/** @return the parameters of the core */
	public TrackerParameters parameters() {
		return new TrackerParameters(get(TrackingSettings.THRESHOLD), get(TrackingSettings.R_OUT), get(
			TrackingSettings.MIN_AREA), Connectivity.parse(String.valueOf(get(TrackingSettings.CONNECTIVITY))), get(
				TrackingSettings.MIN_SECOND_AREA), Method.parse(get(TrackingSettings.METHOD)), get(TrackingSettings.DIAMETER),
			get(TrackingSettings.KINDS), io.github.contacttracker.core.Detection.of(get(TrackingSettings.DETECTION)));
	}

	/** @return the 1-based channel */
	public int channel() {
		return get(TrackingSettings.CHANNEL);
	}

	/** @return the particle diameter in pixels, 0 when not given */
	public double diameter() {
		return get(TrackingSettings.DIAMETER);
	}

	/** @return whether the particles are dark: the frames are inverted before tracking ({@code core.image.Inversion}) */
	public boolean dark() {
		return TrackingSettings.DARK.equals(get(TrackingSettings.PARTICLES));
	}

	/** @return "threshold = 100.0, r_out = 20.0, ...", every setting in order */
	public String echo() {
		final StringBuilder sb = new StringBuilder();
		for (final Setting<?> s : TrackingSettings.ALL)
			sb.append(sb.length() == 0 ? "" : ", ").append(s.name()).append(" = ").append(values.get(s));
		return sb.toString();
	}

	@Override
	public boolean equals(final Object o) {
		return o instanceof SettingValues && ((SettingValues) o).values.equals(values);
	}

	@Override
	public int hashCode() {
		return values.hashCode();
	}

	@Override
	public String toString() {
		return echo();
	}
}
