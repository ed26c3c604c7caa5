#!/usr/bin/env python3
"""ct.batch against `contact-tracker track` on the same frames: a movie's frames as the command line reads them,
repeated to N frames, written as a plain TIFF; `scripts/contact-tracker track` on the TIFF (a new process: JVM
start-up, file reading and the CSV included) against ct.batch on the same frames in memory (in this process, its JVM started and warm, and
in a new Python process: JVM start-up and compilation included), best of R runs each, in wall-clock and in CPU
seconds (all threads: less disturbed by other processes on a shared machine than the wall clock). Also checks
that both give the same spots.

Not part of the tests (needs a movie): python benchmarks/speed.py MOVIE [--frames 300] [--runs 3]
(with the package and tifffile installed). On a shared machine the figures are noisy: run it when idle.
"""
import argparse
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd
import tifffile

import contact_tracker as ct
from contact_tracker import _java



def cpu(who):
    r = resource.getrusage(who)
    return r.ru_utime + r.ru_stime


ap = argparse.ArgumentParser()
ap.add_argument("movie")
ap.add_argument("--frames", type=int, default=300)
ap.add_argument("--runs", type=int, default=3)
args = ap.parse_args()

# the movie's frames as the command line reads them (its own AVI/TIFF readers), through the jar
_java.start()
import jpype  # noqa: E402

imp = _java.cls("io.ImageFiles").open(jpype.JClass("java.nio.file.Path").of(args.movie, []))
stack = imp.getStack()
w, h = imp.getWidth(), imp.getHeight()
planes = [np.asarray(stack.getProcessor(i + 1).convertToByte(False).getPixels(), dtype=np.int8).view(np.uint8)
          .reshape(h, w) for i in range(stack.getSize())]
frames = np.stack([planes[i % len(planes)] for i in range(args.frames)])
java = str(Path(_java.java_home()) / "bin" / "java")

with tempfile.TemporaryDirectory() as d:
    tif, csv = Path(d, "movie.tif"), Path(d, "spots.csv")
    tifffile.imwrite(tif, frames)
    # track as users run it: the repository's launcher (its JVM options for short jobs), else the package's jar
    launcher = Path(__file__).resolve().parents[2] / "scripts" / "contact-tracker"
    cmd = ([str(launcher)] if launcher.is_file() else [java, "-jar", str(_java.JAR)]) + [
        "track", str(tif), "--csv", str(csv), "--no-progress"]
    subprocess.run(cmd, check=True, capture_output=True)  # the file into the page cache
    track, track_cpu = [], []
    for _ in range(args.runs):
        c0 = cpu(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True)
        track.append(time.perf_counter() - t0)
        track_cpu.append(cpu(resource.RUSAGE_CHILDREN) - c0)
    ref = pd.read_csv(csv)
    # ct.batch as a new process meets it: a fresh Python, the JVM started and its compiler cold
    cold = ("import sys, time, tifffile\nf = tifffile.imread(sys.argv[1])\nt0 = time.perf_counter()\n"
            "import contact_tracker as ct\nct.batch(f)\nprint(time.perf_counter() - t0)\n")
    fresh, fresh_cpu = [], []
    for _ in range(args.runs):
        c0 = cpu(resource.RUSAGE_CHILDREN)
        r = subprocess.run([sys.executable, "-c", cold, str(tif)], check=True, capture_output=True, text=True)
        fresh.append(float(r.stdout.split()[-1]))
        fresh_cpu.append(cpu(resource.RUSAGE_CHILDREN) - c0)
batch, batch_cpu = [], []
for _ in range(args.runs):
    c0 = cpu(resource.RUSAGE_SELF)
    t0 = time.perf_counter()
    df = ct.batch(frames)
    batch.append(time.perf_counter() - t0)
    batch_cpu.append(cpu(resource.RUSAGE_SELF) - c0)
assert len(df) == len(ref) and np.array_equal(df["x"].to_numpy(), ref["POSITION_X"].to_numpy()), "not the same spots"

n = len(frames)
print(f"{args.movie}: {n} frames of {w} x {h}, {len(df)} spots (the same from both), best of {args.runs}")
print(f"  track (new process, file in, CSV out)   {min(track):7.2f} s  {1000 * min(track) / n:6.1f} ms/frame"
      f"   CPU {min(track_cpu):7.2f} s")
print(f"  ct.batch (numpy in, DataFrame out)      {min(batch):7.2f} s  {1000 * min(batch) / n:6.1f} ms/frame"
      f"   CPU {min(batch_cpu):7.2f} s   ({min(batch) / min(track):.2f} x track's wall clock, "
      f"{min(batch_cpu) / min(track_cpu):.2f} x its CPU)")
print(f"  ct.batch in a new Python process       {min(fresh):7.2f} s  {1000 * min(fresh) / n:6.1f} ms/frame"
      f"   CPU {min(fresh_cpu):7.2f} s   ({min(fresh) / min(track):.2f} x track's wall clock, "
      f"{min(fresh_cpu) / min(track_cpu):.2f} x its CPU; JVM start-up and reading the TIFF included in the CPU)")
