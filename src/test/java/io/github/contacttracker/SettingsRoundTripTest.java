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
package io.github.contacttracker;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.jdom2.Attribute;
import org.jdom2.Element;
import org.jdom2.JDOMException;
import org.jdom2.input.SAXBuilder;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scijava.Context;
import org.scijava.command.CommandModule;
import org.scijava.command.CommandService;
import org.scijava.prefs.PrefService;

import ij.ImagePlus;
import ij.ImageStack;
import ij.io.FileSaver;
import ij.process.ByteProcessor;
import io.github.contacttracker.cli.ContactTrackerCli;
import io.github.contacttracker.command.ContactTrackerCommand;
import io.github.contacttracker.command.TitledResultsTable;
import io.github.contacttracker.io.SettingsFile;
import io.github.contacttracker.settings.Setting;
import io.github.contacttracker.settings.SettingValues;
import io.github.contacttracker.settings.TrackMateSettings;
import io.github.contacttracker.settings.TrackingSettings;
import io.github.contacttracker.spark.SparkTrack;
import io.github.contacttracker.trackmate.ContactTrackerDetectorFactory;
import net.imglib2.type.numeric.integer.UnsignedByteType;

/**
 * Every setting, each at a value other than its default, goes in through every front end (the command line, the
 * Fiji command, the Spark job, TrackMate's detector settings) and comes back equal from every output that records
 * settings (the CSV's settings file, the TrackMate XML's detector settings, the Fiji spots table, the TrackMate
 * session's marshalled settings). The movie has dark particles in its second channel and a first channel that no threshold of the
 * inverted data reaches, so a run that loses {@code particles} or {@code channel} fails or records them wrong.
 */
class SettingsRoundTripTest {

	@TempDir
	static Path dir;

	static Path movie;

	/** Every setting away from its default. */
	static final SettingValues GIVEN = SettingValues.defaults().with(TrackingSettings.THRESHOLD, 120.0).with(
		TrackingSettings.R_OUT, 9.5).with(TrackingSettings.MIN_AREA, 12).with(TrackingSettings.MIN_SECOND_AREA, 15).with(
			TrackingSettings.CONNECTIVITY, 4).with(TrackingSettings.METHOD, "paper").with(TrackingSettings.DIAMETER, 10.5)
		.with(TrackingSettings.KINDS, 1).with(TrackingSettings.PARTICLES, TrackingSettings.DARK).withText(TrackingSettings.DETECTION,
			TrackingSettings.IMAGE).with(
			TrackingSettings.CHANNEL, 2);

	@BeforeAll
	static void movie() {
		for (final Setting<?> s : TrackingSettings.ALL)
			assertNotEquals(s.defaultValue(), GIVEN.get(s), s.name() + " must differ from its default");
		// 2 channels x 3 frames, 8 bits: channel 1 flat at 10, channel 2 two dark particles on a background of 200
		final int w = 64, h = 64;
		final ImageStack stack = new ImageStack(w, h);
		for (int t = 0; t < 3; t++)
			for (int c = 1; c <= 2; c++) {
				final ByteProcessor p = new ByteProcessor(w, h);
				for (int y = 0; y < h; y++)
					for (int x = 0; x < w; x++)
						p.set(x, y, c == 1 ? 10 : (int) Math.round(200 - 150 * (blob(x - 20 - t * 0.3, y - 22) + blob(x - 41,
							y - 37 + t * 0.2))));
				stack.addSlice(p);
			}
		final ImagePlus imp = new ImagePlus("two channels", stack);
		imp.setDimensions(2, 1, 3);
		imp.setOpenAsHyperStack(true);
		movie = dir.resolve("movie.tif");
		if (!new FileSaver(imp).saveAsTiffStack(movie.toString())) throw new AssertionError("cannot write " + movie);
	}

	private static double blob(final double dx, final double dy) {
		return Math.exp(-(dx * dx + dy * dy) / (2 * 2.5 * 2.5));
	}

	@Test
	void commandLineRecordsEverySettingInTheSettingsFileAndTheXml() throws Exception {
		final Path csv = dir.resolve("cli.csv"), xml = dir.resolve("cli.xml");
		final List<String> args = new ArrayList<>(List.of("track", movie.toString(), "--csv", csv.toString(),
			"--trackmate-xml", xml.toString()));
		for (final Setting<?> s : TrackingSettings.ALL) {
			args.add(s.cliOption());
			args.add(String.valueOf(GIVEN.get(s)));
		}
		final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		assertEquals(0, ContactTrackerCli.run(args.toArray(String[]::new), new PrintStream(out, true,
			StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)), err.toString(
				StandardCharsets.UTF_8));
		assertReadBack(csv, xml);
	}

