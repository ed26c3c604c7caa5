#!/usr/bin/env bash
# Benchmark behind the manual's "Broken files" (src/site/markdown/manual.md): TwelveMonkeys imageio-tiff against our readers, and `track` on the broken
# files. Not part of the build. Needs the packaged project (mvn -B package) and Maven Central (for TwelveMonkeys).
#   scripts/reader-comparison/run.sh hostile          every case file through both readers, -Xmx256m, 15 s limit
#   scripts/reader-comparison/run.sh speed            every frame of the 400-frame bench stack, one thread
#   scripts/reader-comparison/run.sh track [CLI.jar]  the 44 broken-file cases through `track`, -Xmx256m, 30 s limit
#   scripts/reader-comparison/run.sh repeat           all case files 15 times over in one JVM, -Xmx256m: time, heap
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
W=target/reader-comparison
TM=3.12.0
mkdir -p "$W/classes"
if [ ! -f "$W/cp.txt" ]; then
	mvn -B -q dependency:get -Dartifact=com.twelvemonkeys.imageio:imageio-tiff:$TM >/dev/null
	mvn -B -q dependency:build-classpath -Dmdep.outputFile="$W/cp.txt" -Dmdep.includeScope=test >/dev/null
	find ~/.m2/repository/com/twelvemonkeys -path "*/$TM/*.jar" ! -name "*-tests.jar" | tr '\n' ':' > "$W/tm.txt"
fi
CP="$W/classes:$(cat "$W/tm.txt")$(cat "$W/cp.txt"):target/classes:target/test-classes"
javac -nowarn -proc:none -d "$W/classes" -cp "$CP" scripts/reader-comparison/*.java
[ -d "$W/cases" ] || java -cp "$CP" io.github.contacttracker.io.WriteCases "$W/cases"
case "${1:-hostile}" in
hostile)
	for f in "$W"/cases/*.tif; do
		for r in tm ours; do
			start=$(date +%s%N)
			out=$(timeout 15 java -Xmx256m -Djava.awt.headless=true -cp "$CP" ReaderComparison read $r "$f" 2>&1 | head -1 | cut -c1-160 || true)
			echo -e "$(basename "$f")\t$r\t$(( ($(date +%s%N) - start) / 1000000 )) ms\t${out:-TIMEOUT}"
		done
	done ;;
speed)
	[ -f "$W/bench.tif" ] || java -jar target/*-cli.jar bench --frames 400 --rounds 1 --save-stack "$W/bench.tif" >/dev/null
	for m in ours tm open; do java -Xmx1g -Djava.awt.headless=true -cp "$CP" ReaderComparison speed $m "$W/bench.tif"; done ;;
repeat)
	java -Xmx256m -Djava.awt.headless=true -cp "$CP" ReaderComparison repeat ours "$W/cases" ;;
track)
	jar=${2:-$(ls target/*-cli.jar)}
	for f in "$W"/cases/issue-*; do
		start=$(date +%s%N)
		set +e
		timeout 30 java -Xmx256m -Djava.awt.headless=true -jar "$jar" track "$f" --threshold 100 --r-out 5 --csv "$W/out.csv" >/dev/null 2>"$W/err.txt"
		rc=$?
		set -e
		rm -f "$W/out.csv"
		echo -e "$(basename "$f")\texit $rc\t$(( ($(date +%s%N) - start) / 1000000 )) ms\t$(grep -c . "$W/err.txt") lines\t$(head -1 "$W/err.txt" | cut -c1-120)"
	done ;;
esac
