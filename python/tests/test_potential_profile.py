"""ct.pair_potential (the tracker's g(r) and U(r)) and ct.profile (the helper's report)."""
import numpy as np
import pandas as pd

import contact_tracker as ct
from conftest import cli


def test_ideal_gas_has_no_potential():
    """Uniformly random positions (no interaction): g(r) = 1 and U(r) = 0 within their errors."""
    rng = np.random.default_rng(5)
    frames, n, side = 200, 60, 400.0
    spots = pd.DataFrame({"x": rng.uniform(0, side, frames * n), "y": rng.uniform(0, side, frames * n),
                          "frame": np.repeat(np.arange(frames), n)})
    u = ct.pair_potential(spots, bin=5, r_max=60, width=side, height=side)
    assert list(u.columns) == ["r", "r_low", "r_high", "pairs", "expected", "g", "g_error", "u", "u_error"]
    assert len(u) == 12 and u.attrs["frames"] == frames and u.attrs["spots"] == frames * n
    assert (np.abs(u["g"] - 1) < 4 * u["g_error"]).all(), u
    assert (np.abs(u["u"]) < 4 * u["u_error"]).all(), u


def test_same_as_the_potential_command(tmp_path):
    """The same table as `contact-tracker potential` on the same spots, flagged spots dropped by both."""
    rng = np.random.default_rng(8)
    frames, n = 50, 40
    spots = pd.DataFrame({"x": rng.uniform(0, 300, frames * n), "y": rng.uniform(0, 300, frames * n),
                          "frame": np.repeat(np.arange(frames), n),
                          "at_border": rng.uniform(size=frames * n) < 0.1})
    csv = tmp_path / "spots.csv"
    pd.DataFrame({"FRAME": spots["frame"], "POSITION_X": spots["x"].map(repr), "POSITION_Y": spots["y"].map(repr),
                  "FLAG_AT_BORDER": spots["at_border"].astype(int)}).to_csv(csv, index=False)
    cli("potential", csv, "--bin", "6", "--r-max", "90", "--csv", tmp_path / "u.csv", cwd=tmp_path)
    theirs = pd.read_csv(tmp_path / "u.csv")
    ours = ct.pair_potential(spots, bin=6, r_max=90)
    assert ours.attrs["flagged_left_out"] == int(spots["at_border"].sum())
    assert len(theirs) == len(ours)
    assert np.array_equal(ours["pairs"], theirs["PAIRS"])
    assert np.allclose(ours["g"], theirs["G"], rtol=1e-12, equal_nan=True)
    assert np.allclose(ours["u"], theirs["U_KT"], rtol=1e-12, equal_nan=True)
    assert np.allclose(ours["u_error"], theirs["U_KT_ERR"], rtol=1e-12, equal_nan=True)


def test_profile_suggests_what_batch_measures(movie, tracked):
    frames, _ = movie
    report = ct.profile(frames)
    df = ct.batch(frames)
    for name in ("threshold", "r_out", "diameter", "particles"):
        assert report[name] == df.attrs["settings"][name], name
    assert report["particles_profiled"] == len(report["centres"]) == 3
    assert len(report["radius"]) == len(report["level"]) == len(report["count"]) > 10
    assert any("r_out =" in line for line in report["lines"])
    # the command line's profile of the same frames suggests the same values
    out, _ = cli("profile", movie[1], cwd=movie[1].parent)
    assert f"--threshold {report['threshold']:g} --r-out {report['r_out']:g}" in out.splitlines()[-1]


def test_profile_of_a_later_frame_is_the_command_lines(movie):
    """Frame 5 (0-based) of 6: the helper reads it and the four before; the same suggestion as 'profile --frame 6'."""
    frames, plain = movie
    report = ct.profile(list(frames), frame=5)
    assert report["frame"] == 5
    out, _ = cli("profile", plain, "--frame", 6, cwd=plain.parent)
    assert f"--threshold {report['threshold']:g} --r-out {report['r_out']:g} --diameter {report['diameter']:g}" \
        in out.splitlines()[-1]
