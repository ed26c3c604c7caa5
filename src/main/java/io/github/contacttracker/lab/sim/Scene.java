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
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import io.github.contacttracker.core.InvalidInputException;
import net.imglib2.img.array.ArrayImg;

/**
 * A harder scene than the paper's two: a cluster of touching particles (any layout), particles of unlike size
 * and brightness, a background ramp, photon (Poisson) plus read noise, and saturated cores. Every frame shows the
 * same scene moved as a whole by a random sub-pixel offset, with fresh noise; 8-bit, clipped at 255 (the clipped
 * pixels are counted).
 *
 * @param key short name ({@code pair}, {@code hex7}, ...)
 * @param type the particles (profile, background, pixel size, r_out)
 * @param particles the particles, centred on (0, 0) (px)
 * @param rampX background slope along x (grey levels per px), about the frame's centre
 * @param rampY background slope along y
 * @param photonGain grey levels per photon for photon noise, or 0 for the type's additive noise
 * @param readNoise standard deviation of the read noise (grey levels), with photon noise
 * @param threshold the active-area threshold for this scene
 * @param profiles the profile of each kind of particle ({@link Particle#kind()} indexes it): the type's alone, or
 *        one per kind in a {@link #mixed} scene
 */
public record Scene(String key, ParticleType type, List<Particle> particles, double rampX, double rampY,
	double photonGain, double readNoise, double threshold, List<RadialProfile> profiles)
{

	/** The scenes of particles of unlike kinds that {@link #mixed} knows, in order. */
	public static final List<String> MIXED_KEYS = List.of("mixed", "mixed7");

	/** The scenes {@link #of} knows, in order. */
	public static final List<String> KEYS = List.of("pair", "chain4", "triple", "hex7", "hex19", "hex37", "unlike",
		"unlike13", "ramp", "saturated", "photon");

	/** Grey levels per photon of the photon-noise scenes: about 300 photons at a background of 60. */
	public static final double PHOTON_GAIN = 0.2;
	/** Read noise of the photon-noise scenes (grey levels). */
	public static final double READ_NOISE = 1.5;
	/** How much brighter the saturated scene's particles are: their cores clip at 255. */
	public static final double SATURATED_BRIGHTNESS = 2;

	/**
	 * One particle: centre, radial scale of the profile (1.2 = 1.2 times larger), factor on its grey levels and
	 * kind (which of the scene's {@link Scene#profiles() profiles} it has).
	 *
	 * @param x centre x relative to the scene's centre (px)
	 * @param y centre y (px)
	 * @param scale radial scale
	 * @param amplitude brightness factor
	 * @param kind index of its profile among the scene's (0: the type's)
	 */
	public record Particle(double x, double y, double scale, double amplitude, int kind) {

		/** A particle of the scene's type (kind 0). */
		public Particle(final double x, final double y, final double scale, final double amplitude) {
			this(x, y, scale, amplitude, 0);
		}
	}

	/** Copies the lists; every particle's kind must have a profile. */
	public Scene {
		particles = List.copyOf(particles);
		profiles = List.copyOf(profiles);
		for (final Particle p : particles)
			if (p.kind < 0 || p.kind >= profiles.size()) throw new IllegalArgumentException("particle of kind " + p.kind +
				" but " + profiles.size() + " profiles");
	}

	/** A scene whose particles all have the type's profile. */
	public Scene(final String key, final ParticleType type, final List<Particle> particles, final double rampX,
		final double rampY, final double photonGain, final double readNoise, final double threshold)
	{
		this(key, type, particles, rampX, rampY, photonGain, readNoise, threshold, List.of(type.profile()));
	}

	/**
	 * A scene of particles of unlike kinds at contact, each rendered with its own profile: {@code mixed}, a pair of
	 * the first and the last kind, tilted as {@code unlike} is; {@code mixed7}, {@code hex7} with the first kind at
	 * the centre and the ring going through the kinds in turn (second, ..., last, first, ...). The kinds share the
	 * first one's diameter, pixel size, background and noise (a movie's kinds: the same particles in and out of
	 * focus); r_out is the largest of theirs, the threshold the first one's.
	 *
	 * @param key one of {@link #MIXED_KEYS}
	 * @param name the particles' name in reports
	 * @param kinds at least two kinds
	 * @return the scene at contact
	 * @throws InvalidInputException for an unknown key
	 */
	public static Scene mixed(final String key, final String name, final List<ParticleType> kinds) {
		if (kinds.size() < 2) throw new IllegalArgumentException("a mixed scene needs two kinds, not " + kinds.size());
		final ParticleType first = kinds.get(0);
		double rOut = 0;
		final List<RadialProfile> profiles = new ArrayList<>();
		for (final ParticleType k : kinds) {
			rOut = Math.max(rOut, k.rOut());
			profiles.add(k.profile());
		}
		final ParticleType type = new ParticleType(name, first.diameterMicrons(), first.pixelSizeNm(), first.profile(),
			first.background(), first.threshold(), rOut, first.noise());
		final double d = type.diameterPx();
		final int last = kinds.size() - 1;
		final List<Particle> ps = new ArrayList<>();
		switch (key.trim().toLowerCase(Locale.ROOT)) {
			case "mixed" -> {
				for (final Particle p : unlike(d, 1, 1))
					ps.add(new Particle(p.x, p.y, 1, 1, ps.isEmpty() ? 0 : last));
			}
			case "mixed7" -> {
				final List<Particle> hex = hexagon(d);
				for (int k = 0; k < hex.size(); k++)
					ps.add(new Particle(hex.get(k).x, hex.get(k).y, 1, 1, k % kinds.size()));
			}
			default -> throw new InvalidInputException("a mixed scene must be among " + String.join(",", MIXED_KEYS) +
				", not '" + key + "'");
		}
		return new Scene(key.trim().toLowerCase(Locale.ROOT), type, ps, 0, 0, 0, 0, type.threshold(), profiles);
	}

	/**
	 * @param key one of {@link #KEYS}
	 * @param type the particles
	 * @return the scene at contact
	 * @throws InvalidInputException for an unknown key
	 */
	public static Scene of(final String key, final ParticleType type) {
		final double d = type.diameterPx();
		final double th = type.threshold();
		return switch (key.trim().toLowerCase(Locale.ROOT)) {
			case "pair" -> plain("pair", type, line(2, d));
			case "chain4" -> plain("chain4", type, line(4, d));
			case "triple" -> plain("triple", type, triangle(d));
			case "hex7" -> plain("hex7", type, hexagon(d));
			case "hex19" -> plain("hex19", type, hexPatch(d, 2));
			// more than GroupFit fits jointly: its members are fitted in turn, as in a dense field
			case "hex37" -> plain("hex37", type, hexPatch(d, 3));
			case "unlike" -> plain("unlike", type, unlike(d, 1.2, 1.1));
			case "unlike13" -> plain("unlike13", type, unlike(d, 1.3, 1.15));
			case "ramp" -> new Scene("ramp", type, line(2, d), 0.05, 0.03, PHOTON_GAIN, READ_NOISE, th);
			case "saturated" -> bright("saturated", type, d, 0, 0);
			// photon noise where it matters most: bright particles, whose noise grows far above the background's
			case "photon" -> bright("photon", type, d, PHOTON_GAIN, READ_NOISE);
			default -> throw new InvalidInputException("--scene must be among " + String.join(",", KEYS) + ", not '" +
				key + "'");
		};
	}

	/** A pair {@link #SATURATED_BRIGHTNESS} times as bright, cores clipped at 255, with the given noise. */
	private static Scene bright(final String key, final ParticleType type, final double d, final double photonGain,
		final double readNoise)
	{
		final List<Particle> bright = new ArrayList<>();
		for (final Particle p : line(2, d))
			bright.add(new Particle(p.x, p.y, 1, SATURATED_BRIGHTNESS));
		// the threshold keeps its place on the (brighter) profile
		return new Scene(key, type, bright, 0, 0, photonGain, readNoise, type.background() + SATURATED_BRIGHTNESS * (
			type.threshold() - type.background()));
	}

	private static Scene plain(final String key, final ParticleType type, final List<Particle> ps) {
		return new Scene(key, type, ps, 0, 0, 0, 0, type.threshold());
	}

	private static List<Particle> line(final int n, final double d) {
		final List<Particle> ps = new ArrayList<>();
		for (int i = 0; i < n; i++)
			ps.add(new Particle((i - 0.5 * (n - 1)) * d, 0, 1, 1));
		return ps;
	}

	/** The paper's scenario (b) at contact: a touching equilateral triangle. */
	private static List<Particle> triangle(final double d) {
		final double h = d * Math.sqrt(3) / 2;
		return List.of(new Particle(-d / 2, h / 3, 1, 1), new Particle(d / 2, h / 3, 1, 1), new Particle(0, -2 * h / 3,
			1, 1));
	}

	/** A central particle and six touching it, each touching its two neighbours. */
	private static List<Particle> hexagon(final double d) {
		final List<Particle> ps = new ArrayList<>();
		ps.add(new Particle(0, 0, 1, 1));
		for (int k = 0; k < 6; k++) {
			// tilted by 10 degrees, so that no pair lies along the pixel grid
			final double a = Math.toRadians(10 + 60 * k);
			ps.add(new Particle(d * Math.cos(a), d * Math.sin(a), 1, 1));
		}
		return ps;
	}

	/**
	 * A patch of a hexagonal monolayer at contact: a particle and its neighbours out to {@code rings} rings (two: 19
	 * particles), tilted by 10 degrees as {@link #hexagon} is.
	 */
	private static List<Particle> hexPatch(final double d, final int rings) {
		final List<Particle> ps = new ArrayList<>();
		final double a = Math.toRadians(10), b = a + Math.toRadians(60);
		for (int i = -rings; i <= rings; i++)
			for (int j = -rings; j <= rings; j++)
				if (Math.abs(i + j) <= rings) ps.add(new Particle(d * (i * Math.cos(a) + j * Math.cos(b)), d * (i * Math.sin(
					a) + j * Math.sin(b)), 1, 1));
		return ps;
	}

	/** A pair at contact, the right one {@code scale} times larger and {@code amplitude} times brighter. */
	private static List<Particle> unlike(final double d, final double scale, final double amplitude) {
		final double contact = 0.5 * d * (1 + scale);
		// tilted, so that the displacement between them has both an x and a y part
		final double a = Math.toRadians(20);
		final double ux = Math.cos(a) * contact / 2, uy = Math.sin(a) * contact / 2;
		return List.of(new Particle(-ux, -uy, 1, 1), new Particle(ux, uy, scale, amplitude));
	}

	/** @return whether the noise is photon noise (Poisson) plus read noise */
	public boolean photonNoise() {
		return photonGain > 0;
	}

	/**
	 * @param x pixel x
	 * @param y pixel y
	 * @param width frame width
	 * @param height frame height
	 * @return the background at a pixel (the ramp is zero at the frame's centre)
	 */
	public double background(final int x, final int y, final int width, final int height) {
		return type.background() + rampX * (x - 0.5 * (width - 1)) + rampY * (y - 0.5 * (height - 1));
	}

	/**
	 * The variance of a pixel whose exact value is {@code value}, noise and rounding to integers.
	 *
	 * @param value the exact grey level
	 * @return its variance (grey levels squared)
	 */
	public double variance(final double value) {
		final double noise = photonNoise() ? photonGain * Math.max(value, 0) + readNoise * readNoise : type.noise()
			.sigma() * type.noise().sigma();
		return noise + 1.0 / 12;
	}

	/** @return the frame size (px, square-ish: {width, height}) that holds every particle's visible reach */
	public int[] frameSize() {
		final double[] e = extent();
		double profileReach = 0;
		for (final RadialProfile p : profiles)
			profileReach = Math.max(profileReach, p.reach(PaperParticles.REACH_LEVEL));
		final double reach = Math.max(profileReach * e[4], type.rOut());
		final double border = reach + SimulatedStack.MARGIN_PX + 0.5;
		return new int[] { (int) Math.ceil(e[1] - e[0] + 2 * border) + 1, (int) Math.ceil(e[3] - e[2] + 2 * border) +
			1 };
	}

	/** @return {min x, max x, min y, max y, largest scale (at least 1)} of the particles */
	private double[] extent() {
		final double[] e = { Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
			Double.NEGATIVE_INFINITY, 1 };
		for (final Particle p : particles) {
			e[0] = Math.min(e[0], p.x);
			e[1] = Math.max(e[1], p.x);
			e[2] = Math.min(e[2], p.y);
			e[3] = Math.max(e[3], p.y);
			e[4] = Math.max(e[4], p.scale);
		}
		return e;
	}

	/** @return the particles' centres in a frame of {@code frameSize()}, before the frame's offset */
	public List<double[]> layout() {
		final int[] size = frameSize();
		final double[] e = extent();
		final double sx = 0.5 * (size[0] - 1) - 0.5 * (e[0] + e[1]), sy = 0.5 * (size[1] - 1) - 0.5 * (e[2] + e[3]);
		final List<double[]> out = new ArrayList<>();
		for (final Particle p : particles)
			out.add(new double[] { p.x + sx, p.y + sy });
		return out;
	}

	/** @return a renderer of each of the {@link #profiles} */
	public List<ImageSimulator> simulators() {
		final List<ImageSimulator> sims = new ArrayList<>();
		for (final RadialProfile p : profiles)
			sims.add(new ImageSimulator(p));
		return sims;
	}

	/** @return the kind of each particle ({@link Particle#kind()}), in order */
	public int[] kinds() {
		final int[] k = new int[particles.size()];
		for (int i = 0; i < k.length; i++)
			k[i] = particles.get(i).kind;
		return k;
	}

	/**
	 * The exact image of the scene with its particles at {@code centres}.
	 *
	 * @param simulators a renderer of each profile ({@link #simulators()})
	 */
	public NoiseFreeImage render(final List<ImageSimulator> simulators, final List<double[]> centres,
		final int width, final int height)
	{
		final NoiseFreeImage img = NoiseFreeImage.uniform(width, height, 0);
		final double[] px = img.pixels();
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++)
				px[y * width + x] = background(x, y, width, height);
		for (int k = 0; k < particles.size(); k++)
			simulators.get(particles.get(k).kind).addParticle(img, centres.get(k)[0], centres.get(k)[1], particles.get(
				k).scale, particles.get(k).amplitude);
		return img;
	}

	/**
	 * Simulates {@code frameCount} 8-bit frames. The measured pairs are the touching ones.
	 *
	 * @param seed seed of the offsets and the noise: equal seeds give identical stacks
	 * @return the stack with its truth
	 */
	public SimulatedStack<?> simulate(final int frameCount, final long seed) {
		final int[] size = frameSize();
		final int w = size[0], h = size[1];
		final List<double[]> layout = layout();
		final List<ImageSimulator> simulator = simulators();
		final SplittableRandom random = new SplittableRandom(seed);
		final List<ArrayImg<?, ?>> frames = new ArrayList<>();
		final List<List<double[]>> truth = new ArrayList<>();
		long clipped = 0;
		for (int f = 0; f < frameCount; f++) {
			final double ox = random.nextDouble(-0.5, 0.5), oy = random.nextDouble(-0.5, 0.5);
			final List<double[]> centres = new ArrayList<>();
			for (final double[] c : layout)
				centres.add(new double[] { c[0] + ox, c[1] + oy });
			final QuantisedFrame<?> frame = camera(render(simulator, centres, w, h), random, 8, 0);
			frames.add(frame.image());
			truth.add(List.copyOf(centres));
			clipped += frame.clippedPixels();
		}
		return typed(frames, truth, w, h, clipped);
	}

	/**
	 * The camera's frame of an exact image: the scene's noise (photon plus read noise, or the type's additive noise)
	 * and the camera's offset, rounded and clipped to the bit depth's range.
	 *
	 * @param exact the exact image (the light, without the offset); overwritten with what the camera adds to it
	 * @param random the noise source
	 * @param bitDepth 8 or 16
	 * @param offset grey levels the camera adds to every pixel, which carry no photon noise (0 for none)
	 * @return the frame, with its clipped pixels counted
	 */
	public QuantisedFrame<?> camera(final NoiseFreeImage exact, final SplittableRandom random, final int bitDepth,
		final double offset)
	{
		final double[] px = exact.pixels();
		if (!photonNoise()) {
			for (int i = 0; i < px.length; i++)
				px[i] += offset;
			return Quantiser.quantise(exact, type.noise(), random, bitDepth);
		}
		for (int i = 0; i < px.length; i++)
			px[i] = photonGain * Poisson.sample(Math.max(px[i], 0) / photonGain, random) + offset;
		return Quantiser.quantise(exact, NoiseModel.gaussian(readNoise), random, bitDepth);
	}

	/** @return the index pairs of touching particles (centre distance within 1% of the sum of their radii) */
	public List<int[]> touchingPairs() {
		final List<int[]> pairs = new ArrayList<>();
		final double d = type.diameterPx();
		for (int i = 0; i < particles.size(); i++)
			for (int j = i + 1; j < particles.size(); j++) {
				final Particle a = particles.get(i), b = particles.get(j);
				if (Math.hypot(a.x - b.x, a.y - b.y) <= 1.01 * 0.5 * d * (a.scale + b.scale)) pairs.add(new int[] { i, j });
			}
		return pairs;
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private SimulatedStack<?> typed(final List<ArrayImg<?, ?>> frames, final List<List<double[]>> truth,
		final int w, final int h, final long clipped)
	{
		return new SimulatedStack(frames, truth, type, java.util.Optional.empty(), 1.0, touchingPairs(), w, h,
			clipped);
	}

	/**
	 * "Flat-top" particles, a profile that neither preset has: a super-Gaussian core (flat top, steep edge), a
	 * dark ring and a faint bright ring, D = 50 px at 84.7 nm/px; reaches about 1.2 D.
	 *
	 * @return the type
	 */
	public static ParticleType flatTop() {
		final RadialProfile profile = r -> 110 * Math.exp(-Math.pow(r / 14, 4)) - 22 * Math.exp(-sq((r - 25) / 6)) + 7 *
			Math.exp(-sq((r - 42) / 9));
		final double rOut = Math.ceil(profile.reach(PaperParticles.REACH_LEVEL) + PaperParticles.R_OUT_MARGIN_PX);
		return new ParticleType("flat-top 4.2 um", 50 * 84.7 / 1000, 84.7, profile, 70, 70 + 35, rOut, NoiseModel
			.uniform(5));
	}

	private static double sq(final double v) {
		return v * v;
	}
}
