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
package io.github.contacttracker.lab.sim;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import io.github.contacttracker.core.InvalidInputException;
import net.imglib2.img.array.ArrayImg;

/**
 * The scenes of the detection study: movies a new user brings, each with its ground truth, that the threshold's
 * detection finds hard. A tweezer pair of blurred beads pushed from two diameters apart into overlap; dim 16-bit
 * spots a few pixels across on a camera offset; dark spheres on a bright background; fluorescent spheres whose
 * background the camera clips at 0. Every frame shows its particles moved as a whole by a random sub-pixel offset,
 * with fresh noise, at 84.7 nm per pixel.
 */
public final class DetectionScenes {

	/** The scenes {@link #of} knows, in order. */
	public static final List<String> KEYS = List.of("pair-sweep", "dim", "dark", "clipped", "dense", "dense-bidisperse",
		"ring-pair", "dense-polydisperse");

	/** Pixel size of every scene (nm). */
	public static final double PIXEL_NM = 84.7;
	/** Separations of the pair sweep, over the diameter: from this one down to {@link #CLOSEST}. */
	public static final double FARTHEST = 2.0, CLOSEST = 0.5;
	/** Frames of a pair sweep, one per separation, unless told otherwise. */
	public static final int SWEEP_STEPS = 40;
	/** Frames of the other scenes, unless told otherwise. */
	public static final int FRAMES = 5;

	/** The band of every frame of a scene without bands. */
	public static final String ALL = "all";

	private DetectionScenes() {}

	/**
	 * @param key one of {@link #KEYS}
	 * @param frames frames of the movie (a pair sweep: separations, at least 2)
	 * @param seed seed of the layout, offsets and noise: equal seeds give identical movies
	 * @return the movie
	 * @throws InvalidInputException for an unknown key
	 */
	public static DetectionScene of(final String key, final int frames, final long seed) {
		return switch (key.trim().toLowerCase(Locale.ROOT)) {
			case "pair-sweep" -> pairSweep(frames, seed);
			case "dim" -> dim(frames, seed);
			case "dark" -> dark(frames, seed);
			case "clipped" -> clipped(frames, seed);
			case "dense" -> dense(frames, seed);
			case "dense-bidisperse" -> denseBidisperse(frames, seed);
			case "dense-polydisperse" -> densePolydisperse(frames, seed);
			case "ring-pair" -> ringPair(frames, seed);
			default -> throw new InvalidInputException("--detection-scenes must be among " + String.join(",", KEYS) +
				" or all, not '" + key + "'");
		};
	}

	/** @return the frames a scene has unless told otherwise */
	public static int defaultFrames(final String key) {
		return switch (key.trim().toLowerCase(Locale.ROOT)) {
			case "pair-sweep", "ring-pair" -> SWEEP_STEPS;
			case "dense", "dense-bidisperse", "dense-polydisperse" -> DENSE_FRAMES;
			default -> FRAMES;
		};
	}

	/** Frames of the dense monolayer, unless told otherwise: each holds about 1,600 particles. */
	public static final int DENSE_FRAMES = 2;
	/** The dense monolayer's area fraction. */
	public static final double DENSE_AREA_FRACTION = 0.7;
	/** The group of the dense monolayer's small particles, and of its large ones. */
	public static final String SMALL = "D 10", LARGE = "D 14";

	/**
	 * A pair of blurred discs (D 12 px, flat top, Gaussian blur sigma 1.5 px; background 37, peak 160, 8-bit,
	 * Gaussian pixel noise 3) pushed from {@link #FARTHEST} diameters apart to {@link #CLOSEST}, one frame per
	 * separation, along a line tilted by 10 degrees. Frame {@code i}'s label is its separation over the diameter; the
	 * bands are apart or touching (at least 1 D), overlapping by up to a quarter (0.75-1 D) and by more (0.5-0.75 D).
	 *
	 * @param steps separations (frames), at least 2
	 */
	public static DetectionScene pairSweep(final int steps, final long seed) {
		final double d = 12;
		final ParticleType type = new ParticleType("blurred disc D 12 px", d * PIXEL_NM / 1000, PIXEL_NM,
			new BlurredDisc(d / 2, 1.5, 123), 37, 37 + 123 / 2.0, d, NoiseModel.gaussian(3));
		final Scene scene = new Scene("pair-sweep", type, List.of(new Scene.Particle(-d, 0, 1, 1), new Scene.Particle(
			d, 0, 1, 1)), 0, 0, 0, 0, type.threshold());
		return sweep(String.format(Locale.ROOT, "a pair of blurred discs (D 12 px, blur sigma 1.5 px, background 37, peak " +
			"160, 8-bit, noise sigma 3) from %.1f D apart to %.1f D, one frame per separation", FARTHEST, CLOSEST), scene,
			96, 64, 8, d, steps, seed);
	}

