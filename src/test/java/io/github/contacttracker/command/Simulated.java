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

import java.util.List;

import org.scijava.Context;
import org.scijava.command.CommandService;
import org.scijava.module.Module;
import org.scijava.module.ModuleService;

import ij.ImagePlus;
import io.github.contacttracker.ij.TimeSeries;
import io.github.contacttracker.io.Calibration;
import io.github.contacttracker.lab.sim.PaperParticles;
import io.github.contacttracker.lab.sim.ParticleType;
import io.github.contacttracker.lab.sim.Scenario;
import io.github.contacttracker.lab.sim.SimulatedStack;

/** The simulated 5-frame stack the command tests share, and a headless way to run commands. */
final class Simulated {

	static final ParticleType TYPE = PaperParticles.silica553();
	static final int FRAMES = 5;
	/** Centre distance of the pair, in diameters: apart enough that every frame has exactly two spots. */
	static final double SEPARATION = 1.5;
	static final double FRAME_INTERVAL = 0.5;
	static final SimulatedStack<?> STACK = SimulatedStack.simulate(TYPE, Scenario.PAIR, SEPARATION, FRAMES, 20260415L,
		8);
	static final Calibration CALIBRATION = new Calibration(TYPE.pixelSizeMicrons(), TYPE.pixelSizeMicrons(), "micron",
		FRAME_INTERVAL, "s");

	private Simulated() {}

	/** @return a fresh calibrated time series (T = 5) sharing the simulated pixels */
	static ImagePlus image() {
		return TimeSeries.of("simulated pair", STACK.frames(), CALIBRATION);
	}

	/** @return the true centres of frame {@code t} (px) */
	/** @return an image with 2 Z slices and 2 time frames, which every front end refuses (the method is 2D) */
	static ImagePlus zAndT(final String title) {
		final ij.ImageStack zt = new ij.ImageStack(32, 32);
		for (int i = 0; i < 4; i++)
			zt.addSlice(new ij.process.ByteProcessor(32, 32));
		final ImagePlus imp = new ImagePlus(title, zt);
		imp.setDimensions(1, 2, 2);
		imp.setOpenAsHyperStack(true);
		return imp;
	}

	static List<double[]> truth(final int t) {
		return STACK.truth().get(t);
	}

	/** Runs a command headless, with pre- and postprocessing, as scripts and macros do. */
	static Module run(final Context context, final Class<? extends org.scijava.command.Command> command,
		final Object... inputs) throws Exception
	{
		final ModuleService modules = context.service(ModuleService.class);
		return modules.run(context.service(CommandService.class).getCommand(command), true, inputs).get();
	}
}
