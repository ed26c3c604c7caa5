package net.imglib2.algorithm;

/** Compile-only mirror of imglib2-algorithm's {@code Algorithm}: never packaged. */
public interface Algorithm {

	boolean checkInput();

	boolean process();

	String getErrorMessage();
}