	/**
	 * A pair of {@code scene}'s particles (diameter {@code d}) moved from {@link #FARTHEST} diameters apart to
	 * {@link #CLOSEST} about the frame's centre (jittered by up to half a pixel), one frame per separation, along a line
	 * tilted by 10 degrees; each frame labelled with its separation over the diameter and banded by it.
	 */
	private static DetectionScene sweep(final String description, final Scene scene, final int w, final int h,
		final int bitDepth, final double d, final int steps, final long seed)
	{
		if (steps < 2) throw new InvalidInputException("a pair sweep needs at least 2 separations, not " + steps);
		final SplittableRandom random = new SplittableRandom(seed);
		final double cos = Math.cos(Math.toRadians(10)), sin = Math.sin(Math.toRadians(10));
		final List<List<double[]>> centres = new ArrayList<>();
		final double[] labels = new double[steps];
		final List<String> bands = new ArrayList<>();
		for (int i = 0; i < steps; i++) {
			final double s = FARTHEST - (FARTHEST - CLOSEST) * i / (steps - 1);
			final double cx = 0.5 * (w - 1) + random.nextDouble(-0.5, 0.5), cy = 0.5 * (h - 1) + random.nextDouble(-0.5,
				0.5);
			final double ux = 0.5 * s * d * cos, uy = 0.5 * s * d * sin;
			centres.add(List.of(new double[] { cx - ux, cy - uy }, new double[] { cx + ux, cy + uy }));
			labels[i] = s;
			bands.add(pairBand(s));
		}
		return movie(scene.key(), description, scene, w, h, bitDepth, 0, centres, labels, bands, List.of(), true, random);
	}

	/**
	 * A tweezer pair of particles dark inside a bright ring (microgels, or beads a little out of focus, as bright-field
	 * tweezer footage shows them; D 24 px: a core 700 grey levels below the background, Gaussian of sigma 4.2 px, and a
	 * ring 350 above it at the radius of 12 px, sigma 2.2 px) on a 16-bit ramp of light (3,900 at the frame's centre,
	 * rising 7.5 grey levels a px along x and 2 along y), photon noise (2 grey levels a photon) and read noise 10,
	 * pushed from {@link #FARTHEST} diameters apart to {@link #CLOSEST}, one frame per separation, along a line tilted
	 * by 10 degrees; labels and bands as {@link #pairSweep}.
	 *
	 * @param steps separations (frames), at least 2
	 */
	public static DetectionScene ringPair(final int steps, final long seed) {
		final double d = 24, background = 3900;
		final RadialProfile ring = r -> -700 * Math.exp(-r * r / (2 * 4.2 * 4.2)) + 350 * Math.exp(-(r - 12) * (r - 12) /
			(2 * 2.2 * 2.2));
		final ParticleType type = new ParticleType("dark core in a bright ring D 24 px", d * PIXEL_NM / 1000, PIXEL_NM,
			ring, background, background - 350, d, NoiseModel.gaussian(10));
		final Scene scene = new Scene("ring-pair", type, List.of(new Scene.Particle(-d, 0, 1, 1), new Scene.Particle(d, 0,
			1, 1)), 7.5, 2, 2, 10, type.threshold());
		return sweep(String.format(Locale.ROOT, "a tweezer pair of particles dark inside a bright ring (D 24 px, core " +
			"700 below the background, ring 350 above it) on a 16-bit ramp of light (7.5 and 2 grey levels a px about " +
			"3,900), photon and read noise, from %.1f D apart to %.1f D, one frame per separation", FARTHEST, CLOSEST),
			scene, 160, 96, 16, d, steps, seed);
	}

	/** @return the band of a pair {@code s} diameters apart */
	public static String pairBand(final double s) {
		return s >= 1 - 1e-9 ? ">= 1 D" : s >= 0.75 - 1e-9 ? "0.75-1 D" : "0.5-0.75 D";
	}

