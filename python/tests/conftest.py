"""Shared material: a simulated movie made by the tracker's own `simulate` command (a touching triple), written
again as a plain TIFF (pixel units), and `contact-tracker track`'s CSV of it, to compare the package against."""
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import tifffile

from contact_tracker import _java


def java():
    """The `java` executable of the runtime the package uses."""
    return str(Path(_java.java_home()) / "bin" / "java")


def cli(*args, cwd):
    """Runs the command line of the jar the package carries; returns its stdout and stderr."""
    r = subprocess.run([java(), "-Djava.awt.headless=true", "-jar", str(_java.JAR), *map(str, args)], cwd=cwd,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout, r.stderr


def lab(*args, cwd):
    """Runs the lab's command line (the simulator lives in the -lab.jar beside the cli jar in target/)."""
    jar = next((Path(__file__).resolve().parents[2] / "target").glob("Contact_Tracker-*-lab.jar"))
    r = subprocess.run([java(), "-Djava.awt.headless=true", "-jar", str(jar), *map(str, args)], cwd=cwd,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout, r.stderr


@pytest.fixture(scope="session")
def movie(tmp_path_factory):
    """(frames as uint8 numpy stack, path of a plain TIFF of them): a touching triple, 6 frames."""
    d = tmp_path_factory.mktemp("movie")
    lab("simulate", "--scenario", "triple", "--separation", "1.0", "--frames", "6", "--out", "sim.tif",
        "--truth", "truth.csv", cwd=d)
    frames = tifffile.imread(d / "sim.tif")
    plain = d / "plain.tif"
    tifffile.imwrite(plain, frames)  # no calibration: track writes pixels
    return frames, plain


@pytest.fixture(scope="session")
def tracked(movie):
    """track's CSV of the movie (settings measured) as a DataFrame, and what it said on stderr."""
    frames, plain = movie
    csv = plain.with_name("track.csv")
    _, err = cli("track", plain, "--csv", csv, "--no-progress", cwd=plain.parent)
    return pd.read_csv(csv), err
