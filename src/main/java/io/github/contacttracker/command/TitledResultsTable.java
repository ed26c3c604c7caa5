package io.github.contacttracker.command;

import ij.measure.ResultsTable;

/**
 * A {@link ResultsTable} that knows its title before it is shown. ImageJ sets a table's title only in
 * {@link #show(String)}, which does nothing headless; this table reports the title it was made with until then,
 * so scripts and headless runs see the same title as Fiji's window.
 */
public final class TitledResultsTable extends ResultsTable {

	private final String defaultTitle;

	/** @param title the title reported until the table is shown under another */
	public TitledResultsTable(final String title) {
		this.defaultTitle = title;
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