	/**
	 * Dim 16-bit spots: Gaussian-like (sigma 1.2 px, D about 4.5 px, each 0.9 to 1.1 times that), 30 alone and 5
	 * touching pairs (D apart) in 256 x 256 px, each at a peak signal to noise of 3 to 5 over a camera offset of 500
	 * with photon noise (2 grey levels a photon, a background of 10 photons) and read noise 4.
	 */
	public static DetectionScene dim(final int frames, final long seed) {
		final double sigma = 1.2, d = 4.5, peak = 30;
		final double gain = 2, background = 20, read = 4, offset = 500;
		final double noise = Math.sqrt(gain * background + read * read);
		final RadialProfile gaussian = r -> peak * Math.exp(-r * r / (2 * sigma * sigma));
		final ParticleType type = new ParticleType("Gaussian spot D 4.5 px", d * PIXEL_NM / 1000, PIXEL_NM, gaussian,
			background, background + peak / 2, 5, NoiseModel.gaussian(noise));
		final SplittableRandom random = new SplittableRandom(seed);
		final List<double[][]> groups = groups(30, 5, 0, 0, d);
		final List<double[]> layout = place(random, groups, 256, 256, 10, 3 * d);
		final List<Scene.Particle> ps = new ArrayList<>();
		for (final double[] c : layout)
			ps.add(new Scene.Particle(c[0], c[1], random.nextDouble(0.9, 1.1), random.nextDouble(3, 5) * noise / peak));
		final Scene scene = new Scene("dim", type, ps, 0, 0, gain, read, type.threshold());
		return still("dim", "dim 16-bit Gaussian spots (sigma 1.2 px, D 4-5 px), 30 alone and 5 touching pairs in " +
			"256 x 256 px, peak SNR 3-5 over an offset of 500, photon and read noise", scene, 256, 256, 16, offset, layout,
			names(groups), frames, true, random);
	}

	/**
	 * Dark spheres on a bright background, the negative of a fluorescent field: blurred discs (D 10 px, blur sigma 1.2
	 * px) 120 grey levels below a background of 200, 8-bit, Gaussian noise 3; 14 alone, 4 touching pairs and a
	 * touching triangle in 160 x 160 px.
	 */
	public static DetectionScene dark(final int frames, final long seed) {
		final double d = 10;
		final ParticleType type = new ParticleType("dark disc D 10 px", d * PIXEL_NM / 1000, PIXEL_NM, new BlurredDisc(
			d / 2, 1.2, -120), 200, 140, d, NoiseModel.gaussian(3));
		final SplittableRandom random = new SplittableRandom(seed);
		final List<double[][]> groups = groups(14, 4, 1, 0, d);
		final List<double[]> layout = place(random, groups, 160, 160, 12, 2.2 * d);
		final Scene scene = new Scene("dark", type, plain(layout), 0, 0, 0, 0, type.threshold());
		return still("dark", "dark blurred discs (D 10 px, blur sigma 1.2 px) 120 below a background of 200, 8-bit, " +
			"noise sigma 3; 14 alone, 4 touching pairs, a touching triangle in 160 x 160 px", scene, 160, 160, 8, 0,
			layout, names(groups), frames, true, random);
	}

	/**
	 * Fluorescent spheres on a background the camera clips at 0: blurred discs (D 10 px, blur sigma 1.5 px, 100 grey
	 * levels high) on a background of 2 with Gaussian noise 4, 8-bit, so that about a third of the background reads 0;
	 * 12 alone, 3 touching pairs and 2 chains of 4 touching particles in 160 x 160 px. The bound is not given: the noise clipped
	 * at 0 is not the Gaussian it assumes.
	 */
	public static DetectionScene clipped(final int frames, final long seed) {
		final double d = 10;
		final ParticleType type = new ParticleType("bright disc D 10 px, clipped background", d * PIXEL_NM / 1000,
			PIXEL_NM, new BlurredDisc(d / 2, 1.5, 100), 2, 52, d, NoiseModel.gaussian(4));
		final SplittableRandom random = new SplittableRandom(seed);
		final List<double[][]> groups = groups(12, 3, 0, 2, d);
		final List<double[]> layout = place(random, groups, 160, 160, 12, 2.2 * d);
		final Scene scene = new Scene("clipped", type, plain(layout), 0, 0, 0, 0, type.threshold());
		return still("clipped", "bright blurred discs (D 10 px, blur sigma 1.5 px, 100 high) on a background of 2 " +
			"clipped at 0 (noise sigma 4: a third of the background reads 0), 8-bit; 12 alone, 3 touching pairs, 2 " +
			"chains of 4 in 160 x 160 px", scene, 160, 160, 8, 0, layout, names(groups), frames, false, random);
	}

