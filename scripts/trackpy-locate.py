#!/usr/bin/env python3
"""trackpy's locate on every frame of a movie, end to end: the yardstick for `scripts/contact-tracker track`.

Not part of the test suite (needs Python with numpy, trackpy, and PyAV for AVI or tifffile for TIFF:
pip install trackpy av tifffile). Times the import, the decoding and `trackpy.locate(frame, diameter)` with
trackpy's defaults, and prints them on standard error. Pair it with our command line in one run, e.g.
    farm-bench -n 3 --vs "scripts/trackpy-locate.py 1.avi --diameter 35" -- scripts/contact-tracker track 1.avi --csv out.csv
(the diameter: the particles' diameter in pixels, rounded up to odd, as trackpy wants). Dark particles on a bright
background: --invert (trackpy's invert=True); --minmass sets trackpy's minmass, e.g. its tutorial's values for its
own bulk_water sample: --diameter 11 --invert --minmass 20. --csv OUT.csv writes trackpy's features as a spot table
(FRAME, POSITION_X, POSITION_Y in pixels, MASS) that scripts/compare-spots.py compares with ours.
"""
import sys
import time

t0 = time.time()
import argparse  # noqa: E402

import trackpy as tp  # noqa: E402

t1 = time.time()
ap = argparse.ArgumentParser()
ap.add_argument("movie", help="AVI (decoded to grey with PyAV) or TIFF stack")
ap.add_argument("--diameter", type=int, default=35, help="trackpy's feature diameter (odd, px)")
ap.add_argument("--invert", action="store_true", help="dark particles on a bright background (trackpy's invert=True)")
ap.add_argument("--minmass", type=float, default=None, help="trackpy's minmass (default: trackpy's)")
ap.add_argument("--csv", help="write the features here (FRAME, POSITION_X, POSITION_Y, MASS; pixels)")
args = ap.parse_args()
if args.movie.lower().endswith(".avi"):
    import av
    frames = []
    with av.open(args.movie) as container:
        for f in container.decode(video=0):
            frames.append(f.to_ndarray(format="gray"))
else:
    import tifffile
    frames = tifffile.imread(args.movie)
    if frames.ndim == 2:
        frames = frames[None]
t2 = time.time()
extra = {} if args.minmass is None else {"minmass": args.minmass}
found = [tp.locate(frame, args.diameter, invert=args.invert, **extra) for frame in frames]
t3 = time.time()
spots = sum(len(f) for f in found)
if args.csv:
    with open(args.csv, "w") as out:
        out.write("FRAME,POSITION_X,POSITION_Y,MASS\n")
        for t, f in enumerate(found):
            for x, y, m in zip(f["x"], f["y"], f["mass"]):
                out.write(f"{t},{x!r},{y!r},{m!r}\n")
print(f"trackpy: {len(frames)} frames, {spots} spots; import {t1 - t0:.2f} s, read {t2 - t1:.2f} s, "
      f"locate {t3 - t2:.2f} s, total {t3 - t0:.2f} s", file=sys.stderr)
