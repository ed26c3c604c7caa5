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
package io.github.contacttracker.advisor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;

import ij.ImagePlus;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.MemoryCacheImageOutputStream;

import io.github.contacttracker.core.Flag;
import io.github.contacttracker.core.Localization;
import io.github.contacttracker.core.Method;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.image.NoiseEstimate;
import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;
import io.github.contacttracker.lab.sim.GaussianBesselProfile;
import io.github.contacttracker.lab.sim.ImageSimulator;
import io.github.contacttracker.lab.sim.NoiseFreeImage;
import io.github.contacttracker.lab.sim.NoiseModel;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Quantiser;
import io.github.contacttracker.lab.sim.RadialProfile;
import io.github.contacttracker.lab.sim.SmallParticles;

import net.imglib2.RandomAccessibleInterval;
import net.imglib2.img.array.ArrayImgs;
import net.imglib2.type.numeric.integer.UnsignedByteType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The profile helper's suggestions (shared by Fiji's Contact Tracker Profile and {@code contact-tracker profile})
 * on simulated movies, checked the way a user relies on them: with the suggested {@code --threshold},
 * {@code --r-out} and {@code --diameter} the default method ({@code fit}) finds every particle, merges none and
 * puts the centres where the truth is; and on a frame with the real movie's troubles (saturated cores, a drifting
 * background, JPEG compression) the suggested {@code r_out} is where the profile truly meets the background.
 */
class ProfileSuggestionTest {

	/**
	 * A bright-field-like particle of our own, as on the authors' movie (D = 32 px): a core far above the 8-bit range
	 * on background 136 (clipped flat at 255), a deep dark ring, a faint bright ring at 27 px.
	 */
	static final RadialProfile BRIGHT_FIELD = r -> 200 * Math.exp(-r * r / 32) - 80 * Math.exp(-(r - 12) * (r - 12) /
		32) + 12 * Math.exp(-(r - 27) * (r - 27) / 32);
	static final ParticleType BRIGHT_FIELD_TYPE = new ParticleType("bright-field-like", 32 * 0.1, 100, BRIGHT_FIELD, 136,
		200, 40, NoiseModel.gaussian(3));

	/**
	 * A frame of the layout used below, in units of the diameter D: three isolated particles, a pair at contact and
	 * a touching triangle, each at a random sub-pixel offset.
	 */
	static List<double[]> layout(final double d, final SplittableRandom rnd) {
		final double[][] base = { { 2.3, 2.3 }, { 7.7, 2.3 }, { 2.3, 7.7 } };
		final List<double[]> c = new ArrayList<>();
		for (final double[] b : base)
			c.add(new double[] { b[0] * d + rnd.nextDouble(), b[1] * d + rnd.nextDouble() });
		final double px = 6.5 * d + rnd.nextDouble(), py = 5.3 * d + rnd.nextDouble(), a = rnd.nextDouble() * Math.PI;
		c.add(new double[] { px - d / 2 * Math.cos(a), py - d / 2 * Math.sin(a) });
		c.add(new double[] { px + d / 2 * Math.cos(a), py + d / 2 * Math.sin(a) });
		final double tx = 7.2 * d + rnd.nextDouble(), ty = 7.6 * d + rnd.nextDouble(), b = rnd.nextDouble() * Math.PI;
		for (int k = 0; k < 3; k++)
			c.add(new double[] { tx + d / Math.sqrt(3) * Math.cos(b + k * 2 * Math.PI / 3), ty + d / Math.sqrt(3) * Math
				.sin(b + k * 2 * Math.PI / 3) });
		return c;
	}

	static Stream<Arguments> particles() {
		return Stream.of(Arguments.of(PaperParticles.silica553(), 0.06), Arguments.of(PaperParticles.silica206(), 0.1),
			Arguments.of(BRIGHT_FIELD_TYPE, 0.1));
	}

