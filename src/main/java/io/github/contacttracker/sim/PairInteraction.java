package io.github.contacttracker.sim;

/**
 * A known pair potential for simulated fluids: the truth that a measured U(r) is compared with. Distances in
 * pixels, energies in units of kT.
 */
public interface PairInteraction {

	/**
	 * @param r centre distance (px)
	 * @return U(r)/kT; {@code +Infinity} where the particles would overlap
	 */
	double energyKt(double r);

	/** @return the distance (px) beyond which U is exactly 0 */
	double range();

	/** @return a short description for reports */
	String describe();
}