	/**
	 * A dense monolayer of two sizes with no particle alone: as many bright blurred discs of D 10 px as of D 14 px
	 * (blur sigma 1.2 px and 1.7 px, 100 grey levels above a background of 30, 8-bit, Gaussian noise 3) at an area
	 * fraction of {@value #DENSE_AREA_FRACTION} in 512 x 512 px, about 1,600 particles, their centres anywhere in the
	 * frame (some cut by its edge). They are placed at random, overlapping, and pushed apart pair by pair until none
	 * overlaps ({@link #unjam}): most end touching their neighbours. The bound is not given: a Fisher matrix over
	 * every particle of the frame is too large to invert here.
	 */
	public static DetectionScene denseBidisperse(final int frames, final long seed) {
		final double d = 10, large = 1.4;
		final int w = 512, h = 512;
		final ParticleType type = new ParticleType("bright disc D 10 and 14 px, dense", d * PIXEL_NM / 1000, PIXEL_NM,
			new BlurredDisc(d / 2, 1.2, 100), 30, 80, d, NoiseModel.gaussian(3));
		final SplittableRandom random = new SplittableRandom(seed);
		final int n = 2 * (int) Math.round(DENSE_AREA_FRACTION * w * h / (Math.PI / 4 * d * d * (1 + large * large)));
		final double[] x = new double[n], y = new double[n], r = new double[n], scale = new double[n];
		final List<String> groups = new ArrayList<>();
		for (int i = 0; i < n; i++) {
			x[i] = random.nextDouble(0, w - 1);
			y[i] = random.nextDouble(0, h - 1);
			scale[i] = i % 2 == 0 ? 1 : large;
			r[i] = d / 2 * scale[i];
			groups.add(i % 2 == 0 ? SMALL : LARGE);
		}
		final List<double[]> layout = new ArrayList<>();
		final List<Scene.Particle> ps = new ArrayList<>();
		pack(x, y, r, scale, w, h, layout, ps);
		final Scene scene = new Scene("dense-bidisperse", type, ps, 0, 0, 0, 0, type.threshold());
		return still("dense-bidisperse", String.format(Locale.ROOT, "a dense monolayer of bright blurred discs, as " +
			"many of D 10 px as of D 14 px (blur sigma 1.2 and 1.7 px, 100 above a background of 30, 8-bit, noise sigma " +
			"3), area fraction %.1f, %d particles in 512 x 512 px, none alone", DENSE_AREA_FRACTION, n), scene, w, h, 8,
			0, layout, groups, frames, false, random);
	}

	/** The polydisperse packing's smallest diameter (px), and its largest over its smallest. */
	public static final double POLY_SMALLEST = 7, POLY_RANGE = 1.9;
	/**
	 * The polydisperse packing's discs are this share of its spheres' diameters: the confocal slice cuts each sphere
	 * off its equator, so neighbours that touch show as discs a dark line apart.
	 */
	public static final double POLY_SECTION = 0.9;
	/** The polydisperse packing's area fraction (of its spheres' equators; of its discs, {@link #POLY_SECTION} squared times it). */
	public static final double POLY_AREA_FRACTION = 0.72;
	/** The polydisperse packing's size bands: discs of diameter below 9 px, 9 to 11 px, and above. */
	public static final String POLY_SMALL = "D 7-9", POLY_MEDIUM = "D 9-11", POLY_LARGE = "D 11-13.3";

