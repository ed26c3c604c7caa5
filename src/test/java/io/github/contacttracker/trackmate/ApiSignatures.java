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
package io.github.contacttracker.trackmate;

import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The linkage-relevant shape of a class, one line per fact: its kind, type parameters and generic supertypes; its
 * public and protected constructors; every public method a call on it resolves to (inherited ones included) and
 * its protected ones, with erased parameter and return types and whether abstract, default, static or concrete;
 * its public fields. A call our bytecode makes on a class links if its line is among the class's lines.
 * <p>
 * {@link MirrorContractTest} compares the compile-only mirror against lines recorded from the RELEASED TrackMate
 * jar with {@link #main}: {@code java -cp <released jars>:target/test-classes ApiSignatures CLASS...}.
 */
final class ApiSignatures {

	private ApiSignatures() {}

	/** Prints the lines of every named class (and its public nested classes), sorted per class. */
	public static void main(final String... classNames) throws ClassNotFoundException {
		for (final String name : classNames)
			for (final String line : describe(Class.forName(name, false, ApiSignatures.class.getClassLoader())))
				System.out.println(line);
	}

	/** @return the lines of {@code c} and of its public and protected nested classes */
	static List<String> describe(final Class<?> c) {
		final List<String> lines = new ArrayList<>();
		lines.add(typeLine(c));
		final List<String> members = new ArrayList<>();
		for (final Constructor<?> k : c.getDeclaredConstructors())
			if (visible(k.getModifiers())) members.add("ctor " + c.getName() + "(" + erasures(k.getParameterTypes()) + ")");
		// every public method a call on this type can resolve to, inherited ones included (invokevirtual and
		// invokeinterface resolve through the hierarchy), plus the protected ones declared here
		for (final Method m : c.getMethods())
			if (!m.isSynthetic() && !m.isBridge()) members.add(methodLine(c, m));
		for (final Method m : c.getDeclaredMethods())
			if (Modifier.isProtected(m.getModifiers()) && !m.isSynthetic() && !m.isBridge()) members.add(methodLine(c, m));
		for (final Field f : c.getFields())
			if (!f.isSynthetic()) members.add("field " + c.getName() + "." + f.getName() + " " + f.getType().getName() +
				(Modifier.isStatic(f.getModifiers()) ? " static" : "") + (Modifier.isFinal(f.getModifiers()) ? " final" : ""));
		members.sort(null);
		for (int i = members.size() - 1; i > 0; i--)
			if (members.get(i).equals(members.get(i - 1))) members.remove(i);
		lines.addAll(members);
		final Class<?>[] nested = c.getDeclaredClasses();
		Arrays.sort(nested, (a, b) -> a.getName().compareTo(b.getName()));
		for (final Class<?> n : nested)
			if (visible(n.getModifiers())) lines.addAll(describe(n));
		return lines;
	}

	static String typeLine(final Class<?> c) {
		final String kind = c.isInterface() ? "interface" : c.isEnum() ? "enum" : Modifier.isAbstract(c.getModifiers())
			? "abstract class" : "class";
		final StringBuilder sb = new StringBuilder("type ").append(c.getName()).append(' ').append(kind);
		final TypeVariable<?>[] tv = c.getTypeParameters();
		if (tv.length > 0) sb.append(" <").append(Arrays.stream(tv).map(v -> v.getName() + " extends " + Arrays.stream(v
			.getBounds()).map(Type::getTypeName).collect(Collectors.joining(" & "))).collect(Collectors.joining(", ")))
			.append('>');
		if (!c.isInterface() && !c.isEnum() && c.getGenericSuperclass() != null) sb.append(" extends ").append(c
			.getGenericSuperclass().getTypeName());
		final Type[] interfaces = c.getGenericInterfaces();
		if (interfaces.length > 0) sb.append(c.isInterface() ? " extends " : " implements ").append(Arrays.stream(
			interfaces).map(Type::getTypeName).sorted().collect(Collectors.joining(", ")));
		return sb.toString();
	}

	static String methodLine(final Class<?> c, final Method m) {
		final int mod = m.getModifiers();
		final String how = Modifier.isStatic(mod) ? "static" : Modifier.isAbstract(mod) ? "abstract" : m.isDefault()
			? "default" : "concrete";
		return "method " + c.getName() + "." + m.getName() + "(" + erasures(m.getParameterTypes()) + ") " + m
			.getReturnType().getName() + " " + how;
	}

	private static String erasures(final Class<?>[] types) {
		return Arrays.stream(types).map(Class::getName).collect(Collectors.joining(","));
	}

	private static boolean visible(final int modifiers) {
		return Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers);
	}
}
