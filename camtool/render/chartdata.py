"""The numbers behind ``camtool chart``: each chart's curves and marks, computed by the library.

Every function here calls the formula library (the model ladder, the
composition geometry, the Airy disc) and returns a :class:`ChartData`: curves
and marks in millimetres (distances, blur discs), f-numbers or seconds,
never in display units. The plotting layer (:mod:`camtool.render.chartplot`)
only draws what it is handed, converting lengths to the user's units; the
tests compare these numbers with direct library calls, and the committed
example charts are checked for drift through them (:meth:`ChartData.to_json`).

Nothing here imports a plotting library.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from camtool.dof.ladder import LensData, compare_models, depth_of_field

__all__ = [
    "MAX_PIXELS",
    "ChartData",
    "Curve",
    "Mark",
    "aperture_data",
    "blur_data",
    "card_data",
    "dof_data",
    "log_space",
    "marks_data",
    "raster_pixels",
    "shot_data",
    "trade_data",
]


MAX_PIXELS = 12_000 * 12_000
"""The most pixels a PNG chart may have: a 40 × 40 in print at 300 dpi (144 megapixels).

The Agg canvas holds 4 bytes a pixel and PNG encoding copies the image once
more; at this bound ``camtool chart`` peaks near 0.65 GB of resident memory,
so the largest chart accepted fits well inside a 4 GiB address space."""


def raster_pixels(width_in: float, height_in: float, dpi: float) -> tuple[int, int]:
    """The pixel width and height of a ``width_in`` × ``height_in`` inch figure drawn at ``dpi``.

    Whole pixels, truncated, as the Agg canvas sizes its buffer."""
    return int(width_in * dpi), int(height_in * dpi)


@dataclass
class Curve:
    """One plotted line: ``x`` and ``y`` (same length), a legend ``label``, the ``group`` it belongs to
    (colour and line style) and its ``role`` (``near``, ``far``, ``defocus``, ``airy``, ``total``, ``blur``, ``rung``)."""

    label: str
    group: int
    role: str
    x: list[float]
    y: list[float]


@dataclass
class Mark:
    """A marked value: a vertical line at ``x`` (``y`` None), a horizontal one at ``y`` (``x`` None) or a point."""

    label: str
    group: int
    x: float | None
    y: float | None


@dataclass
class ChartData:
    """Everything one chart shows, in library units (mm, f-numbers, seconds).

    ``kind`` is the chart (``dof``, ``blur``, ``aperture``, ``trade``, ``card``, ``marks``, ``shot``);
    ``title`` names the question and ``scene`` the lens, sensor, CoC, model and
    distance plane; ``extra`` holds what a kind needs beyond curves and
    marks (the frame width for blur %, the card's table).
    """

    kind: str
    title: str
    scene: str
    curves: list[Curve] = field(default_factory=list)
    marks: list[Mark] = field(default_factory=list)
    extra: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready mapping (infinity as null, as camtool's JSON output writes it).

        Examples
        --------
        >>> ChartData("dof", "t", "s", [Curve("a", 0, "near", [1.0], [float("inf")])]).to_json()["curves"][0]["y"]
        [None]
        """
        return {
            "kind": self.kind,
            "title": self.title,
            "scene": self.scene,
            "curves": [{"label": c.label, "group": c.group, "role": c.role, "x": _plain(c.x), "y": _plain(c.y)}
                       for c in self.curves],
            "marks": [{"label": m.label, "group": m.group, "x": _value(m.x), "y": _value(m.y)} for m in self.marks],
            "extra": {key: _deep(value) for key, value in self.extra.items()},
        }


def _value(v: float | None) -> float | None:
    return None if v is None or math.isinf(v) else float(v)


def _plain(values: Sequence[float]) -> list[float | None]:
    return [_value(v) for v in values]


def _deep(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return [_deep(v) for v in value]
    if isinstance(value, float):
        return _value(value)
    return value


def _floats(values: Any, count: int) -> list[float]:
    """A result column as a list of floats (a scalar repeated ``count`` times)."""
    if isinstance(values, (int, float)):
        return [float(values)] * count
    return [float(v) for v in values]


def log_space(low: float, high: float, count: int) -> list[float]:
    """``count`` values from ``low`` to ``high`` (both > 0), evenly spaced on a log scale.

    Examples
    --------
    >>> [round(v, 9) for v in log_space(1.0, 100.0, 3)]
    [1.0, 10.0, 100.0]
    """
    if count < 2:
        return [low]
    step = math.log(high / low) / (count - 1)
    values = [low * math.exp(step * i) for i in range(count)]
    values[-1] = high
    return values


def _array(values: Sequence[float]) -> Any:
    import numpy as np

    return np.asarray(values, dtype=float)


def _bands(focal_lengths: Sequence[float], f_numbers: Sequence[float]) -> list[tuple[float, float, str]]:
    """(f, N, legend label) per band: one per f-number, or one per focal length when several are given."""
    if len(focal_lengths) > 1:
        return [(f, f_numbers[0], f"{f:g} mm") for f in focal_lengths]
    return [(focal_lengths[0], n, f"f/{n:g}") for n in f_numbers]


def dof_data(focal_lengths: Sequence[float], f_numbers: Sequence[float], coc_mm: float, distances_mm: Sequence[float],
             model: str = "auto", distance_from: str = "sensor", lens: LensData | None = None,
             diffraction: bool = False, wavelength_nm: float = 550.0, tolerance: float = 0.01,
             scene: str = "") -> ChartData:
    """Near and far limits (mm) against focus distance (mm), one band per f-number (or focal length).

    Each band is :func:`camtool.dof.ladder.depth_of_field` over the focus
    distances; its hyperfocal distance (the library's ``hyperfocal_mm`` at
    the first distance) is a vertical mark. A far limit of infinity stays
    infinite (null in JSON).

    Parameters
    ----------
    focal_length_mm, f_numbers : lists of f > 0 mm and N > 0; several of one of them make the bands
    coc_mm : float, c > 0 mm
    distances_mm : list of focus distances > 0 mm from ``distance_from``
    model, distance_from, lens, diffraction, wavelength_nm, tolerance
        As for :func:`camtool.dof.ladder.depth_of_field`.
    scene : str, the scene line of the chart's title

    Examples
    --------
    Thin lens from the lens, H = f²/(N·c) + f, near = s(H − f)/(H + s − 2f),
    far = s(H − f)/(H − s) (Wikipedia, "Depth of field"): 50 mm f/8, c = 0.03 mm,
    3 m gives H = 10 466.7 mm, near 2337.9 mm and far 4185.3 mm.

    >>> data = dof_data([50.0], [8.0], 0.03, [3000.0, 20000.0], model="thin", distance_from="lens")
    >>> round(data.curves[0].y[0], 1), round(data.curves[1].y[0], 1), data.curves[1].y[1]
    (2337.9, 4185.3, inf)
    >>> round(data.marks[0].x, 1)
    10466.7
    """
    s = _array(distances_mm)
    data = ChartData("dof", "Depth of field against focus distance", scene)
    used: list[str] = []
    for group, (f, n, label) in enumerate(_bands(focal_lengths, f_numbers)):
        result = depth_of_field(model, f, n, coc_mm, s, distance_from, lens, diffraction, wavelength_nm, tolerance)
        limits = result.limits
        x = [float(v) for v in s]
        data.curves.append(Curve(f"{label} near", group, "near", x, _floats(limits.near_mm, len(x))))
        data.curves.append(Curve(f"{label} far", group, "far", x, _floats(limits.far_mm, len(x))))
        h = _floats(limits.hyperfocal_mm, len(x))[0]
        data.marks.append(Mark(f"H {label}", group, h, None))
        names = [result.model] if isinstance(result.model, str) else [str(v) for v in result.model]
        used.extend(name for name in names if name not in used)
    data.extra["models"] = used
    return data


def blur_data(focal_lengths: Sequence[float], f_numbers: Sequence[float], magnification: float, width_mm: float,
              offsets_mm: Sequence[float], scene: str = "") -> ChartData:
    """Background blur disc (mm on the sensor) against the background's distance behind the subject (mm).

    One curve per focal length at constant framing (magnification m: each
    focal length stands at its own distance, ``compose``'s question) or per
    f-number, from :func:`camtool.geometry.compose.plane_view`; the blur of a
    background at infinity, f·m/N, is a horizontal mark. ``extra`` carries
    the frame width (for the % axis) and the blur in % per curve.

    Parameters
    ----------
    focal_lengths, f_numbers : lists of f > 0 mm and N (0.7 to 1024); several of one of them make the curves
    magnification : float, subject magnification m > 0
    width_mm : float, frame width > 0 mm
    offsets_mm : list of background distances behind the subject, > 0 mm (``inf`` allowed)

    References
    ----------
    Wikipedia, "Depth of field", section "Foreground and background blur".

    Examples
    --------
    >>> data = blur_data([50.0, 100.0], [2.0], 0.02, 36.0, [5100.0, float("inf")])
    >>> [round(v, 4) for v in data.curves[1].y]
    [0.5, 1.0]
    >>> data.marks[0].y
    0.5
    """
    from camtool.geometry.compose import plane_view

    x = _array(offsets_mm)
    data = ChartData("blur", "Background blur against distance behind the subject", scene)
    reference = focal_lengths[0]
    data.extra["width_mm"] = width_mm
    data.extra["magnification"] = magnification
    data.extra["blur_pct"] = []
    for group, (f, n, label) in enumerate(_bands(focal_lengths, f_numbers)):
        view = plane_view(f, n, magnification, width_mm, x, reference_focal_length_mm=reference)
        data.curves.append(Curve(label, group, "blur", [float(v) for v in x], _floats(view.blur_mm, len(x))))
        data.extra["blur_pct"].append(_floats(view.blur_pct, len(x)))
        far = plane_view(f, n, magnification, width_mm, float("inf"))
        data.marks.append(Mark(f"{label} at ∞", group, None, float(far.blur_mm)))
    return data


def aperture_data(focal_length_mm: float, coc_mm: float, near_mm: float, far_mm: float,
                  f_numbers: Sequence[float], focus_mm: float | None = None, distance_from: str = "sensor",
                  pupil_magnification: float = 1.0, wavelength_nm: float = 550.0, scene: str = "",
                  criterion: Any = None) -> ChartData:
    """Blur (mm) at the scene's near and far limits from defocus, and the Airy disc, against f-number; the optimum marked.

    With a contrast ``criterion`` (:class:`camtool.dof.wave.Criterion`) the
    contrast optimum is marked too: the f-number whose MTF at the criterion's
    frequency is highest at both limits (:func:`camtool.dof.wave.contrast_optimum`,
    ``extra["contrast_f_number"]``), beside the root-sum-square one.

    The optimum aperture is :func:`camtool.dof.closeup.optimum_for_limits`:
    focused half-way between the near and far images (Hansma's rule), the
    f-number whose defocus and diffraction blurs are equal, which is where
    their root-sum-square is smallest. The lens is focused there, or at
    ``focus_mm`` when given. Defocus: the blur disc (f/N)·|v_s − v_o|/v_o of
    a point at each limit (:func:`camtool.geometry.thinlens.blur_diameter_mm`,
    distances from the lens); diffraction: the Airy disc 2.44·λ·N(1 + m/P)
    (:func:`camtool.dof.diffraction.airy_diameter_mm`); ``total`` adds the
    larger defocus blur and the Airy disc in quadrature. The defocus blur
    falls as K/N and the Airy disc grows as A·N, so the curves cross at
    N* = √(K/A) (``extra["crossing_f_number"]``), where the total is
    smallest: with the optimum's own focus this is the optimum again, up to
    the difference between the thin-lens blur and Hansma's Δ/(2·N_w).

    Parameters
    ----------
    focal_length_mm : float, f > 0 mm
    coc_mm : float, c > 0 mm (drawn as a reference line)
    near_mm, far_mm : float, the scene's nearest and farthest points, near < far (``inf`` allowed), mm
    f_numbers : list of N > 0
    focus_mm : float or None, the focus distance (None: the optimum's, half-way between the images)
    distance_from : ``"sensor"`` or ``"lens"``
    pupil_magnification : float, P > 0
    wavelength_nm : float, λ in nm

    References
    ----------
    P. K. Hansma, "View camera focusing in practice", *Photo Techniques*, 1996 (the optimum);
    Born and Wolf, *Principles of Optics*, §8.5.2 (Airy disc); Wikipedia, "Circle of confusion".

    Examples
    --------
    Focused where the thin-lens depth of field just spans 2–4 m
    (:func:`camtool.dof.inverse.focus_for_limits`: 2666.7 mm from the lens,
    f/10.616), both limits blur by exactly c = 0.03 mm at f/10.616, so
    K = 0.03 · 10.616; the Airy disc at f/8 is 2.44 · 550 nm · 8 · (1 + 50/2616.7):

    >>> data = aperture_data(50.0, 0.03, 2000.0, 4000.0, [8.0, 11.0], focus_mm=8000.0 / 3.0, distance_from="lens")
    >>> near, far, airy, total = data.curves
    >>> round(near.y[0] * 8.0, 4), round(far.y[0] * 8.0, 4), round(airy.y[0], 5)
    (0.3185, 0.3185, 0.01094)
    >>> round(data.extra["crossing_f_number"], 2)  # √(K/A) = √(0.31848/0.0013676)
    15.26
    """
    from camtool.dof.closeup import optimum_for_limits
    from camtool.dof.diffraction import airy_diameter_mm
    from camtool.geometry.thinlens import blur_diameter_mm, focus_geometry, working_f_number

    best = optimum_for_limits(focal_length_mm, near_mm, far_mm, distance_from, 0.0, pupil_magnification,
                              wavelength_nm)
    if focus_mm is None:
        focus_mm = float(best.distance_mm)
    geometry = focus_geometry(focal_length_mm, focus_mm, distance_from)
    # the limits as object distances from the lens: from the sensor, less the image distance of the focus
    shift = geometry.image_mm if distance_from == "sensor" else 0.0
    n = _array(f_numbers)
    near_blur = blur_diameter_mm(focal_length_mm, n, geometry.object_mm, near_mm - shift)
    far_blur = blur_diameter_mm(focal_length_mm, n, geometry.object_mm, far_mm - shift)
    airy = airy_diameter_mm(working_f_number(n, geometry.magnification, pupil_magnification), wavelength_nm)
    worst = [max(a, b) for a, b in zip(near_blur, far_blur)]
    total = [math.hypot(w, a) for w, a in zip(worst, airy)]
    x = [float(v) for v in n]
    data = ChartData("aperture", "Defocus and diffraction blur against f-number", scene)
    data.curves = [
        Curve("defocus at the near limit", 0, "defocus", x, [float(v) for v in near_blur]),
        Curve("defocus at the far limit", 1, "defocus", x, [float(v) for v in far_blur]),
        Curve("diffraction (Airy disc)", 2, "airy", x, [float(v) for v in airy]),
        Curve("total (root sum of squares)", 3, "total", x, total),
    ]
    k = max(near_blur[0], far_blur[0]) * x[0]  # defocus = K/N
    a = float(airy[0]) / x[0]  # Airy disc = A·N
    optimum = float(best.optimum.f_number)
    data.marks = [Mark(f"optimum aperture f/{optimum:.3g}", 3, optimum, float(best.optimum.blur_mm)),
                  Mark(f"CoC {coc_mm:.3g} mm", 4, None, coc_mm)]
    data.extra.update({"focus_mm": focus_mm, "near_mm": near_mm, "far_mm": far_mm,
                       "optimum_f_number": optimum, "optimum_blur_mm": float(best.optimum.blur_mm),
                       "optimum_focus_mm": float(best.distance_mm),
                       "crossing_f_number": math.sqrt(k / a), "crossing_blur_mm": math.sqrt(k * a),
                       "wavelength_nm": wavelength_nm})
    if criterion is not None:
        from camtool.dof.wave import contrast_optimum, criterion_frequency

        nu = float(criterion_frequency(criterion, coc_mm))
        by_contrast = contrast_optimum(focal_length_mm, near_mm, far_mm, nu, distance_from, wavelength_nm)
        data.marks.append(Mark(f"contrast optimum f/{by_contrast.f_number:.3g} ({criterion.label()})", 5,
                               by_contrast.f_number, None))
        data.extra.update({"contrast_f_number": by_contrast.f_number, "contrast_mtf": by_contrast.mtf})
    return data


def trade_data(focal_length_mm: float | None, f_number: float, coc_mm: float, distance_mm: float,
               distance_from: str = "sensor", lens: LensData | None = None, diffraction: bool = False,
               wavelength_nm: float = 550.0, repeat: int = 3, scene: str = "") -> ChartData:
    """Every rung of the model ladder: its error against the most complete rung and its time per evaluation.

    From :func:`camtool.dof.ladder.compare_models` for this one scene, timed
    on the spot (best of ``repeat``). Each rung is a point: x the time per
    evaluation in seconds, y the difference (a fraction; 0 for the most
    complete geometric rung, the reference; ``wave`` last) and, in ``extra["estimates"]``, the error
    ``auto`` estimates for it.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm, distance_mm : float
        One scene, as for :func:`camtool.dof.ladder.compare_models`.
    distance_from, lens, diffraction, wavelength_nm : as there
    repeat : int, timed runs per rung (the best counts)

    Examples
    --------
    >>> data = trade_data(50.0, 8.0, 0.03, 3000.0, repeat=1)
    >>> [(c.label, round(c.y[0], 4)) for c in data.curves]
    [('approx', 0.0287), ('thin', 0.0), ('wave', 0.0702)]
    """
    rows = compare_models(focal_length_mm, f_number, coc_mm, distance_mm, distance_from, lens, diffraction,
                          wavelength_nm, repeat=repeat)
    data = ChartData("trade", "Model ladder: error against time per evaluation", scene)
    for group, row in enumerate(rows):
        data.curves.append(Curve(str(row.result.model), group, "rung", [row.time_per_evaluation_s],
                                 [float(row.difference)]))
    data.extra["estimates"] = [float(row.result.error_estimate) for row in rows]
    data.extra["reference"] = [str(row.result.model) for row in rows if str(row.result.model).split("+")[0] != "wave"][-1]
    return data


PAPERS = {"a6": (148.0 / 25.4, 105.0 / 25.4), "letter-quarter": (5.5, 4.25)}
"""Card sizes in inches, landscape: ISO 216 A6 (148 × 105 mm) and a quarter of US Letter (5.5 × 4.25 in)."""


def card_data(focal_length_mm: float, f_numbers: Sequence[float], distances_mm: Sequence[float], coc_mm: float,
              model: str = "auto", distance_from: str = "sensor", lens: LensData | None = None,
              scene: str = "") -> ChartData:
    """A depth-of-field card: near and far limits (mm) for each focus distance (rows) and f-number (columns).

    One :func:`camtool.dof.ladder.depth_of_field` call over the grid;
    ``extra`` holds ``distances_mm``, ``f_numbers``, ``near_mm`` and
    ``far_mm`` (row-major lists) and the hyperfocal distance per f-number.

    Parameters
    ----------
    focal_length_mm : float, f > 0 mm
    f_numbers : list of N > 0 (the columns)
    distances_mm : list of focus distances > 0 mm (the rows; ``inf`` allowed)
    coc_mm : float, c > 0 mm
    model, distance_from, lens : as for :func:`camtool.dof.ladder.depth_of_field`

    Examples
    --------
    >>> card = card_data(50.0, [8.0], [3000.0], 0.03, model="thin", distance_from="lens")
    >>> [round(card.extra[k][0][0]) for k in ("near_mm", "far_mm")], round(card.extra["hyperfocal_mm"][0])
    ([2338, 4185], 10467)
    """
    import numpy as np

    n = _array(f_numbers)[None, :]
    s = _array(distances_mm)[:, None]
    result = depth_of_field(model, focal_length_mm, n, coc_mm, s, distance_from, lens)
    shape = (len(distances_mm), len(f_numbers))
    near = np.broadcast_to(result.limits.near_mm, shape)
    far = np.broadcast_to(result.limits.far_mm, shape)
    hyper = np.broadcast_to(result.limits.hyperfocal_mm, shape)[0]
    models = sorted({str(v) for v in np.ravel(result.model)})
    data = ChartData("card", f"Depth of field · {focal_length_mm:g} mm", scene)
    data.extra = {
        "focal_length_mm": focal_length_mm,
        "f_numbers": [float(v) for v in f_numbers],
        "distances_mm": [float(v) for v in distances_mm],
        "near_mm": [[float(v) for v in row] for row in near],
        "far_mm": [[float(v) for v in row] for row in far],
        "hyperfocal_mm": [float(v) for v in hyper],
        "models": models,
    }
    return data


def marks_data(lenses: Sequence[tuple[str, float, LensData | None]], f_number: float, marks_mm: Sequence[float],
               coc_mm: float, model: str = "auto", distance_from: str = "sensor", aperture_label: str = "",
               scene: str = "") -> ChartData:
    """A focus puller's sheet: near and far limits (mm) around each focus mark (rows) for each lens (columns:
    ``(label, focal length, lens data)``), at one f-number; ``aperture_label`` is how the stop was given (T2.8).

    >>> sheet = marks_data([("50 mm", 50.0, None)], 8.0, [3000.0], 0.03, model="thin", distance_from="lens")
    >>> [round(sheet.extra[k][0][0]) for k in ("near_mm", "far_mm")]
    [2338, 4185]
    """
    near: list[list[float]] = [[] for _ in marks_mm]
    far: list[list[float]] = [[] for _ in marks_mm]
    models: set[str] = set()
    for _, focal, lens in lenses:
        card = card_data(focal, [f_number], marks_mm, coc_mm, model, distance_from, lens)
        for row, (a, b) in enumerate(zip(card.extra["near_mm"], card.extra["far_mm"])):
            near[row].append(a[0])
            far[row].append(b[0])
        models.update(card.extra["models"])
    data = ChartData("marks", f"Focus marks · {aperture_label or f'f/{f_number:g}'}", scene)
    data.extra = {"lenses": [label for label, _, _ in lenses], "focal_lengths_mm": [f for _, f, _ in lenses],
                  "f_number": f_number, "marks_mm": [float(v) for v in marks_mm], "near_mm": near, "far_mm": far,
                  "models": sorted(models)}
    return data


def shot_data(frames: Sequence[float], focal_lengths_mm: Sequence[float], f_numbers: Sequence[float],
              distances_mm: Sequence[float], coc_mm: float, model: str = "auto", distance_from: str = "sensor",
              lens: LensData | None = None, scene: str = "") -> ChartData:
    """The near and far envelope of a shot: for each frame (its focus, focal length and f-number) the limits, in
    one :func:`camtool.dof.ladder.depth_of_field` call; curves ``focus``, ``near`` and ``far`` against the frame.

    >>> shot = shot_data([1, 2], [50.0, 50.0], [8.0, 8.0], [3000.0, 20000.0], 0.03, model="thin", distance_from="lens")
    >>> round(shot.curves[1].y[0], 1), round(shot.curves[2].y[0], 1), shot.curves[2].y[1]
    (2337.9, 4185.3, inf)
    """
    import numpy as np

    result = depth_of_field(model, _array(focal_lengths_mm), _array(f_numbers), coc_mm, _array(distances_mm),
                            distance_from, lens)
    count = len(frames)
    near = np.broadcast_to(result.limits.near_mm, (count,))
    far = np.broadcast_to(result.limits.far_mm, (count,))
    x = [float(v) for v in frames]
    data = ChartData("shot", "Depth of field over the shot", scene)
    data.curves = [Curve("focus", 0, "focus", x, [float(v) for v in distances_mm]),
                   Curve("near", 1, "near", x, [float(v) for v in near]),
                   Curve("far", 1, "far", x, [float(v) for v in far])]
    data.extra = {"models": sorted({str(v) for v in np.ravel(result.model)})}
    return data