	/**
	 * Tolerances on the worst of 21 centres: the fit's centres scatter by about the Cramer-Rao bound per coordinate,
	 * 0.015 px for the 5.53 um-like particles (about 1.2 nm at 84.7 nm/px; the accuracy report) and 0.02-0.03 px
	 * for the 2.06 um-like (37 nm/px) and bright-field-like ones (their reported standard errors). The tolerance is
	 * 4 of those (0.06 px; 0.1 px), below the first pass's pull at contact (0.06-0.1 px per particle for the
	 * 5.53 um-like ones, more for the others). Measured: worst 0.044, 0.039 and 0.020 px.
	 */
	@ParameterizedTest
	@MethodSource("particles")
	void theSuggestedValuesTrackTheMovieCorrectly(final ParticleType type, final double tolerance) {
		final double d = type.diameterPx();
		final int size = (int) Math.ceil(10 * d);
		final SplittableRandom rnd = new SplittableRandom(17);
		final ImageSimulator sim = new ImageSimulator(type.profile(), 3);
		final List<List<double[]>> truth = new ArrayList<>();
		final List<RandomAccessibleInterval<UnsignedByteType>> frames = new ArrayList<>();
		for (int t = 0; t < 3; t++) {
			final List<double[]> c = layout(d, rnd);
			truth.add(c);
			frames.add(Quantiser.toUnsignedBytes(sim.render(c, size, size, type.background()), type.noise(), rnd).image());
		}
		// no diameter given: estimated from the pair and the triangle at contact
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(frames.get(0), 0, 0);
		assertEquals(d, r.diameter(), 0.1 * d, "diameter estimated within 10%");
		assertEquals(3, r.particles(), "the three isolated particles are profiled: " + r.centres().size());
		final TrackerParameters params = TrackerParameters.of(r.suggestedThreshold(true), r.suggestedROut());
		assertEquals(Method.FIT, params.method());
		final List<FrameResult> results = StackTracker.withThreads(1, () -> new StackTracker(params).track(frames,
			false));
		double worst = 0;
		for (int t = 0; t < frames.size(); t++) {
			final List<Localization> spots = results.get(t).spots();
			assertEquals(truth.get(t).size(), spots.size(), "frame " + t + ": one spot per particle, none lost");
			for (final Localization s : spots) {
				assertFalse(s.has(Flag.MERGED), "no merge");
				assertFalse(s.has(Flag.FELL_BACK), "no fallback");
			}
			for (final double[] c : truth.get(t)) {
				double best = Double.POSITIVE_INFINITY;
				for (final Localization s : spots)
					best = Math.min(best, Math.hypot(s.x() - c[0], s.y() - c[1]));
				worst = Math.max(worst, best);
			}
		}
		assertTrue(worst < tolerance, type.name() + ": worst centre error " + worst + " px with threshold " + params
			.threshold() + ", r_out " + params.rOut());
	}

	/**
	 * Particles a few pixels across ({@link SmallParticles}, about 7.5 px in diameter, as in trackpy's bulk_water
	 * sample): at the suggested threshold their active areas hold about 20 px, and the default {@code min_area} of 20
	 * px dropped a quarter of them as noise (on the real sample the sharpest, in-focus ones). The helper suggests
	 * half the area of its profile's active disc instead, and with it every particle is found, one spot each, the
	 * isolated ones unflagged and as close to the truth as their reported errors say.
	 */
	@Test
	void smallParticlesAreKeptWithTheSuggestedMinArea() {
		final SmallParticles.Field field = SmallParticles.simulate(3, 11);
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(field.frames().get(0), 0, 0);
		final double threshold = r.suggestedThreshold(true);
		final int minArea = r.suggestedMinArea(threshold);
		// the threshold's min_area is what is tested: by the threshold (auto would find the pairs by the image)
		final TrackerParameters params = TrackerParameters.of(threshold, r.suggestedROut()).withDiameter(r
			.suggestedDiameter()).withDetection(io.github.contacttracker.core.Detection.THRESHOLD);
		assertTrue(minArea < TrackerParameters.DEFAULT_MIN_AREA && minArea >= 5, "half of an active area of about 20 px: " +
			minArea);
		// measured: the default finds 57 of the 126 particles; the suggestion (10 px) 122 (the 3 pairs: 4 of 6), the
		// 120 isolated ones all unflagged, 0.030 px from the truth for reported errors of 0.028
		final int[] byDefault = found(field, params, null);
		assertTrue(byDefault[0] < 0.6 * byDefault[1], "the default min_area drops many: " + byDefault[0] + " of " +
			byDefault[1] + " found");
		final double[] errors = new double[2];
		final int[] suggested = found(field, params.withMinArea(minArea), errors);
		assertEquals(suggested[1] - 2 * field.frames().size(), suggested[2], "every isolated particle, unflagged");
		assertTrue(suggested[3] <= suggested[1], "one spot per particle at most: " + suggested[3]);
		assertTrue(errors[0] < 1.3 * errors[1], "centres within their reported errors: rms " + errors[0] + " px, " +
			"reported " + errors[1]);
	}

