#!/usr/bin/env python3
"""Speed of Contact Tracker's command line against trackpy on the same frames, end to end.

Not part of the test suite (needs Python with numpy, tifffile and trackpy: pip install trackpy tifffile).
First make the benchmark stack (512x512 8-bit, 12 particles of 5.53 um, 4 touching pairs) with
    scripts/contact-tracker bench --frames 400 --save-stack bench.tif
then run
    scripts/compare-trackpy-speed.py bench.tif [--threads N]
It times `scripts/contact-tracker track bench.tif ... --csv` for the paper's method and the default method (file
in, CSV out, JVM start-up included; best of 3 new processes), then `trackpy.locate` on every frame (and `locate` +
`refine_leastsq`, trackpy's accurate path, on a few), and prints ms/frame and the ratio to trackpy.locate. Ours
run first: after numpy's first calls its BLAS threads may spin for a while and take a core from a short run.
"""
import argparse
import os
import subprocess
import tempfile
import time

import tifffile
import trackpy as tp

ap = argparse.ArgumentParser()
ap.add_argument("stack")
ap.add_argument("--threads", default="0")
ap.add_argument("--diameter", type=int, default=31, help="trackpy's feature diameter (odd, px)")
args = ap.parse_args()

here = os.path.dirname(os.path.abspath(__file__))
n = len(tifffile.TiffFile(args.stack).pages)

# Our command line first: after numpy's first calls its BLAS threads may keep spinning for a while, which would
# take a core from a short run started right after trackpy.
ours = {}
with tempfile.TemporaryDirectory() as d:
    for method in ("paper", "fit"):
        runs = []
        for _ in range(3):  # best of 3 new processes (the first also pays for reading the file into the page cache)
            t0 = time.perf_counter()
            subprocess.run([os.path.join(here, "contact-tracker"), "track", args.stack, "--threshold", "85",
                            "--r-out", "61", "--method", method, "--threads", args.threads, "--no-progress", "--csv",
                            os.path.join(d, "spots.csv")], check=True, stdout=subprocess.DEVNULL)
            runs.append(time.perf_counter() - t0)
        ours[method] = min(runs) / n

frames = tifffile.imread(args.stack)
assert len(frames) == n, f"{len(frames)} frames read, {n} pages"
tp.quiet()
t0 = time.perf_counter()
for f in frames:
    tp.locate(f, args.diameter, minmass=1000)
locate = (time.perf_counter() - t0) / n
few = min(n, 10)
t0 = time.perf_counter()
for f in frames[:few]:
    tp.refine_leastsq(tp.locate(f, args.diameter, minmass=1000), f, args.diameter, fit_function="gauss")
leastsq = (time.perf_counter() - t0) / few

print(f"{n} frames of {frames.shape[2]}x{frames.shape[1]}")
print(f"  trackpy.locate                      {1000 * locate:8.1f} ms/frame")
print(f"  trackpy.locate + refine_leastsq     {1000 * leastsq:8.1f} ms/frame ({few} frames)")
for method in ("paper", "fit"):
    print(f"  contact-tracker track --method {method:5s} {1000 * ours[method]:8.1f} ms/frame  "
          f"({locate / ours[method]:5.1f} x trackpy.locate's speed; file in, CSV out, JVM start-up included)")
