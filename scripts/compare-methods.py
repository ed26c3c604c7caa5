#!/usr/bin/env python3
"""Agreement of two methods' centres on the same movie, against the errors they report.

    scripts/compare-methods.py A.csv B.csv

A.csv and B.csv are spots CSVs of the same movie (e.g. `track MOVIE --method paper --csv A.csv` and `track MOVIE
--csv B.csv`, same --threshold/--r-out/--diameter). Each unflagged spot of A is matched with the nearest spot of B
in its frame (skipped if that one is flagged); prints the differences A - B in x and y (px) and the same in units
of the combined reported standard error sqrt(SIGMA_A^2 + SIGMA_B^2). Were the reported errors right, that would
have a std of 1 or less (the two methods read the same pixels, so their errors are correlated). Standard library
only.
"""
import collections
import csv
import math
import sys

def load(p):
    d = collections.defaultdict(list)
    for r in csv.DictReader(open(p)):
        d[int(r['FRAME'])].append(r)
    return d
a, b = load(sys.argv[1]), load(sys.argv[2])
z = []; dx = []; n = 0
for f in a:
    for r in a[f]:
        if int(r['FLAG_AT_BORDER']) or any(int(r[k]) for k in r if k.startswith('FLAG_')): continue
        x, y = float(r['POSITION_X']), float(r['POSITION_Y'])
        best = min(b.get(f, []), key=lambda s: (float(s['POSITION_X'])-x)**2 + (float(s['POSITION_Y'])-y)**2, default=None)
        if best is None or any(int(best[k]) for k in best if k.startswith('FLAG_')): continue
        for c, s in (('X','SIGMA_X'), ('Y','SIGMA_Y')):
            d = float(r['POSITION_'+c]) - float(best['POSITION_'+c])
            sig = math.hypot(float(r[s]), float(best[s]))
            z.append(d / sig); dx.append(d)
        n += 1
z.sort(); dx.sort()
m = lambda v: sum(v)/len(v)
sd = lambda v: math.sqrt(sum((t-m(v))**2 for t in v)/(len(v)-1))
print(f"{n} particles matched; difference A - B: mean {m(dx):+.4f} px, std {sd(dx):.4f} px, median |d| {sorted(abs(t) for t in dx)[len(dx)//2]:.4f} px")
print(f"in units of the combined reported error: mean {m(z):+.2f}, std {sd(z):.2f}, |z|<2: {sum(abs(t)<2 for t in z)/len(z):.1%}, |z|<3: {sum(abs(t)<3 for t in z)/len(z):.1%}")