	/**
	 * A confocal slice of a dense packing of spheres of many sizes, as public confocal stacks of colloidal packings show
	 * them: bright flat discs of diameters spread evenly from {@value #POLY_SMALLEST} px to {@value #POLY_RANGE} times
	 * that (blur sigma 0.9 px at the smallest, growing with the disc), 40 grey levels above a background of 8, 8-bit,
	 * Gaussian pixel noise 9 (a per-pixel signal to noise of 4.4), at an area fraction of {@value #POLY_AREA_FRACTION}
	 * in 256 x 256 px (the spheres' equators; the discs are {@value #POLY_SECTION} of them across), about 320 particles,
	 * placed as in {@link #denseBidisperse}: none alone, most a dark line from their neighbours.
	 */
	public static DetectionScene densePolydisperse(final int frames, final long seed) {
		final double d = POLY_SMALLEST;
		final int w = 256, h = 256;
		final ParticleType type = new ParticleType("bright flat disc D 7-13.3 px, dense", d * PIXEL_NM / 1000,
			PIXEL_NM, new BlurredDisc(d / 2, 0.9, 40), 8, 28, d, NoiseModel.gaussian(9));
		final SplittableRandom random = new SplittableRandom(seed);
		// the mean equator of a sphere whose diameter is spread evenly over [D, R D]: D^2 (1 + R + R^2) / 3 times pi / 4
		final double sphere = d / POLY_SECTION;
		final double meanArea = Math.PI / 4 * sphere * sphere * (1 + POLY_RANGE + POLY_RANGE * POLY_RANGE) / 3;
		final int n = (int) Math.round(POLY_AREA_FRACTION * w * h / meanArea);
		final double[] x = new double[n], y = new double[n], r = new double[n], scale = new double[n];
		final List<String> groups = new ArrayList<>();
		for (int i = 0; i < n; i++) {
			x[i] = random.nextDouble(0, w - 1);
			y[i] = random.nextDouble(0, h - 1);
			scale[i] = random.nextDouble(1, POLY_RANGE);
			r[i] = d / 2 * scale[i] / POLY_SECTION;
			final double disc = d * scale[i];
			groups.add(disc < 9 ? POLY_SMALL : disc < 11 ? POLY_MEDIUM : POLY_LARGE);
		}
		final List<double[]> layout = new ArrayList<>();
		final List<Scene.Particle> ps = new ArrayList<>();
		pack(x, y, r, scale, w, h, layout, ps);
		final Scene scene = new Scene("dense-polydisperse", type, ps, 0, 0, 0, 0, type.threshold());
		return still("dense-polydisperse", String.format(Locale.ROOT, "a confocal slice of a dense packing of many " +
			"sizes: bright flat discs of D 7 to 13.3 px spread evenly (blur sigma 0.9 px at the smallest), 40 above a " +
			"background of 8, 8-bit, noise sigma 9, each %.2f of its sphere's diameter, spheres at area fraction %.2f, %d particles in 256 x 256 px, none alone",
			POLY_SECTION, POLY_AREA_FRACTION, n), scene, w, h, 8, 0, layout, groups, frames, false, random);
	}

	/** The area fraction of the dense monolayer of one size. */
	public static final double DENSE_ONE_SIZE_FRACTION = 0.6;

	/**
	 * A dense monolayer of one size with no particle alone: bright blurred discs of D 14 px (blur sigma 1.7 px, 100
	 * grey levels above a background of 30, 8-bit, Gaussian noise 3) at an area fraction of
	 * {@value #DENSE_ONE_SIZE_FRACTION} in 256 x 256 px, about 200 particles, placed as in {@link #denseBidisperse}.
	 */
	public static DetectionScene dense(final int frames, final long seed) {
		final double d = 14;
		final int w = 256, h = 256;
		final ParticleType type = new ParticleType("bright disc D 14 px, dense", d * PIXEL_NM / 1000, PIXEL_NM,
			new BlurredDisc(d / 2, 1.7, 100), 30, 80, d, NoiseModel.gaussian(3));
		final SplittableRandom random = new SplittableRandom(seed);
		final int n = (int) Math.round(DENSE_ONE_SIZE_FRACTION * w * h / (Math.PI / 4 * d * d));
		final double[] x = new double[n], y = new double[n], r = new double[n], scale = new double[n];
		for (int i = 0; i < n; i++) {
			x[i] = random.nextDouble(0, w - 1);
			y[i] = random.nextDouble(0, h - 1);
			r[i] = d / 2;
			scale[i] = 1;
		}
		final List<double[]> layout = new ArrayList<>();
		final List<Scene.Particle> ps = new ArrayList<>();
		pack(x, y, r, scale, w, h, layout, ps);
		final Scene scene = new Scene("dense", type, ps, 0, 0, 0, 0, type.threshold());
		return still("dense", String.format(Locale.ROOT, "a dense monolayer of bright blurred discs of D 14 px (blur " +
			"sigma 1.7 px, 100 above a background of 30, 8-bit, noise sigma 3), area fraction %.1f, %d particles in " +
			"256 x 256 px, none alone", DENSE_ONE_SIZE_FRACTION, n), scene, w, h, 8, 0, layout, java.util.Collections
				.nCopies(n, TOUCHING), frames, false, random);
	}

