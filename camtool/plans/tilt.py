"""Tilt and swing: every decision ``camtool tilt`` makes, from the question asked to rows of numbers.

What sets the tilt (the tilt itself, a hinge distance J, or two points the
plane of sharp focus must pass through), what sets the focus (a distance, the
lens-to-film distance, the hyperfocal setting, or the two points), which
models answer (``auto``, ``thin``, ``thick``, ``raytrace``, ``all``), the
conventions the answers are given in (``along``, ``angles_from``,
``hinge_from``, ``distance_from``), the wedge and its extent at a distance,
the f-number a wedge needs and the optimum against diffraction, and the tilt
range of a lens preset. The formulas are in :mod:`camtool.geometry.tilt`,
:mod:`camtool.dof.tilt` and :mod:`camtool.optics.tilted`; derivation and
conventions in docs/tilt.md.

Lengths in mm, angles in degrees. Errors are :class:`DomainError` on the
parameter given (``tilt_deg``, ``hinge_mm``, ``points``, ``image_distance_mm``,
``at_mm``, ``half_depth_mm``, ...), :class:`SettingsError` naming the
parameters that do not go together, :class:`TiltError` for a question the
geometry cannot answer on one parameter, :class:`BeyondLensRange` for a tilt
the lens preset cannot make, and ``ModelUnavailable`` for ``raytrace``
without a prescription.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

from camtool.core.errors import CamtoolError, DomainError
from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData, ModelUnavailable
from camtool.dof.tilt import TiltLens
from camtool.exposure.calculator import SettingsError

__all__ = ["HYPERFOCAL_DEFINITION", "KEYS", "MODELS", "BeyondLensRange", "SettingsError", "TiltAnswer", "TiltError",
           "TiltRow", "check_lens", "check_question", "solve_tilt"]

KEYS = ["model", "movement", "focal_length_mm", "f_number", "coc_mm", "tilt_deg", "hinge_mm", "image_distance_mm",
        "focus_mm", "near_mm", "far_mm", "focus_plane_deg", "near_plane_deg", "far_plane_deg", "wedge_deg",
        "at_mm", "above_mm", "below_mm", "across_mm", "hyperfocal_mm", "hyperfocal_near_mm",
        "half_depth_mm", "f_number_needed", "f_number_optimum", "blur_optimum_mm",
        "along", "angles_from", "hinge_from", "distance_from", "hyperfocal_definition"]
"""Every key a row of :func:`solve_tilt` carries (JSON and CSV), in order."""
MODELS = ("thin", "thick", "raytrace", "auto", "all")
HYPERFOCAL_DEFINITION = {"sight": "far limit plane parallel to the line of sight (Merklinger)",
                         "axis": "far limit plane parallel to the lens axis"}
"""What the hyperfocal setting means along each line (a row's ``hyperfocal_definition``)."""
ALONG_TEXT = {"sight": "along the line of sight (the film's normal through the lens)", "axis": "along the lens axis"}
ANGLE_TEXT = {"film": "from the film plane", "lens": "from the lens plane", "horizon": "from the line of sight"}
HINGE_TEXT = {"lens": "J from the lens (front principal point), parallel to the film",
              "pupil": "J from the entrance pupil, parallel to the film"}
_COMPUTED = KEYS[7:25]  # the keys left None when the focus is not set


class TiltError(CamtoolError, ValueError):
    """A question the tilt geometry cannot answer as asked: ``param`` names the parameter, ``reason`` says why."""

    def __init__(self, param: str, reason: str) -> None:
        self.param = param
        self.reason = reason
        super().__init__(f"{param}: {reason}")


class BeyondLensRange(TiltError):
    """A tilt (given, or found from a hinge or two points) beyond the tilt range of the lens preset ``lens_id``."""

    def __init__(self, param: str, tilt_deg: float, limit_deg: float, lens_id: str) -> None:
        self.tilt_deg, self.limit_deg, self.lens_id = tilt_deg, limit_deg, lens_id
        super().__init__(param, f"{tilt_deg:.3g}° is outside the tilt range of {lens_id}: ±{limit_deg:g}°")


class TiltRow(NamedTuple):
    """One row: the model, the movement, the scene, and where the planes are (None: not asked for or not set)."""

    model: str
    movement: str
    focal_length_mm: float
    f_number: float | None
    coc_mm: float
    tilt_deg: float
    hinge_mm: float
    image_distance_mm: float | None = None
    focus_mm: float | None = None
    near_mm: float | None = None
    far_mm: float | None = None
    focus_plane_deg: float | None = None
    near_plane_deg: float | None = None
    far_plane_deg: float | None = None
    wedge_deg: float | None = None
    at_mm: float | None = None
    above_mm: float | None = None
    below_mm: float | None = None
    across_mm: float | None = None
    hyperfocal_mm: float | None = None
    hyperfocal_near_mm: float | None = None
    half_depth_mm: float | None = None
    f_number_needed: float | None = None
    f_number_optimum: float | None = None
    blur_optimum_mm: float | None = None
    along: str = "sight"
    angles_from: str = "film"
    hinge_from: str = "lens"
    distance_from: str = "sensor"
    hyperfocal_definition: str = HYPERFOCAL_DEFINITION["sight"]


class TiltAnswer(NamedTuple):
    """The rows (one per scene and model, scenes in the order of the lists), the movement, the models used,
    and what the numbers mean in words (the models, the conventions, no tilt, the wedge's extent, real rays)."""

    rows: tuple[TiltRow, ...]
    movement: str
    models: tuple[str, ...]
    notes: tuple[str, ...]


def check_question(*, tilt_deg: Sequence[float] = (), swing_deg: Sequence[float] = (), hinge_mm: Sequence[float] = (),
                   points: Sequence[tuple[float, float]] = (), focus_mm: Sequence[float] = (),
                   image_distance_mm: Sequence[float] = (), hyperfocal: bool = False, at_mm: float | None = None,
                   half_depth_mm: float | None = None, optimum: bool = False) -> None:
    """Refuse a question asked in ways that do not go together, before any equipment is looked up.

    One of the tilt, the swing, the hinge distance or two points sets the
    movement; at most one of the distance, the image distance, the
    hyperfocal setting and the two points sets the focus; the half-depth of
    a wedge needs the distance where it counts, the optimum needs the
    half-depth.

    >>> check_question(tilt_deg=[3.0], swing_deg=[3.0])
    Traceback (most recent call last):
    ...
    camtool.exposure.calculator.SettingsError: give tilt_deg or swing_deg, not both
    """
    if swing_deg and tilt_deg:
        raise SettingsError("give {tilt_deg} or {swing_deg}, not both", ["tilt_deg", "swing_deg"])
    if sum(bool(x) for x in (focus_mm, image_distance_mm, hyperfocal, len(points) == 2)) > 1:
        raise SettingsError("give one focus: {focus_mm}, {image_distance_mm}, {hyperfocal} or two {points}",
                            ["focus_mm", "image_distance_mm", "hyperfocal", "points"])
    if points and len(points) != 2:
        raise TiltError("points", f"{len(points)} points given: give exactly two")
    angles = swing_deg or tilt_deg
    if points and (angles or hinge_mm):
        raise SettingsError("two {points} set the tilt themselves: drop {tilt_deg}/{swing_deg}/{hinge_mm}",
                            ["points", "tilt_deg", "swing_deg", "hinge_mm"])
    if angles and hinge_mm:
        raise SettingsError("give {tilt_deg} (or {swing_deg}) or {hinge_mm}, not both",
                            ["tilt_deg", "swing_deg", "hinge_mm"])
    if not (angles or hinge_mm or points):
        raise SettingsError("Missing option '{tilt_deg}' (or {swing_deg}, {hinge_mm}, or two {points}).",
                            ["tilt_deg", "swing_deg", "hinge_mm", "points"])
    if (half_depth_mm is not None or optimum) and at_mm is None:
        raise SettingsError("{half_depth_mm} needs {at_mm} (the distance where the wedge must reach that far)",
                            ["half_depth_mm", "at_mm"])
    if optimum and half_depth_mm is None:
        raise SettingsError("{optimum} needs {half_depth_mm} (the wedge to balance against diffraction)",
                            ["optimum", "half_depth_mm"])


def solve_tilt(*, focal_length_mm: Sequence[float] = (), f_number: Sequence[float] = (), coc_mm: Sequence[float],
               tilt_deg: Sequence[float] = (), swing_deg: Sequence[float] = (), hinge_mm: Sequence[float] = (),
               points: Sequence[tuple[float, float]] = (), focus_mm: Sequence[float] = (),
               image_distance_mm: Sequence[float] = (), hyperfocal: bool = False, at_mm: float | None = None,
               half_depth_mm: float | None = None, optimum: bool = False, wavelength_nm: float = 550.0,
               sensor_height_mm: float = 24.0, distance_from: str = "sensor", along: str = "sight",
               angles_from: str = "film", hinge_from: str = "lens", model: str = "auto", lens: LensData | None = None,
               lens_preset: Any = None) -> TiltAnswer:
    """The hinge, the plane of sharp focus and the wedge for every combination of the lists, for each model.

    Decides: the movement (swing when ``swing_deg`` is given, else tilt); the
    tilt from ``tilt_deg``/``swing_deg``, from a hinge distance J measured
    from the lens (asin(f/J)) or the entrance pupil (``hinge_from``), or from
    two ``points`` (distance along the line of sight, height above the lens;
    from the sensor the lens position is iterated); the focus from
    ``focus_mm`` (along the line of sight or the lens axis, ``along``),
    ``image_distance_mm``, ``hyperfocal`` or the two points; the models:
    ``auto`` is thick when the lens data give a pupil magnification or a
    hiatus, else thin, ``all`` every model the data allow, ``raytrace`` needs
    a prescription (its wedge is the thick one, or the raytrace rung along the
    axis); with a prescription the focal length is its own (a given one must
    agree within 1 %); the wedge's extent above and below the plane of focus at
    ``at_mm`` (from the sensor or the lens, ``distance_from``), the f-number a
    ``half_depth_mm`` there needs (it becomes the row's f-number when none is
    given), and with ``optimum`` the f-number that balances defocus against
    diffraction at ``wavelength_nm``; angles from the film, the lens plane or
    the line of sight (``angles_from``). ``lens_preset`` brings the tilt range
    (``tilt_max_deg``) a tilt must stay within.

    The hinge rule J = f/sin θ (Merklinger, *Focusing the View Camera*, 1993):
    f = 90 mm tilted 3° puts the hinge line 90/sin 3° = 1719.7 mm from the lens.

    >>> row = solve_tilt(focal_length_mm=[90.0], f_number=[11.0], coc_mm=[0.03], tilt_deg=[3.0],
    ...                  focus_mm=[2000.0]).rows[0]
    >>> round(row.hinge_mm, 1), round(row.focus_mm, 6), row.model
    (1719.7, 2000.0, 'thin')
    """
    check_question(tilt_deg=tilt_deg, swing_deg=swing_deg, hinge_mm=hinge_mm, points=points, focus_mm=focus_mm,
                   image_distance_mm=image_distance_mm, hyperfocal=hyperfocal, at_mm=at_mm,
                   half_depth_mm=half_depth_mm, optimum=optimum)
    check_lens(model=model, lens=lens, focal_length_mm=focal_length_mm, f_number=f_number, half_depth_mm=half_depth_mm)
    movement = "swing" if swing_deg else "tilt"
    lenses = _models(model, lens)
    focal = _focal_lengths(focal_length_mm, lens)
    angles = list(swing_deg or tilt_deg)
    settings = angles or list(hinge_mm) or [math.nan]
    focuses = list(focus_mm) or list(image_distance_mm) or [math.nan]
    how = ("image" if image_distance_mm else "distance" if focus_mm else "hyperfocal" if hyperfocal
           else "points" if points else None)
    limit = getattr(lens_preset, "tilt_max_deg", None) if lens_preset is not None else None
    scene = _Scene(lens, how, tuple(points), at_mm, half_depth_mm, optimum, wavelength_nm, sensor_height_mm,
                   None if limit is None else float(limit), getattr(lens_preset, "id", ""),
                   "swing_deg" if swing_deg else "tilt_deg" if angles else "hinge_mm",
                   {"along": along, "angles_from": angles_from, "hinge_from": hinge_from,
                    "distance_from": distance_from, "hyperfocal_definition": HYPERFOCAL_DEFINITION[along]})
    rows = []
    for f, n, c, setting, focus in itertools.product(focal, list(f_number) or [math.nan], coc_mm, settings, focuses):
        for name, thick in lenses:
            row = scene.row(name, thick, f, n, c, setting, focus)
            row["movement"] = movement
            rows.append(TiltRow(**row))
    models = tuple(dict.fromkeys(r.model for r in rows))
    notes = [f"{' / '.join(models)} model", f"{movement} θ and angles {ANGLE_TEXT[angles_from]}", HINGE_TEXT[hinge_from],
             f"focus, near, far {ALONG_TEXT[along]}", f"hyperfocal: {HYPERFOCAL_DEFINITION[along]}"]
    if any(r.tilt_deg == 0 for r in rows):
        notes.append("no tilt: the wedge is ordinary depth of field (hinge at infinity)")
    if at_mm is not None:
        notes.append("above/below: the wedge either side of the plane of focus, parallel to the film")
    if "raytrace" in models:
        notes.append("raytrace: film at the real focus, plane of focus by real rays across the picture's height, "
                     + ("wedge along the axis by real rays" if along == "axis" else "wedge from thick"))
    return TiltAnswer(tuple(rows), movement, models, tuple(notes))


def check_lens(*, model: str = "auto", lens: LensData | None = None, focal_length_mm: Sequence[float] = (),
               f_number: Sequence[float] = (), half_depth_mm: float | None = None) -> None:
    """Refuse a model the lens data do not allow, a focal length a prescription contradicts, no f-number.

    ``raytrace`` needs a prescription (``ModelUnavailable``); with one, each
    focal length given must be its own within 1 % (``DomainError``), without
    one a focal length is needed; the f-number may be left out only when
    ``half_depth_mm`` asks for it.

    >>> check_lens(focal_length_mm=[90.0], half_depth_mm=1000.0)
    >>> check_lens(focal_length_mm=[90.0])
    Traceback (most recent call last):
    ...
    camtool.exposure.calculator.SettingsError: Missing option 'f_number' (or half_depth_mm with at_mm to get the f-number).
    """
    _models(model, lens)
    _focal_lengths(focal_length_mm, lens)
    if not f_number and half_depth_mm is None:
        raise SettingsError("Missing option '{f_number}' (or {half_depth_mm} with {at_mm} to get the f-number).",
                            ["f_number", "half_depth_mm", "at_mm"])


def _models(model: str, lens: LensData | None) -> list[tuple[str, bool]]:
    """(name, thick lens?) per model row: thin always, thick with lens data, raytrace with a prescription."""
    if model not in MODELS:
        raise DomainError("model", model, ", ".join(MODELS))
    thick = lens is not None and lens.thick_parameters() is not None
    from camtool.dof.rungs import in_air, traceable

    traced = lens is not None and traceable(lens)
    if model == "raytrace" and not traced:
        found = lens.prescription if lens is not None else None
        raise ModelUnavailable("raytrace", in_air(found) if found is not None else "a lens prescription")
    if model == "auto":  # the rung of the hyperfocal distance, as dof and hyperfocal have it at H and beyond
        from camtool.dof.ladder import hyperfocal_rung

        return [("thick", True)] if hyperfocal_rung(lens) == "thick" else [("thin", False)]
    if model == "all":
        return [("thin", False)] + ([("thick", True)] if thick else []) + ([("raytrace", True)] if traced else [])
    return [(model, model != "thin")]


def _focal_lengths(given: Sequence[float], lens: LensData | None) -> list[float]:
    """The prescription's focal length (each one given must agree within 1 %), else those given."""
    if lens is not None and lens.prescription is not None:
        from camtool.dof.ladder import prescription_focal_length

        return [prescription_focal_length(lens, f) for f in (list(given) or [None])]  # type: ignore[list-item]
    if not given:
        raise SettingsError("Missing option '{focal_length_mm}'.", ["focal_length_mm"])
    return list(given)


def _cos(theta: float) -> float:
    return math.cos(math.radians(theta))


class _Scene:
    """What every row of one question shares; :meth:`row` solves one scene with one model."""

    def __init__(self, data: LensData | None, how: str | None, points: tuple[tuple[float, float], ...],
                 at: float | None, half_depth: float | None, optimum: bool, wavelength: float,
                 sensor_height: float, limit: float | None, lens_id: str, setting_param: str,
                 conventions: dict[str, str]) -> None:
        self.data, self.how, self.points, self.at, self.half_depth = data, how, points, at, half_depth
        self.optimum, self.wavelength, self.sensor_height = optimum, wavelength, sensor_height
        self.limit, self.lens_id, self.setting_param, self.conventions = limit, lens_id, setting_param, conventions

    def row(self, model: str, thick: bool, f: float, n: float, c: float, setting: float,
            focus: float) -> dict[str, Any]:
        from camtool.dof import tilt as lib

        data, conventions = self.data, self.conventions
        lens = _tilt_lens(data, f, thick)
        along, distance_from = conventions["along"], conventions["distance_from"]
        if self.points:
            try:
                theta, v0 = _from_points(lens, self.points, distance_from)
            except DomainError as error:
                typed = " and ".join(f"{x / 1000:g} m@{h / 1000:g} m" for x, h in self.points)
                raise DomainError("points", typed, error.valid) from None
            param = "points"
        elif self.setting_param != "hinge_mm":
            theta, v0, param = setting, None, self.setting_param
        else:
            theta, v0, param = _tilt_for_hinge(lens, setting, conventions["hinge_from"]), None, "hinge_mm"
        if self.limit is not None and abs(theta) > self.limit * (1 + 1e-9):
            raise BeyondLensRange(param, theta, self.limit, self.lens_id)
        if v0 is None and self.how is not None:
            if self.how == "image":
                if focus < f:
                    raise DomainError("image_distance_mm", focus, "at least the focal length, {limit} (focus at "
                                      "infinity along the axis)", limit=f)
                v0 = focus * _cos(theta)
            elif self.how == "distance":
                v0 = lib.film_for_focus(lens, theta, focus, along, distance_from)
            elif self.how == "hyperfocal":
                if not math.isfinite(n):
                    raise SettingsError("{hyperfocal} needs {f_number}", ["hyperfocal", "f_number"])
                v0 = lib.hyperfocal_film(lens, n, c, theta, along)
        row: dict[str, Any] = {"model": model, "focal_length_mm": f, "f_number": n if math.isfinite(n) else None,
                               "coc_mm": c, "tilt_deg": theta, **conventions}
        # a hinge given is reported as given (not through asin and back)
        row["hinge_mm"] = setting if param == "hinge_mm" else abs(_hinge_from(lens, theta, conventions["hinge_from"]))
        row.update(dict.fromkeys(_COMPUTED))
        if v0 is None:
            return row
        self._fill(row, lib, lens, n, c, theta, v0)
        if model == "raytrace":
            assert data is not None
            _traced(row, data, lens, theta, v0, self.sensor_height, conventions)
        return row

    def _fill(self, row: dict[str, Any], lib: Any, lens: TiltLens, n: float, c: float, theta: float,
              v0: float) -> None:
        """The wedge's distances and angles in the conventions asked for."""
        at, half_depth, conventions = self.at, self.half_depth, self.conventions
        f = lens.focal_length_mm
        cos = _cos(theta)
        along, sensor = conventions["along"], conventions["distance_from"] == "sensor"

        def distance(k: float) -> float:
            return _distance_at(f, theta, k, v0, lens, along, sensor)

        def angle(phi: float) -> float:
            return _angle(phi, theta, conventions["angles_from"])

        row["image_distance_mm"] = v0 / cos
        plane = lib.tilt_wedge(lens, n, c, theta, v0) if math.isfinite(n) else None
        # the focus needs no f-number
        k_focus = cos / f - 1.0 / v0
        row["focus_mm"] = distance(k_focus)
        from camtool.geometry.tilt import plane_angle_deg

        row["focus_plane_deg"] = angle(float(plane_angle_deg(f, theta, k_focus)))
        sight_offset = v0 + lens.hiatus_mm * cos if sensor else 0.0
        at_h = None
        if at is not None:
            at_h = at - sight_offset
            if not at_h > 0:
                raise DomainError("at_mm", at, "beyond the lens ({limit} from the sensor)", limit=sight_offset)
            row["at_mm"] = at
        if half_depth is not None and at_h is not None:
            row["half_depth_mm"] = half_depth
            if theta == 0:
                raise TiltError("half_depth_mm", "needs a tilt: with none the wedge is a slab parallel to the film, "
                                "unbounded above and below")
            needed = lib.required_f_number(lens, c, theta, v0, at_h, half_depth)
            row["f_number_needed"] = needed
            if self.optimum:
                m = abs(f / (1.0 / (1.0 / f - 1.0 / (v0 / cos)) - f)) if v0 / cos > f else 0.0
                best, blur = lib.optimum_f_number(needed, c, self.wavelength, m, lens.pupil_magnification)
                row["f_number_optimum"], row["blur_optimum_mm"] = best, blur
            if not math.isfinite(n):
                n = needed
                row["f_number"] = needed
                plane = lib.tilt_wedge(lens, n, c, theta, v0)
        if plane is None:
            return
        row["near_mm"], row["far_mm"] = distance(plane.k_near), distance(plane.k_far)
        row["near_plane_deg"], row["far_plane_deg"] = angle(plane.near_deg), angle(plane.far_deg)
        row["wedge_deg"] = abs(plane.near_deg - plane.far_deg)
        if at_h is not None:
            s = math.sin(math.radians(abs(theta)))
            if s == 0:
                row["above_mm"] = row["below_mm"] = math.inf
                row["across_mm"] = (1.0 / plane.k_far if plane.k_far > 0 else math.inf) - 1.0 / plane.k_near
            else:
                row["above_mm"] = f / s * at_h * (plane.k_near - plane.k_focus)
                row["below_mm"] = f / s * at_h * (plane.k_focus - plane.k_far)
                row["across_mm"] = sum(f * at_h * abs(plane.k_focus - k) / math.hypot(s, f * k)
                                       for k in (plane.k_near, plane.k_far))
        v_h = lib.hyperfocal_film(lens, n, c, theta, along)
        hyper = lib.tilt_wedge(lens, n, c, theta, v_h)
        # distances of the hyperfocal setting: its own lens-to-film spacing
        row["hyperfocal_mm"] = _distance_at(f, theta, hyper.k_focus, v_h, lens, along, sensor)
        row["hyperfocal_near_mm"] = _distance_at(f, theta, hyper.k_near, v_h, lens, along, sensor)


def _angle(phi: float, theta: float, angles_from: str) -> float:
    """An angle from the film (``phi``) as measured from the film, the lens plane or the line of sight."""
    return {"film": phi, "lens": phi - theta, "horizon": 90.0 - phi}[angles_from]


def _tilt_lens(data: LensData | None, f: float, thick: bool) -> TiltLens:
    if not thick or data is None:
        return TiltLens(f)
    known = data.thick_parameters()
    assert known is not None
    p, delta = known
    return TiltLens(f, float(p), float(delta))


def _pupil_y(lens: TiltLens, theta: float) -> float:
    """Height (y) of the entrance pupil above H's line of sight: e·sin θ."""
    return lens.entrance_pupil_mm * math.sin(math.radians(theta))


def _hinge_from(lens: TiltLens, theta: float, hinge_from: str) -> float:
    from camtool.geometry.tilt import hinge_distance_mm

    j = hinge_distance_mm(lens.focal_length_mm, theta)
    return float(j - _pupil_y(lens, theta) if hinge_from == "pupil" and math.isfinite(j) else j)


def _tilt_for_hinge(lens: TiltLens, hinge: float, hinge_from: str) -> float:
    """Tilt for a hinge J from the lens (asin(f/J)) or from the entrance pupil (e·s² + J·s − f = 0)."""
    from camtool.geometry.tilt import tilt_for_hinge_deg

    e = lens.entrance_pupil_mm
    if hinge_from == "lens" or e == 0 or math.isinf(hinge):
        tilt = float(tilt_for_hinge_deg(lens.focal_length_mm, hinge))
        if not abs(tilt) < 90.0:  # J = f/sin θ: a hinge at the focal length or closer needs a tilt of 90° or more
            raise DomainError("hinge_mm", hinge, "more than {limit} from the lens (the focal length: a tilt below 90°)",
                              limit=lens.focal_length_mm)
        return tilt
    f = lens.focal_length_mm
    disc = hinge * hinge + 4.0 * e * f
    sin = (-hinge + math.sqrt(disc)) / (2.0 * e) if disc >= 0 else 2.0
    if not 0 < sin <= 1:
        raise DomainError("hinge_mm", hinge, "far enough from the entrance pupil for a tilt below 90°")
    return math.degrees(math.asin(sin))


def _from_points(lens: TiltLens, points: tuple[tuple[float, float], ...], distance_from: str) -> tuple[float, float]:
    """Tilt and film distance v for the plane through two points (from the sensor: iterate the lens position)."""
    from camtool.geometry.tilt import plane_through_points

    f = lens.focal_length_mm
    shift = 0.0
    solution = None
    for _ in range(60 if distance_from == "sensor" else 1):
        (x1, h1), (x2, h2) = points
        solution = plane_through_points(f, x1 - shift, -h1, x2 - shift, -h2)
        cos = _cos(solution.tilt_deg)
        v0 = 1.0 / (cos / f - solution.reciprocal_mm)
        new_shift = v0 + lens.hiatus_mm * cos
        if abs(new_shift - shift) < 1e-12 * max(1.0, new_shift):
            break
        shift = new_shift
    assert solution is not None
    cos = _cos(solution.tilt_deg)
    return solution.tilt_deg, 1.0 / (cos / f - solution.reciprocal_mm)


def _distance_at(f: float, theta: float, k: float, v0: float, lens: TiltLens, along: str, sensor: bool) -> float:
    from camtool.geometry.tilt import axis_reciprocal

    cos = _cos(theta)
    recip = axis_reciprocal(f, theta, k) if along == "axis" else k
    if recip <= 1e-13 / f:  # parallel to the line (to rounding) or crossing it behind the lens
        return math.inf
    offset = (v0 / cos + lens.hiatus_mm if along == "axis" else v0 + lens.hiatus_mm * cos) if sensor else 0.0
    return float(1.0 / recip + offset)


def _traced(row: dict[str, Any], data: LensData, lens: TiltLens, theta: float, v0: float, sensor_height: float,
            conventions: dict[str, str]) -> None:
    """Real rays: the film at the real best focus of the point where the plane of focus crosses the lens axis;
    the plane of focus through the picture's top and bottom edges; the wedge along the axis by the raytrace rung."""
    from camtool.dof.ladder import depth_of_field
    from camtool.dof.realray import real_focus
    from camtool.optics.tilted import traced_plane_of_focus

    assert data.prescription is not None and data.first_order is not None
    f = lens.focal_length_mm
    cos = _cos(theta)
    n, c = row["f_number"], row["coc_mm"]
    z_hp = data.first_order.z_h_prime_mm
    axis_focus = 1.0 / (1.0 / f - cos / v0) if v0 > f * cos else math.inf
    sensor_plane = conventions["distance_from"] == "sensor"
    if n is not None:
        v0 = (real_focus(data.prescription, n, axis_focus, "lens").film_z_mm - z_hp) * cos
    k_model = cos / f - 1.0 / v0
    field = math.degrees(math.atan(sensor_height / 2.0 / v0))
    traced = traced_plane_of_focus(data.prescription, theta, v0, k_model, field_deg=field)
    if n is not None and conventions["along"] == "axis":
        limits = depth_of_field("raytrace", f, n, c, axis_focus, "lens", lens=data).limits
        offset = (v0 / cos + lens.hiatus_mm) if sensor_plane else 0.0
        row["near_mm"], row["far_mm"] = limits.near_mm + offset, limits.far_mm + offset
    row["image_distance_mm"] = v0 / cos
    row["focus_mm"] = _traced_distance(traced, f, theta, v0, lens, conventions["along"], sensor_plane)
    row["focus_plane_deg"] = _angle(traced.focus_deg, theta, conventions["angles_from"])
    j = abs(traced.hinge_mm)
    if conventions["hinge_from"] == "pupil" and math.isfinite(j):
        j = abs(traced.hinge_mm - _pupil_y(lens, theta))
    row["hinge_mm"] = j


def _traced_distance(traced: Any, f: float, theta: float, v0: float, lens: TiltLens, along: str, sensor: bool) -> float:
    """Where the traced plane crosses the line of sight (or the lens axis) in the plane asked for."""
    cos = _cos(theta)
    if along == "sight":
        k = traced.k_focus
        if not k > 0:
            return math.inf
        return float(1.0 / k + ((v0 + lens.hiatus_mm * cos) if sensor else 0.0))
    # the traced line through (0, J) and (1/k, 0) met by t·(cos θ, sin θ)
    j, k = traced.hinge_mm, traced.k_focus
    s = math.sin(math.radians(theta))
    denominator = s + j * k * cos
    if not (math.isfinite(j) and denominator * j > 0):
        return math.inf
    return float(j / denominator + ((v0 / cos + lens.hiatus_mm) if sensor else 0.0))
