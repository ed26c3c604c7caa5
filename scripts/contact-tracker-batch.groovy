#@ File (label = "Input folder (TIFF images)", style = "directory") input
#@ File (label = "Output folder (CSV per image)", style = "directory") output
#@ Double (label = "Threshold (grey level)", value = 100) threshold
#@ Double (label = "r_out (px)", value = 20) r_out
#@ Integer (label = "Min area (px)", value = 20) min_area
#@ String (label = "Method", value = "paper") method
#@ Integer (label = "Channel", value = 1) channel
#@ Double (label = "Particle diameter (px, 0 = not given)", value = 0) diameter
#@ Integer (label = "Kinds of particle (0 = automatic, 1 = all alike)", value = 0, min = 0, max = 4) kinds
#@ String (label = "Particles", choices = {"bright", "dark"}, value = "bright") particles
#@ Boolean (label = "Also save a TrackMate XML per image", value = false) trackmate
#@ CommandService commands
#@ LogService log
#@output Integer done
#@output Integer failed

// Contact Tracker batch (SciJava script, Groovy): localizes every TIFF of the input folder with the
// "Contact Tracker" command and saves one CSV of spots per image (image.tif -> image.csv), the same CSV as the
// command line writes. In Fiji: open it in the script editor and Run, or File > Open... and Run.
// Headless:
//   ImageJ-linux64 --headless --console --run contact-tracker-batch.groovy \
//     'input="/data/movies",output="/data/spots",threshold=110,r_out=55,min_area=20,method="paper",channel=1,diameter=0,kinds=0,particles="bright",trackmate=false'

import io.github.contacttracker.io.ImageFiles
import io.github.contacttracker.command.ContactTrackerCommand
import io.github.contacttracker.core.TrackerParameters

done = 0
failed = 0
def tiffs = (input.listFiles() ?: new File[0]).findAll { it.isFile() && it.name.toLowerCase() ==~ /.*\.tiff?/ }
	.sort { it.name }
if (tiffs.isEmpty()) log.warn("Contact Tracker batch: no TIFF in " + input)
for (f in tiffs) {
	// Contact Tracker's checked readers: a broken or hostile file is one line naming it, and the batch goes on
	def imp
	try {
		imp = ImageFiles.open(f.toPath())
	}
	catch (IOException e) {
		log.error("Contact Tracker batch: " + f.name + ": " + e.message)
		failed++
		continue
	}
	def base = f.name.replaceFirst(/(?i)\.tiff?$/, "")
	def csv = new File(output, base + ".csv")
	def xml = trackmate ? new File(output, base + ".xml") : null
	// every input is given, so that no dialog opens for a missing one and none takes the dialog's last value
	def module = commands.run(ContactTrackerCommand, true,
		"imp", imp, "threshold", threshold, "r_out", r_out, "min_area", min_area,
		"min_second_area", TrackerParameters.DEFAULT_MIN_SECOND_AREA, "connectivity", "8", "method", method,
		"channel", channel, "diameter", diameter, "kinds", kinds, "particles", particles, "pair_cutoff", 0d, "overlay", false, "table", false,
		"results", "spots", "threads", 0, "csv", csv, "trackmate_xml", xml).get()
	if (module.isCanceled()) {
		log.error("Contact Tracker batch: " + f.name + ": " + module.getCancelReason())
		failed++
	}
	else {
		println(f.name + ": " + module.getOutput("spots").size() + " spots -> " + csv)
		done++
	}
	imp.close()
}
println("Contact Tracker batch: " + done + " image(s) done, " + failed + " failed")
