package io.github.contacttracker.command;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.scijava.Context;

/** A test class that runs our commands in one SciJava context, made before its tests and disposed after them. */
abstract class WithContext {

	protected static Context context;

	@BeforeAll
	static void start() {
		context = new Context();
	}

	@AfterAll
	static void stop() {
		context.dispose();
	}
}
