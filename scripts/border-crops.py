#!/usr/bin/env python3
"""How the image border treats the particles it cuts, measured on a real movie without ground truth.

Crops the movie (left, top, right and bottom edges moved inwards in steps), tracks every crop and the whole
movie with scripts/contact-tracker at the same values, and compares each crop's spots near its new edge with the
same particles' spots in the whole movie, where they lie far from any edge (in units of the crop spot's reported
SIGMA_X/Y). Spots are grouped by the crop's flags and by whether a particle lies beyond the new edge within the
profile's reach (1.5 r_out), whose light the crop cannot show. A second table groups the same spots, whatever their
flags, by the share of the information on the centre that the new edge cuts off (from the radial profile that
'contact-tracker profile' measures on the movie's first frame), the quantity the profile methods' AT_BORDER rule
reads.

  scripts/border-crops.py MOVIE --threshold T --r-out R [--diameter D] [--step 20] [--work DIR]

Needs numpy, av (PyAV) and tifffile (pip install av tifffile). The crops are written to a temporary folder.
"""
import argparse
import collections
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))


def frames(movie):
    if movie.lower().endswith((".tif", ".tiff")):
        import tifffile
        return tifffile.imread(movie)
    import av
    return np.stack([f.to_ndarray(format="gray") for f in av.open(movie).decode(video=0)])


def load(path):
    by = collections.defaultdict(list)
    with open(path) as f:
        for r in csv.DictReader(f):
            by[int(r["FRAME"])].append(r)
    return by


