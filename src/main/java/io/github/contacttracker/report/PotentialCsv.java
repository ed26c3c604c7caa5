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
package io.github.contacttracker.report;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import io.github.contacttracker.io.AtomicFile;
import io.github.contacttracker.potential.PairCorrelation;

/**
 * Writes g(r) and U(r) as CSV, one row per bin: {@code R} (bin centre, the spots' units), {@code PAIRS},
 * {@code G}, {@code U_KT} (U/kT, after the zero shift if one was set), {@code U_KT_ERR} (standard error from
 * the pair count). An empty bin has empty {@code U_KT} and {@code U_KT_ERR} cells: U is unbounded there.
 */
public final class PotentialCsv {

	/** The header row. */
	public static final String HEADER = "R,PAIRS,G,U_KT,U_KT_ERR";

	private PotentialCsv() {}

	/** Writes the table to {@code file}, atomically. */
	public static void write(final Path file, final PairCorrelation.Result result) throws IOException {
		AtomicFile.write(file, out -> {
			final Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
			write(w, result);
			w.flush();
		});
	}

	/** Writes the table to {@code out} (not closed). */
	public static void write(final Writer out, final PairCorrelation.Result result) throws IOException {
		out.write(HEADER + "\n");
		for (int i = 0; i < result.bins().size(); i++) {
			final PairCorrelation.Bin b = result.bins().get(i);
			out.write(number(b.r()) + "," + b.pairs() + "," + number(b.g()) + "," + (b.pairs() > 0 ? number(result.u(i)) +
				"," + number(b.uError()) : ",") + "\n");
		}
	}

	/** @return {@code v} rounded to 12 significant digits (no binary noise such as 0.30000000000000004) */
	static String number(final double v) {
		if (v == 0) return "0";
		return new BigDecimal(v).round(new MathContext(12)).stripTrailingZeros().toPlainString();
	}
}
