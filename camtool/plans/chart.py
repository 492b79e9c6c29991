"""Charts: every decision of ``camtool chart`` (what each kind plots, its scene and model, the size and format).

:func:`image_format` picks the output format from the file's extension or the
one asked for, :func:`figure_size` the size (a card's paper by default) and
:func:`check_pixels` bounds a PNG; :func:`dof_chart`, :func:`blur_chart`,
:func:`aperture_chart`, :func:`trade_chart` and :func:`card_chart` decide each
chart's ranges and defaults and compute its numbers with
:mod:`camtool.render.chartdata`, returning a :class:`~camtool.render.chartdata.ChartData`
that the plotting layer only draws. Errors are :class:`camtool.core.errors.InputError`
(inputs named by placeholder) or ``DomainError``.

Lengths in millimetres, sizes in inches.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from camtool.core.errors import DomainError, InputError, braced
from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData, focal_lengths, hyperfocal
from camtool.render.chartdata import (
    MAX_PIXELS,
    PAPERS,
    ChartData,
    aperture_data,
    blur_data,
    card_data,
    dof_data,
    log_space,
    marks_data,
    raster_pixels,
    shot_data,
    trade_data,
)

__all__ = [
    "BLUR_FOCAL_LENGTHS_MM",
    "CARD_DISTANCES_M",
    "CARD_F_NUMBERS",
    "DEFAULT_SIZE_IN",
    "IMAGE_FORMATS",
    "POINTS",
    "aperture_chart",
    "blur_chart",
    "card_chart",
    "check_pixels",
    "dof_chart",
    "figure_size",
    "image_format",
    "lens_label",
    "marks_chart",
    "read_shot",
    "shot_chart",
    "trade_chart",
]

IMAGE_FORMATS = ("png", "svg", "pdf")
DEFAULT_SIZE_IN = (8.0, 5.0)
POINTS = 161
"""Points per curve, evenly spaced on a log scale."""
CARD_DISTANCES_M = [0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0, 20.0, math.inf]
CARD_DISTANCES_FT = [2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 15.0, 25.0, 50.0]
CARD_F_NUMBERS = [2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0]
BLUR_FOCAL_LENGTHS_MM = [24.0, 35.0, 50.0, 85.0, 135.0, 200.0]


def image_format(*, output: str, given: str | None) -> str:
    """The image format: ``given``, else the extension of ``output`` (``-`` is standard output and needs ``given``).

    >>> image_format(output="dof.SVG", given=None), image_format(output="-", given="png")
    ('svg', 'png')
    """
    suffix = Path(output).suffix.lower().lstrip(".") if output != "-" else ""
    if output == "-" and given is None:
        raise InputError("image_format", "{output} - writes to standard output: give {image_format} png, svg or pdf.",
                         usage=True)
    if given is not None:
        if suffix and suffix != given:
            raise InputError("output", f"{braced(output)} has the extension .{suffix} but {{image_format}} is {given}")
        return given
    if suffix not in IMAGE_FORMATS:
        shown = f".{suffix}" if suffix else "no extension"
        raise InputError("output", f"{braced(output)} has {shown}: use .png, .svg or .pdf, or give {{image_format}}")
    return suffix


def figure_size(*, size_in: tuple[float, float] | None, paper: str | None = None) -> tuple[float, float]:
    """The figure size in inches: ``size_in`` when given, else the card's ``paper``, else 8 × 5 in.

    >>> figure_size(size_in=None), [round(v, 3) for v in figure_size(size_in=None, paper="a6")]
    ((8.0, 5.0), [5.827, 4.134])
    """
    if size_in is not None:
        return size_in
    return PAPERS[paper] if paper is not None else DEFAULT_SIZE_IN


def check_pixels(*, size_in: tuple[float, float], dpi: float) -> None:
    """Refuse, before anything is computed, a PNG of more than :data:`~camtool.render.chartdata.MAX_PIXELS` pixels."""
    width, height = size_in
    across, down = raster_pixels(width, height, dpi)
    if across * down > MAX_PIXELS:
        raise InputError("dpi", f"{dpi:g} with {{size}} {width:g}x{height:g} in is {across} × {down} pixels "
                         f"({across * down / 1e6:.1f} megapixels); a PNG chart has at most {MAX_PIXELS / 1e6:.0f} "
                         "megapixels (40x40 in at 300 dpi): give a smaller {dpi} or {size}")


def lens_label(focal_lengths_mm: Sequence[float]) -> str:
    """The lens part of a chart's scene line: ``"35, 50 mm"``."""
    return ", ".join(f"{f:g}" for f in focal_lengths_mm) + " mm"


