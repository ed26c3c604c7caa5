package net.imglib2.algorithm;

/** Compile-only mirror of imglib2-algorithm's {@code MultiThreaded}: never packaged. */
public interface MultiThreaded {

	void setNumThreads();

	void setNumThreads(int numThreads);

	int getNumThreads();
}
