package io.github.contacttracker.trackmate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import javax.swing.ImageIcon;
import javax.swing.JPanel;

import org.jdom2.Element;
import org.junit.jupiter.api.Test;
import org.scijava.plugin.SciJavaPlugin;

import fiji.plugin.trackmate.Model;
import fiji.plugin.trackmate.Settings;
import fiji.plugin.trackmate.Spot;
import fiji.plugin.trackmate.SpotBase;
import fiji.plugin.trackmate.TrackMateFactoryBase;
import fiji.plugin.trackmate.TrackMateModule;
import fiji.plugin.trackmate.detection.SpotDetector;
import fiji.plugin.trackmate.detection.SpotDetectorFactory;
import fiji.plugin.trackmate.detection.SpotDetectorFactoryBase;
import fiji.plugin.trackmate.gui.components.ConfigurationPanel;
import ij.ImagePlus;
import net.imagej.ImgPlus;
import net.imagej.axis.AxisType;
import net.imglib2.Interval;
import net.imglib2.algorithm.Algorithm;
import net.imglib2.algorithm.Benchmark;
import net.imglib2.algorithm.OutputAlgorithm;

/**
 * Pins the compile-only TrackMate mirror (src/trackmate-mirror) to the real TrackMate 8 API (sources of
 * trackmate-sc/TrackMate, imagej-common and imglib2-algorithm): type kinds, supertypes, exact parameter and return types
 * (erasures) and abstract-vs-default. A wrong erasure or kind links here and fails inside Fiji, so any edit of
 * the mirror must keep this test true to the real sources, not the other way round.
 */
class MirrorContractTest {

	private static Method method(final Class<?> c, final String name, final Class<?>... params) {
		try {
			return c.getDeclaredMethod(name, params);
		}
		catch (final NoSuchMethodException e) {
			throw new AssertionError(c.getName() + " lacks " + name + Arrays.toString(params), e);
		}
	}

	private static void assertAbstract(final Class<?> c, final Class<?> returns, final String name,
		final Class<?>... params)
	{
		final Method m = method(c, name, params);
		assertTrue(Modifier.isAbstract(m.getModifiers()), m + " must be abstract");
		assertEquals(returns, m.getReturnType(), m + " return type");
	}

	private static void assertDefault(final Class<?> c, final Class<?> returns, final String name,
		final Class<?>... params)
	{
		final Method m = method(c, name, params);
		assertTrue(m.isDefault(), m + " must be a default method");
		assertEquals(returns, m.getReturnType(), m + " return type");
	}

	private static void assertDeclares(final Class<?> c, final int count) {
		final long n = Arrays.stream(c.getDeclaredMethods()).filter(m -> !m.isSynthetic()).count();
		assertEquals(count, n, c.getName() + " must declare exactly the mirrored methods: " +
			Arrays.toString(c.getDeclaredMethods()));
	}

	@Test
	void trackMateModule() {
		final Class<?> c = TrackMateModule.class;
		assertTrue(c.isInterface());
		assertEquals(List.of(SciJavaPlugin.class), List.of(c.getInterfaces()));
		assertAbstract(c, String.class, "getInfoText");
		assertAbstract(c, String.class, "getKey");
		assertAbstract(c, String.class, "getName");
		assertDefault(c, ImageIcon.class, "getIcon");
		assertDefault(c, boolean.class, "forbidMultithreading");
		assertDefault(c, String.class, "getUrl");
		assertDeclares(c, 6);
	}

	@Test
	void trackMateFactoryBase() {
		final Class<?> c = TrackMateFactoryBase.class;
		assertTrue(c.isInterface());
		assertEquals(List.of(TrackMateModule.class), List.of(c.getInterfaces()));
		final TypeVariable<?>[] tv = c.getTypeParameters();
		assertEquals(1, tv.length);
		assertEquals("F", tv[0].getName());
		assertEquals(TrackMateFactoryBase.class, ((ParameterizedType) tv[0].getBounds()[0]).getRawType());
		assertAbstract(c, Map.class, "getDefaultSettings");
		assertDefault(c, String.class, "marshal", Map.class, Element.class);
		assertDefault(c, String.class, "unmarshal", Element.class, Map.class);
		assertDefault(c, String.class, "checkSettings", Map.class);
		assertDefault(c, String.class, "toString", Map.class);
		assertDefault(c, TrackMateFactoryBase.class, "copy"); // erasure of F
		assertDeclares(c, 6);
	}

	@Test
	void spotDetectorFactoryBaseAndFactory() {
		final Class<?> base = SpotDetectorFactoryBase.class;
		assertTrue(base.isInterface());
		final ParameterizedType sup = (ParameterizedType) base.getGenericInterfaces()[0];
		assertEquals(TrackMateFactoryBase.class, sup.getRawType());
		assertEquals(base, ((ParameterizedType) sup.getActualTypeArguments()[0]).getRawType(),
			"extends TrackMateFactoryBase<SpotDetectorFactoryBase<T>>");
		assertRealNativeBound(base);
		assertAbstract(base, ConfigurationPanel.class, "getDetectorConfigurationPanel", Settings.class, Model.class);
		assertDefault(base, boolean.class, "has2Dsegmentation");
		assertDeclares(base, 2);

		final Class<?> f = SpotDetectorFactory.class;
		assertTrue(f.isInterface());
		assertEquals(List.of(SpotDetectorFactoryBase.class), List.of(f.getInterfaces()));
		assertRealNativeBound(f);
		assertAbstract(f, SpotDetector.class, "getDetector", ImgPlus.class, Map.class, Interval.class, int.class);
		assertDeclares(f, 1);
	}

