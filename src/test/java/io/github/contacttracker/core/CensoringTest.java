package io.github.contacttracker.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import net.imglib2.img.array.ArrayImgs;

class CensoringTest {

	@Test
	void eightBitClipsAtBothEnds() {
		final Plane plane = Plane.of(ArrayImgs.unsignedBytes(new byte[4], 2, 2));
		assertEquals(0, plane.floor());
		assertEquals(255, plane.saturation());
		final Censoring c = Censoring.of(plane, 2);
		assertTrue(c.clipped(0));
		assertTrue(c.clipped(255));
		assertFalse(c.clipped(1));
		// the band: within 3 sigma (6 grey levels) of a clip level, by the model
		assertFalse(c.usable(6));
		assertTrue(c.usable(6.5));
		assertTrue(c.usable(248.5));
		assertFalse(c.usable(249));
	}

	@Test
	void floatingPointNeverClips() {
		final Plane plane = Plane.of(ArrayImgs.floats(new float[4], 2, 2));
		final Censoring c = Censoring.of(plane, 2);
		assertFalse(c.active());
		assertFalse(c.clipped(-1e30));
		assertTrue(c.usable(1e30));
	}
}
