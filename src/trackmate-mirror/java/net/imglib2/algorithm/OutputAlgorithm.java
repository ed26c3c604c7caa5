package net.imglib2.algorithm;

/** Compile-only mirror of imglib2-algorithm's {@code OutputAlgorithm}: never packaged. */
public interface OutputAlgorithm<F> extends Algorithm {

	F getResult();
}