def _one_list(focal: Sequence[float], apertures: Sequence[float]) -> None:
    if len(focal) > 1 and len(apertures) > 1:
        raise InputError("f_number", "Give several f-numbers or several focal lengths ({f_number} or "
                         "{focal_length}), not both: each curve is one of them.", usage=True)


def _range(low: float, high: float) -> None:
    if not low < high:
        raise InputError("high", f"{high:g} is outside the valid range: more than {{low}} ({low:g})")


def dof_chart(*, focal_lengths_mm: Sequence[float], f_numbers: Sequence[float], coc_mm: float,
              from_mm: float | None = None, to_mm: float | None = None, model: str = "auto",
              distance_from: str = "sensor", lens: LensData | None = None, diffraction: bool = False,
              wavelength_nm: float = 550.0, tolerance: float = 0.01, squeeze: float | None = None) -> ChartData:
    """Near and far limits against focus distance: the focal lengths (the lens's own when not given) and the range.

    An anamorphic ``squeeze`` S adds, for each band, the horizontal limits: the thin lens of f/S at the same
    f-number and CoC (docs/cine.md §5a); the bands as computed are those of vertical blur.

    The range defaults to 10 × the longest focal length (at least 0.3 m) to
    twice the longest thin-lens hyperfocal distance (at least 10 m); the data
    are :func:`camtool.render.chartdata.dof_data` over :data:`POINTS` focus
    distances, ``extra["models"]`` names the rungs used and the scene line
    starts with the focal lengths.

    Examples
    --------
    50 mm f/8, c = 0.03 mm from the lens: H = f²/(N·c) + f = 10 466.7 mm (Wikipedia, "Hyperfocal distance"),
    so the range ends at twice that:

    >>> data = dof_chart(focal_lengths_mm=[50.0], f_numbers=[8.0], coc_mm=0.03, model="thin", distance_from="lens")
    >>> round(data.curves[0].x[-1], 1), round(data.marks[0].x, 1)
    (20933.3, 10466.7)
    """
    focal = focal_lengths(lens, list(focal_lengths_mm))
    if not focal:
        raise InputError("focal_length", "Missing option '{focal_length}'.", usage=True)
    _one_list(focal, f_numbers)
    start = max(300.0, 10.0 * max(focal)) if from_mm is None else from_mm
    stop = to_mm
    if stop is None:
        longest = max(float(hyperfocal("thin", f, n, coc_mm, distance_from).hyperfocal_mm)
                      for f in focal for n in f_numbers)
        stop = max(10_000.0, 2.0 * longest)
    if math.isinf(stop):
        raise DomainError("high", "inf", "a finite distance")
    _range(start, stop)
    distances = log_space(start, stop, POINTS)
    data = dof_data(focal, f_numbers, coc_mm, distances, model, distance_from, lens, diffraction, wavelength_nm,
                    tolerance, scene=lens_label(focal))
    if squeeze is not None:
        from camtool.plans.cine import desqueezed_width_mm

        desqueezed_width_mm(1.0, squeeze)  # the bound
        across = dof_data([f / squeeze for f in focal], f_numbers, coc_mm, distances, "thin", distance_from)
        groups = len(data.curves) // 2
        for curve, source in zip(across.curves, data.curves):
            curve.label = source.label.replace(" near", " horizontal near").replace(" far", " horizontal far")
            curve.group += groups
        data.curves += across.curves
        data.extra["squeeze"] = squeeze
    return data


