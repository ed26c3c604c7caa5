#!/usr/bin/env python3
"""One channel of a colour movie against the mean of its three, on the paper authors' own colour footage.

The authors' toolbox (GitHub yucelharun/mpostracker) ships a saved project, singleParticle.mPos, that holds the first
frame of their colour movie singleParticle.avi (a trapped particle, in red). This script moves that frame along a
known random path (an Ornstein-Uhlenbeck walk of 1.5 px, sub-pixel shifts by cubic splines, noise of 1.5 grey
levels per channel), writes it as an uncompressed RGB AVI, and as the grey AVI of each frame's mean of red, green
and blue (what ImageJ's 8-bit conversion makes), tracks the red channel of the first (--channel 1) and the second
with scripts/contact-tracker at the values it measures itself, and prints each one's rms distance from the truth
(after the common offset: the profile's centre need not be the frame's).

  scripts/colour-check.py singleParticle.mPos [--frames 300] [--work DIR]

Needs numpy, scipy and av (PyAV). The movies are written to a temporary folder (or --work).
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import av
import numpy as np
import scipy.io
from scipy import ndimage

here = os.path.dirname(os.path.abspath(__file__))


def write_avi(path, frames, pix_fmt):
    out = av.open(path, 'w')
    stream = out.add_stream('rawvideo', rate=35)
    stream.height, stream.width = frames[0].shape[:2]
    stream.pix_fmt = 'bgr24' if pix_fmt == 'rgb24' else 'gray'
    for f in frames:
        for p in stream.encode(av.VideoFrame.from_ndarray(f, format=pix_fmt)):
            out.mux(p)
    for p in stream.encode():
        out.mux(p)
    out.close()


def errors(csv_path, truth):
    rows = list(csv.DictReader(open(csv_path)))
    by_frame = {}
    for r in rows:
        by_frame.setdefault(int(r['FRAME']), []).append(r)
    d = np.array([(float(r[0]['POSITION_X']) - truth[t, 0], float(r[0]['POSITION_Y']) - truth[t, 1])
                  for t, r in sorted(by_frame.items()) if len(r) == 1 and r[0]['FLAG_MERGED'] == '0'])
    d -= d.mean(axis=0)
    return len(rows), len(d), np.sqrt((d ** 2).mean(axis=0))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('mpos', help="the authors' saved project singleParticle.mPos")
    ap.add_argument('--frames', type=int, default=300)
    ap.add_argument('--work', help='folder for the movies (default: a temporary one)')
    a = ap.parse_args()
    first = scipy.io.loadmat(a.mpos, squeeze_me=True, struct_as_record=False)['ss'].A6.astype(float)
    rng = np.random.default_rng(1)
    truth = np.zeros((a.frames, 2))
    c = np.exp(-1 / 10)
    for t in range(1, a.frames):
        truth[t] = c * truth[t - 1] + np.sqrt(1 - c * c) * 1.5 * rng.standard_normal(2)
    colour, grey = [], []
    for t in range(a.frames):
        f = np.empty_like(first)
        for ch in range(3):
            bg = np.median(first[..., ch])
            f[..., ch] = ndimage.shift(first[..., ch] - bg, (truth[t, 1], truth[t, 0]), order=3, mode='constant') + bg
        f = np.clip(np.round(f + rng.normal(0, 1.5, f.shape)), 0, 255).astype(np.uint8)
        colour.append(f)
        grey.append(np.floor((f.astype(int).sum(axis=2) + 1) / 3).astype(np.uint8))
    with tempfile.TemporaryDirectory() as tmp:
        work = a.work or tmp
        os.makedirs(work, exist_ok=True)
        runs = [('red channel (--channel 1)', 'colour.avi', colour, 'rgb24', ['--channel', '1']),
                ('mean of red, green, blue', 'mean.avi', grey, 'gray', [])]
        print('%d frames of %d x %d; truth: a walk of 1.5 px rms' % (a.frames, first.shape[1], first.shape[0]))
        for label, name, frames, fmt, extra in runs:
            movie = os.path.join(work, name)
            write_avi(movie, frames, fmt)
            out = os.path.join(work, name + '.csv')
            subprocess.run([os.path.join(here, 'contact-tracker'), 'track', movie, '--csv', out] + extra, check=True,
                           stdout=subprocess.DEVNULL)
            spots, used, rms = errors(out, truth)
            print('%-28s %4d spots, %4d single unflagged: rms error x %.4f px, y %.4f px' % (label, spots, used,
                                                                                          rms[0], rms[1]))


if __name__ == '__main__':
    sys.exit(main())