	/**
	 * Bright marks burned into the frame, as a timestamp's digits (12 marks 5 x 6 px, 7 px apart, brighter than the
	 * particles), among particles 20 px across: the marks' spacing is no particle's (two particles of the measured
	 * profile 6 px apart would be one spot), so it is left out of the diameter's estimate, and said.
	 */
	@Test
	void marksBurnedIntoTheFrameDoNotSetTheDiameter() {
		final ImagePlus imp = io.github.contacttracker.io.ProfileScenes.particles("stamped", 1,
			io.github.contacttracker.io.Calibration.PIXELS);
		for (int k = 0; k < 12; k++)
			for (int y = 4; y < 10; y++)
				for (int x = 6 + 7 * k; x < 11 + 7 * k; x++)
					imp.getProcessor().set(x, y, 250);
		@SuppressWarnings({ "unchecked", "rawtypes" })
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse((RandomAccessibleInterval) ImagePlusFrames.of(imp, 1)
			.frame(0), 0, 0);
		// measured: 19.88 px, 12 spots left out; before, 6.99 px (the marks' spacing) and a threshold above the centre
		assertEquals(io.github.contacttracker.io.ProfileScenes.SMALL.diameterPx(), r.diameter(), 0.1 * 20,
			"the particles' diameter, not the marks' spacing");
		assertTrue(r.findings().stream().anyMatch(f -> f instanceof Finding.SpotsTooClose c && c.spots() == 12), r
			.findings().toString());
		assertTrue(r.threshold() < r.peak(), "a threshold the particles rise above");
	}

	/**
	 * Tracks the field with {@code params} ({@code fit}).
	 *
	 * @param errors if not null, gets the rms distance of the isolated particles' spots from the truth and the rms of
	 *        their reported errors (both per coordinate, px)
	 * @return {particles found (a spot within 1 px), particles, isolated particles found by an unflagged spot, spots}
	 */
	private static int[] found(final SmallParticles.Field field, final TrackerParameters params, final double[] errors) {
		final List<FrameResult> results = StackTracker.withThreads(1, () -> new StackTracker(params).track(field
			.frames(), false));
		int found = 0, particles = 0, unflagged = 0, spots = 0;
		double squares = 0, sigmas = 0;
		for (int t = 0; t < results.size(); t++) {
			final List<Localization> ls = results.get(t).spots();
			spots += ls.size();
			final List<double[]> truth = field.truth().get(t);
			for (int k = 0; k < truth.size(); k++) {
				particles++;
				Localization best = null;
				for (final Localization l : ls)
					if (best == null || Math.hypot(l.x() - truth.get(k)[0], l.y() - truth.get(k)[1]) < Math.hypot(best.x() -
						truth.get(k)[0], best.y() - truth.get(k)[1])) best = l;
				if (best == null || Math.hypot(best.x() - truth.get(k)[0], best.y() - truth.get(k)[1]) >= 1) continue;
				found++;
				if (k < 2 || best.isFlagged()) continue; // (the pair: particles 0 and 1)
				unflagged++;
				squares += (Math.pow(best.x() - truth.get(k)[0], 2) + Math.pow(best.y() - truth.get(k)[1], 2)) / 2;
				sigmas += (best.sigmaX() * best.sigmaX() + best.sigmaY() * best.sigmaY()) / 2;
			}
		}
		if (errors != null) {
			errors[0] = Math.sqrt(squares / unflagged);
			errors[1] = Math.sqrt(sigmas / unflagged);
		}
		return new int[] { found, particles, unflagged, spots };
	}

