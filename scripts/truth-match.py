#!/usr/bin/env python3
"""Matches the spots `contact-tracker track` found on a simulated movie to the movie's truth.

Usage: scripts/truth-match.py TRUTH.csv SPOTS.csv [--pixel-size UM]

TRUTH.csv is the truth `contact-tracker simulate --detection-scene KEY` writes (frame, particle, x_px, y_px,
diameter_px, band); SPOTS.csv the spot table of `track MOVIE --csv SPOTS.csv` on that movie. In each frame the
particles and spots are matched nearest first, each used once, a spot to a particle within a quarter of the
particle's diameter. Prints per band (and for all): the particles, the share found, the share of those found whose
spot carries a flag (any FLAG_ column but FLAG_SECOND_PASS), the distance of the spots from the truth at the median
and the 90th percentile (px); then the spots matched to no particle (false spots, and second spots on one), and how
many of those carry no flag. The spots'
positions are divided by --pixel-size (um a pixel; default 0.0847, the detection scenes' calibration, which
`simulate` writes into the movie) to compare them with the truth's pixels.
"""
import argparse
import importlib.util
import math
import os
from collections import defaultdict

# the tables read, and the flags that count, as scripts/compare-spots.py does for every script
_spec = importlib.util.spec_from_file_location("compare_spots", os.path.join(os.path.dirname(os.path.abspath(
    __file__)), "compare-spots.py"))
compare = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare)


def percentile(values, q):
    if not values:
        return float("nan")
    s = sorted(values)
    return s[min(len(s) - 1, int(q * (len(s) - 1) + 0.5))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("truth")
    parser.add_argument("spots")
    parser.add_argument("--pixel-size", type=float, default=0.0847)
    args = parser.parse_args()
    if not args.pixel_size > 0:
        parser.error("--pixel-size must be positive")
    truth, spots = defaultdict(list), defaultdict(list)
    for r in compare.rows(args.truth):
        truth[int(r["frame"])].append((float(r["x_px"]), float(r["y_px"]), float(r["diameter_px"]), r["band"]))
    for r in compare.rows(args.spots):
        spots[int(float(r["FRAME"]))].append((float(r["POSITION_X"]) / args.pixel_size,
                                              float(r["POSITION_Y"]) / args.pixel_size, bool(compare.flags_set(r))))
    bands = defaultdict(lambda: {"n": 0, "found": 0, "flagged": 0, "errors": []})
    false_spots = false_unflagged = 0
    for frame in sorted(set(truth) | set(spots)):
        t, s = truth.get(frame, []), spots.get(frame, [])
        pairs = sorted((math.hypot(p[0] - q[0], p[1] - q[1]), i, j) for i, p in enumerate(t) for j, q in enumerate(s)
                       if abs(p[0] - q[0]) < p[2] and abs(p[1] - q[1]) < p[2])
        used_t, used_s = {}, set()
        for d, i, j in pairs:
            if i in used_t or j in used_s or d >= 0.25 * t[i][2]:
                continue
            used_t[i] = (j, d)
            used_s.add(j)
        for i, p in enumerate(t):
            for key in (p[3], "all"):
                b = bands[key]
                b["n"] += 1
                if i in used_t:
                    j, d = used_t[i]
                    b["found"] += 1
                    b["flagged"] += s[j][2]
                    b["errors"].append(d)
        for j, q in enumerate(s):
            if j not in used_s:
                false_spots += 1
                false_unflagged += not q[2]
    print(f"{'band':<14} {'particles':>9} {'found':>7} {'flagged':>8} {'median px':>10} {'90th px':>8}")
    order = []
    for frame in sorted(truth):
        for p in truth[frame]:
            if p[3] not in order:
                order.append(p[3])
    for key in order + ["all"]:
        b = bands[key]
        found = b["found"]
        print(f"{key:<14} {b['n']:>9} {100.0 * found / b['n']:>6.1f}% "
              f"{(100.0 * b['flagged'] / found if found else float('nan')):>7.1f}% "
              f"{percentile(b['errors'], 0.5):>10.3f} {percentile(b['errors'], 0.9):>8.3f}")
    print(f"spots matched to no particle (a second spot on one included): {false_spots} ({false_unflagged} unflagged)")


if __name__ == "__main__":
    main()
