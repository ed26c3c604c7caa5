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
package io.github.contacttracker.lab.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import io.github.contacttracker.core.Method;
import io.github.contacttracker.lab.eval.DistanceError;
import io.github.contacttracker.lab.eval.SceneStudy;
import io.github.contacttracker.cli.Report;

/** The markdown pages of {@code accuracy --report}: the paper's protocol, or the harder scenes. */
final class AccuracyReport {

	/** One row of the paper's protocol: a configuration ({@code silica 5.53 um pair}), a separation, a method. */
	private record Row(String configuration, String heading, DistanceError e, double crb) {}

	private final List<Row> rows = new ArrayList<>();
	private final int reps;

	/** @param reps noisy images per separation */
	AccuracyReport(final int reps) {
		this.reps = reps;
	}

	/**
	 * @param configuration particles and scenario ({@code silica 5.53 um pair})
	 * @param heading the configuration's heading line, as {@code accuracy} prints it
	 */
	void add(final String configuration, final String heading, final DistanceError e, final double crb) {
		rows.add(new Row(configuration, heading, e, crb));
	}

	/** @return the paper's protocol: the rows at contact, a summary per method, then every separation */
	Report paper() {
		final Report report = new Report("Accuracy: the paper's protocol").paragraph(String.format(Locale.ROOT,
			"Two and three particles of each profile, from two diameters apart down to contact, %d noisy images per " +
				"separation. Per separation and method: the mean error of the measured centre-to-centre distance " +
				"(measured - true) and its standard deviation, that spread over the Cramér-Rao bound (CRB) of the " +
				"configuration, the mean reported standard error (σ), the images in which a particle of the pair was " +
				"lost and those in which one fell back to its first-pass centre.", reps));
		final List<List<String>> contact = new ArrayList<>();
		for (final Row r : rows)
			if (r.e.separationOverD() == 1) contact.add(List.of(r.configuration, "`" + r.e.method().key() + "`", Report
				.signed(r.e.meanErrorNm()), Report.two(r.e.stdNm()), Report.two(r.crb), Report.two(r.e.stdNm() / r.crb),
				Report.two(r.e.meanSigmaNm()), Integer.toString(r.e.failures()), Integer.toString(r.e.fallbacks())));
		if (!contact.isEmpty()) report.heading("At contact (r/D = 1)").table(List.of("particles", "method",
			"mean error (nm)", "std (nm)", "CRB (nm)", "std / CRB", "reported σ (nm)", "lost", "fell back"), contact);

		report.heading("Every method over the whole run").paragraph("Worst |mean error| and the range of std / CRB " +
			"over every separation and configuration; reported σ over the observed spread; particles lost and " +
			"fallbacks, summed.");
		final Map<Method, List<Row>> byMethod = new LinkedHashMap<>();
		for (final Row r : rows)
			byMethod.computeIfAbsent(r.e.method(), m -> new ArrayList<>()).add(r);
		final List<List<String>> summary = new ArrayList<>();
		for (final Map.Entry<Method, List<Row>> m : byMethod.entrySet()) {
			double worst = 0, lo = Double.POSITIVE_INFINITY, hi = 0, slo = Double.POSITIVE_INFINITY, shi = 0;
			int lost = 0, fell = 0;
			for (final Row r : m.getValue()) {
				worst = Math.max(worst, Math.abs(r.e.meanErrorNm()));
				lo = Math.min(lo, r.e.stdNm() / r.crb);
				hi = Math.max(hi, r.e.stdNm() / r.crb);
				slo = Math.min(slo, r.e.meanSigmaNm() / r.e.stdNm());
				shi = Math.max(shi, r.e.meanSigmaNm() / r.e.stdNm());
				lost += r.e.failures();
				fell += r.e.fallbacks();
			}
			summary.add(List.of("`" + m.getKey().key() + "`", Report.two(worst), Report.two(lo) + " to " + Report.two(hi),
				Report.two(slo) + " to " + Report.two(shi), Integer.toString(lost), Integer.toString(fell)));
		}
		report.table(List.of("method", "worst mean error (nm)", "std / CRB", "reported σ / spread", "lost",
			"fell back"), summary);

		report.heading("Every separation");
		String heading = null;
		List<List<String>> table = new ArrayList<>();
		for (final Row r : rows) {
			if (!r.heading.equals(heading)) {
				if (heading != null) report.paragraph("**" + heading + "**").table(SEPARATION_HEADER, table);
				heading = r.heading;
				table = new ArrayList<>();
			}
			table.add(List.of(String.format(Locale.ROOT, "%.2f", r.e.separationOverD()), "`" + r.e.method().key() + "`",
				Report.signed(r.e.meanErrorNm()), Report.two(r.e.stdNm()), Report.two(r.e.stdNm() / r.crb), Report.two(
					r.e.meanSigmaNm()), Integer.toString(r.e.failures()), Integer.toString(r.e.fallbacks()), Report.two(
						r.crb)));
		}
		if (heading != null) report.paragraph("**" + heading + "**").table(SEPARATION_HEADER, table);
		return report;
	}

