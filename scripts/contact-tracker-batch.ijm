// Contact Tracker batch (ImageJ macro): localizes every TIFF of a folder with "Contact Tracker" and saves one
// CSV of spots per image (image.tif -> image.csv), the same CSV as the command line writes.
//
// Headless (Fiji):
//   ImageJ-linux64 --headless --console -macro /path/to/contact-tracker-batch.ijm \
//     "input=[/data/movies] output=[/data/spots] threshold=110 r_out=55 min_area=20 method=paper channel=1 diameter=0 kinds=0 particles=bright"
// In Fiji: Plugins > Macros > Run... and pick this file; without an argument it asks for the values.
//
// Keys not given take the defaults below. An image that fails (a broken file, Z and T both > 1, a bad
// value, ...) is reported with its name and reason and the batch goes on with the next one; no image is left open.

args = getArgument();
if (args == "") {
	Dialog.create("Contact Tracker batch");
	Dialog.addDirectory("Input folder (TIFF images)", "");
	Dialog.addDirectory("Output folder (CSV per image)", "");
	Dialog.addNumber("Threshold (grey level)", 100);
	Dialog.addNumber("r_out (px)", 20);
	Dialog.addNumber("Min area (px)", 20);
	Dialog.addString("Method", "paper");
	Dialog.addNumber("Channel", 1);
	Dialog.addNumber("Particle diameter (px, 0 = not given)", 0);
	Dialog.addNumber("Kinds of particle (0 = automatic, 1 = all alike)", 0);
	Dialog.addChoice("Particles", newArray("bright", "dark"), "bright");
	Dialog.show();
	input = Dialog.getString();
	output = Dialog.getString();
	threshold = Dialog.getNumber();
	r_out = Dialog.getNumber();
	min_area = Dialog.getNumber();
	method = Dialog.getString();
	channel = Dialog.getNumber();
	diameter = Dialog.getNumber();
	kinds = Dialog.getNumber();
	particles = Dialog.getChoice();
} else {
	input = value(args, "input", "");
	output = value(args, "output", "");
	threshold = value(args, "threshold", "100");
	r_out = value(args, "r_out", "20");
	min_area = value(args, "min_area", "20");
	method = value(args, "method", "paper");
	channel = value(args, "channel", "1");
	diameter = value(args, "diameter", "0");
	kinds = value(args, "kinds", "0");
	particles = value(args, "particles", "bright");
}
if (input == "" || !File.isDirectory(input)) exit("Contact Tracker batch: input folder not found: '" + input + "'");
if (output == "" || !File.isDirectory(output)) exit("Contact Tracker batch: output folder not found: '" + output + "'");
if (!endsWith(input, "/") && !endsWith(input, File.separator)) input = input + File.separator;
if (!endsWith(output, "/") && !endsWith(output, File.separator)) output = output + File.separator;
options = "threshold=" + threshold + " r_out=" + r_out + " min_area=" + min_area + " method=" + method +
	" channel=" + channel + " diameter=" + diameter + " kinds=" + kinds + " particles=" + particles +
	" overlay=false table=false";

setBatchMode(true);
list = getFileList(input);
done = 0;
failed = 0;
for (i = 0; i < list.length; i++) {
	name = list[i];
	if (!matches(toLowerCase(name), ".*\\.tiff?")) continue;
	csv = output + File.getNameWithoutExtension(name) + ".csv";
	if (File.exists(csv)) deleted = File.delete(csv); // so that a failure cannot leave an old CSV looking new
	// opened by Contact Tracker's checked readers: a broken or hostile file is one line here, and the batch goes on
	// (ImageJ's open() may stop the macro, print several lines, run out of memory or not end on such a file)
	error = call("io.github.contacttracker.command.MovieOpener.open", input + name);
	if (error != "") {
		failed++;
		print(name + ": FAILED: " + error);
		continue;
	}
	// a failing image is reported in the Log ("Contact Tracker ('name'): reason") instead of stopping the batch
	IJ.redirectErrorMessages();
	run("Contact Tracker", options + " csv=[" + csv + "]");
	spots = nResults; // the spots are also in the Results table (getResult("POSITION_X", i), ...)
	close("*");
	if (File.exists(csv)) {
		done++;
		print(name + ": " + spots + " spots -> " + csv);
	} else {
		failed++;
		print(name + ": FAILED (the reason is in the line above)");
	}
}
setBatchMode(false);
print("Contact Tracker batch: " + done + " image(s) done, " + failed + " failed");
print("open images: " + nImages);

// The value of key in "key=value key=[value with spaces] ...", or the default.
function value(options, key, default) {
	return call("ij.Macro.getValue", options, key, default);
}