	@Test
	void fijiCommandRecordsEverySettingInTheSettingsFileTheXmlAndItsTable() throws Exception {
		final Path csv = dir.resolve("fiji.csv"), xml = dir.resolve("fiji.xml");
		final List<Object> inputs = new ArrayList<>(List.of("imp", new ImagePlus(movie.toString()), "table", false,
			"csv", csv.toFile(), "trackmate_xml", xml.toFile()));
		for (final Setting<?> s : TrackingSettings.ALL) {
			inputs.add(s.name()); // the macro key is the command's input name
			inputs.add(String.valueOf(GIVEN.get(s)));
		}
		final Context context = new Context();
		try {
			// the command's own inputs (threads, pair_cutoff, ...) at their defaults, not as an earlier run left them
			context.service(PrefService.class).clearAll();
			final CommandModule m = context.service(CommandService.class).run(ContactTrackerCommand.class, true, inputs
				.toArray()).get();
			assertEquals(false, m.isCanceled(), m.getCancelReason());
			assertEquals(GIVEN, ((TitledResultsTable) m.getOutput("spots")).settings(), "the Fiji table's settings");
		}
		finally {
			context.dispose();
		}
		assertReadBack(csv, xml);
	}

	@Test
	void sparkJobRecordsEverySettingInTheSettingsFileAndTheXml() throws Exception {
		final Path out = Files.createDirectories(dir.resolve("spark"));
		final List<String> args = new ArrayList<>(List.of(movie.toString(), "--out-dir", out.toString(),
			"--trackmate-xml", "--master", "local[1]"));
		for (final Setting<?> s : TrackingSettings.ALL) {
			args.add(s.cliOption());
			args.add(String.valueOf(GIVEN.get(s)));
		}
		final ByteArrayOutputStream o = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
		assertEquals(0, SparkTrack.run(args.toArray(String[]::new), new PrintStream(o, true, StandardCharsets.UTF_8),
			new PrintStream(err, true, StandardCharsets.UTF_8)), err.toString(StandardCharsets.UTF_8));
		assertReadBack(out.resolve("movie.csv"), out.resolve("movie.xml"));
	}

	@Test
	void trackMateSessionKeepsEverySetting() {
		final ContactTrackerDetectorFactory<UnsignedByteType> factory = new ContactTrackerDetectorFactory<>();
		final Map<String, Object> map = TrackMateSettings.toMap(GIVEN);
		assertNull(factory.checkSettings(map));
		final Element element = new Element("DetectorSettings");
		assertNull(factory.marshal(map, element));
		final Map<String, Object> back = new HashMap<>();
		assertNull(factory.unmarshal(element, back));
		assertEquals(GIVEN, TrackMateSettings.values(back));
	}

	@Test
	void settingsFileRefusesWhatItDoesNotKnowInOneLine() {
		final String text = SettingsFile.text(GIVEN);
		assertEquals(GIVEN, read(text));
		assertEquals("f line 3: expected 'name = value' of a setting (threshold, r_out, min_area, min_second_area, " +
			"connectivity, method, diameter, kinds, particles, detection, channel), not 'rout = 3'", error(text.replace("r_out =",
				"rout =").replace(" = 9.5", " = 3")));
		assertEquals("f line 6: connectivity must be one of 8, 4, not 6", error(text.replace("connectivity = 4",
			"connectivity = 6")));
		assertEquals("f line 13: connectivity is given twice", error(text + "connectivity = 4\n"));
		assertEquals("f: the setting channel is missing", error(text.replace("channel = 2\n", "")));
	}

	private static SettingValues read(final String text) {
		try {
			final Path f = Files.writeString(dir.resolve("f"), text);
			return SettingsFile.read(f);
		}
		catch (final IOException e) {
			throw new AssertionError(e);
		}
	}

	private static String error(final String text) {
		try {
			read(text);
		}
		catch (final RuntimeException e) {
			return e.getMessage().replace(dir.resolve("f").toString(), "f");
		}
		throw new AssertionError("accepted:\n" + text);
	}

	/** The settings file beside {@code csv} and the detector settings of {@code xml} hold {@link #GIVEN}. */
	private static void assertReadBack(final Path csv, final Path xml) throws IOException, JDOMException {
		assertEquals(GIVEN, SettingsFile.read(SettingsFile.beside(csv)), "the settings file of " + csv);
		final Element detector = new SAXBuilder().build(xml.toFile()).getRootElement().getChild("Settings").getChild(
			"DetectorSettings");
		final Map<String, Object> map = new HashMap<>();
		for (final Attribute a : detector.getAttributes())
			if (!a.getName().equals(TrackMateSettings.XML_ATTRIBUTE_DETECTOR_NAME)) map.put(a.getName(), TrackMateSettings
				.parse(a.getName(), a.getValue()));
		assertEquals(GIVEN, TrackMateSettings.values(map), "the detector settings of " + xml);
	}
}
