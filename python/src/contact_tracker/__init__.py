"""Contact Tracker in Python: sub-pixel centres of colloidal particles, also when they touch.

trackpy's idiom over Contact Tracker's Java engine, run in this process through JPype:

    import contact_tracker as ct
    spots = ct.batch(frames)               # a numpy stack, or any sequence of 2D frames (a PIMS reader)
    spot = ct.locate(image, threshold=186, r_out=43)

The result is a pandas DataFrame with trackpy's columns where they mean the same (`x`, `y`, `frame`, `mass`,
`ep`), so it goes straight into `trackpy.link`, plus the tracker's own (`sigma_x`, `sigma_y`, `kind`, each flag
as a boolean column, ...), and the settings used in `df.attrs["settings"]`. Settings have the command line's
names (`threshold`, `r_out`, `min_area`, `method`, `diameter`, `kinds`, `particles`, ...); those not given are
measured on the first frame by the profile helper, as `contact-tracker track` does. Bad input raises ValueError
with the tracker's one-line message.
"""
import numpy as np
import pandas as pd

from . import _java

__all__ = ["locate", "batch", "profile", "pair_potential", "settings"]

# Our column keys (the CSV's) -> the DataFrame's names; trackpy's names where they mean the same.
_NAMES = {
    "FRAME": "frame", "POSITION_X": "x", "POSITION_Y": "y", "RADIUS": "radius", "QUALITY": "quality",
    "FIRST_PASS_X": "first_pass_x", "FIRST_PASS_Y": "first_pass_y", "SIGMA_X": "sigma_x", "SIGMA_Y": "sigma_y",
    "ACTIVE_AREA": "active_area", "ACTIVE_RADIUS": "active_radius", "SECOND_AREA": "second_area",
    "ITERATIONS": "iterations", "KIND": "kind",
}
_INTEGER = {"FRAME", "ACTIVE_AREA", "SECOND_AREA", "ITERATIONS", "KIND"}
_FLAG = "FLAG_"
# trackpy's column order first
_ORDER = ["y", "x", "mass", "ep", "frame"]


def settings():
    """The tracking settings: {name: (default, help)}, from the tracker's one descriptor of them."""
    with _java.errors():
        ts = _java.cls("settings.TrackingSettings")
        return {str(s.name()): (None if s.isImageSpecific() else _value(s.defaultValue()), str(s.help()))
                for s in ts.ALL}


def _value(v):
    """A Java setting value as Python's int, float or str."""
    text = str(v)
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _planes(frames):
    """The frames as Java arrays, one per frame, of the pixel type ImageJ would hold them in; the frames' width,
    height and numbers (PIMS's frame_no where every frame has one, as trackpy takes it, else 0, 1, ...)."""
    import jpype
    numbers = None
    if isinstance(frames, np.ndarray):
        stack = frames[None] if frames.ndim == 2 else frames
    else:
        try:
            listed = list(frames)  # one pass: a PIMS reader decodes each frame once
        except TypeError:
            raise ValueError(f"frames must be a 2D image, a 3D stack or a sequence of 2D frames, not "
                             f"{type(frames).__name__}") from None
        if not listed:
            raise ValueError("no frame given")
        numbered = [getattr(f, "frame_no", None) for f in listed]
        if all(isinstance(v, (int, np.integer)) for v in numbered):
            numbers = np.asarray(numbered, dtype=np.int64)
        stack = [np.asarray(f) for f in listed]
        shapes = {f.shape for f in stack}
        if len(shapes) > 1:
            raise ValueError(f"the frames differ in size: {sorted(shapes)}")
        if stack[0].ndim != 2:
            raise ValueError(f"a frame must be 2D (height x width), not of shape {stack[0].shape}"
                             + (" (colour: pass one channel, e.g. frame[..., 1])" if stack[0].ndim == 3
                                and stack[0].shape[-1] in (3, 4) else ""))
        stack = np.stack(stack)
    if stack.ndim != 3:
        raise ValueError(f"an image must be 2D or a 3D stack of 2D frames, not of shape {frames.shape}"
                         + (" (colour: pass one channel, e.g. image[..., 1])" if frames.ndim in (3, 4)
                            and frames.shape[-1] in (3, 4) else ""))
    if stack.shape[0] == 0 or stack.shape[1] == 0 or stack.shape[2] == 0:
        raise ValueError(f"an empty image (shape {stack.shape})")
    if stack.dtype.kind not in "uif":
        raise ValueError(f"pixels must be numbers, not {stack.dtype}")
    _java.start()
    n, h, w = stack.shape
    # as ImageJ holds them: 8 and 16-bit unsigned as they are, everything else as 32-bit float
    if stack.dtype == np.uint8:
        flat, jtype = np.ascontiguousarray(stack).reshape(n, h * w).view(np.int8), jpype.JByte
    elif stack.dtype == np.uint16:
        flat, jtype = np.ascontiguousarray(stack).reshape(n, h * w).view(np.int16), jpype.JShort
    else:
        flat, jtype = np.ascontiguousarray(stack, dtype=np.float32).reshape(n, h * w), jpype.JFloat
    planes = jpype.JArray(jpype.JObject)(n)
    for t in range(n):
        planes[t] = jpype.JArray(jtype)(flat[t])
    return planes, w, h, numbers if numbers is not None else np.arange(n, dtype=np.int64)


