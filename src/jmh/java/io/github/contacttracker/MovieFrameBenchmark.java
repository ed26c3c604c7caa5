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
package io.github.contacttracker;

import java.util.List;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import ij.IJ;
import ij.ImagePlus;
import io.github.contacttracker.core.TrackerParameters;
import io.github.contacttracker.core.track.FrameResult;
import io.github.contacttracker.core.track.StackTracker;
import io.github.contacttracker.ij.ImagePlusFrames;

/**
 * The default method's cost per frame of a real movie after its start-up: the movie's profile measured once in the
 * set-up, then its first {@value #FRAMES} frames tracked with it, as every frame of a long movie is (detection,
 * iterative pass, the fit of every group), on {@code threads} threads (the frames spread over them). The score is
 * per frame. The movie is given, a grey 8-bit or RGB file ImageJ opens (RGB made 8-bit grey), with its values:
 *
 * <pre>
 * scripts/jmh-bench MovieFrameBenchmark -p movie=/path/to/1.avi -p values=186,43,34.06
 * </pre>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 4, time = 3)
@Measurement(iterations = 5, time = 3)
@Fork(1)
public class MovieFrameBenchmark {

	/** Frames tracked per operation (the score is divided by it): the movie must hold at least these. */
	static final int FRAMES = 30;

	@Param({ "" })
	public String movie;

	/** threshold, r_out, diameter */
	@Param({ "186,43,34.06" })
	public String values;

	@Param({ "1", "2" })
	public int threads;

	private List<?> frames;
	private StackTracker tracker;
	private StackTracker.ProfileStage stage;
	private final int[] indices = new int[FRAMES];

	@Setup
	public void setUp() {
		if (movie.isEmpty()) throw new IllegalArgumentException("give the movie: -p movie=PATH");
		final String[] v = values.split(",");
		final ImagePlus opened = IJ.openImage(movie);
		if (opened == null) throw new IllegalArgumentException("ImageJ cannot open " + movie);
		ImagePlus grey = opened;
		if (opened.getBitDepth() != 8) {
			grey = opened.duplicate();
			new ij.process.StackConverter(grey).convertToGray8();
		}
		frames = ImagePlusFrames.of(grey, 1).frames();
		if (frames.size() < FRAMES) throw new IllegalArgumentException("the movie has " + frames.size() +
			" frames, fewer than " + FRAMES);
		for (int t = 0; t < FRAMES; t++)
			indices[t] = t;
		tracker = new StackTracker(TrackerParameters.of(Double.parseDouble(v[0]), Double.parseDouble(v[1]))
			.withDiameter(Double.parseDouble(v[2])));
		stage = StackTracker.withThreads(threads, () -> tracker.profileStage(frames.size(), this::frame, () -> false));
	}

	@SuppressWarnings({ "rawtypes", "unchecked" })
	private net.imglib2.RandomAccessibleInterval frame(final int t) {
		return (net.imglib2.RandomAccessibleInterval) frames.get(t);
	}

	/** @return the spots of the movie's first {@value #FRAMES} frames */
	@Benchmark
	@OperationsPerInvocation(FRAMES)
	@SuppressWarnings("unchecked")
	public List<FrameResult> frame() {
		return StackTracker.withThreads(threads, () -> tracker.trackWith(stage, indices, this::frame, () -> false));
	}
}
