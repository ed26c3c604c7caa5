package fiji.plugin.trackmate;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.NavigableSet;
import java.util.Set;
import java.util.TreeMap;

import net.imglib2.algorithm.MultiThreaded;

/**
 * Compile-only mirror of TrackMate's {@code SpotCollection} (a class): the spots of a movie by frame, what a
 * {@code SpotGlobalDetector} returns. The real {@code put(frame, spots)} sets each spot's {@code FRAME} and sets
 * {@code VISIBILITY} to 0 (TrackMate's filters make them visible later); the mirror does the same so tests see
 * what TrackMate sees. Never packaged.
 */
public class SpotCollection implements MultiThreaded {

	public static final Double ZERO = Double.valueOf(0d);
	public static final Double ONE = Double.valueOf(1d);
	public static final String VISIBILITY = "VISIBILITY";

	private final TreeMap<Integer, Set<Spot>> content = new TreeMap<>();

	public SpotCollection() {}

	public void put(final int frame, final Collection<Spot> spots) {
		final Set<Spot> set = new HashSet<>(spots);
		for (final Spot spot : set) {
			spot.putFeature(Spot.FRAME, Double.valueOf(frame));
			spot.putFeature(VISIBILITY, ZERO);
		}
		content.put(frame, set);
	}

	public Iterable<Spot> iterable(final int frame, final boolean visibleSpotsOnly) {
		final List<Spot> out = new ArrayList<>();
		final Set<Spot> set = content.get(frame);
		if (set == null) return null;
		for (final Spot s : set)
			if (!visibleSpotsOnly || ONE.equals(s.getFeature(VISIBILITY))) out.add(s);
		return out;
	}

	public final int getNSpots(final boolean visibleSpotsOnly) {
		int n = 0;
		for (final Integer frame : content.keySet())
			n += getNSpots(frame, visibleSpotsOnly);
		return n;
	}

	public int getNSpots(final int frame, final boolean visibleSpotsOnly) {
		int n = 0;
		final Iterable<Spot> it = iterable(frame, visibleSpotsOnly);
		if (it != null) for (@SuppressWarnings("unused") final Spot s : it)
			n++;
		return n;
	}

	@Override
	public void setNumThreads() {}

	@Override
	public void setNumThreads(final int numThreads) {}

	@Override
	public int getNumThreads() {
		return 1;
	}

	public NavigableSet<Integer> keySet() {
		return content.navigableKeySet();
	}
}