def batch(frames, threads=0, **settings):
    """Localizes the particles of every frame, in one run of the tracker (the particles' profile and kinds measured
    over the whole movie, as `contact-tracker track` does).

    frames: a 3D numpy stack (frames x height x width), or any sequence of 2D frames (a PIMS reader, a list).
    threads: worker threads (0: one per processor).
    settings: the command line's settings by name (`threshold=186, r_out=43, method="paper"`), see settings().
    Returns a DataFrame, a row per spot: x, y (px, pixel (0, 0)'s centre at 0, 0), frame, mass (brightness above
    the threshold within `radius` of the centre), ep (the rms of sigma_x and sigma_y, px), then the tracker's
    columns; the settings used in df.attrs["settings"].
    """
    planes, w, h, numbers = _planes(frames)
    return _track(planes, w, h, numbers, threads, settings)


def locate(image, threads=0, **settings):
    """Localizes the particles of one 2D image; as batch(), the `frame` column 0 (or the image's PIMS frame_no)."""
    image_array = np.asarray(image)
    if image_array.ndim != 2:
        raise ValueError(f"locate takes one 2D image (height x width), not shape {image_array.shape}: batch takes "
                         "stacks")
    planes, w, h, _ = _planes(image_array)
    number = getattr(image, "frame_no", 0)
    return _track(planes, w, h, np.asarray([number if isinstance(number, (int, np.integer)) else 0]), threads,
                  settings)


def _track(planes, w, h, numbers, threads, settings):
    import jpype
    given = jpype.JClass("java.util.LinkedHashMap")()
    for name, value in settings.items():
        given.put(name, str(value))
    with _java.errors():
        frames = _java.cls("pipeline.PixelPlanes")(planes, w, h)
        table = _java.cls("pipeline.ColumnTracking").track(frames, "frames", given, int(threads))
    data = {}
    for key, column in zip(table.keys(), table.columns()):
        key = str(key)
        values = np.asarray(column)
        if key.startswith(_FLAG):
            data[key[len(_FLAG):].lower()] = values != 0
        elif key in _NAMES:
            data[_NAMES[key]] = values.astype(np.int64) if key in _INTEGER else values
    data["frame"] = numbers[data["frame"]]
    data["mass"] = np.asarray(table.mass())
    data["ep"] = np.sqrt((data["sigma_x"] ** 2 + data["sigma_y"] ** 2) / 2)
    names = _ORDER + [c for c in data if c not in _ORDER]
    df = pd.DataFrame({c: data[c] for c in names})
    df.attrs["settings"] = {str(k): _value(v) for k, v in table.settings().items()}
    df.attrs["measured"] = [str(s) for s in table.measured()]
    df.attrs["notice"] = str(table.notice())
    df.attrs["summary"] = str(table.summary())
    df.attrs["warnings"] = [str(s) for s in table.warnings()]
    return df


def profile(image, frame=0, diameter=0.0, max_radius=0.0, particles=None):
    """The profile helper's report on one frame (of an image or a stack), as `contact-tracker profile` prints it.

    Returns a dict: the suggested settings (`threshold`, `r_out`, `diameter`, `min_area`, `particles`, to pass to
    locate/batch), the radial profile (`radius`, `level`, `count` as numpy arrays), `background`, `noise`,
    `peak`, `centres` (x, y of the particles profiled), `lines` (the report's text) and `warnings`.
    """
    if isinstance(image, np.ndarray) and image.ndim == 2:
        window, first = image, 0
    else:
        # only the frames the helper reads: the frame and the next four (earlier ones near the end)
        try:
            n = len(image)
        except TypeError:
            raise ValueError(f"profile takes a 2D image, a 3D stack or a sequence of frames, not "
                             f"{type(image).__name__}") from None
        if not 0 <= frame < n:
            raise ValueError(f"frame {frame} does not exist: there {'is 1 frame' if n == 1 else f'are {n} frames'}"
                             " (counted from 0)")
        kind_frames = int(_java.cls("advisor.ProfileAnalysis").KIND_FRAMES)
        first = max(0, min(frame, n - kind_frames))
        window = image[first:first + kind_frames]
    planes, w, h, _ = _planes(window)
    with _java.errors():
        frames = _java.cls("pipeline.PixelPlanes")(planes, w, h)
        report = _java.cls("pipeline.ProfileSummary").of(frames, int(frame) - first, float(diameter),
                                                         float(max_radius), particles)
        out = {}
        for k, v in report.items():
            k = str(k)
            if k in ("radius", "level", "count"):
                out[k] = np.asarray(v)
            elif k == "centres":
                out[k] = np.asarray([[c[0], c[1]] for c in v], dtype=float).reshape(-1, 2)
            elif k in ("lines", "warnings"):
                out[k] = [str(s) for s in v]
            elif k == "frame":
                out[k] = int(v) + first
            elif k == "diameter_estimated":
                out[k] = str(v) == "true"
            else:
                out[k] = _value(v)
    return out


