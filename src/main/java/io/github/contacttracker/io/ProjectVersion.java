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
package io.github.contacttracker.io;

/** The project's version, for {@code --version}, the files we write and the reports' stamps. */
public final class ProjectVersion {

	/** What {@link #get()} says when the classes do not run from a jar (tests, an IDE). */
	public static final String DEVELOPMENT = "(development build)";

	private ProjectVersion() {}

	/**
	 * @return the version of the jar these classes run from (its manifest's {@code Implementation-Version}, which
	 *         Maven writes from the pom's {@code version}), or {@link #DEVELOPMENT} outside a jar
	 */
	public static String get() {
		final String version = ProjectVersion.class.getPackage().getImplementationVersion();
		return version == null ? DEVELOPMENT : version;
	}
}