def blur_chart(*, f_numbers: Sequence[float], sensor_width_mm: float, sensor_height_mm: float, sensor_label: str,
               focal_lengths_mm: Sequence[float] = (), subject_size_mm: float | None = None,
               fill: float | None = None, fill_axis: str = "height", magnification: float | None = None,
               from_mm: float | None = None, to_mm: float | None = None) -> ChartData:
    """Background blur against distance behind the subject at constant framing, and its scene line.

    The focal lengths default to :data:`BLUR_FOCAL_LENGTHS_MM`, the range to
    0.1 m to 100 m behind the subject; the magnification is given, or the one
    that makes the subject fill ``fill`` of the frame's ``fill_axis``.

    Examples
    --------
    A background at infinity blurs by f·m/N (Wikipedia, "Depth of field", "Foreground and background blur"):
    100 mm at m = 0.02, f/2 gives 1 mm.

    >>> data = blur_chart(f_numbers=[2.0], focal_lengths_mm=[100.0], magnification=0.02, sensor_width_mm=36.0,
    ...                   sensor_height_mm=24.0, sensor_label="full frame")
    >>> round(data.marks[0].y, 12)
    1.0
    """
    from camtool.geometry.compose import magnification_for_fill

    focal = list(focal_lengths_mm) or BLUR_FOCAL_LENGTHS_MM
    _one_list(focal, f_numbers)
    if (magnification is None) == (subject_size_mm is None or fill is None):
        raise InputError("magnification", "Give {subject_size} and {fill}, or {magnification}.", usage=True)
    frame = sensor_height_mm if fill_axis == "height" else sensor_width_mm
    start = from_mm or 100.0
    stop = to_mm or 100_000.0
    _range(start, stop)
    if magnification is not None:
        m, subject = magnification, f"m = {magnification:.4g}"
    else:
        assert subject_size_mm is not None and fill is not None
        m = magnification_for_fill(subject_size_mm, fill, frame)
        subject = f"subject {subject_size_mm / 1000:g} m fills {fill:g} of the {fill_axis}"
    scene = " · ".join([lens_label(focal), f"f/{', '.join(f'{n:g}' for n in f_numbers)}", subject, sensor_label,
                        "thin lens", "background distance from the subject"])
    return blur_data(focal, f_numbers, m, sensor_width_mm, log_space(start, stop, POINTS), scene)


def aperture_chart(*, focal_length_mm: float, coc_mm: float, near_mm: float | None, far_mm: float | None,
                   from_f_number: float = 1.4, to_f_number: float = 64.0, focus_mm: float | None = None,
                   distance_from: str = "sensor", pupil_magnification: float | None = None,
                   wavelength_nm: float = 550.0, criterion: Any = None) -> ChartData:
    """Defocus and diffraction blur against f-number for a scene from ``near_mm`` to ``far_mm`` (both needed).

    The pupil magnification defaults to 1; the focus to the optimum's
    (:func:`camtool.render.chartdata.aperture_data`). A contrast ``criterion``
    marks the contrast optimum as well (docs/wave.md).

    Examples
    --------
    The Airy disc 2.44·λ·N at f/8 and 550 nm, focused at infinity on a scene at infinity (m = 0) (Born and Wolf §8.5.2):

    >>> data = aperture_chart(focal_length_mm=50.0, coc_mm=0.03, near_mm=2000.0, far_mm=4000.0, from_f_number=8.0,
    ...                       to_f_number=11.0, focus_mm=8000.0 / 3.0, distance_from="lens")
    >>> round(data.curves[2].y[0] / (1.0 + 50.0 / (8000.0 / 3.0 - 50.0)), 6) == round(2.44 * 550e-6 * 8.0, 6)
    True
    """
    _range(from_f_number, to_f_number)
    if near_mm is None or far_mm is None:
        raise InputError("near", "Give the scene's {near} and {far}.", usage=True)
    return aperture_data(focal_length_mm, coc_mm, near_mm, far_mm, log_space(from_f_number, to_f_number, POINTS),
                         focus_mm, distance_from, pupil_magnification if pupil_magnification is not None else 1.0,
                         wavelength_nm, criterion=criterion)


def trade_chart(*, focal_length_mm: float, f_number: float, coc_mm: float, distance_mm: float,
                distance_from: str = "sensor", lens: LensData | None = None, diffraction: bool = False,
                wavelength_nm: float = 550.0) -> ChartData:
    """Every rung of the model ladder the lens data allow for one scene: error against time per evaluation."""
    return trade_data(focal_length_mm, f_number, coc_mm, distance_mm, distance_from, lens, diffraction, wavelength_nm)