	/**
	 * Pushes the discs of radii {@code r} apart ({@link #unjam}) and adds each centre to {@code layout} and each
	 * particle, of radial scale {@code scale}, to {@code ps}: the packing of every dense scene.
	 */
	private static void pack(final double[] x, final double[] y, final double[] r, final double[] scale, final int w,
		final int h, final List<double[]> layout, final List<Scene.Particle> ps)
	{
		unjam(x, y, r, w, h);
		for (int i = 0; i < x.length; i++) {
			layout.add(new double[] { x[i], y[i] });
			ps.add(new Scene.Particle(x[i], y[i], scale[i], 1));
		}
	}

	/**
	 * Pushes overlapping discs apart until none overlaps by more than 0.01 px: each sweep moves both discs of every
	 * overlapping pair apart along their line by half the overlap, centres kept inside the frame; a grid of cells as
	 * wide as the largest disc finds the pairs. At the dense monolayer's area fraction, well below random close
	 * packing (about 0.84 for two sizes), a few hundred sweeps do.
	 *
	 * @throws IllegalStateException when the discs still overlap after 5,000 sweeps
	 */
	private static void unjam(final double[] x, final double[] y, final double[] r, final int w, final int h) {
		final int n = x.length;
		double rMax = 0;
		for (final double v : r)
			rMax = Math.max(rMax, v);
		final double cell = 2 * rMax;
		final int cw = (int) Math.ceil(w / cell) + 1, ch = (int) Math.ceil(h / cell) + 1;
		final int[] head = new int[cw * ch], next = new int[n];
		for (int sweep = 0; sweep < 5000; sweep++) {
			Arrays.fill(head, -1);
			for (int i = 0; i < n; i++) {
				final int c = (int) (y[i] / cell) * cw + (int) (x[i] / cell);
				next[i] = head[c];
				head[c] = i;
			}
			double worst = 0;
			for (int i = 0; i < n; i++) {
				final int cx = (int) (x[i] / cell), cy = (int) (y[i] / cell);
				for (int gy = Math.max(0, cy - 1); gy <= Math.min(ch - 1, cy + 1); gy++)
					for (int gx = Math.max(0, cx - 1); gx <= Math.min(cw - 1, cx + 1); gx++)
						for (int j = head[gy * cw + gx]; j >= 0; j = next[j]) {
							if (j <= i) continue;
							final double dx = x[j] - x[i], dy = y[j] - y[i], dist = Math.hypot(dx, dy);
							final double overlap = r[i] + r[j] - dist;
							if (overlap <= 0) continue;
							worst = Math.max(worst, overlap);
							// half the overlap each, a little more so that the pair ends just touching
							final double push = 0.5 * overlap + 1e-4, ux = dist > 0 ? dx / dist : 1, uy = dist > 0 ? dy / dist : 0;
							x[i] = Math.min(w - 1, Math.max(0, x[i] - push * ux));
							y[i] = Math.min(h - 1, Math.max(0, y[i] - push * uy));
							x[j] = Math.min(w - 1, Math.max(0, x[j] + push * ux));
							y[j] = Math.min(h - 1, Math.max(0, y[j] + push * uy));
						}
			}
			if (worst <= 0.01) return;
		}
		throw new IllegalStateException("the discs still overlap after 5000 sweeps");
	}

	private static List<Scene.Particle> plain(final List<double[]> layout) {
		final List<Scene.Particle> ps = new ArrayList<>();
		for (final double[] c : layout)
			ps.add(new Scene.Particle(c[0], c[1], 1, 1));
		return ps;
	}

	/** The group of a particle alone, and of one that touches another. */
	public static final String ALONE = "alone", TOUCHING = "touching";

	/**
	 * @return groups of particles, each as its members' offsets from the group's centre: {@code singles} alone,
	 *         {@code pairs} touching pairs, {@code triples} touching triangles and {@code chains} straight chains of 4
	 *         touching particles, {@code d} across
	 */
	private static List<double[][]> groups(final int singles, final int pairs, final int triples, final int chains,
		final double d)
	{
		final List<double[][]> g = new ArrayList<>();
		for (int i = 0; i < singles; i++)
			g.add(new double[][] { { 0, 0 } });
		for (int i = 0; i < pairs; i++)
			g.add(new double[][] { { -d / 2, 0 }, { d / 2, 0 } });
		final double hgt = d * Math.sqrt(3) / 2;
		for (int i = 0; i < triples; i++)
			g.add(new double[][] { { -d / 2, hgt / 3 }, { d / 2, hgt / 3 }, { 0, -2 * hgt / 3 } });
		for (int i = 0; i < chains; i++)
			g.add(new double[][] { { -1.5 * d, 0 }, { -0.5 * d, 0 }, { 0.5 * d, 0 }, { 1.5 * d, 0 } });
		return g;
	}

