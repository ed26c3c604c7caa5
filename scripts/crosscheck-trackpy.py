#!/usr/bin/env python3
"""Cross-check of `contact-tracker potential` against trackpy's g(r) (trackpy.static.pair_correlation_2d).

Not part of the test suite (it needs Python with numpy, pandas and trackpy: pip install trackpy). It makes two
point sets in a W x H field, many frames each: uniform random points (g = 1) and hard discs placed by random
sequential addition (g = 0 inside the disc diameter, a contact peak outside), writes them as a spots CSV in our
format, runs `scripts/contact-tracker potential` on it, runs trackpy on the same frames (its per-particle edge
correction; ours is the exact pair geometry of the rectangle), and prints both g(r) per bin with the difference
in units of our error bar (1/sqrt(PAIRS) relative).

usage: scripts/crosscheck-trackpy.py [OUT_DIR]
"""
import os
import subprocess
import sys

import numpy as np
import pandas as pd
from trackpy.static import pair_correlation_2d

W, H, N, FRAMES, SIGMA, BIN, RMAX = 100.0, 80.0, 60, 400, 6.0, 1.0, 30.0


def uniform(rng):
    return rng.uniform(0, W, N), rng.uniform(0, H, N)


def hard_discs(rng):
    xs, ys = [], []
    while len(xs) < N:
        x, y = rng.uniform(0, W), rng.uniform(0, H)
        if all((x - a) ** 2 + (y - b) ** 2 >= SIGMA ** 2 for a, b in zip(xs, ys)):
            xs.append(x)
            ys.append(y)
    return np.array(xs), np.array(ys)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "crosscheck-output"
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    rng = np.random.default_rng(7)
    for name, make in (("uniform", uniform), ("hard discs", hard_discs)):
        rows = []
        for f in range(FRAMES):
            x, y = make(rng)
            rows.append(pd.DataFrame({"FRAME": f, "POSITION_X": x, "POSITION_Y": y}))
        spots = pd.concat(rows, ignore_index=True)
        spots.insert(0, "ID", range(len(spots)))
        csv = os.path.join(out, name.replace(" ", "-") + "-spots.csv")
        spots.to_csv(csv, index=False)
        ours_csv = os.path.join(out, name.replace(" ", "-") + "-gr.csv")
        subprocess.run([os.path.join(here, "contact-tracker"), "potential", csv, "--bin", str(BIN), "--r-max",
                        str(RMAX), "--width", str(W), "--height", str(H), "--csv", ours_csv], check=True,
                       stdout=subprocess.DEVNULL)
        ours = pd.read_csv(ours_csv)
        # trackpy, frame by frame, averaged over frames; x/y columns, boundary = the field
        tp = []
        for f, frame in spots.groupby("FRAME"):
            feat = pd.DataFrame({"x": frame.POSITION_X.values, "y": frame.POSITION_Y.values})
            edges, g = pair_correlation_2d(feat, cutoff=RMAX, dr=BIN, boundary=(0, W, 0, H), handle_edge=True)
            tp.append(g)
        g_tp = np.mean(tp, axis=0)
        centres = (edges[:-1] + edges[1:]) / 2 if len(edges) == len(g_tp) + 1 else edges[:len(g_tp)]
        print(f"{name}: {FRAMES} frames of {N} points in {W:g} x {H:g}")
        print("    R   | ours G  | trackpy g | (ours - trackpy) / our error")
        worst = 0.0
        for _, row in ours.iterrows():
            i = int(np.argmin(np.abs(centres - row.R)))
            if abs(centres[i] - row.R) > BIN / 4 or pd.isna(row.G) or row.PAIRS == 0:
                continue
            err = row.G / np.sqrt(row.PAIRS)
            z = (row.G - g_tp[i]) / err
            worst = max(worst, abs(z))
            if int(row.R) % 3 == 0:
                print(f"  {row.R:5.1f} | {row.G:7.4f} | {g_tp[i]:9.4f} | {z:+6.2f}")
        print(f"  largest |difference| over all bins: {worst:.2f} error bars\n")


if __name__ == "__main__":
    main()
