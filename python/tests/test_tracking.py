"""ct.locate and ct.batch: the same spots as `contact-tracker track`, trackpy's columns, any sequence of frames."""
import numpy as np
import pandas as pd
import pytest

import contact_tracker as ct

# the package's columns and track's CSV columns that hold the same values
SAME = {"x": "POSITION_X", "y": "POSITION_Y", "frame": "FRAME", "radius": "RADIUS", "quality": "QUALITY",
        "first_pass_x": "FIRST_PASS_X", "first_pass_y": "FIRST_PASS_Y", "sigma_x": "SIGMA_X", "sigma_y": "SIGMA_Y",
        "active_area": "ACTIVE_AREA", "active_radius": "ACTIVE_RADIUS", "second_area": "SECOND_AREA",
        "iterations": "ITERATIONS", "kind": "KIND"}
FLAGS = ["second_pass", "fell_back", "degenerate", "at_border", "merged", "not_converged", "unmodelled_neighbour"]


def test_batch_gives_tracks_spots_to_the_last_digit(movie, tracked):
    frames, _ = movie
    ref, err = tracked
    df = ct.batch(frames)
    assert len(df) == len(ref) == 3 * len(frames)
    for ours, theirs in SAME.items():
        # track writes Double.toString, which reads back to the same double: equal, not close
        assert np.array_equal(df[ours].to_numpy(), ref[theirs].to_numpy()), ours
    for flag in FLAGS:
        assert df[flag].dtype == bool
        assert np.array_equal(df[flag].to_numpy(), ref["FLAG_" + flag.upper()].to_numpy() == 1), flag
    # the settings measured as track measured them
    s = df.attrs["settings"]
    measured = f"--threshold {s['threshold']:g} --r-out {s['r_out']:g} --diameter {s['diameter']:g}"
    assert measured in err, (measured, err)
    assert df.attrs["measured"] == ["threshold", "r_out", "diameter"]


def test_trackpy_columns(movie):
    frames, _ = movie
    df = ct.batch(frames, threshold=85, r_out=61)
    assert list(df.columns[:5]) == ["y", "x", "mass", "ep", "frame"]
    assert df["frame"].dtype == np.int64 and sorted(set(df["frame"])) == list(range(len(frames)))
    assert np.allclose(df["ep"], np.sqrt((df["sigma_x"] ** 2 + df["sigma_y"] ** 2) / 2))
    assert (df["mass"] > 0).all()
    assert df.attrs["settings"]["threshold"] == 85.0 and df.attrs["settings"]["r_out"] == 61.0
    assert df.attrs["measured"] == ["diameter"]


def test_locate_is_batch_of_one_frame(movie):
    frames, _ = movie
    one = ct.locate(frames[2], threshold=85, r_out=61, diameter=65)
    assert len(one) == 3 and (one["frame"] == 0).all()
    alone = ct.batch(frames[2:3], threshold=85, r_out=61, diameter=65)
    assert np.array_equal(one["x"].to_numpy(), alone["x"].to_numpy())


def test_any_sequence_of_frames(movie):
    """A list of frames, and PIMS frames whose frame_no numbers them (as trackpy takes it)."""
    import pims
    frames, _ = movie
    settings = dict(threshold=85, r_out=61, diameter=65)
    stack = ct.batch(frames, **settings)
    listed = ct.batch(list(frames), **settings)
    pd.testing.assert_frame_equal(stack, listed)
    numbered = ct.batch([pims.Frame(f, frame_no=10 + i) for i, f in enumerate(frames)], **settings)
    assert np.array_equal(numbered["frame"].to_numpy(), stack["frame"].to_numpy() + 10)
    assert np.array_equal(numbered["x"].to_numpy(), stack["x"].to_numpy())


def test_pixel_types(movie):
    """16-bit, float32 and float64 frames of the same values: the same centres as 8-bit ones."""
    frames, _ = movie
    settings = dict(threshold=85, r_out=61, diameter=65)
    x8 = ct.batch(frames, **settings)["x"].to_numpy()
    for dtype in (np.uint16, np.float32, np.float64, np.int32):
        assert np.array_equal(ct.batch(frames.astype(dtype), **settings)["x"].to_numpy(), x8), dtype


def test_dark_particles_are_measured_as_dark(movie):
    """The movie inverted: taken for dark particles, inverted back (255 - v), the same spots as the movie's."""
    frames, _ = movie
    dark = ct.batch(255 - frames, r_out=61, diameter=65)
    assert dark.attrs["settings"]["particles"] == "dark" and "particles" in dark.attrs["measured"]
    bright = ct.batch(frames, r_out=61, diameter=65, threshold=dark.attrs["settings"]["threshold"])
    assert np.array_equal(dark["x"].to_numpy(), bright["x"].to_numpy())


def test_trackpy_links_the_output(movie):
    import trackpy as tp
    tp.quiet()
    frames, _ = movie
    linked = tp.link(ct.batch(frames, threshold=85, r_out=61), search_range=10)
    assert linked["particle"].nunique() == 3
    assert (linked.groupby("particle")["frame"].nunique() == len(frames)).all()
