#!/usr/bin/env python3
"""Draws the spots of one frame on that frame, to look at: unflagged spots green, flagged ones red.

Usage: scripts/overlay.py MOVIE SPOTS.csv FRAME OUT.png [--zoom Z] [--pixel-size UM]

MOVIE is what `contact-tracker track` read (a TIFF stack, a folder of images, one image, or an AVI); SPOTS.csv its
spot table; FRAME the 0-based frame (the table's FRAME column). Each spot is a dot at its centre and a circle of its
RADIUS; a spot is flagged when any FLAG_ column but FLAG_SECOND_PASS is set. The frame is scaled to its 0.5 and 99.5
percentiles and enlarged Z times (default 3, nearest neighbour). The table's positions are in the movie's
calibrated units: --pixel-size gives the units a pixel (default: the TIFF's own ImageJ calibration where it has
one, else 1). Needs numpy and Pillow; tifffile for TIFF stacks; imageio with imageio-ffmpeg for AVI.
"""
import argparse
import importlib.util
import os
import sys

# the spot table read, and the flags that count, as scripts/compare-spots.py does for every script
_spec = importlib.util.spec_from_file_location("compare_spots", os.path.join(os.path.dirname(os.path.abspath(
    __file__)), "compare-spots.py"))
compare = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare)


def frame_of(movie, index):
    """The frame `index` of the movie as a 2-D float array, and the TIFF's pixel size (or None)."""
    import numpy as np
    from PIL import Image
    if os.path.isdir(movie):
        names = sorted(n for n in os.listdir(movie) if not n.startswith("."))
        return np.asarray(Image.open(os.path.join(movie, names[index])).convert("F")), None
    lower = movie.lower()
    if lower.endswith((".tif", ".tiff")):
        try:
            return _tiff_frame(movie, index)
        except (ImportError, ValueError, KeyError):  # (a compression tifffile cannot decode without imagecodecs)
            image = Image.open(movie)
            image.seek(index)
            return np.asarray(image.convert("F")), None
    if lower.endswith(".avi"):
        import imageio.v3 as iio
        data = np.asarray(iio.imread(movie, index=index), float)
        return (data.mean(axis=-1) if data.ndim == 3 else data), None
    return np.asarray(Image.open(movie).convert("F")), None


def _tiff_frame(movie, index):
    """A TIFF's frame by tifffile, with its ImageJ calibration (units a pixel) where it has one."""
    import numpy as np
    import tifffile
    with tifffile.TiffFile(movie) as tif:
        data = tif.asarray()
        size = None
        page = tif.pages[0]
        meta = tif.imagej_metadata or {}
        res = page.tags.get("XResolution")
        if meta.get("unit") not in (None, "pixel", "") and res is not None and res.value[0]:
            size = res.value[1] / res.value[0]
        colour = page.samplesperpixel > 1
    data = np.asarray(data, float)
    if colour:
        data = data.mean(axis=-1)  # the mean of the channels, as track reads colour frames
    return data.reshape((-1,) + data.shape[-2:])[index], size


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("movie")
    parser.add_argument("spots")
    parser.add_argument("frame", type=int)
    parser.add_argument("out")
    parser.add_argument("--zoom", type=float, default=3)
    parser.add_argument("--pixel-size", type=float)
    args = parser.parse_args()
    if args.frame < 0 or not args.zoom > 0 or args.pixel_size is not None and not args.pixel_size > 0:
        parser.error("FRAME must be 0 or more, --zoom and --pixel-size positive")
    import numpy as np
    from PIL import Image, ImageDraw
    try:
        img, size = frame_of(args.movie, args.frame)
    except (IndexError, OSError, ValueError) as e:
        sys.exit(f"overlay.py: cannot read frame {args.frame} of {args.movie}: {e}")
    unit = args.pixel_size or size or 1.0
    lo, hi = np.percentile(img, [0.5, 99.5])
    grey = np.clip((img - lo) / max(hi - lo, 1e-12) * 255, 0, 255).astype(np.uint8)
    h, w = grey.shape
    z = args.zoom
    picture = Image.fromarray(grey).resize((round(w * z), round(h * z)), Image.NEAREST).convert("RGB")
    draw = ImageDraw.Draw(picture)
    spots = flagged = 0
    for row in compare.rows(args.spots):
        if int(float(row["FRAME"])) != args.frame:
            continue
        bad = bool(compare.flags_set(row))
        x, y = float(row["POSITION_X"]) / unit, float(row["POSITION_Y"]) / unit
        r = float(row.get("RADIUS") or 0) / unit
        colour = (255, 40, 40) if bad else (40, 230, 40)
        cx, cy = (x + 0.5) * z, (y + 0.5) * z
        if r > 0:
            draw.ellipse([cx - r * z, cy - r * z, cx + r * z, cy + r * z], outline=colour)
        draw.ellipse([cx - 1.5, cy - 1.5, cx + 1.5, cy + 1.5], fill=colour)
        spots += 1
        flagged += bad
    picture.save(args.out)
    print(f"{args.out}: frame {args.frame}, {spots} spots, {flagged} flagged (red), pixel {unit:g} units")


if __name__ == "__main__":
    main()
