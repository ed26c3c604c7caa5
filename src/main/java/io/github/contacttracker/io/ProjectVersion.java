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
