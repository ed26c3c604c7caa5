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
package io.github.contacttracker.command;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.scijava.Context;
import org.scijava.prefs.PrefService;

/**
 * A test class that runs our commands in one SciJava context, made before its tests and disposed after them. The
 * values a command remembers (SciJava's preferences, on disk) are forgotten before and after each test, so that every
 * test starts from the documented defaults and leaves nothing for the next one.
 */
public abstract class WithContext {

	protected static Context context;

	@BeforeAll
	public static void start() {
		context = new Context();
	}

	@BeforeEach
	@AfterEach
	public void forgetRememberedValues() {
		context.service(PrefService.class).clearAll();
	}

	@AfterAll
	public static void stop() {
		context.dispose();
	}
}