	@Test
	void spotDetectorAndAlgorithms() {
		assertTrue(SpotDetector.class.isInterface());
		assertEquals(Set.of(OutputAlgorithm.class, Benchmark.class), Set.of(SpotDetector.class.getInterfaces()));
		final Type out = SpotDetector.class.getGenericInterfaces()[0];
		assertEquals("net.imglib2.algorithm.OutputAlgorithm<java.util.List<fiji.plugin.trackmate.Spot>>",
			out.getTypeName());
		assertRealNativeBound(SpotDetector.class);
		assertDeclares(SpotDetector.class, 0);
		assertAbstract(Algorithm.class, boolean.class, "checkInput");
		assertAbstract(Algorithm.class, boolean.class, "process");
		assertAbstract(Algorithm.class, String.class, "getErrorMessage");
		assertAbstract(OutputAlgorithm.class, Object.class, "getResult");
		assertEquals(List.of(Algorithm.class), List.of(OutputAlgorithm.class.getInterfaces()));
		assertAbstract(Benchmark.class, long.class, "getProcessingTime");
	}

	@Test
	void spotIsAnInterfaceAndSpotBaseTheClassToCreate() {
		assertTrue(Spot.class.isInterface(), "TrackMate 7.11+ and 8: Spot is an interface");
		assertAbstract(Spot.class, void.class, "putFeature", String.class, Double.class);
		assertAbstract(Spot.class, Double.class, "getFeature", String.class);
		assertFalse(SpotBase.class.isInterface());
		assertEquals(net.imglib2.AbstractEuclideanSpace.class, SpotBase.class.getSuperclass());
		assertTrue(Arrays.asList(SpotBase.class.getInterfaces()).contains(Spot.class));
		try {
			SpotBase.class.getConstructor(double.class, double.class, double.class, double.class, double.class);
		}
		catch (final NoSuchMethodException e) {
			throw new AssertionError("SpotBase(x, y, z, radius, quality) is what the detector calls", e);
		}
	}

	@Test
	void configurationPanelSettingsModelAndImgPlus() throws Exception {
		assertTrue(Modifier.isAbstract(ConfigurationPanel.class.getModifiers()));
		assertEquals(JPanel.class, ConfigurationPanel.class.getSuperclass());
		assertAbstract(ConfigurationPanel.class, void.class, "setSettings", Map.class);
		assertAbstract(ConfigurationPanel.class, Map.class, "getSettings");
		assertAbstract(ConfigurationPanel.class, void.class, "clean");

		assertEquals(ImagePlus.class, Settings.class.getField("imp").getType());
		assertTrue(Modifier.isFinal(Settings.class.getField("imp").getModifiers()));
		for (final String f : List.of("dx", "dy", "dz", "dt"))
			assertEquals(double.class, Settings.class.getField(f).getType(), f);
		assertFalse(Settings.class.isInterface() || Model.class.isInterface());

		assertFalse(ImgPlus.class.isInterface());
		assertEquals(int.class, ImgPlus.class.getMethod("dimensionIndex", AxisType.class).getReturnType());
		assertEquals(double.class, ImgPlus.class.getMethod("averageScale", int.class).getReturnType());
		assertTrue(AxisType.class.isInterface());
		for (final String axis : List.of("X", "Y", "Z", "TIME", "CHANNEL"))
			assertEquals(AxisType.class, net.imagej.axis.Axes.class.getField(axis).getType(), axis);
	}

	/**
	 * Our factory implements every method of TrackMate's module and factory interfaces but {@code copy()}, so it
	 * links whether a TrackMate release declares one abstract or default.
	 */
	@Test
	void ourFactoryImplementsEveryInterfaceMethodExceptCopy() {
		final List<String> missing = new ArrayList<>();
		final Set<Class<?>> seen = new HashSet<>();
		final List<Class<?>> todo = new ArrayList<>(List.of(SpotDetectorFactory.class));
		while (!todo.isEmpty()) {
			final Class<?> i = todo.remove(0);
			if (!seen.add(i) || i == SciJavaPlugin.class) continue;
			todo.addAll(List.of(i.getInterfaces()));
			for (final Method m : i.getDeclaredMethods()) {
				if (m.isSynthetic() || Modifier.isStatic(m.getModifiers()) || m.getName().equals("copy")) continue;
				try {
					ContactTrackerDetectorFactory.class.getDeclaredMethod(m.getName(), m.getParameterTypes());
				}
				catch (final NoSuchMethodException e) {
					missing.add(i.getSimpleName() + "." + m.getName());
				}
			}
		}
		assertTrue(missing.isEmpty(), "not implemented by the factory: " + missing);
		assertTrue(Modifier.isPublic(ContactTrackerDetectorFactory.class.getModifiers()));
	}

	private static void assertRealNativeBound(final Class<?> c) {
		final TypeVariable<?>[] tv = c.getTypeParameters();
		assertEquals(1, tv.length, c.getName());
		final Set<String> bounds = new HashSet<>();
		for (final Type b : tv[0].getBounds())
			bounds.add(((ParameterizedType) b).getRawType().getTypeName());
		assertEquals(Set.of("net.imglib2.type.numeric.RealType", "net.imglib2.type.NativeType"), bounds, c.getName());
	}
}