def card_chart(*, focal_length_mm: float, coc_mm: float, f_numbers: Sequence[float] = (),
               exact_stops: bool = False, distances_mm: Sequence[float] = (), units: str = "metric",
               model: str = "auto", distance_from: str = "sensor", lens: LensData | None = None) -> ChartData:
    """A printable card: the f-numbers (exact stops if asked; default f/2.8 to f/22) and distances of its cells.

    The rows default to 0.5 m to 20 m and infinity, or 2 ft to 50 ft and
    infinity with imperial units; each cell is
    :func:`camtool.render.chartdata.card_data`'s.

    Examples
    --------
    50 mm f/8, c = 0.03 mm, 3 m from the lens: near 2337.9 mm, far 4185.3 mm (Wikipedia, "Depth of field"):

    >>> card = card_chart(focal_length_mm=50.0, coc_mm=0.03, f_numbers=[8.0], distances_mm=[3000.0], model="thin",
    ...                   distance_from="lens")
    >>> [round(card.extra[k][0][0], 1) for k in ("near_mm", "far_mm")]
    [2337.9, 4185.3]
    """
    from camtool.core.units import exact_f_number

    apertures = ([float(exact_f_number(n)) for n in f_numbers] if exact_stops else list(f_numbers)) or CARD_F_NUMBERS
    rows = list(distances_mm) or ([v * 304.8 for v in CARD_DISTANCES_FT] + [math.inf] if units == "imperial"
                                  else [v * 1000.0 for v in CARD_DISTANCES_M])
    return card_data(focal_length_mm, apertures, rows, coc_mm, model, distance_from, lens)


MARKS_FT = (3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 15.0, 20.0, 30.0, 50.0)
"""A focus puller's default marks, in feet (with --units imperial)."""
MARKS_M = (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 7.0, 10.0, 15.0)
"""The default marks in metres."""


def marks_chart(*, lenses: Sequence[tuple[str, float, LensData | None]], f_number: float, coc_mm: float,
                marks_mm: Sequence[float] = (), units: str = "metric", model: str = "auto",
                distance_from: str = "sensor", aperture_label: str = "") -> ChartData:
    """A printable focus-pull sheet: near and far around each mark for each lens of a set, at one stop.

    Marks default to 3 ft to 50 ft (imperial) or 1 m to 15 m; each lens is a column, in the order given.

    >>> sheet = marks_chart(lenses=[("50", 50.0, None)], f_number=8.0, coc_mm=0.03, marks_mm=[3000.0], model="thin",
    ...                     distance_from="lens")
    >>> round(sheet.extra["far_mm"][0][0], 1)   # 50 mm f/8, c = 0.03 mm at 3 m: far 4185.3 mm (as card_chart)
    4185.3
    """
    if not lenses:
        raise InputError("focal_length", "give the lenses of the sheet: {focal_length} (a list) or --lenses", usage=True)
    marks = list(marks_mm) or ([v * 304.8 for v in MARKS_FT] if units == "imperial" else [v * 1000.0 for v in MARKS_M])
    return marks_data(lenses, f_number, marks, coc_mm, model, distance_from, aperture_label)


SHOT_COLUMNS = {
    "frame": ("frame",),
    "focus": ("focus", "distance", "focus_distance", "focus_mm", "distance_mm", "focus_distance_mm"),
    "focal_length": ("focal_length", "focal_length_mm", "f"),
    "aperture": ("t_stop", "f_number", "n", "aperture", "tstop", "fstop", "iris"),
}
"""The columns of a camera's per-frame CSV and the names each may carry (case, dashes and spaces ignored)."""
MAX_SHOT_FRAMES = 1_000_000
"""The most frames a shot chart reads (some 11 hours at 24 fps)."""


class Shot(NamedTuple):
    """A camera's per-frame data: frame numbers, focus distances (mm), focal lengths (mm) and apertures (a
    :class:`~camtool.core.units.TStop` when the column is ``t_stop`` or the cell says ``T2.8``)."""

    frames: list[float]
    distances_mm: list[float]
    focal_lengths_mm: list[float]
    apertures: list[float]


