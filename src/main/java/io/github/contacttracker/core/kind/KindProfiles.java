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
package io.github.contacttracker.core.kind;

import java.io.Serializable;
import java.util.Collection;
import java.util.List;

import io.github.contacttracker.core.image.Plane;
import io.github.contacttracker.core.profile.EmpiricalProfile;
import io.github.contacttracker.core.radial.Estimate;
import io.github.contacttracker.core.radial.Particle;

/**
 * The measured radial profile of each kind of particle, and the {@link Kinds} that tell a particle's kind: what the
 * profile methods refine the centres with. One kind: one profile for every particle. Immutable and serializable
 * (a distributed job ships it to its workers).
 */
public final class KindProfiles implements Serializable {

	private static final long serialVersionUID = 1L;

	/** null: one kind, every particle drawn with {@code profiles[0]} */
	private final Kinds kinds;
	/** kind {@code c + 1}'s profile at {@code c} */
	private final EmpiricalProfile[] profiles;
	private KindProfiles(final Kinds kinds, final EmpiricalProfile[] profiles) {
		this.kinds = kinds;
		this.profiles = profiles.clone();
	}

	/** @return the position of the kind with most particles in the sample (0 for none or one kind) */
	private static int mainOf(final Kinds kinds) {
		int m = 0;
		if (kinds != null) {
			final List<Kinds.Kind> all = kinds.describe();
			for (int c = 1; c < all.size(); c++)
				if (all.get(c).count() > all.get(m).count()) m = c;
		}
		return m;
	}

	/** @return one profile for all particles */
	public static KindProfiles one(final EmpiricalProfile profile) {
		return new KindProfiles(null, new EmpiricalProfile[] { profile });
	}

	/**
	 * @param kinds the kinds ({@link Kinds#count()} at least 2)
	 * @param profiles kind {@code c + 1}'s profile at {@code c}
	 * @return the profiles of several kinds
	 */
	public static KindProfiles of(final Kinds kinds, final EmpiricalProfile[] profiles) {
		if (kinds.count() != profiles.length) throw new IllegalArgumentException(kinds.count() + " kinds but " +
			profiles.length + " profiles");
		return profiles.length == 1 ? one(profiles[0]) : new KindProfiles(kinds, profiles);
	}

	/** @return the number of kinds (profiles) */
	public int count() {
		return profiles.length;
	}

	/** @return the kinds, or null for one kind */
	public Kinds kinds() {
		return kinds;
	}

	/** @return the profile at position {@code c} (kind {@code c + 1}) */
	public EmpiricalProfile profile(final int c) {
		return profiles[c];
	}

	/** @return the profile of the kind with most particles (with one kind, the profile) */
	public EmpiricalProfile main() {
		return profiles[mainOf(kinds)];
	}

	/**
	 * @return the position of the profile that draws a particle of kind {@code kind} (1-based; 0, unclassified, and
	 *         any kind with one profile: the main kind's)
	 */
	public int position(final int kind) {
		return position(kinds, kind);
	}

	/**
	 * @return the position among {@code kinds}' profiles (null or one kind: 0) of the profile that draws a particle of
	 *         kind {@code kind}: {@code kind - 1}; for 0, unclassified, the kind with most particles
	 */
	public static int position(final Kinds kinds, final int kind) {
		if (kinds == null || kinds.count() < 2) return 0;
		return kind < 1 || kind > kinds.count() ? mainOf(kinds) : kind - 1;
	}

	/**
	 * @param sample the particles of a few frames (every one but the degenerate: a kind may be all merges at a low
	 *        threshold)
	 * @param count kinds to find: 0 automatically, or that many
	 * @return the kinds {@link Kinds#find(java.util.Collection, int)} finds, or null when they are fewer than two
	 */
	public static Kinds tellApart(final Collection<KindFeatures> sample, final int count) {
		final Kinds kinds = Kinds.find(sample, count);
		return kinds.count() < 2 ? null : kinds;
	}

	/**
	 * Tells the kind of each particle of a frame, at its centre {@code estimates[k]}, among {@code kinds} (null or one
	 * kind: all 0, nothing measured).
	 *
	 * @param reach the outermost radius of the particles' profiles read (px): {@code r_out}
	 */
	public static int[] kindsOf(final Kinds kinds, final Plane plane, final Particle[] particles,
		final Estimate[] estimates, final double reach)
	{
		if (kinds == null || kinds.count() < 2) return new int[particles.length];
		return kindsOf(kinds, KindFeatures.measureCore(plane, particles, estimates, reach)); // only what places them
	}

	/** @return the kind of each particle of features {@code f} among {@code kinds} (null: one kind, all 0) */
	public static int[] kindsOf(final Kinds kinds, final KindFeatures[] f) {
		final int[] out = new int[f.length];
		if (kinds != null && kinds.count() >= 2) for (int k = 0; k < out.length; k++)
			out[k] = kinds.kindOf(f[k]);
		return out;
	}

	/** @return the profile drawing each particle, by its kind ({@link #position}) */
	public EmpiricalProfile[] byParticle(final int[] kindOf) {
		final EmpiricalProfile[] out = new EmpiricalProfile[kindOf.length];
		for (int k = 0; k < out.length; k++)
			out[k] = profiles[position(kindOf[k])];
		return out;
	}
}
