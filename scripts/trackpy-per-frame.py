#!/usr/bin/env python3
"""Per-frame cost of Contact Tracker's default method after start-up, against trackpy.locate in process.

Not part of the test suite (needs Python with numpy, tifffile and trackpy: pip install trackpy tifffile). STACK is a
TIFF stack of a movie's frames (e.g. the paper authors' 1.avi repeated to 300 frames). In one run, alternating:
  * trackpy: the frames loaded once, then trackpy.locate(frame, DIAMETER) timed per frame in process, wall clock and
    CPU (the process's, all its threads);
  * ours: `scripts/contact-tracker track` in a new process on the whole stack and on its first SHORT frames, so that
    the difference over the frames between is the per-frame cost after start-up (the profile measured, the JIT warm),
    wall clock and CPU (user + system of the process, all its threads).
Prints medians over --rounds rounds. On a shared machine the figures are noisy: compare the ratio within one run.
    scripts/trackpy-per-frame.py one300.tif --diameter 35 -- --threshold 186 --r-out 43 --diameter 34.06
(options after -- go to `track`).
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import tifffile
import trackpy as tp

ap = argparse.ArgumentParser()
ap.add_argument("stack")
ap.add_argument("--diameter", type=int, default=35, help="trackpy's feature diameter (odd, px)")
ap.add_argument("--short", type=int, default=30, help="frames of the short run whose cost is subtracted")
ap.add_argument("--rounds", type=int, default=3)
argv = sys.argv[1:]
split = argv.index("--") if "--" in argv else len(argv)
args = ap.parse_args(argv[:split])
args.track_options = argv[split + 1:]  # options for `track`, after --

here = os.path.dirname(os.path.abspath(__file__))
frames = tifffile.imread(args.stack)
n = len(frames)
if n <= args.short:
    sys.exit(f"trackpy-per-frame: error: the stack has {n} frames, not more than --short {args.short}")
tp.quiet()


def ours(path):
    """Wall and CPU seconds of `track` on a stack, in a new process."""
    with tempfile.TemporaryDirectory() as d:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run([os.path.join(here, "contact-tracker"), "track", path, *args.track_options, "--no-progress",
                        "--csv", os.path.join(d, "spots.csv")], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


with tempfile.TemporaryDirectory() as d:
    short = os.path.join(d, "short.tif")
    tifffile.imwrite(short, frames[:args.short])
    ours(short)  # the class archive and the page cache, once
    wall, cpu, locate, locate_cpu, spots = [], [], [], [], 0
    for _ in range(args.rounds):
        w1, c1 = ours(args.stack)
        w0, c0 = ours(short)
        wall.append((w1 - w0) / (n - args.short))
        cpu.append((c1 - c0) / (n - args.short))
        per, per_cpu = [], []
        for f in frames:
            t0, c0 = time.perf_counter(), time.process_time()
            spots = len(tp.locate(f, args.diameter))
            per.append(time.perf_counter() - t0)
            per_cpu.append(time.process_time() - c0)
        locate.append(statistics.median(per))
        locate_cpu.append(statistics.median(per_cpu))
ms = 1000
print(f"{n} frames of {frames.shape[2]}x{frames.shape[1]}, {os.cpu_count()} cores, medians of {args.rounds} rounds")
print(f"  trackpy.locate (diameter {args.diameter}), in process, wall:     {ms * statistics.median(locate):6.1f} ms/frame "
      f"({spots} features in the last frame)")
print(f"  trackpy.locate, in process, CPU (all its threads):          {ms * statistics.median(locate_cpu):6.1f} ms/frame")
print(f"  contact-tracker track, per frame after start-up, wall:           {ms * statistics.median(wall):6.1f} ms/frame "
      f"(ratio {statistics.median(locate) / statistics.median(wall):.2f}x)")
print(f"  contact-tracker track, per frame after start-up, CPU:            {ms * statistics.median(cpu):6.1f} ms/frame "
      f"(CPU against CPU {statistics.median(locate_cpu) / statistics.median(cpu):.2f}x)")
