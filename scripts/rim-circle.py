#!/usr/bin/env python3
"""An independent centre for beads that wear a bright rim, to check `track` against: a circle fitted to the rim.

Not part of the test suite (it needs Python with numpy, pandas, scipy and tifffile). For each spot of a spots CSV
written by `scripts/contact-tracker track`, it samples the frame along 360 rays from the spot, takes the brightest
point of each ray between RMIN and RMAX px (sub-pixel, by a parabola), fits a circle to those points by least
squares, drops the fifth of them farthest from it (a tether, dust on the rim) and fits again, three times over from
the new centre. It prints the rim's radius, the mean and rms difference of the spots from the circles' centres, and
the frame-to-frame motion of both (the same motion says both follow the bead).

usage: scripts/rim-circle.py MOVIE SPOTS.csv [RMIN RMAX]
  MOVIE  a TIFF stack, or a folder of single-frame TIFFs (read in name order)
  RMIN RMAX  where the rim's brightest ring lies (px; default 20 45, a bead about 62 px across)
"""
import glob
import os
import sys

import numpy as np
import pandas as pd
import tifffile
from scipy.ndimage import map_coordinates


def frames(movie):
    files = sorted(glob.glob(os.path.join(movie, '*.tif*'))) if os.path.isdir(movie) else [movie]
    for f in files:
        a = tifffile.imread(f).astype(float)
        if a.ndim == 3 and a.shape[-1] in (3, 4):  # colour: the mean of red, green and blue, as `track` reads it
            a = a[..., :3].mean(-1)
        for plane in (a if a.ndim == 3 else [a]):
            yield plane


def rim_centre(img, cx, cy, rmin, rmax):
    angles = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    radii = np.arange(rmin, rmax, 0.25)
    rows = np.arange(len(angles))
    for _ in range(3):
        xs = cx + np.outer(np.cos(angles), radii)
        ys = cy + np.outer(np.sin(angles), radii)
        v = map_coordinates(img, [ys, xs], order=1)
        k = np.clip(v.argmax(1), 1, len(radii) - 2)
        lo, mid, hi = v[rows, k - 1], v[rows, k], v[rows, k + 1]
        curvature = lo - 2 * mid + hi
        offset = np.where(curvature < 0, 0.5 * (lo - hi) / np.where(curvature < 0, curvature, -1), 0)
        r = radii[k] + 0.25 * offset
        px, py = cx + r * np.cos(angles), cy + r * np.sin(angles)
        a = np.c_[2 * px, 2 * py, np.ones_like(px)]
        b = px ** 2 + py ** 2
        sol = np.linalg.lstsq(a, b, rcond=None)[0]
        radius = np.sqrt(sol[2] + sol[0] ** 2 + sol[1] ** 2)
        off = np.abs(np.hypot(px - sol[0], py - sol[1]) - radius)
        keep = off < np.quantile(off, 0.8)
        sol = np.linalg.lstsq(a[keep], b[keep], rcond=None)[0]
        cx, cy = sol[0], sol[1]
    return cx, cy, np.sqrt(sol[2] + cx ** 2 + cy ** 2)


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    movie, csv = sys.argv[1], sys.argv[2]
    rmin, rmax = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) == 5 else (20.0, 45.0)
    spots = pd.read_csv(csv)
    rows = []
    for t, img in enumerate(frames(movie)):
        for _, s in spots[spots.FRAME == t].iterrows():
            x, y, r = rim_centre(img, s.POSITION_X, s.POSITION_Y, rmin, rmax)
            rows.append((t, s.POSITION_X, s.POSITION_Y, x, y, r))
    m = pd.DataFrame(rows, columns=['frame', 'x', 'y', 'rim_x', 'rim_y', 'rim_r'])
    dx, dy = m.x - m.rim_x, m.y - m.rim_y
    print(f'{len(m)} spots; rim radius {m.rim_r.mean():.2f} px')
    print(f'spot - rim centre: mean {dx.mean():+.3f} {dy.mean():+.3f} px', end='')
    if len(m) < 3:
        print()
        return
    print(f', rms about it {dx.std():.3f} {dy.std():.3f} px')
    print(f'frame-to-frame motion (rms): spots {np.diff(m.x).std():.3f} {np.diff(m.y).std():.3f} px, rim centres '
          f'{np.diff(m.rim_x).std():.3f} {np.diff(m.rim_y).std():.3f} px')


if __name__ == '__main__':
    main()
