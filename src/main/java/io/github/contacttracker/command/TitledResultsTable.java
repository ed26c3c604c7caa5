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

import ij.measure.ResultsTable;
import io.github.contacttracker.settings.SettingValues;

/**
 * A {@link ResultsTable} that knows its title before it is shown. ImageJ sets a table's title only in
 * {@link #show(String)}, which does nothing headless; this table reports the title it was made with until then,
 * so scripts and headless runs see the same title as Fiji's window. A table of spots also carries the settings
 * they were found with ({@link #settings()}), as the CSV's settings file does, for scripts to keep with it.
 */
public final class TitledResultsTable extends ResultsTable {

	private final String defaultTitle;
	private final SettingValues settings;

	/** @param title the title reported until the table is shown under another */
	public TitledResultsTable(final String title) {
		this(title, null);
	}

	/**
	 * @param title the title reported until the table is shown under another
	 * @param settings the settings of the run whose results the table holds, or {@code null}
	 */
	public TitledResultsTable(final String title, final SettingValues settings) {
		this.defaultTitle = title;
		this.settings = settings;
	}

	/** @return the settings of the run whose results the table holds, or {@code null} for a table of none */
	public SettingValues settings() {
		return settings;
	}

	@Override
	public String getTitle() {
		final String shown = super.getTitle();
		return shown != null ? shown : defaultTitle;
	}

	/** Shows the table in its window (nothing headless). */
	public void show() {
		show(defaultTitle);
	}
}
