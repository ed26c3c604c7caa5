"""Bad input: a Python exception with the tracker's one-line message, never a Java stack trace."""
import numpy as np
import pandas as pd
import pytest

import contact_tracker as ct


def one_line(excinfo):
    message = str(excinfo.value)
    assert "\n" not in message and "java." not in message and " at " not in message, message
    e = excinfo.value
    assert e.__cause__ is None and (e.__context__ is None or e.__suppress_context__), "a Java exception chained"
    return message


@pytest.mark.parametrize("settings, message", [
    (dict(r_out=-1), "r_out must be a positive number of pixels, not -1.0"),
    (dict(method="best"), "method must be one of "),
    (dict(min_area="many"), "min_area must be a whole number, not 'many'"),
    (dict(threshold=300, r_out=61, diameter=65), "threshold 300 is outside the data range"),
    (dict(rout=40), "unknown setting 'rout': the settings are threshold, r_out, min_area"),
])
def test_bad_settings(movie, settings, message):
    frames, _ = movie
    with pytest.raises(ValueError) as e:
        ct.batch(frames[:2], **settings)
    assert message in one_line(e)


@pytest.mark.parametrize("frames, message", [
    (np.zeros(10, np.uint8), "an image must be 2D or a 3D stack of 2D frames, not of shape (10,)"),
    (np.zeros((4, 5, 6, 3), np.uint8), "(colour: pass one channel, e.g. image[..., 1])"),
    ([np.zeros((4, 5)), np.zeros((5, 4))], "the frames differ in size"),
    ([], "no frame given"),
    (np.array([["a", "b"]]), "pixels must be numbers, not <U1"),
    (np.zeros((0, 5), np.uint8), "an empty image"),
    (42, "frames must be a 2D image, a 3D stack or a sequence of 2D frames, not int"),
])
def test_bad_frames(frames, message):
    with pytest.raises(ValueError) as e:
        ct.batch(frames, threshold=1, r_out=5)
    assert message in one_line(e)


def test_nan_pixel_named():
    image = np.full((40, 40), 10.0)
    image[3, 7] = np.nan
    with pytest.raises(ValueError) as e:
        ct.locate(image, threshold=5, r_out=5)
    assert "frame 1, pixel (7, 3) is NaN" in one_line(e)


def test_nothing_to_measure_is_a_value_error():
    with pytest.raises(ValueError) as e:
        ct.locate(np.full((60, 60), 7, np.uint8))
    assert "cannot measure the particles" in one_line(e) and "no blob" in one_line(e)


def test_locate_refuses_a_stack(movie):
    frames, _ = movie
    with pytest.raises(ValueError) as e:
        ct.locate(frames)
    assert "locate takes one 2D image" in one_line(e)


def test_pair_potential_bad_input():
    spots = pd.DataFrame({"x": [1.0, 2.0], "y": [1.0, 2.0], "frame": [0, 0]})
    with pytest.raises(ValueError) as e:
        ct.pair_potential(spots.drop(columns="frame"), bin=1, r_max=5)
    assert one_line(e) == "spots lack the column frame"
    with pytest.raises(ValueError) as e:
        ct.pair_potential(spots, bin=1, r_max=5, width=10)
    assert "give both width and height" in one_line(e)
    with pytest.raises(ValueError) as e:
        ct.pair_potential(spots, bin=-1, r_max=5)
    one_line(e)