	/** @return per particle, in {@link #place}'s order, {@link #ALONE} or {@link #TOUCHING} */
	private static List<String> names(final List<double[][]> groups) {
		final List<String> names = new ArrayList<>();
		for (final double[][] g : groups)
			for (int k = 0; k < g.length; k++)
				names.add(g.length == 1 ? ALONE : TOUCHING);
		return names;
	}

	/**
	 * Places the groups at random, each turned by a random angle, its members at least {@code border} px inside the
	 * frame and at least {@code clearance} px from every other group's members.
	 *
	 * @return every member's centre, group by group
	 * @throws IllegalStateException when the groups do not fit
	 */
	private static List<double[]> place(final SplittableRandom random, final List<double[][]> groups, final int w,
		final int h, final double border, final double clearance)
	{
		final List<double[]> placed = new ArrayList<>();
		for (final double[][] g : groups) {
			boolean done = false;
			for (int attempt = 0; attempt < 10_000 && !done; attempt++) {
				final double cx = random.nextDouble(border, w - 1 - border), cy = random.nextDouble(border, h - 1 - border);
				final double a = random.nextDouble(0, 2 * Math.PI), cos = Math.cos(a), sin = Math.sin(a);
				final double[][] m = new double[g.length][];
				boolean fits = true;
				for (int k = 0; k < g.length && fits; k++) {
					m[k] = new double[] { cx + cos * g[k][0] - sin * g[k][1], cy + sin * g[k][0] + cos * g[k][1] };
					fits = m[k][0] >= border && m[k][0] <= w - 1 - border && m[k][1] >= border && m[k][1] <= h - 1 - border;
					for (final double[] p : placed)
						fits &= Math.hypot(p[0] - m[k][0], p[1] - m[k][1]) >= clearance;
				}
				if (fits) {
					placed.addAll(Arrays.asList(m));
					done = true;
				}
			}
			if (!done) throw new IllegalStateException(groups.size() + " groups do not fit in " + w + " x " + h + " px");
		}
		return placed;
	}

	/** A movie of one layout, moved as a whole by a random sub-pixel offset in each frame; one band. */
	private static DetectionScene still(final String key, final String description, final Scene scene, final int w,
		final int h, final int bitDepth, final double offset, final List<double[]> layout, final List<String> groups,
		final int frames, final boolean boundKnown, final SplittableRandom random)
	{
		if (frames < 1) throw new InvalidInputException("a scene needs at least 1 frame, not " + frames);
		final List<List<double[]>> centres = new ArrayList<>();
		final List<String> bands = new ArrayList<>();
		final double[] labels = new double[frames];
		for (int f = 0; f < frames; f++) {
			final double ox = random.nextDouble(-0.5, 0.5), oy = random.nextDouble(-0.5, 0.5);
			final List<double[]> c = new ArrayList<>();
			for (final double[] p : layout)
				c.add(new double[] { p[0] + ox, p[1] + oy });
			centres.add(c);
			bands.add(ALL);
			labels[f] = Double.NaN;
		}
		return movie(key, description, scene, w, h, bitDepth, offset, centres, labels, bands, groups, boundKnown,
			random);
	}

	private static DetectionScene movie(final String key, final String description, final Scene scene, final int w,
		final int h, final int bitDepth, final double offset, final List<List<double[]>> centres, final double[] labels,
		final List<String> bands, final List<String> groups, final boolean boundKnown, final SplittableRandom random)
	{
		final List<ImageSimulator> sims = scene.simulators();
		final List<ArrayImg<?, ?>> frames = new ArrayList<>();
		long clipped = 0;
		for (final List<double[]> c : centres) {
			final QuantisedFrame<?> f = scene.camera(scene.render(sims, c, w, h), random, bitDepth, offset);
			frames.add(f.image());
			clipped += f.clippedPixels();
		}
		return new DetectionScene(key, description, scene, bitDepth, frames, centres, labels, bands, groups, boundKnown,
			clipped);
	}
}