	private static final List<String> SEPARATION_HEADER = List.of("r/D", "method", "mean error (nm)", "std (nm)",
		"std / CRB", "reported σ (nm)", "lost", "fell back", "CRB (nm)");

	/** @return the harder scenes at contact: a table per particle type, then a summary */
	static Report scenes(final List<SceneStudy.Result> results, final SceneStudy study, final int reps) {
		final Report report = new Report("Accuracy: harder scenes at contact").paragraph(String.format(Locale.ROOT,
			"Method `%s`, %d images per scene, every scene at contact. Per scene: the mean error of the distance over " +
				"every touching pair, the worst pair's mean, the spread, the scene's Cramér-Rao bound (CRB), the worst " +
				"pair's std / CRB, every particle's largest bias along x, y, radial or tangential (and where), lost " +
				"and extra spots, flagged spots, reported σ over the observed spread, pixels clipped at 255 or 0, and spots " +
				"the tracker gave another kind than their particle's (each kind of particle counted as the label most of " +
				"its spots have).",
			study.method().key(), reps));
		String particle = null;
		List<List<String>> table = new ArrayList<>();
		final List<String> header = List.of("scene", "mean error (nm)", "worst pair (nm)", "std (nm)", "CRB (nm)",
			"std / CRB (worst pair)", "position bias (nm)", "where", "lost", "extra", "flagged", "reported σ / spread",
			"clipped px", "wrong kind");
		int lost = 0, extra = 0, flagged = 0, wrongKind = 0;
		double bias = 0, lo = Double.POSITIVE_INFINITY, hi = 0, slo = Double.POSITIVE_INFINITY, shi = 0;
		for (final SceneStudy.Result r : results) {
			if (!r.particle().equals(particle)) {
				if (particle != null) report.heading(particle).table(header, table);
				particle = r.particle();
				table = new ArrayList<>();
			}
			table.add(List.of(r.scene(), Report.signed(r.meanError()), Report.signed(r.worstPairMean()), Report.two(r
				.std()), Report.two(r.crb()), Report.two(r.worstStdOverCrb()), Report.signed(r.bias()), r.biasWhere(),
				Integer.toString(r.lost()), Integer.toString(r.extra()), Integer.toString(r.flagged()), Report.two(r
					.sigmaRatioMin()) + " to " + Report.two(r.sigmaRatioMax()), Long.toString(r.clipped()), Integer.toString(r
					.wrongKind())));
			lost += r.lost();
			extra += r.extra();
			flagged += r.flagged();
			wrongKind += r.wrongKind();
			bias = Math.max(bias, Math.abs(r.bias()));
			lo = Math.min(lo, r.worstStdOverCrb());
			hi = Math.max(hi, r.worstStdOverCrb());
			slo = Math.min(slo, r.sigmaRatioMin());
			shi = Math.max(shi, r.sigmaRatioMax());
		}
		if (particle != null) report.heading(particle).table(header, table);
		return report.heading("Over every scene").bullets(List.of( //
			"particles lost: " + lost + "; extra spots: " + extra + "; flagged spots: " + flagged + "; spots of the " +
				"wrong kind: " + wrongKind, //
			"std / CRB of the worst pair: " + Report.two(lo) + " to " + Report.two(hi), //
			"largest bias of a particle's position: " + Report.two(bias) + " nm", //
			"reported σ / observed spread: " + Report.two(slo) + " to " + Report.two(shi)));
	}
}