def pair_potential(spots, bin, r_max, width=None, height=None, start_frame=0, flagged="drop", zero=None):
    """g(r) and U(r)/kT with their errors from spots (a DataFrame of locate/batch, or any with x, y, frame and
    optional boolean flag columns), by the tracker's Java code (as `contact-tracker potential`).

    bin, r_max: bin width and largest r, in the spots' units. width, height: the field of view (both or neither;
    else inferred from the spots). start_frame: leave out earlier frames. flagged: "drop" (spots with a warning
    flag left out) or "keep". zero: (from, to), a range of r where U is set to 0 on average (where the particles
    no longer interact).
    Returns a DataFrame, a row per bin: r, r_low, r_high, pairs, expected, g, g_error, u, u_error.
    """
    if flagged not in ("drop", "keep"):
        raise ValueError(f"flagged must be drop or keep, not '{flagged}'")
    if (width is None) != (height is None):
        raise ValueError("give both width and height of the field of view, or neither (then it is inferred from "
                         "the spots)")
    if not isinstance(spots, pd.DataFrame):
        raise ValueError(f"spots must be a DataFrame (of locate or batch), not {type(spots).__name__}")
    missing = [c for c in ("x", "y", "frame") if c not in spots.columns]
    if missing:
        raise ValueError(f"spots lack the column{'s' if len(missing) > 1 else ''} {', '.join(missing)}")
    import jpype
    _java.start()
    spot_set = _java.cls("potential.SpotSet")
    columns = jpype.JClass("java.util.LinkedHashMap")()
    double_array = jpype.JArray(jpype.JDouble)
    columns.put(spot_set.X, double_array(np.ascontiguousarray(spots["x"], dtype=np.float64)))
    columns.put(spot_set.Y, double_array(np.ascontiguousarray(spots["y"], dtype=np.float64)))
    columns.put(spot_set.FRAME, double_array(np.ascontiguousarray(spots["frame"], dtype=np.float64)))
    flag_names = [str(f.name()) for f in _java.cls("core.Flag").values()]
    for name in flag_names:
        if name.lower() in spots.columns:
            columns.put(spot_set.FLAG_PREFIX + name, double_array(
                np.ascontiguousarray(spots[name.lower()], dtype=np.float64)))
    with _java.errors():
        selection = spot_set.Selection(int(start_frame), flagged == "drop")
        chosen = spot_set.fromColumns(columns, selection)
        if chosen.size() == 0:
            raise ValueError(f"no spot left ({chosen.flaggedLeftOut()} flagged, {chosen.earlyLeftOut()} before the "
                             "start frame)")
        fov = _java.cls("potential.FieldOfView")
        # the field as the command line's potential takes it (one rule: SpotSet.inferredField)
        field = fov.of(float(width), float(height)) if width is not None else chosen.inferredField()
        result = _java.cls("potential.PairCorrelation").compute(chosen, field, float(bin), float(r_max))
        if zero is not None:
            low, high = zero
            result = result.withZero(float(low), float(high))
        bins = list(result.bins())
        rows = {
            "r": [b.r() for b in bins], "r_low": [b.rLow() for b in bins], "r_high": [b.rHigh() for b in bins],
            "pairs": [int(b.pairs()) for b in bins], "expected": [b.expected() for b in bins],
            "g": [b.g() for b in bins], "g_error": [b.gError() for b in bins],
            "u": [result.u(i) for i in range(len(bins))], "u_error": [b.uError() for b in bins],
        }
        df = pd.DataFrame({k: np.asarray(v, dtype=np.int64 if k == "pairs" else np.float64) for k, v in rows.items()})
        df.attrs.update(frames=int(result.frames()), spots=int(result.spots()), field=(field.width(), field.height()),
                        field_inferred=bool(field.inferred()), flagged_left_out=int(chosen.flaggedLeftOut()))
    return df