	/**
	 * The real movie's troubles (issue 11: noise estimated at 0.59, r_out suggested at 66 px where a 32 px
	 * particle's image ends within 40 px): dense bright-field-like particles with saturated cores, a background
	 * rising by 8 grey levels across the frame, Gaussian pixel noise of 3 grey levels, and the frame stored as a
	 * JPEG at quality 0.3 (8x8 block artefacts that smooth the noise within blocks, as MJPEG does). The truth: the
	 * noise is the standard deviation of (stored frame - exact image) on the background; the profile meets the
	 * background where |P(r)| falls below it; r_out is that plus 2 px.
	 */
	@Test
	void realMovieConditionsGiveTheTrueROut() throws IOException {
		final int w = 480, h = 480;
		final SplittableRandom rnd = new SplittableRandom(3);
		final List<double[]> centres = scattered(40, w, h, 20, 40, rnd);
		final NoiseFreeImage exact = new ImageSimulator(BRIGHT_FIELD, 3).render(centres, w, h, 0);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				exact.pixels()[y * w + x] += 132 + 8.0 * (x + y) / (w + h); // the drifting background
		final byte[] noisy = ((net.imglib2.img.basictypeaccess.array.ByteArray) Quantiser.toUnsignedBytes(exact,
			NoiseModel.gaussian(4), rnd).image().update(null)).getCurrentStorageArray();
		final byte[] stored = jpeg(noisy, w, h, 0.5f);
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(stored, w, h));

