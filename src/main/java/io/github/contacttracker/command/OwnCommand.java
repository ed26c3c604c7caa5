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

import org.scijava.ItemVisibility;
import org.scijava.command.ContextCommand;
import org.scijava.event.EventService;
import org.scijava.log.LogService;
import org.scijava.module.ModuleService;
import org.scijava.plugin.Parameter;
import org.scijava.widget.Button;

/**
 * What our three commands share: the dialog's first row (a one-line description and a Help button opening the
 * manual's page) and the run's own checks ({@link OwnInputs}), started by the initializer {@code macroInputs}
 * (each command names it in its {@code @Plugin}). A plain {@link ContextCommand}, so
 * {@code commandService.run(...)} returns the module as usual.
 */
abstract class OwnCommand extends ContextCommand {

	@Parameter
	protected LogService log;

	// What the command does, in one line (a message with no value: not remembered, no macro key).
	@Parameter(visibility = ItemVisibility.MESSAGE, persist = false, required = false)
	private String header;

	@Parameter(label = "Help", callback = "openManual", persist = false, required = false,
		description = DialogHelp.TIP + "Shows the manual's section on this command (it comes with the plugin)")
	private Button help;

	@Parameter(required = false)
	private EventService events;

	@Parameter(required = false)
	private ModuleService modules;

	/** This run's checks: refused values, a macro's values and left-out keys. */
	protected final OwnInputs own = new OwnInputs(this);

	/** The dialog sized to its rows and beside the command's image, not over it. */
	protected final DialogBesideImage besideImage;

	private final DialogHelp.Page page;

	/**
	 * @param title the dialog's title (the command's label)
	 * @param header what the command does, one line (plain text)
	 * @param page the manual's page on it ({@link DialogHelp})
	 */
	OwnCommand(final String title, final String header, final DialogHelp.Page page) {
		this.header = "<html><b>" + header + "</b></html>";
		this.page = page;
		this.besideImage = new DialogBesideImage(title, this::image, this::dialogOpened);
	}

	/** Called when the command's dialog has opened, its inputs shown (on the event thread). */
	protected void dialogOpened() {
		// nothing by default
	}

	/** @return the command's image, beside which its dialog goes (null: none, the dialog is only sized) */
	protected ij.ImagePlus image() {
		return null;
	}

	/**
	 * The initializer: from here on the run's own checks follow the module ({@link OwnInputs}): in an ImageJ macro
	 * the keys it leaves out keep their defaults and a value that does not convert is refused by the run.
	 */
	private void macroInputs() {
		own.start(events, modules);
		besideImage.arm();
	}

	/**
	 * Reports a run's failure where nothing else does: headless, to the log (standard error). With a screen the
	 * cancel reason is already shown in a dialog (a macro's in ImageJ's Macro Error, {@link MacroFailure}): the
	 * Console opening over it would show the same line a second time.
	 *
	 * @param line the command's title and the one-line reason
	 */
	protected void errorOnce(final String line) {
		if (java.awt.GraphicsEnvironment.isHeadless()) log.error(line);
		else log.debug(line);
	}

	/** The Help button: the manual's page on this command. */
	private void openManual() {
		DialogHelp.open(page);
	}
}
