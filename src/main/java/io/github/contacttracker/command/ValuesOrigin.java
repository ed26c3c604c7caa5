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

import java.util.Locale;

import ij.Prefs;

/**
 * Where the values in Contact Tracker's dialog come from: measured on this image, measured on another one or
 * remembered from a run on another image, or the defaults. The dialog remembers its last values (SciJava keeps
 * them); measured on one image they fit no other, and a person opening the dialog on a new image saw 186 / 43 /
 * 34.06 for 11 px particles with nothing saying so. The dialog now says it, in words, above the values.
 * <p>
 * What was measured, and what was run, is kept for the session in ImageJ's preferences (one line each: the image's
 * title and the three values the helper fills in).
 */
final class ValuesOrigin {

	/** Preference keys. */
	static final String MEASURED = "contacttracker.measured", RUN = "contacttracker.run";

	/**
	 * The values the helper fills in, on an image.
	 *
	 * @param image the image's title
	 */
	record Values(String image, double threshold, double rOut, double diameter) {

		/** @return whether the three values are the same (to the dialog's 0.01) */
		boolean same(final Values o) {
			return o != null && Math.abs(threshold - o.threshold) < 0.005 && Math.abs(rOut - o.rOut) < 0.005 && Math.abs(
				diameter - o.diameter) < 0.005;
		}

		String line() {
			return String.format(Locale.ROOT, "%s\t%s\t%s\t%s", image.replace('\t', ' '), threshold, rOut, diameter);
		}

		static Values parse(final String line) {
			if (line == null) return null;
			final String[] f = line.split("\t");
			if (f.length != 4) return null;
			try {
				return new Values(f[0], Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]));
			}
			catch (final NumberFormatException e) {
				return null;
			}
		}
	}

	private ValuesOrigin() {}

	/** Notes values the helper measured on an image. */
	static void measured(final Values v) {
		Prefs.set(MEASURED, v.line());
	}

	/** Notes the values of a run on an image. */
	static void run(final Values v) {
		Prefs.set(RUN, v.line());
	}

	/**
	 * @param now the dialog's values and its image
	 * @param defaults the default values
	 * @return the dialog's line on where the values come from (HTML: what needs doing in bold)
	 */
	static String describe(final Values now, final Values defaults) {
		return describe(now, defaults, Values.parse(Prefs.get(MEASURED, null)), Values.parse(Prefs.get(RUN, null)));
	}

	/**
	 * @param measured the values last measured (null: none)
	 * @param run the values of the last run (null: none)
	 */
	static String describe(final Values now, final Values defaults, final Values measured, final Values run) {
		final String text;
		if (now.same(defaults)) text = "Values: the defaults, which fit no particular image: <b>press Measure from " +
			"the image</b>";
		else if (now.same(measured) && measured.image().equals(now.image())) text = "Values: measured on this image";
		else if (now.same(measured)) text = "Values: measured on '" + escape(measured.image()) + "', <b>another " +
			"image: press Measure from the image</b>";
		else if (now.same(run) && run.image().equals(now.image())) text = "Values: as in the last run on this image";
		else if (now.same(run)) text = "Values: from the last run, on '" + escape(run.image()) + "', <b>another " +
			"image: press Measure from the image</b>";
		else text = "Values: as set by hand";
		return "<html>" + text + "</html>";
	}

	private static String escape(final String s) {
		return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
	}
}
