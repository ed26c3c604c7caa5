#!/usr/bin/env python3
"""Compares two spot tables of the same movie (CSV files written by `contact-tracker track`).

Usage: scripts/compare-spots.py A.csv B.csv [--within PX]

Matches the spots of each frame nearest first (each spot used once, within PX pixels, default 5) and prints how many
matched, how many are in one table only, and the distances between matched spots at the median, 90th and 99th
percentile and the largest, in the tables' position units.

Also the reading of spot tables that the other scripts share (footage-suite, perturbation-check, truth-match.py,
overlay.py load this file): rows, flags_set (which flags count as warnings), flag_summary and match.
"""
import argparse
import csv
import math
from collections import Counter, defaultdict


def rows(path):
    """The rows of a spot table as dicts by column name (lines starting with # skipped)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def flags_set(row):
    """The warning flags set on a spot: its FLAG_ columns set, but FLAG_SECOND_PASS, which marks the normal case."""
    return [k for k, v in row.items() if k.startswith("FLAG_") and k != "FLAG_SECOND_PASS" and (v or "0") not in
            ("0", "false")]


def flag_summary(table):
    """The spots of a table's rows, how many carry a warning flag, and a Counter of the flags set."""
    counts, flagged = Counter(), 0
    for r in table:
        on = flags_set(r)
        flagged += bool(on)
        counts.update(on)
    return len(table), flagged, counts


def load(path):
    frames = defaultdict(list)
    for d in rows(path):
        frames[int(float(d["FRAME"]))].append((float(d["POSITION_X"]), float(d["POSITION_Y"])))
    return frames


def match(a, b, within):
    """Matches the spots of each frame of two loaded tables nearest first, each used once, within `within`.

    Returns the matched distances (sorted) and the counts of spots in a only and in b only."""
    distances, only_a, only_b = [], 0, 0
    for frame in sorted(set(a) | set(b)):
        sa, sb = a.get(frame, []), b.get(frame, [])
        pairs = sorted((math.hypot(p[0] - q[0], p[1] - q[1]), i, j) for i, p in enumerate(sa)
                       for j, q in enumerate(sb))
        used_a, used_b = set(), set()
        for d, i, j in pairs:
            if d > within:
                break
            if i in used_a or j in used_b:
                continue
            used_a.add(i)
            used_b.add(j)
            distances.append(d)
        only_a += len(sa) - len(used_a)
        only_b += len(sb) - len(used_b)
    distances.sort()
    return distances, only_a, only_b


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--within", type=float, default=5)
    args = ap.parse_args()
    distances, only_a, only_b = match(load(args.a), load(args.b), args.within)
    print(f"matched {len(distances)}, only in {args.a}: {only_a}, only in {args.b}: {only_b}")
    if distances:
        def q(p):
            return distances[min(len(distances) - 1, int(p * len(distances)))]
        print(f"distance: median {q(0.5):.4f}, 90th percentile {q(0.9):.4f}, 99th {q(0.99):.4f}, "
              f"largest {distances[-1]:.4f}")


if __name__ == "__main__":
    main()
