package net.imglib2.algorithm;

/** Compile-only mirror of imglib2-algorithm's {@code Benchmark}: never packaged. */
public interface Benchmark {

	long getProcessingTime();
}