		// the truth: the stored frame's noise on the background, far from every particle, about its local mean (the
		// JPEG's 8x8 blocks quantise a block's mean in steps of a few grey levels: on a smooth background that is a
		// local offset, part of the local background, not noise)
		final boolean[] far = new boolean[w * h];
		final double[] err = new double[w * h];
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				boolean f = true;
				for (final double[] c : centres)
					f &= Math.hypot(x - c[0], y - c[1]) > 45;
				far[y * w + x] = f;
				err[y * w + x] = (stored[y * w + x] & 0xff) - exact.pixels()[y * w + x];
			}
		double n = 0, sum2 = 0;
		for (int y = 12; y < h - 12; y += 2)
			for (int x = 12; x < w - 12; x += 2) {
				if (!far[y * w + x]) continue;
				double m = 0, k = 0;
				for (int v = y - 12; v <= y + 12; v++)
					for (int u = x - 12; u <= x + 12; u++)
						if (far[v * w + u]) {
							m += err[v * w + u];
							k++;
						}
				final double e = err[y * w + x] - m / k;
				n++;
				sum2 += e * e;
			}
		assertTrue(n > 500, "background pixels: " + n);
		final double trueNoise = Math.sqrt(sum2 / n);
		final double trueROut = BRIGHT_FIELD.reach(trueNoise) + Margins.R_OUT_MARGIN_PX;
		// the conditions are the real movie's: the pixel-difference estimator sees little of the JPEG noise
		assertTrue(NoiseEstimate.sigma(plane) < 0.8 * trueNoise, "Immerkaer " + NoiseEstimate.sigma(plane) +
			" against the true " + trueNoise);

		final ProfileAnalysis.Result auto = ProfileAnalysis.analyse(ArrayImgs.unsignedBytes(stored, w, h), 32, 0);
		for (int k = 0; k < auto.radius().length; k += 3) 		assertEquals(trueNoise, auto.noise(), 0.25 * trueNoise, "noise");
		assertEquals(trueROut, auto.rOut(), 2, "r_out within 2 px of the truth " + trueROut);
		assertEquals(List.of(), auto.findings().stream().filter(f -> f instanceof Finding.NotBackToBackground).toList());
		// at a point too, and with the diameter estimated
		final double[] c = centres.get(0);
		final ProfileAnalysis.Result one = ProfileAnalysis.analyse(ArrayImgs.unsignedBytes(stored, w, h), Math.round(
			c[0]), Math.round(c[1]), 0, 0);
		assertEquals(trueROut, one.rOut(), 2, "r_out at a point within 2 px of the truth " + trueROut);
		assertEquals(c[0], one.x(), 0.2);
		assertEquals(c[1], one.y(), 0.2);
	}

	/**
	 * A field so dense that no pixel lies a diameter away from every particle: a hexagonal lattice of 29 px, the
	 * estimated diameter 27-28 px. The helper found no background around any particle and refused ("only 0 background
	 * pixels lie between 54.88 and 68.60 px from the particle at ..."), and so did {@code track} without values; on the
	 * paper authors' single image Test_im.png (50 particles 27.5-38 px apart in 250 x 250 px) too. Now the mask around
	 * the neighbours narrows until background is left, and the helper says so. (On Test_im.png the values it then
	 * measures find all 50 particles; on this perfect lattice the neighbours' rings, all at the same distances, still
	 * show in the profile, and the helper's other warnings say what follows.)
	 */
	@Test
	void aFieldWithoutBackgroundBeyondADiameterIsMeasuredWithANarrowerMask() {
		final int w = 250, h = 250;
		final SplittableRandom rnd = new SplittableRandom(5);
		final List<double[]> centres = new ArrayList<>();
		for (int row = 0; 8 + row * 29 * Math.sqrt(3) / 2 < h - 8; row++)
			for (double x = 8 + (row % 2) * 14.5; x < w - 8; x += 29)
				centres.add(new double[] { x + rnd.nextDouble(-1, 1), 8 + row * 29 * Math.sqrt(3) / 2 + rnd.nextDouble(-1,
					1) });
		final RadialProfile profile = r -> 120 * Math.exp(-r * r / 32) - 16 * Math.exp(-(r - 14) * (r - 14) / 18);
		final RandomAccessibleInterval<UnsignedByteType> frame = Quantiser.toUnsignedBytes(new ImageSimulator(profile,
			3).render(centres, w, h, 65), NoiseModel.gaussian(3), rnd).image();
		final ProfileAnalysis.Result r = ProfileAnalysis.analyse(frame, 0, 0);
		final List<Finding> narrowed = r.findings().stream().filter(f -> f instanceof Finding.NeighboursMaskedCloser)
			.toList();
		assertEquals(1, narrowed.size(), "said once: " + r.findings());
		final Finding.NeighboursMaskedCloser f = (Finding.NeighboursMaskedCloser) narrowed.get(0);
		assertTrue(f.mask() < f.wanted() && f.mask() >= r.diameter() / 2, f + " at diameter " + r.diameter());
		assertEquals(28, r.diameter(), 1.5, "the lattice's spacing, less its jitter");
	}

	/** {@code count} random centres at least {@code margin} inside a w x h frame and more than {@code apart} apart. */
	static List<double[]> scattered(final int count, final int w, final int h, final double margin,
		final double apart, final SplittableRandom rnd)
	{
		final List<double[]> centres = new ArrayList<>();
		while (centres.size() < count) {
			final double[] c = { margin + rnd.nextDouble() * (w - 2 * margin), margin + rnd.nextDouble() * (h - 2 *
				margin) };
			boolean free = true;
			for (final double[] o : centres)
				free &= Math.hypot(c[0] - o[0], c[1] - o[1]) > apart;
			if (free) centres.add(c);
		}
		return centres;
	}

	/** Stores a grey frame as a JPEG of the given quality and reads it back. */
	static byte[] jpeg(final byte[] pixels, final int w, final int h, final float quality) throws IOException {
		final BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_BYTE_GRAY);
		img.getRaster().setDataElements(0, 0, w, h, pixels);
		final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		final ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
		try (MemoryCacheImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
			writer.setOutput(out);
			final ImageWriteParam p = writer.getDefaultWriteParam();
			p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
			p.setCompressionQuality(quality);
			writer.write(null, new IIOImage(img, null, null), p);
		}
		finally {
			writer.dispose();
		}
		final BufferedImage back = ImageIO.read(new ByteArrayInputStream(bytes.toByteArray()));
		final byte[] out = new byte[w * h];
		back.getRaster().getDataElements(0, 0, w, h, out);
		return out;
	}

	/**
	 * The kinds of particle are found on the frame profiled and the next ones, or the ones before it at the movie's
	 * end: the rarest kind of the authors' tracking-test-project.avi has 2 particles a frame, a kind needs 3.
	 */
	@Test
	void kindsAreFoundOnTheFrameAndItsNeighbours() {
		assertEquals(List.of(0), ProfileAnalysis.kindFrames(0, 1));
		assertEquals(List.of(0, 1, 2, 3, 4), ProfileAnalysis.kindFrames(0, 360));
		assertEquals(List.of(7, 8, 9, 10, 11), ProfileAnalysis.kindFrames(7, 360));
		assertEquals(List.of(9, 5, 6, 7, 8), ProfileAnalysis.kindFrames(9, 10));
		assertEquals(List.of(2, 0, 1, 3), ProfileAnalysis.kindFrames(2, 4));
	}
}
