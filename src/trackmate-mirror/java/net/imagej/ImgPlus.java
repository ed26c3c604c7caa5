package net.imagej;

import net.imagej.axis.Axes;
import net.imagej.axis.AxisType;
import net.imglib2.Interval;
import net.imglib2.RandomAccess;
import net.imglib2.img.Img;
import net.imglib2.img.ImgFactory;
import net.imglib2.img.WrappedImg;

/**
 * Compile-only mirror of imagej-common's {@code ImgPlus}: never packaged. The real class extends
 * {@code AbstractCalibratedRealInterval<CalibratedAxis>} and implements {@code Img<T>}, {@code WrappedImg<T>} and
 * {@code ImgPlusMetadata}; this mirror keeps the class kind, the type parameter, the constructors tests use and
 * the non-generic members Contact Tracker calls: {@code dimensionIndex(AxisType)} (real: default method of
 * {@code TypedSpace}) and {@code averageScale(int)} (real: {@code CalibratedSpace}), both reached with
 * {@code invokevirtual} on {@code ImgPlus}. Do not call {@code axis(int)}: its erasure differs in the real
 * hierarchy.
 */
public class ImgPlus<T> implements Img<T>, WrappedImg<T> {

	private final Img<T> img;
	private final String name;
	private final AxisType[] axes;
	private final double[] scales;

	public ImgPlus(final Img<T> img) {
		this(img, null, null, null);
	}

	public ImgPlus(final Img<T> img, final String name) {
		this(img, name, null, null);
	}

	public ImgPlus(final Img<T> img, final String name, final AxisType[] axes) {
		this(img, name, axes, null);
	}

	public ImgPlus(final Img<T> img, final String name, final AxisType[] axisTypes, final double[] cal) {
		this.img = img;
		this.name = name;
		final int n = img.numDimensions();
		this.axes = new AxisType[n];
		this.scales = new double[n];
		for (int d = 0; d < n; d++) {
			axes[d] = axisTypes != null && d < axisTypes.length ? axisTypes[d]
				: d == 0 ? Axes.X : d == 1 ? Axes.Y : new Unknown();
			scales[d] = cal != null && d < cal.length ? cal[d] : 1;
		}
	}

	public int dimensionIndex(final AxisType axisType) {
		for (int d = 0; d < axes.length; d++)
			if (axes[d] == axisType) return d;
		return -1;
	}

	public double averageScale(final int d) {
		return scales[d];
	}

	public String getName() {
		return name;
	}

	@Override
	public Img<T> getImg() {
		return img;
	}

	@Override
	public RandomAccess<T> randomAccess() {
		return img.randomAccess();
	}

	@Override
	public RandomAccess<T> randomAccess(final Interval interval) {
		return img.randomAccess(interval);
	}

	@Override
	public long min(final int d) {
		return img.min(d);
	}

	@Override
	public long max(final int d) {
		return img.max(d);
	}

	@Override
	public long dimension(final int d) {
		return img.dimension(d);
	}

	@Override
	public int numDimensions() {
		return img.numDimensions();
	}

	@Override
	public ImgFactory<T> factory() {
		return img.factory();
	}

	@Override
	public ImgPlus<T> copy() {
		return new ImgPlus<>(img.copy(), name, axes.clone(), scales.clone());
	}

	private static final class Unknown implements AxisType {

		@Override
		public String getLabel() {
			return "Unknown";
		}

		@Override
		public boolean isXY() {
			return false;
		}

		@Override
		public boolean isSpatial() {
			return false;
		}
	}
}