def read_shot(path: str) -> Shot:
    """The rows of a per-frame camera CSV (``frame``, ``focus``, ``focal_length``, ``t_stop`` or ``f_number``;
    :data:`SHOT_COLUMNS`), each cell through the one parser of its quantity and its one bound: a bare focus is in
    metres (in mm in a ``*_mm`` column), a bare focal length in mm. A bad cell is an error naming its row (1 = the
    first data row) and column; an unreadable file a :class:`~camtool.core.files.FileProblem`."""
    from camtool.core.ranges import DISTANCE_MM, F_NUMBER, FOCAL_LENGTH_MM, describe
    from camtool.core.records import open_source, records
    from camtool.core.units import TStop, UnitError, parse_f_number, parse_length, parse_t_stop

    stream, name = open_source(path)
    columns: dict[str, int] = {}
    units: dict[str, str] = {}
    out = Shot([], [], [], [])
    with stream:
        for row, cells, problem in records(stream, name):
            if problem is not None:
                raise InputError("frames", f"{{frames}} row {row}: {braced(problem)}")
            if row == 0:
                keys = [str(c).strip().lower().replace("-", "_").replace(" ", "_") for c in cells]
                for quantity, names in SHOT_COLUMNS.items():
                    where = next((i for i, k in enumerate(keys) if k in names), None)
                    if where is not None:
                        columns[quantity], units[quantity] = where, "mm" if keys[where].endswith("_mm") else ""
                        if quantity == "aperture" and keys[where] in ("t_stop", "tstop"):
                            units[quantity] = "T"  # a bare number in a T-stop column is a T-stop
                missing = [q for q in ("focus", "focal_length", "aperture") if q not in columns]
                if missing:
                    raise InputError("frames", f"{{frames}} has no {', '.join(missing)} column (its header: "
                                               f"{braced(', '.join(keys)[:120])})")
                continue
            if isinstance(cells, dict):
                raise InputError("frames", "{frames} is CSV with a header row, not JSON lines")
            if len(out.frames) >= MAX_SHOT_FRAMES:
                raise InputError("frames", f"{{frames}} has more than {MAX_SHOT_FRAMES:,} frames")

            def cell(quantity: str, cells: list[str] = cells) -> str:
                index = columns[quantity]
                return str(cells[index]).strip() if index < len(cells) else ""

            try:
                shown = "focus"
                focus = parse_length(cell("focus"), units["focus"] or "m")
                if not DISTANCE_MM[0] < focus <= DISTANCE_MM[1] and focus != math.inf:
                    raise UnitError(f"{cell('focus')!r} is outside {describe(DISTANCE_MM, 'mm', allow_inf=True)}")
                shown = "focal_length"
                focal = parse_length(cell("focal_length"), "mm")
                if not FOCAL_LENGTH_MM[0] <= focal <= FOCAL_LENGTH_MM[1]:
                    raise UnitError(f"{cell('focal_length')!r} is outside {describe(FOCAL_LENGTH_MM, 'mm')}")
                shown = "aperture"
                text = cell("aperture")
                t = parse_t_stop(text)
                value = t if t is not None else parse_f_number(text)
                if not F_NUMBER[0] <= value <= F_NUMBER[1]:
                    raise UnitError(f"{text!r} is outside {describe(F_NUMBER)}")
                shown = "frame"
                frame = float(cell("frame")) if "frame" in columns else float(len(out.frames) + 1)
                if not math.isfinite(frame):
                    raise UnitError(f"{cell('frame')!r} is not a frame number")
            except (UnitError, ValueError) as error:
                raise InputError("frames", f"{{frames}} row {row}, column {shown}: {braced(str(error))}") from None
            out.frames.append(frame)
            out.distances_mm.append(focus)
            out.focal_lengths_mm.append(focal)
            out.apertures.append(TStop(value) if t is not None or units["aperture"] == "T" else value)
    if not out.frames:
        raise InputError("frames", "{frames} has no frames")
    return out


def shot_chart(*, shot: Shot, f_numbers: Sequence[float], coc_mm: float, model: str = "auto",
               distance_from: str = "sensor", lens: LensData | None = None) -> ChartData:
    """The near/far envelope of a shot over its frames (``f_numbers``: the f-number of each frame's aperture)."""
    return shot_data(shot.frames, shot.focal_lengths_mm, f_numbers, shot.distances_mm, coc_mm, model, distance_from,
                     lens)