def radial_profile(movie, work):
    """The movie's radial profile (grey level against radius) as 'contact-tracker profile' measures it."""
    out = os.path.join(work, "profile.csv")
    if not os.path.exists(out):
        subprocess.run([os.path.join(here, "contact-tracker"), "profile", movie, "--csv", out], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return np.array([float(r["r_px"]) for r in rows]), np.array([float(r["level"]) for r in rows])


def share_cut(profile, x, y, width, height, reach):
    """Share of the Fisher information on x (or y, the larger) from pixels outside the frame (uniform noise)."""
    rr, level = profile
    gx, gy = np.meshgrid(np.arange(np.ceil(x - reach), np.floor(x + reach) + 1),
                         np.arange(np.ceil(y - reach), np.floor(y + reach) + 1))
    dx, dy = gx - x, gy - y
    r = np.hypot(dx, dy)
    inside = (r < reach) & (r > 0)
    slope = (np.interp(r + 0.01, rr, level) - np.interp(r - 0.01, rr, level)) / 0.02
    rs = np.where(r > 0, r, 1)
    wx, wy = (slope * dx / rs) ** 2, (slope * dy / rs) ** 2
    out = inside & ((gx < 0) | (gy < 0) | (gx >= width) | (gy >= height))
    return max(wx[out].sum() / wx[inside].sum(), wy[out].sum() / wy[inside].sum())


def share_table(movie, work, rows):
    print("the same spots, any flags, by the share of the information on the centre the new edge cuts off (%s):"
          % os.path.basename(movie))
    print("| share cut off | a particle beyond the new edge within reach | spots | rms error / SIGMA | beyond 3 SIGMA |")
    print("|---|---|---|---|---|")
    bins = [0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 1.01]
    for beyond in (False, True):
        for lo, hi in zip(bins, bins[1:]):
            e = np.array([q[2:] for q in rows if q[1] == beyond and lo <= q[0] < hi])
            if len(e):
                print("| %g-%g | %s | %d | %.2f | %.1f%% |" % (lo, min(hi, 1), "yes" if beyond else "no", len(e),
                      np.sqrt(np.mean(e ** 2)), 100 * np.mean(np.max(np.abs(e), axis=1) > 3)))
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("movie")
    ap.add_argument("--threshold", required=True)
    ap.add_argument("--r-out", required=True, type=float)
    ap.add_argument("--diameter")
    ap.add_argument("--step", type=int, default=20, help="px between crops (default 20)")
    ap.add_argument("--work", help="folder for the crops and CSVs (default: a temporary one)")
    a = ap.parse_args()
    import tifffile
    stack = frames(a.movie)
    h, w = stack.shape[1:]
    reach = 1.5 * a.r_out
    margin = int(np.ceil(reach))
    crops = {"full": (0, 0, w, h)}
    for x0 in range(margin, w // 2 + 1, a.step):
        crops["L%d" % x0] = (x0, 0, w, h)
    for y0 in range(margin, h // 2 + 1, a.step):
        crops["T%d" % y0] = (0, y0, w, h)
    for x1 in range(w // 2, w - margin + 1, a.step):
        crops["R%d" % x1] = (0, 0, x1, h)
    for y1 in range(h // 2, h - margin + 1, a.step):
        crops["B%d" % y1] = (0, 0, w, y1)
    work = a.work or tempfile.mkdtemp(prefix="border-crops-")
    os.makedirs(work, exist_ok=True)
    values = ["--threshold", a.threshold, "--r-out", str(a.r_out)] + (["--diameter", a.diameter] if a.diameter else [])
    for name, (x0, y0, x1, y1) in crops.items():
        tif, out = os.path.join(work, name + ".tif"), os.path.join(work, name + ".csv")
        if os.path.exists(out):
            continue
        tifffile.imwrite(tif, np.ascontiguousarray(stack[:, y0:y1, x0:x1]), imagej=True, metadata={"axes": "TYX"})
        subprocess.run([os.path.join(here, "contact-tracker"), "track", tif, *values, "--csv", out], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.remove(tif)
        print("tracked", name, file=sys.stderr)
    full = load(os.path.join(work, "full.csv"))
    flags = [k for k in next(iter(full.values()))[0] if k.startswith("FLAG_") and k != "FLAG_SECOND_PASS"]
    groups = collections.defaultdict(list)
    groups_by_share = []  # (share cut off, particle beyond, error x / SIGMA_X, error y / SIGMA_Y)
    profile = radial_profile(a.movie, work)
    for name, (x0, y0, x1, y1) in crops.items():
        if name == "full":
            continue
        for t, spots in load(os.path.join(work, name + ".csv")).items():
            whole = full[t]
            fx = np.array([float(r["POSITION_X"]) for r in whole])
            fy = np.array([float(r["POSITION_Y"]) for r in whole])
            for r in spots:
                x, y = float(r["POSITION_X"]) + x0, float(r["POSITION_Y"]) + y0
                d2 = (fx - x) ** 2 + (fy - y) ** 2
                j = int(np.argmin(d2))
                ref = whole[j]
                if d2[j] > 9 or any(ref[q] == "1" for q in flags):
                    continue  # no unflagged counterpart in the whole movie
                X, Y = float(ref["POSITION_X"]), float(ref["POSITION_Y"])
                if min(X + 0.5, Y + 0.5, w - 0.5 - X, h - 0.5 - Y) < reach:
                    continue  # near the movie's own edge: the same in both
                far = min(X - x0 + 0.5, Y - y0 + 0.5, x1 - 0.5 - X, y1 - 0.5 - Y) >= reach
                if far:  # the reference: how well a crop agrees with the whole movie where the edge plays no part
                    if not any(r[q] == "1" for q in flags):
                        groups[("(far from the new edge)", False)].append(
                            ((x - X) / float(r["SIGMA_X"]), (y - Y) / float(r["SIGMA_Y"])))
                    continue
                beyond = any(not (x0 <= float(g["POSITION_X"]) < x1 and y0 <= float(g["POSITION_Y"]) < y1) and
                             (float(g["POSITION_X"]) - X) ** 2 + (float(g["POSITION_Y"]) - Y) ** 2 < reach ** 2
                             for g in whole)
                e = ((x - X) / float(r["SIGMA_X"]), (y - Y) / float(r["SIGMA_Y"]))
                groups_by_share.append((share_cut(profile, X - x0, Y - y0, x1 - x0, y1 - y0, reach), beyond) + e)
                set_ = [q[5:] for q in flags if r[q] == "1"]
                key = "unflagged" if not set_ else "AT_BORDER" if "AT_BORDER" in set_ else "other flags"
                groups[(key, beyond)].append(((x - X) / float(r["SIGMA_X"]), (y - Y) / float(r["SIGMA_Y"])))
    share_table(a.movie, work, groups_by_share)
    print("crop spots within %.0f px (1.5 r_out) of the crop's new edge, against the whole movie (%s, %d crops; the "
          "last row: unflagged spots farther from it):" % (reach, os.path.basename(a.movie), len(crops) - 1))
    print("| crop's flags | a particle beyond the new edge within reach | spots | rms error / SIGMA | beyond 3 SIGMA |")
    print("|---|---|---|---|---|")
    for k in sorted(groups, key=lambda k: (k[0].startswith("("), k)):
        e = np.array(groups[k])
        print("| %s | %s | %d | %.2f | %.1f%% |" % (k[0], "yes" if k[1] else "no", len(e), np.sqrt(np.mean(e ** 2)),
                                                  100 * np.mean(np.max(np.abs(e), axis=1) > 3)))
    print("(CSVs in %s)" % work, file=sys.stderr)


if __name__ == "__main__":
    main()
